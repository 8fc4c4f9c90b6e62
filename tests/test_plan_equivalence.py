"""The `tree` encoding plans exactly when native complete retrieval finds a tree (universal FOON, sampled goals).

The full run (default kitchen + 5 random kitchens, >= 200 goals) is `bench/planning.py`.
"""

from __future__ import annotations

import random

import pytest

from foon2pddl.analysis.reachability import reachable
from foon2pddl.experiment.protocol import sample_kitchen
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.planners.goal_replanner import GoalReplanner
from foon2pddl.planners.solve import plan


@pytest.fixture(scope="module")
def network(universal):
    foon, _ = universal
    goals = random.Random(4).sample(sorted(foon.producers), 20)
    return foon, [resolve_goal(spec_of_node(n), foon) for n in goals]


@pytest.mark.parametrize("kitchen_seed", [None, 11])
def test_fd_plans_iff_fixpoint_reaches_and_plans_validate(network, kitchen_seed):
    foon, goals = network
    kitchen = default_kitchen(foon) if kitchen_seed is None else sample_kitchen(default_kitchen(foon), 0.7, kitchen_seed)
    reach = reachable(foon, kitchen.nodes)
    replanner = GoalReplanner(foon, kitchen)
    solved = 0
    for goal in goals:
        expected = any(reach.can_make(c) for c in goal.candidates)
        fresh = plan(foon, kitchen, goal)
        reused = replanner.plan(goal)
        assert fresh.status == ("solved" if expected else "unsolvable"), goal.describe()
        assert reused.status == fresh.status, goal.describe()
        for outcome in (fresh, reused):
            if outcome.tree is not None:
                assert outcome.validation.ok, outcome.validation.problems
                assert outcome.tree.goal in goal.candidates
        solved += expected
    assert 0 < solved < len(goals)  # the sample has both kinds, so the test can fail either way
