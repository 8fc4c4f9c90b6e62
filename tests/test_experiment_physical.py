"""Success as physical execution in the experiment: schedule verdicts in records, the report's physical tables.

Oracles: `planners.executable.schedule` run directly on the trees native retrieval returns, and counts
of hand-built records.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from foon2pddl.experiment import physical, runner
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.records import CellStatus, Record
from foon2pddl.experiment.render import table2_physical, verdicts_md
from foon2pddl.experiment.tables import ReportData
from foon2pddl.planners.executable import Verdict, schedule


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """One trial of 40 goals on REG and GEN, with one and with two objects per kitchen item."""
    out = {}
    for per_item in (1, 2):
        config = Config(paths=(), protocol=Protocol(trials=1, goals=40, objects_per_item=per_item),
                        networks=("reg", "gen"), solvers=("native-complete", "fd-lifted-gen"),
                        out_dir=tmp_path_factory.mktemp(f"per{per_item}"))
        out[per_item] = (config, runner.run(config, progress=False))
    return out


def test_every_tree_gets_the_verdict_schedule_gives_it(runs):
    from foon2pddl.retrieval.api import retrieve

    config, summary = runs[1]
    trial = summary.trials[0]
    view = runner.views(config)[0]
    nodes = view.map_kitchen(trial.kitchen).project(view.foon.level).nodes
    checked = 0
    for r in summary.records:
        if r.network != "reg" or r.solver != "native-complete":
            continue
        assert (r.executable is not None) == r.solved
        if not r.solved:
            continue
        tree = retrieve(view.foon, nodes, view.goal_of(trial.goals[r.goal - 1]), "complete").tree
        verdict = schedule(tree, nodes)
        assert r.executable == verdict.verdict
        assert (r.executable_reason or "") == verdict.message
        checked += 1
    assert checked >= 5


def test_every_tree_that_is_not_executable_names_its_label_and_step(runs):
    _, summary = runs[1]
    bad = [r for r in summary.records if r.solved and r.executable != Verdict.EXECUTABLE]
    assert bad  # the example kitchen has one cutting board: some trees need two
    for r in bad:
        step, label = physical.failure_of(r.executable_reason)
        assert step >= 1 and label and label != r.executable_reason
        assert f"step {step} " in r.executable_reason and label in r.executable_reason
        if r.executable == Verdict.SHORT and r.extra_objects is not None:
            assert r.extra_objects >= 1


def test_more_objects_per_item_never_make_a_tree_less_executable(runs):
    one = {r.key[:4]: r for r in runs[1][1].records}
    two = {r.key[:4]: r for r in runs[2][1].records}
    assert one.keys() == two.keys()
    assert all(a.solved == two[k].solved for k, a in one.items())  # FOON's answer does not depend on objects
    gained = 0
    for k, a in one.items():
        if a.solved and a.executable == Verdict.EXECUTABLE:
            assert two[k].executable == Verdict.EXECUTABLE
        if a.executable == Verdict.SHORT and a.extra_objects is not None and a.extra_objects <= 1:
            assert two[k].executable == Verdict.EXECUTABLE  # one more object per label was all it needed
            gained += 1
    assert gained >= 1


def test_objects_per_item_is_in_the_identity_only_when_not_one(runs):
    assert "objects_per_item" not in Protocol().identity()
    assert Protocol(objects_per_item=3).identity()["objects_per_item"] == 3
    with pytest.raises(Exception, match="at least 1"):
        Protocol(objects_per_item=0)


def _rec(trial, goal, network, solver, verdict, reason=None, extra=None, solved=True):
    return Record(trial=trial, goal=goal, network=network, solver=solver, goal_label=f"g{goal}",
                  status=CellStatus.SOLVED if solved else CellStatus.UNSOLVABLE, validated=solved or None,
                  units=3 if solved else None, executable=verdict if solved else None, executable_reason=reason,
                  extra_objects=extra)


def _data(records):
    trials = tuple({"trial": t, "goals": ["a", "b", "c"], "kitchen_nodes": 5} for t in (1, 2))
    return ReportData(tuple(records), ("reg", "gen"), ("native-complete", "fd-lifted-gen"), trials)


SHORT = "step 3 (pick-and-place) needs one more bowl in 'bowl (empty)': the kitchen has 1 there, none free"
USED = ("step 4 (pour) needs 'milk (in [cup])' again, but step 2 moved the milk on (in this order of the units "
        "the unit making it must fire again)")


def test_counts_of_hand_built_records():
    records = [_rec(1, 1, "reg", "native-complete", "executable"), _rec(1, 2, "reg", "native-complete", "short",
               SHORT, 1), _rec(1, 3, "reg", "native-complete", None, solved=False),
               _rec(2, 1, "reg", "native-complete", "used-up", USED), _rec(2, 2, "reg", "native-complete", "executable"),
               _rec(1, 1, "gen", "native-complete", "executable"), _rec(1, 1, "gen", "fd-lifted-gen", "short", SHORT),
               _rec(2, 1, "gen", "native-complete", "executable"), _rec(2, 2, "gen", "fd-lifted-gen", "executable")]
    data = _data(records)
    assert physical.physical_successes(data)["reg"] == {1: (2, 1), 2: (2, 1)}
    rows = {(v.solver, v.network): v for v in physical.verdict_rows(data)}
    assert rows[("native-complete", "reg")].trees == 4 and rows[("native-complete", "reg")].share == 0.5
    short = {(s.solver, s.network): s for s in physical.short_rows(data)}
    assert short[("native-complete", "reg")] == physical.ShortRow("native-complete", "reg", 1, 1, 1.0, 1, 1)
    assert short[("fd-lifted-gen", "gen")].more_suffice == 0  # more objects would not do: no number given
    assert physical.short_labels(data) == [("reg", "bowl", 1, 3), ("reg", "milk", 1, 4)]
    network, solver, gen = physical.gen_rows(data)
    assert (network, solver) == ("gen", "fd-lifted-gen")
    assert [(g.category, g.concrete, g.concrete_executable) for g in gen] == [(1, 1, 0), (1, 1, 1)]
    assert "| 1 | 1 of 2 | 1 of 1 |" in table2_physical(data)
    assert "50.0 %" in verdicts_md(data)


REPLAY = "plan does not validate: step 3 (pour milk_1, cup_1): the milk is not in cup_1"


def test_physical_plans_count_per_trial_and_say_whether_each_passed_the_replay():
    """A physical planner's plans per trial beside the reference's trees (the second Table 2), its plans that
    fail the replay (errors with a plan) and the goals the reference solves that it has no plan for."""
    plan = dict(plan_length=4, repeated=0)
    records = [_rec(1, 1, "reg", "native-complete", "executable"), _rec(1, 2, "reg", "native-complete", "short", SHORT, 1),
               _rec(2, 1, "reg", "native-complete", "executable"), _rec(2, 2, "reg", "native-complete", "executable"),
               replace(_rec(1, 1, "reg", "fd-relational", "executable"), **plan),
               replace(_rec(1, 2, "reg", "fd-relational", "short", SHORT, 1), **plan),
               replace(_rec(2, 1, "reg", "fd-relational", None, solved=False), status=CellStatus.ERROR, reason=REPLAY,
                       plan_length=4),
               _rec(2, 2, "reg", "fd-relational", None, solved=False)]
    trials = tuple({"trial": t, "goals": ["a", "b"], "kitchen_nodes": 5} for t in (1, 2))
    data = ReportData(tuple(records), ("reg",), ("native-complete", "fd-relational"), trials)
    assert physical.planner_successes(data) == {("fd-relational", "reg"): {1: 1, 2: 0}}
    (row,) = physical.physical_planners(data)
    assert (row.plans, row.replay_failures, row.no_plan) == (3, (REPLAY,), (("unsolvable", 1),))
    table = table2_physical(data)
    assert "| trial | REG executable (of 2) | REG `fd-relational` plans carried out |" in table
    assert "| 1 | 1 of 2 | 1 |" in table and "| 2 | 2 of 2 | 0 |" in table


def test_a_reason_naming_neither_label_nor_step_is_kept_whole():
    assert physical.failure_of("something else") == (0, "something else")
    assert physical.failure_of("step 2 (chop) needs 'onion (chopped)', which no earlier step makes") == (
        2, "onion (chopped)")


def test_the_report_has_the_physical_sections_and_the_comparison_says_what_changes(runs, tmp_path):
    from foon2pddl.experiment.report import render_markdown

    config, summary = runs[1]
    data = ReportData(summary.records, config.networks, config.solvers, tuple(t.summary() for t in summary.trials),
                      _meta(config, summary))
    text = render_markdown(data, {"successes.png": "s.png", "times.png": "t.png"})
    for heading in ("## Physical execution", "## GEN: concrete against category-level success",
                    "The paper's Table 2 under physical execution", "**Physical execution.**"):
        assert heading in text


def _meta(config, summary):
    from foon2pddl.experiment.networks import NETWORKS

    return {"command": "foon2pddl experiment", "goal_limits": {}, "inputs": "the example", "files": 1,
            "fingerprint": "0" * 64, "trials": 1, "goals": 40, "level": 3, "seed": 0, "kitchen_fraction": "0.9",
            "similarity": "cook", "objects_per_item": 1, "default_kitchen": summary.default_kitchen,
            "goal_pool": summary.goal_pool,
            "network_sizes": [{"name": NETWORKS[v.name].label, "units": len(v.foon.units), "nodes": len(v.foon.nodes),
                               "what": ""} for v in runner.views(config)],
            "solver_descriptions": [], "time_limit": "60", "jobs": 1, "scheduler": None, "wall": "1 s", "ran": 1,
            "skipped": 0, "history": [], "machine": "test", "code": "test"}


def test_a_solver_replays_holders_exactly_when_its_encoding_has_them(monkeypatch):
    """The report's "relational replay (holders included)" follows the solver's registered encoding, not its
    name: a solver registered with the relational encoding under another name is replayed with holders."""
    from foon2pddl.experiment.solvers import SOLVERS

    assert physical.replays_holders("fd-relational") and not physical.replays_holders("fd-instances")
    assert not physical.replays_holders("fd-tree") and not physical.replays_holders("native-complete")
    monkeypatch.setitem(SOLVERS, "my-relational", replace(SOLVERS["fd-instances"], name="my-relational",
                                                          encoding="relational"))
    assert physical.replays_holders("my-relational")
    records = [_rec(1, 1, "reg", "native-complete", "executable"),
               replace(_rec(1, 1, "reg", "my-relational", "executable"), plan_length=4, repeated=0)]
    data = ReportData(tuple(records), ("reg",), ("native-complete", "my-relational"),
                      ({"trial": 1, "goals": ["a"], "kitchen_nodes": 5},))
    (row,) = physical.physical_planners(data)
    assert row.holders


def test_fd_relational_plans_are_replayed_and_reported_beside_the_native_trees(tmp_path):
    config = Config(paths=(), protocol=Protocol(trials=1, goals=12), networks=("reg",),
                    solvers=("native-complete", "fd-relational"), out_dir=tmp_path)
    summary = runner.run(config, progress=False)
    relational = [r for r in summary.records if r.solver == "fd-relational"]
    assert relational and not [r for r in relational if r.status == CellStatus.ERROR]
    solved = [r for r in relational if r.solved]
    assert solved and all(r.executable in (Verdict.EXECUTABLE, Verdict.SHORT) for r in solved)  # each replayed
    data = ReportData(summary.records, config.networks, config.solvers, tuple(t.summary() for t in summary.trials))
    (row,) = physical.physical_planners(data)
    assert (row.solver, row.solved) == ("fd-relational", len(solved)) and row.replayed + row.more_objects == len(solved)
    assert row.mean_steps is not None and row.mean_units is not None
    for r in solved:
        if r.executable == Verdict.SHORT:  # a plan that draws more objects than the kitchen has: label and step
            step, label = physical.failure_of(r.executable_reason)
            assert r.extra_objects >= 1 and step >= 1 and f"one more {label} in " in r.executable_reason
    from foon2pddl.experiment.report import render_markdown

    data = ReportData(summary.records, config.networks, config.solvers, data.trials, _meta(config, summary))
    text = render_markdown(data, {"successes.png": "s.png", "times.png": "t.png"})
    assert f"- `fd-relational` REG: {len(solved)} plans, every one passes the relational replay" in text
    assert "REG `fd-relational` plans carried out" in text  # the second Table 2 counts its plans per trial
    assert f"| 1 | {sum(r.executable == 'executable' for r in summary.records if r.solver == 'native-complete')} of " \
        in text


def test_a_physical_plan_fits_the_kitchen_exactly_when_scheduling_its_tree_does(example):
    """`drawn_by_plan` on the trace of a tree scheduled over an unlimited kitchen gives the verdict and words
    `schedule` gives the same tree over one object per item (the same objects, bound in the same order)."""
    import random

    from foon2pddl.model.goal import Goal, spec_of_node
    from foon2pddl.model.kitchen import default_kitchen
    from foon2pddl.planners.executable import drawn_by_plan, needed
    from foon2pddl.retrieval.api import retrieve

    foon = example.foon
    nodes = default_kitchen(foon).nodes
    seen = set()
    for node in random.Random(7).sample(sorted(foon.producers), 60):
        tree = retrieve(foon, nodes, Goal(spec_of_node(node), (node,), foon.level), "complete").tree
        unlimited = needed(tree, nodes) if tree is not None else None
        if unlimited is None or not unlimited.ok:
            continue
        for per_item in (1, 2):
            plan, tree_verdict = drawn_by_plan(unlimited.trace, nodes, per_item), schedule(tree, nodes, per_item=per_item)
            assert (plan.verdict, plan.message) == (tree_verdict.verdict, tree_verdict.message), node.describe()
            assert plan.drawn == unlimited.drawn
            seen.add((per_item, plan.verdict))
        stated = {n: k for n, k in unlimited.drawn[:2]}  # the kitchen says how many of two nodes: enough there
        plan, tree_verdict = drawn_by_plan(unlimited.trace, nodes, stated=stated), schedule(tree, nodes, stated=stated)
        assert (plan.verdict, plan.message) == (tree_verdict.verdict, tree_verdict.message), node.describe()
        seen.add(("stated", plan.verdict))
    assert {(1, Verdict.SHORT), (1, Verdict.EXECUTABLE), (2, Verdict.EXECUTABLE)} <= seen
    assert {("stated", Verdict.SHORT), ("stated", Verdict.EXECUTABLE)} <= seen


def test_fd_instances_plans_that_need_more_objects_say_how_many_and_where(tmp_path):
    config = Config(paths=(), protocol=Protocol(trials=1, goals=40), networks=("reg",),
                    solvers=("native-complete", "fd-instances"), out_dir=tmp_path)
    summary = runner.run(config, progress=False)
    plans = [r for r in summary.records if r.solver == "fd-instances" and r.solved]
    assert plans and all(r.repeated is not None and r.plan_length >= r.units for r in plans)
    short = [r for r in plans if r.executable == Verdict.SHORT]
    assert short and len(short) < len(plans)  # the example kitchen has one cutting board; some plans take two
    for r in short:
        step, label = physical.failure_of(r.executable_reason)
        assert r.extra_objects >= 1 and step >= 1 and f"one more {label} in " in r.executable_reason
    data = ReportData(summary.records, config.networks, config.solvers, tuple(t.summary() for t in summary.trials))
    (row,) = physical.physical_planners(data)
    assert (row.solved, row.replayed, row.more_objects) == (len(plans), len(plans) - len(short), len(short))
    from foon2pddl.experiment.report import render_markdown

    data = ReportData(summary.records, config.networks, config.solvers, data.trials, _meta(config, summary))
    text = render_markdown(data, {"successes.png": "s.png", "times.png": "t.png"})
    assert "| fd-instances | REG |" in text and "only with more objects" in text
    assert f"`fd-instances` REG {row.replayed:.1f}." in text  # the comparison with the paper says it too
