"""`cleanup.command_scope` removes its directory however the command ends, also when a dying process writes
there after the first removal (`test_signals`' random signals hit that only now and then)."""

from __future__ import annotations

import os
import shutil
import tempfile

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
