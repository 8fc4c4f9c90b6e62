"""Translations the experiment reuses: lifted GEN translated once per trial, and one translation shared by
`fd-tree` and `fd-tree-opt` (a directory of SAS files keyed by the PDDL they translate).

The oracle is planning each goal afresh (`planners.solve.plan`, pruned per goal), which the reuse replaces.
"""

from __future__ import annotations

import random

import pytest

from foon2pddl.experiment import worker
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.fd_solvers import OPTIMAL_SEARCH
from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import Protocol, sample_kitchen
from foon2pddl.experiment.setting import Setting
from foon2pddl.experiment.solvers import get_solver
from foon2pddl.generalize.categories import shipped_index
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.tasktree import validate
from foon2pddl.planners import fd_reuse
from foon2pddl.planners.goal_replanner import GoalReplanner
from foon2pddl.planners.sas import parse_sas
from foon2pddl.planners.solve import plan

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
    config = Config(paths=(), protocol=Protocol(trials=1, goals=3), networks=("reg",),
                           solvers=("fd-tree", "fd-tree-opt"), out_dir=tmp_path / "out")
    summary = runner.run(config, progress=False)
    assert len(summary.records) == 6 and all(r.status != "error" for r in summary.records)
    assert len(set(seen)) == 1 and seen[0] is not None
    from pathlib import Path

    assert not Path(seen[0]).exists()


@pytest.mark.parametrize("seed", [4, 5])
def test_one_translation_from_the_default_kitchen_serves_a_kitchen_within_it_as_its_own_would(example, seed):
    """`for_kitchen` (every experiment trial on one translation): the task is the one compiled from the smaller
    kitchen, the translation keeps the operators the translator keeps for it, and every goal gets the status
    that planning it afresh (pruned per goal, its own translation) gives."""
    foon = example.foon
    whole = default_kitchen(foon)
    base = GoalReplanner(foon, whole, kitchens=True)
    kitchen = sample_kitchen(whole, 0.9, seed)
    derived, own = base.for_kitchen(kitchen), GoalReplanner(foon, kitchen)
    assert derived.task.init == own.task.init != base.task.init
    assert derived.task.actions == own.task.actions
    ops = derived.translated.sas.operators
    assert len(ops) == len(own.translated.sas.operators) < len(base.translated.sas.operators)
    assert sorted(o.split("\n")[1] for o in ops) == sorted(o.split("\n")[1] for o in own.translated.sas.operators)
    atoms = {f for f in derived.translated.sas.facts if f.startswith("atom ")}
    owned = {f for f in own.translated.sas.facts if f.startswith("atom ")}
    assert atoms - owned == {fd_reuse.sas_fact_name(a) for a in own.task.init}  # kitchen atoms: not static here
    statuses = set()
    for goal in _goals(foon, 20, seed, kitchen):
        reused, fresh = derived.plan(goal, time_limit=60), plan(foon, kitchen, goal, time_limit=60)
        assert reused.status == fresh.status, goal.describe()
        if reused.tree is not None:
            assert validate(reused.tree, kitchen.nodes).ok
        statuses.add(str(reused.status))
    assert statuses == {"solved", "unsolvable"}


def test_only_a_kitchen_within_the_translated_one_is_served(example):
    from foon2pddl.model.kitchen import Kitchen

    foon = example.foon
    whole = default_kitchen(foon)
    made = next(n for n in sorted(foon.producers) if n not in whole.nodes)
    with pytest.raises(ValueError):
        GoalReplanner(foon, whole, kitchens=True).for_kitchen(Kitchen(whole.nodes | {made}))
    with pytest.raises(ValueError):  # not built to serve other kitchens
        GoalReplanner(foon, whole).for_kitchen(sample_kitchen(whole, 0.5, 1))
    with pytest.raises(ValueError):  # the lifted encoding's domain depends on the kitchen
        GoalReplanner(foon, whole, "gen-lifted", category_index=INDEX, kitchens=True).for_kitchen(
            sample_kitchen(whole, 0.5, 1))


