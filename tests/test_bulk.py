"""Network-sized builds and the cyclic garbage collector (`model.bulk`)."""

from __future__ import annotations

import gc
from unittest.mock import patch

from foon2pddl.model import bulk


def test_builds_hold_back_full_collections_only():
    before = gc.get_threshold()
    with bulk.full_gc_paused():
        assert gc.isenabled()
        assert gc.get_threshold()[:2] == before[:2] and gc.get_threshold()[2] > before[2]
        with bulk.full_gc_paused():  # nests
            assert gc.get_threshold()[2] > before[2]
        assert gc.get_threshold()[2] > before[2]
    assert gc.get_threshold() == before


def test_a_process_keeping_its_builds_freezes_them():
    """Under KEEP_BUILDS (the CLI) nothing is collected during a build, and what it built is frozen after."""
    made = []
    try:
        with patch.object(bulk, "KEEP_BUILDS", True):
            frozen = gc.get_freeze_count()
            with bulk.full_gc_paused():
                assert not gc.isenabled()
                with bulk.full_gc_paused():  # nests: still off, nothing frozen yet
                    made.append([[] for _ in range(100)])
                    assert not gc.isenabled()
                assert not gc.isenabled() and gc.get_freeze_count() == frozen
            assert gc.isenabled()
            assert gc.get_freeze_count() >= frozen + 100  # the lists built are in the permanent generation
    finally:
        gc.unfreeze()
        gc.enable()
