"""The retrieval methods table: one lookup for the API, the CLI and the experiment."""

from __future__ import annotations

import pytest

from foon2pddl.errors import UsageError
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.retrieval import METHODS, retrieve
from foon2pddl.retrieval.methods import Limits, Method, get_method, register
from foon2pddl.retrieval.result import Retrieval
from foon2pddl.status import RetrievalStatus

WHOLE, CHOPPED, KNIFE = make_node("onion", [make_state("whole")]), make_node("onion", [make_state("chopped")]), \
    make_node("knife")
FOON = Foon((FunctionalUnit((WHOLE, KNIFE), Motion("chop"), (CHOPPED, KNIFE)),), 3)
GOAL = Goal(GoalSpec("onion"), (CHOPPED,), 3)


def test_every_method_finds_the_one_tree_and_says_what_it_honours():
    for name, method in METHODS.items():
        assert method.name == name and method.description
        found = retrieve(FOON, [WHOLE, KNIFE], GOAL, name)
        assert found.tree is not None and len(found.tree) == 1 and found.method == name
        assert (found.bound is not None) == method.bounded
        assert method.needs_rates == ("rates" in method.honours)


def test_unknown_method_and_unknown_limit_are_refused():
    with pytest.raises(UsageError, match="unknown retrieval method 'fastest' \\(expected one of greedy"):
        retrieve(FOON, [WHOLE, KNIFE], GOAL, "fastest")
    with pytest.raises(ValueError, match="unknown limits"):
        Method("m", "d", lambda *a: None, frozenset({"patience"}))


def test_a_registered_method_is_used_by_retrieve_and_the_experiment():
    seen: list[Limits] = []

    def refuse(foon, nodes, goal, limits):
        seen.append(limits)
        return Retrieval(None, RetrievalStatus.BUDGET_EXHAUSTED, "refuse", "never tries")

    register(Method("refuse", "gives up at once", refuse, frozenset({"budget"})))
    try:
        assert get_method("refuse").run is refuse
        done = retrieve(FOON, [WHOLE, KNIFE], GOAL, "refuse", budget=7)
        assert done.reason == RetrievalStatus.BUDGET_EXHAUSTED and seen[-1].budget == 7
        # the candidate check runs for every method: a goal node not in the network is an input error
        stray = Goal(GoalSpec("onion"), (make_node("onion", [make_state("sliced")]),), 3)
        with pytest.raises(UsageError, match="is not a node of the network"):
            retrieve(FOON, [WHOLE, KNIFE], stray, "refuse")
    finally:
        del METHODS["refuse"]
    assert "refuse" not in METHODS


def test_the_experiment_native_solver_runs_retrieve(monkeypatch):
    """`experiment.native_solver.Native` goes through `retrieve` (candidate check included), not its own dispatch."""
    from foon2pddl.experiment import solvers
    from foon2pddl.experiment.setting import Setting
    from foon2pddl.retrieval import api

    calls = []
    real = api.retrieve

    def spy(*args, **kwargs):
        calls.append(args[3])
        return real(*args, **kwargs)

    monkeypatch.setattr(api, "retrieve", spy)

    class View:
        foon = FOON

        def goal_of(self, node):
            return Goal(GoalSpec(node.describe()), (node,), 3)

        def map_kitchen(self, kitchen):
            return kitchen

    from foon2pddl.model.kitchen import Kitchen

    setting = Setting(View(), Kitchen(frozenset({WHOLE, KNIFE})))
    for name in ("native-greedy", "native-complete", "native-optimal"):
        outcome = solvers.get_solver(name).prepare(setting).solve(CHOPPED)
        assert outcome.status == "solved" and outcome.units == 1
    assert calls == ["greedy", "complete", "optimal"]