_SAS = ("begin_version\n3\nend_version\nbegin_metric\n0\nend_metric\n3\n"
        "begin_variable\nvar0\n-1\n2\nAtom a()\nNegatedAtom a()\nend_variable\n"
        "begin_variable\nvar1\n-1\n2\nAtom b()\nNegatedAtom b()\nend_variable\n"
        f"begin_variable\nvar2\n-1\n2\nAtom {fd_reuse.ANCHOR}()\nNegatedAtom {fd_reuse.ANCHOR}()\nend_variable\n"
        "0\nbegin_state\n0\n1\n1\nend_state\nbegin_goal\n1\n2 0\nend_goal\n3\n"
        "begin_operator\nmake-b \n1\n0 0\n1\n0 1 -1 0\n1\nend_operator\n"
        f"begin_operator\n{fd_reuse.ANCHOR} \n0\n1\n0 2 -1 0\n0\nend_operator\n"
        f"begin_operator\n{fd_reuse.FORGET_OP}0 \n0\n1\n0 0 -1 1\n0\nend_operator\n0\n")


def test_a_new_initial_state_drops_what_it_cannot_reach():
    sas = parse_sas(_SAS, f"atom {fd_reuse.ANCHOR}()", (fd_reuse.ANCHOR, fd_reuse.FORGET_OP))
    assert [o.split("\n")[1] for o in sas.operators] == ["make-b "]  # the anchor and forget operators go
    kept = sas.at_init({"atom a()"})
    assert kept.state == (0, 1, 1) and "begin_state\n0\n1\n1\nend_state\n" in kept.head and len(kept.operators) == 1
    assert {"atom a()", "atom b()"} <= set(kept.facts)
    bare = sas.at_init(set())
    assert bare.state == (1, 1, 1) and bare.operators == ()
    assert "atom a()" not in bare.facts and "atom b()" not in bare.facts  # goals on them: unsolvable, no search
    assert bare.relevant([(1, 0)]) == []
    with pytest.raises(ValueError):
        sas.at_init({"atom c()"})  # a fact the translation does not have


def test_a_goal_task_holds_only_the_variables_its_operators_and_goal_mention():
    sas = parse_sas(_SAS, f"atom {fd_reuse.ANCHOR}()", (fd_reuse.ANCHOR, fd_reuse.FORGET_OP))
    text = sas.task_text([(1, 0)], list(sas.operators), {0, 1})
    assert text.count("begin_variable") == 2 and "begin_state\n0\n1\nend_state" in text
    assert "begin_goal\n1\n1 0\nend_goal" in text and "1\n0 0\n1\n0 1 -1 0\n" in text
    alone = sas.task_text([(1, 0)], [], set())  # var1 alone is renumbered 0
    assert alone.count("begin_variable") == 1 and "begin_goal\n1\n0 0\nend_goal" in alone
    assert "NegatedAtom b()" in alone and "Atom a()" not in alone and "begin_state\n1\nend_state" in alone


def test_only_a_forgettable_translation_starts_elsewhere_and_auxiliary_names_are_reserved():
    from foon2pddl.pddl.task import Action, PlanningTask

    sas = parse_sas(_SAS, f"atom {fd_reuse.ANCHOR}()", (fd_reuse.ANCHOR, fd_reuse.FORGET_OP))
    task = PlanningTask("d", "p", "tree", 3, (), (), (), ())
    with pytest.raises(ValueError, match="forgettable"):  # a dropped static atom would go unseen
        fd_reuse.TranslatedTask(task, sas, 0.0).at_init(task)
    assert fd_reuse.TranslatedTask(task, sas, 0.0, forgettable=True).at_init(task).sas.state == (1, 1, 1)
    taken = PlanningTask("d", "p", "tree", 3, (), (Action(f"{fd_reuse.ANCHOR}ed", (), ()),), (), ())
    with pytest.raises(ValueError, match="foon2pddl-reuse-"):  # parse_sas would skip it by its prefix
        fd_reuse._anchored(taken)
