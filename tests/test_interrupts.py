"""An interrupt that lands inside a weak-reference callback is not lost and prints no traceback."""

from __future__ import annotations

import os
import signal
import time
import weakref

import pytest

from foon2pddl.io.interrupts import Terminated, sigterm_raises


class _Node:
    pass


def test_an_interrupt_inside_a_weakref_callback_is_delivered_after_it(capfd):
    # a SIGTERM whose handler runs while the garbage collector runs a cache's weakref callback (model/memo.py)
    def callback(_ref):
        os.kill(os.getpid(), signal.SIGTERM)
        for _ in range(10_000):  # the handler runs here, inside the callback
            pass

    with pytest.raises(Terminated), sigterm_raises():
        node = _Node()
        ref = weakref.ref(node, callback)
        del node
        for _ in range(500):
            time.sleep(0.01)
    assert ref() is None
    assert "Exception ignored" not in capfd.readouterr().err
