"""`fd-instances` answers goals no task tree reaches from the kitchen without planning, and the
planner agrees: for every such goal of a sparse trial kitchen, Fast Downward on the instances
encoding (the unscreened path) finds no plan either."""

from __future__ import annotations

import pytest

from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import Protocol, draw
from foon2pddl.experiment.records import CellStatus
from foon2pddl.experiment.setting import Setting
from foon2pddl.experiment.solvers import SOLVERS
from foon2pddl.io.inputs import load_network
from foon2pddl.planners import solve as planners_solve


@pytest.fixture(scope="module")
def trial_setting():
    view = build_view("reg", load_network([]), 3)
    trial = draw(view.foon, Protocol(trials=1, goals=12, kitchen_fraction=0.5, seed=3)).trials[0]
    return view, Setting(view, trial.kitchen, 60.0), trial.goals


def test_screened_goals_are_unsolvable_for_the_planner_too(trial_setting, monkeypatch):
    view, setting, goals = trial_setting
    prepared = SOLVERS["fd-instances"].prepare(setting)
    screened = [g for g in goals if not any(prepared.reach.can_make(c) for c in view.goal_of(g).candidates)]
    assert screened and len(screened) < len(goals), "the trial must mix reachable and unreachable goals"
    calls = []
    real_plan = planners_solve.plan
    monkeypatch.setattr(planners_solve, "plan", lambda *a, **k: calls.append(a) or real_plan(*a, **k))
    for g in screened:
        out = prepared.solve(g)
        assert out.status == CellStatus.UNSOLVABLE and "no task tree" in out.reason
    assert calls == []  # answered from the fixpoint
    for g in screened:  # the independent oracle: the planner on the compiled task
        outcome = real_plan(view.foon, prepared.kitchen, view.goal_of(g), "instances", view.foon.level,
                            time_limit=60.0)
        assert outcome.result.status == "unsolvable", (g.describe(), outcome.result.message)


def test_reachable_goals_still_plan(trial_setting, monkeypatch):
    view, setting, goals = trial_setting
    prepared = SOLVERS["fd-instances"].prepare(setting)
    reachable = [g for g in goals if any(prepared.reach.can_make(c) for c in view.goal_of(g).candidates)]
    calls = []
    real_plan = planners_solve.plan
    monkeypatch.setattr(planners_solve, "plan", lambda *a, **k: calls.append(a) or real_plan(*a, **k))
    outcomes = [prepared.solve(g) for g in reachable]
    assert len(calls) == len(reachable)
    assert all(o.status != CellStatus.ERROR for o in outcomes)
    assert any(o.status == CellStatus.SOLVED for o in outcomes)
