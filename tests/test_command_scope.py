"""`cleanup.command_scope` removes its directory however the command ends, also when a dying process writes
there after the first removal (`test_signals`' random signals hit that only now and then)."""

from __future__ import annotations

import os
import shutil
import tempfile
from types import SimpleNamespace

import pytest

from foon2pddl.planners import cleanup


@pytest.fixture
def private_tmp(tmp_path, monkeypatch):
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    return tmp_path


def test_a_file_written_after_the_first_removal_is_removed_too(private_tmp, monkeypatch):
    removals, real = [], shutil.rmtree

    def racing_rmtree(path, ignore_errors=False):
        real(path, ignore_errors=ignore_errors)
        removals.append(path)
        if len(removals) == 1:  # a dying worker's last write lands after the removal
            os.makedirs(os.path.join(path, "dask-scratch-space"))

    monkeypatch.setattr(cleanup.shutil, "rmtree", racing_rmtree)
    with cleanup.command_scope() as scope:
        assert os.path.dirname(scope) == str(private_tmp)
    assert list(private_tmp.iterdir()) == []
    assert len(removals) == 2


def test_a_process_writing_there_for_a_while_does_not_outlast_the_removals(private_tmp, monkeypatch):
    """A process the kills do not stop at once (a worker in uninterruptible I/O on a loaded machine finishes its
    system call first) recreates the directory for a while: the removals go on until it stops, bounded by
    `REMOVAL_SECONDS` of the clock, not by a count of tries (20 tries 0.02 s apart once lost that race)."""
    clock = [0.0]
    fake_time = SimpleNamespace(monotonic=lambda: clock[0], sleep=lambda s: clock.__setitem__(0, clock[0] + s))
    monkeypatch.setattr(cleanup, "time", fake_time)
    real = shutil.rmtree

    def racing_rmtree(path, ignore_errors=False):
        real(path, ignore_errors=ignore_errors)
        if clock[0] < 1.5:  # the straggler writes for 1.5 s of the clock, then is gone
            os.makedirs(os.path.join(path, "dask-scratch-space"))

    monkeypatch.setattr(cleanup.shutil, "rmtree", racing_rmtree)
    monkeypatch.setattr(cleanup, "kill_marked", lambda *a, **k: None)  # nothing to kill here: the clock alone
    with cleanup.command_scope():
        pass
    assert list(private_tmp.iterdir()) == []
    assert 1.5 <= clock[0] <= cleanup.REMOVAL_SECONDS + 0.5
