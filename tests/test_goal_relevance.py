"""Per-goal shortcuts of the experiment's planners keep their answers: the SAS operators relevant to a
goal (Fast Downward reuse), stubborn-set pruning in optimal search, and the lifted GEN image network
shared by a trial's goals."""

from __future__ import annotations

import random

import pytest

from foon2pddl.experiment.fd_solvers import OPTIMAL_SEARCH
from foon2pddl.generalize import relevance
from foon2pddl.generalize.categories import load_index
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.encode_lifted import encode_lifted
from foon2pddl.pddl.render import render
from foon2pddl.planners import fd_reuse
from foon2pddl.planners import sas as sas_text
from foon2pddl.planners.goal_replanner import GoalReplanner
from foon2pddl.retrieval.optimal import optimal


@pytest.fixture(scope="module")
def setting(example):
    foon = example.foon
    kitchen = default_kitchen(foon)
    goals = [resolve_goal(spec_of_node(n), foon) for n in random.Random(3).sample(sorted(foon.producers), 14)]
    return foon, kitchen, goals


def test_optimal_reuse_with_relevance_and_stubborn_sets_finds_native_optima(setting, monkeypatch):
    foon, kitchen, goals = setting
    replanner = GoalReplanner(foon, kitchen, optimal=True, search=OPTIMAL_SEARCH)
    sas = replanner.translated.sas
    assert sas.prunable
    kept, solved = [], 0
    for goal in goals:
        native = optimal(foon, kitchen.nodes, goal)
        outcome = replanner.plan(goal)
        assert outcome.status == ("solved" if native.tree is not None else "unsolvable"), goal.describe()
        if native.tree is not None:
            assert native.proven_optimal
            assert len(outcome.tree) == len(native.tree), goal.describe()  # both optimal: same size
            assert outcome.validation.ok
            solved += 1
            (atoms,) = replanner.node_atoms[outcome.tree.goal]  # one writing per node in the tree encoding
            facts = [sas.facts[fd_reuse.sas_fact_name(a)] for a in atoms if fd_reuse.sas_fact_name(a) in sas.facts]
            kept.append(len(sas.relevant(facts)))
    assert solved >= 5 and max(kept) < len(sas.operators)  # the goals' parts are strictly smaller


def test_relevance_keeps_exactly_the_operators_that_lead_to_the_goal():
    ops = ("begin_operator\na\n0\n1\n0 0 -1 1\n1\nend_operator\n",      # makes v0=1
           "begin_operator\nb\n1\n0 1\n1\n0 1 -1 1\n1\nend_operator\n",  # needs v0=1, makes v1=1
           "begin_operator\nc\n0\n1\n0 2 -1 1\n1\nend_operator\n")      # makes v2=1: irrelevant to v1
    parsed = tuple(sas_text.parse_op(op) for op in ops)
    makers = {}
    for k, op in enumerate(parsed):
        for f in op.makes:
            makers.setdefault(f, []).append(k)
    sas = sas_text.Sas("", (), "0\n", (), ops, "0\n", {}, (9, 0), parsed, {f: tuple(v) for f, v in makers.items()}, True)
    assert sas.relevant([(1, 1)]) == [0, 1]
    assert sas.relevant([(2, 1)]) == [2]
    assert sas.relevant([(0, 1), (2, 1)]) == [0, 2]
    conditional = sas_text.parse_op("begin_operator\nd\n0\n1\n1 3 0 0 -1 1\n1\nend_operator\n")
    assert conditional.conditional and conditional.needs == ((3, 0),)


def test_lifted_tasks_are_the_same_with_the_shared_ground_instances(setting, monkeypatch):
    foon, kitchen, goals = setting
    index = load_index()
    shared = [render(encode_lifted(foon, kitchen, g, index).task) for g in goals[:6]]
    assert relevance._GROUNDED  # the ground instances were kept
    for goal, text in zip(goals[:6], shared, strict=True):
        relevance._GROUNDED.clear()  # rebuilt from scratch for this goal alone
        assert render(encode_lifted(foon, kitchen, goal, index).task) == text
