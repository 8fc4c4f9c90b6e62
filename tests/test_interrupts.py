"""Interrupts that land where Python cannot propagate them as they are (a weak-reference callback, a
dataclass field's `__set_name__`) are not lost and print no traceback."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
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


#: Run the CLI with a signal sent while a class of the package whose fields have defaults is being created:
#: Python 3.11 wraps an exception raised in `__set_name__` (a dataclass `field()`) in a RuntimeError.
_SIGNAL_IN_SET_NAME = """
import dataclasses, os, signal, sys
module, signum = sys.argv[1], getattr(signal, sys.argv[2])
original = dataclasses.Field.__set_name__
def signalling(self, owner, name):
    if owner.__module__ == module:
        os.kill(os.getpid(), signum)
        for _ in range(10_000):  # the handler runs here
            pass
    return original(self, owner, name)
dataclasses.Field.__set_name__ = signalling
sys.argv = ["foon2pddl", "plan", "--goal", "guacamole"]
from foon2pddl.__main__ import run
run()
"""


@pytest.mark.parametrize(("module", "name", "status", "word"), [
    ("foon2pddl.model.foon", "SIGTERM", 143, "terminated"),  # imported by the command (click has started it)
    ("foon2pddl.model.foon", "SIGINT", 130, "interrupted"),
])
def test_a_signal_while_a_dataclass_is_created_exits_without_a_traceback(module, name, status, word):
    # found by test_signals at load 10: `plan` printed "RuntimeError: Error calling __set_name__ on 'Field'
    # instance 'origin' in 'Overrides'" and its traceback when SIGTERM came during a lazy import
    done = subprocess.run([sys.executable, "-c", _SIGNAL_IN_SET_NAME, module, name], capture_output=True,
                          text=True, timeout=120)
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
    assert done.returncode == status, (done.returncode, done.stderr[-2000:])
    assert done.stderr.strip().splitlines()[-1] == word


_SIGNAL_IN_CALLBACK_AT_START = """
import os, signal, sys, time, weakref
from foon2pddl.io.interrupts import exit_on_signals
exit_on_signals()  # as `foon2pddl` does first, while its modules load
class Node:
    pass
def callback(_ref):
    os.kill(os.getpid(), getattr(signal, sys.argv[1]))
    for _ in range(10_000):  # the handler runs here, inside the callback
        pass
node = Node()
ref = weakref.ref(node, callback)
del node
for _ in range(500):
    time.sleep(0.01)
print("not interrupted")
"""


@pytest.mark.parametrize(("name", "status"), [("SIGTERM", 143), ("SIGINT", 130)])
def test_a_signal_inside_a_weakref_callback_at_start_up_still_ends_the_process(name, status):
    # found by test_signals at load 12: SIGTERM landed in importlib's module-lock weakref callback while the
    # CLI's modules loaded; Python printed "Exception ignored ... Traceback" and the command ran to its end
    done = subprocess.run([sys.executable, "-c", _SIGNAL_IN_CALLBACK_AT_START, name], capture_output=True,
                          text=True, timeout=120)
    assert (done.returncode, done.stdout) == (status, ""), done.stderr[-2000:]
    assert "Traceback" not in done.stderr and "Exception ignored" not in done.stderr, done.stderr[-2000:]
