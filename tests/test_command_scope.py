"""`cleanup.command_scope` removes its directory however the command ends, also at the two moments
`test_signals`' random signals hit only now and then: a signal held while the directory is made, and a file a
dying process writes there after the first removal."""

from __future__ import annotations

import os
import shutil
import signal
import tempfile

import pytest

from foon2pddl.planners import cleanup


class _Stopped(Exception):
    """What the test's SIGTERM handler raises (the CLI's handler ends the command the same way)."""


def _raise(signum, frame):
    raise _Stopped


@pytest.fixture
def private_tmp(tmp_path, monkeypatch):
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    return tmp_path


def test_a_signal_held_while_the_directory_is_made_still_removes_it(private_tmp, monkeypatch):
    made = tempfile.mkdtemp

    def make_then_signal(*args, **kwargs):
        path = made(*args, **kwargs)
        os.kill(os.getpid(), signal.SIGTERM)  # held by signals_deferred: delivered as its block ends
        return path

    monkeypatch.setattr(tempfile, "mkdtemp", make_then_signal)
    old = signal.signal(signal.SIGTERM, _raise)
    try:
        with pytest.raises(_Stopped), cleanup.command_scope():
            pytest.fail("the held signal ends the command before it starts")
    finally:
        signal.signal(signal.SIGTERM, old)
    assert list(private_tmp.iterdir()) == []
    assert os.environ["TMPDIR"] == str(private_tmp) and cleanup.SCOPE_MARK not in os.environ


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
