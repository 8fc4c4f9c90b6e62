"""Native retrieval and Fast Downward agree under constraints (universal FOON, seeded pairs).

The full floor (200 pairs) is `bench/constraints.py`; this runs a sample of it.
"""

from __future__ import annotations

import pytest

from foon2pddl.analysis.constraints import removal
from foon2pddl.experiment.bans import sample_pairs
from foon2pddl.model.constraints import violations
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.tasktree import validate
from foon2pddl.planners.solve import plan
from foon2pddl.retrieval.constrained import retrieve_constrained


def check_pair(foon, kitchen, node, cons) -> bool:
    """Assert native complete, the oracle and FD agree; every tree validates and honours `cons`."""
    goal = Goal(spec_of_node(node), (node,), foon.level)
    native = retrieve_constrained(foon, kitchen, goal, cons, "complete").result
    expected = removal(foon, cons).solvable(kitchen.nodes, goal)
    assert (native.tree is not None) == expected, (node.describe(), cons, native.detail)
    outcome = plan(foon, kitchen, goal, constraints=cons)  # excluded by the constraints: an outcome, not raised
    status = outcome.status
    assert status == ("solved" if expected else "unsolvable"), (node.describe(), cons, status)
    trees = [native.tree] + ([outcome.tree] if outcome is not None and outcome.tree is not None else [])
    for tree in trees:
        if tree is not None:
            assert validate(tree, kitchen.nodes).ok
            assert not violations(tree.units, cons), violations(tree.units, cons)
    return expected


@pytest.mark.parametrize("seed", [1, 2])
def test_native_complete_and_fast_downward_agree_under_constraints(universal, seed):
    foon = universal[0]
    kitchen = default_kitchen(foon)
    solved = [check_pair(foon, kitchen, node, cons) for node, cons in sample_pairs(foon, kitchen, 10, seed)]
    assert any(solved) and not all(solved)  # both kinds occur, so the test can fail either way
