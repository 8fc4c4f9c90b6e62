"""What the experiment's main process computes once and ships to workers: trials drawn once per point, Dask
tasks that name their trial instead of carrying its kitchen, record lines written without `asdict`."""

from __future__ import annotations

import json
import pickle
from dataclasses import asdict, replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.errors import FoonError
from foon2pddl.experiment import grid, runner, worker
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.protocol import Protocol, draw, goal_pool, make_trial
from foon2pddl.experiment.records import CellStatus, Record
from foon2pddl.model.kitchen import default_kitchen


@pytest.fixture(scope="module")
def reg(example):
    return example.foon


def test_draw_equals_trials_drawn_one_by_one(reg):
    protocol = Protocol(trials=4, goals=7, kitchen_fraction=0.6, seed=3)
    drawn = draw(reg, protocol)
    assert drawn.trials == tuple(make_trial(reg, protocol, i) for i in range(1, 5))
    assert drawn.kitchen == default_kitchen(reg) and drawn.pool == goal_pool(reg)
    assert [t.index for t in drawn.trials] == [1, 2, 3, 4]


def _config(tmp_path, **kw) -> Config:
    return Config((), Protocol(trials=2, goals=12), ("reg", "gen"), ("native-complete", "native-greedy"),
                  tmp_path, **kw)


def test_trials_are_drawn_once_per_point_of_the_sweep(tmp_path):
    config = _config(tmp_path, sweeps=(("kitchen-fraction", (0.5, 0.9)), ("banned-motions", (0, 2))))
    for point in config.points:
        assert grid.trials_at(config, point) is grid.trials_at(config, point)  # cached, not redrawn
    by_fraction = {dict(p)["kitchen-fraction"]: grid.trials_at(config, p) for p in config.points}
    assert len(by_fraction[0.5][0].kitchen) < len(by_fraction[0.9][0].kitchen)
    # a network hook (banned motions) changes what can be made, not what is asked
    half = [p for p in config.points if dict(p)["kitchen-fraction"] == 0.5]
    assert grid.trials_at(config, half[0]) == grid.trials_at(config, half[1])


def test_a_task_names_its_trial_and_the_worker_resolves_the_same_batch(tmp_path):
    config = _config(tmp_path, sweeps=(("kitchen-fraction", (0.5, 0.9)), ("banned-motions", (0, 1))))
    job = worker.Job(config.paths, worker.fingerprint(config.paths), config.protocol, config.time_limit)
    batches = grid.plan_batches(config, set())
    assert len(batches) == 4 * 2 * 2 * 2 + 2 * 2  # points x trials x networks x solvers, a probe per solver/network
    for batch in batches:
        ref = batch.ref()
        shipped = pickle.dumps(ref)
        assert b"ObjectNode" not in shipped and b"Kitchen" not in shipped  # no node travels with a task
        assert pickle.loads(shipped).resolve(job) == batch
        assert ref.records(CellStatus.LOST, "x") == batch.records(CellStatus.LOST, "x")
        assert [r.goal_label for r in ref.records(CellStatus.LOST, "x")] == [
            batch.trial.goals[g - 1].describe() for g in batch.goals]


def test_a_worker_that_draws_other_goals_answers_with_errors_not_wrong_cells(tmp_path):
    config = _config(tmp_path)
    job = worker.Job(config.paths, worker.fingerprint(config.paths), config.protocol, config.time_limit)
    batch = grid.plan_batches(config, set())[0]
    ref = batch.ref()
    wrong = replace(ref, labels=(*ref.labels[1:], ref.labels[0]))
    with pytest.raises(FoonError, match="other goals"):
        wrong.resolve(job)
    with pytest.raises(FoonError, match="other goals"):
        replace(ref, trial=99).resolve(job)
    records = worker.dask_task(wrong, job)
    assert [r.goal for r in records] == list(batch.goals)
    assert {r.status for r in records} == {CellStatus.ERROR} and "other goals" in records[0].reason


def _old_to_json(record: Record) -> str:
    """The line format as first written (dataclasses.asdict): the oracle for the faster `to_json`."""
    data = asdict(record)
    data["status"] = str(record.status)
    data["solved"] = record.solved
    data["times"] = {k: round(v, 6) for k, v in sorted(record.times.items())}
    data["setup"] = round(record.setup, 6)
    for name in ("bound", "gap", "worker", "time_limit", "executable", "executable_reason", "extra_objects",
                 "repeated"):
        if data[name] is None:
            del data[name]
    if not record.params:
        del data["params"]
    return json.dumps(data, sort_keys=True, ensure_ascii=False)


_text = st.text(max_size=12)
_num = st.floats(min_value=0, max_value=1e6, allow_nan=False)
_opt_bool = st.none() | st.booleans()


@settings(max_examples=200, deadline=None)
@given(st.builds(
    Record, trial=st.integers(1, 50), goal=st.integers(1, 500), network=_text, solver=_text, goal_label=_text,
    status=st.sampled_from(list(CellStatus)), reason=_text, times=st.dictionaries(_text, _num, max_size=4),
    setup=_num, units=st.none() | st.integers(0, 10**6), plan_length=st.none() | st.integers(0, 10**6),
    validated=_opt_bool, proven_optimal=_opt_bool, foon_valid=_opt_bool, bound=st.none() | _num,
    gap=st.none() | _num, params=st.dictionaries(_text, st.integers() | _num | _text, max_size=3),
    worker=st.none() | _text, time_limit=st.none() | _num, executable=st.none() | _text,
    executable_reason=st.none() | _text, extra_objects=st.none() | st.integers(0, 100),
    repeated=st.none() | st.integers(0, 100)))
def test_record_lines_are_byte_identical_to_the_asdict_format(record):
    line = record.to_json()
    assert line == _old_to_json(record)
    back = Record.from_json(line)
    assert back.key == record.key and back.status == record.status


def test_collector_off_while_building_then_frozen_then_as_it_was():
    import gc

    from foon2pddl.experiment import collector

    for enabled in (True, False):
        (gc.enable if enabled else gc.disable)()
        try:
            with collector.building() as settle:
                assert not gc.isenabled() and gc.get_freeze_count() == 0
                settle()
                assert gc.isenabled() == enabled and gc.get_freeze_count() > 0
                settle()  # idempotent
            assert gc.isenabled() == enabled and gc.get_freeze_count() == 0
            with pytest.raises(RuntimeError), collector.building() as settle:
                settle()
                raise RuntimeError("a failed run")
            assert gc.isenabled() == enabled and gc.get_freeze_count() == 0
        finally:
            gc.enable()


def test_a_run_builds_its_networks_with_the_collector_off_and_runs_cells_with_them_frozen(tmp_path, monkeypatch):
    import gc

    seen = {"views": [], "cells": []}
    real_view, real_here = runner.view, runner.run_here

    def view(*args):
        seen["views"].append(gc.isenabled())
        if args[-1] == "gen" and len(seen["views"]) <= 3:  # a failed build here: the batches build it again
            raise RuntimeError("gen failed once")
        return real_view(*args)

    def run_here(*args):
        seen["cells"].append((gc.isenabled(), gc.get_freeze_count() > 0))
        return real_here(*args)

    monkeypatch.setattr(runner, "view", view)
    monkeypatch.setattr(runner, "run_here", run_here)
    summary = runner.run(_config(tmp_path), progress=False)
    assert summary.ran == 2 * 12 * 2 * 2 and all(r.status != CellStatus.ERROR for r in summary.records)
    assert seen["views"] and not any(seen["views"])
    assert seen["cells"] == [(True, True)]
    assert gc.isenabled() and gc.get_freeze_count() == 0
