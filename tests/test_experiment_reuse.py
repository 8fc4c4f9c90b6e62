"""Translations the experiment reuses: lifted GEN translated once per trial, and one translation shared by
`fd-tree` and `fd-tree-opt` (a directory of SAS files keyed by the PDDL they translate).

The oracle is planning each goal afresh (`planners.solve.plan`, pruned per goal), which the reuse replaces.
"""

from __future__ import annotations

import random

import pytest

from foon2pddl.experiment import worker
from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import sample_kitchen
from foon2pddl.experiment.solvers import OPTIMAL_SEARCH, Setting, get_solver
from foon2pddl.generalize.categories import shipped_index
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.tasktree import validate
from foon2pddl.planners import fd_reuse
from foon2pddl.planners.solve import GoalReplanner, plan

INDEX = shipped_index()


@pytest.fixture(scope="module")
def kitchen():
    return read_kitchen(example_path("example_kitchen.txt"))


def _goals(foon, count: int, seed: int, kitchen=None) -> list[Goal]:
    """Goals as the experiment draws them: nodes some unit makes, none in the kitchen."""
    have = kitchen.project(foon.level).nodes if kitchen is not None else frozenset()
    nodes = random.Random(seed).sample(sorted(n for n in foon.producers if n not in have), count)
    return [Goal(spec_of_node(n), (n,), foon.level) for n in nodes]


@pytest.mark.parametrize("seed", [1, 2])
def test_lifted_gen_on_one_translation_solves_exactly_what_planning_each_goal_solves(example, kitchen, seed):
    foon = example.foon
    kitchen = kitchen if seed == 1 else sample_kitchen(default_kitchen(foon), 0.6, seed)
    replanner = GoalReplanner(foon, kitchen, "gen-lifted", foon.level, category_index=INDEX, time_limit=60)
    statuses = []
    for goal in _goals(foon, 25, seed, kitchen):
        fresh = plan(foon, kitchen, goal, "gen-lifted", category_index=INDEX, time_limit=60)
        reused = replanner.plan(goal, time_limit=60)
        assert reused.status == fresh.status, goal.describe()
        if reused.tree is not None:
            assert validate(reused.tree, kitchen.nodes).ok  # its goal may be renamed (lime juice for lemon juice)
        statuses.append(str(reused.status))
    assert "solved" in statuses and "unsolvable" in statuses  # both kinds: the test can fail either way


def test_every_goal_action_of_the_lifted_task_is_one_writing_of_its_candidate(example, kitchen):
    from foon2pddl.pddl.compile import compile_goal

    foon = example.foon
    nodes = tuple(sorted(foon.nodes))
    task = compile_goal(foon, kitchen, Goal(spec_of_node(nodes[0]), nodes, 3), "gen-lifted", 3, prune=False,
                        category_index=INDEX).task
    aux = [a for a in task.actions if a.unit is None]
    replanner = GoalReplanner(foon, kitchen, "gen-lifted", 3, category_index=INDEX, time_limit=60)
    assert set(replanner.node_atoms) == set(nodes)
    assert sum(map(len, replanner.node_atoms.values())) == len(aux) > len(nodes)  # some node has two writings
    assert [alt for n in nodes for alt in replanner.node_atoms[n]] == [tuple(a.pre) for a in aux]


def test_fd_tree_and_fd_tree_opt_share_one_translation_through_the_cache(example, kitchen, tmp_path, monkeypatch):
    calls = []
    translate = fd_reuse.fd.translate

    def counting(*args, **kw):
        calls.append(args[0])
        return translate(*args, **kw)

    monkeypatch.setattr(fd_reuse.fd, "translate", counting)
    view = build_view("reg", example, 3)
    setting = Setting(view, kitchen, 60, tmp_path)
    tree = get_solver("fd-tree").prepare(setting)
    opt = get_solver("fd-tree-opt").prepare(setting)
    assert len(calls) == 1 and len(list(tmp_path.glob("*.sas"))) == 1
    assert opt.replanner.translated.sas == tree.replanner.translated.sas
    assert opt.replanner.translated.search == OPTIMAL_SEARCH
    for goal in _goals(example.foon, 8, 3):
        node = goal.candidates[0]
        a, b = tree.solve(node), opt.solve(node)
        assert a.status == b.status
        if b.units is not None:
            assert b.units <= a.units  # the optimal search on the shared translation is still optimal


def test_a_cache_entry_is_keyed_by_the_pddl_and_options_and_written_whole(tmp_path):
    fd_reuse.store_sas(tmp_path, "d", "p", ("--x",), "begin_version\n3\nend_version\n")
    assert fd_reuse.cached_sas(tmp_path, "d", "p", ("--x",)) == "begin_version\n3\nend_version\n"
    assert fd_reuse.cached_sas(tmp_path, "d", "p", ("--y",)) is None
    assert fd_reuse.cached_sas(tmp_path, "d2", "p", ("--x",)) is None
    assert not list(tmp_path.glob("*.part"))
    fd_reuse.store_sas(tmp_path / "missing", "d", "p", (), "x")  # a failed write only loses the reuse
    assert fd_reuse.cached_sas(tmp_path / "missing", "d", "p", ()) is None


def test_a_local_run_shares_a_private_cache_and_removes_it(tmp_path, monkeypatch):
    from foon2pddl.experiment import runner

    seen = []
    run_batch = worker.run_batch

    def spy(batch, job, *args, **kw):
        seen.append(job.cache)
        return run_batch(batch, job, *args, **kw)

    monkeypatch.setattr(runner, "run_here", lambda batches, job, sink, progress: [
        sink(r) or progress.update() for b in batches for r in spy(b, job)])
    config = runner.Config(paths=(), protocol=runner.Protocol(trials=1, goals=3), networks=("reg",),
                           solvers=("fd-tree", "fd-tree-opt"), out_dir=tmp_path / "out")
    summary = runner.run(config, progress=False)
    assert len(summary.records) == 6 and all(r.status != "error" for r in summary.records)
    assert len(set(seen)) == 1 and seen[0] is not None
    from pathlib import Path

    assert not Path(seen[0]).exists()
