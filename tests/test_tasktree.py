"""Task tree simulation and plan justification (plan -> tree), on random FOONs (hypothesis)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from test_retrieval_properties import problems

from foon2pddl.model.foon import FunctionalUnit, Motion, make_node
from foon2pddl.model.tasktree import TaskTree, justify, validate


def random_run(units, kitchen, order):
    """A delete-free plan: units fired in a shuffled order while any can fire (each at most once)."""
    have, plan, pending = set(kitchen), [], [units[i] for i in order]
    progress = True
    while progress:
        progress = False
        for u in list(pending):
            if set(u.inputs) <= have:
                plan.append(u)
                have.update(u.outputs)
                pending.remove(u)
                progress = True
    return plan, have


@settings(max_examples=150, deadline=None)
@given(problems(), st.randoms(use_true_random=False))
def test_justified_plan_is_a_valid_subsequence(problem, rnd) -> None:
    foon, kitchen, goal = problem
    order = list(range(len(foon.units)))
    rnd.shuffle(order)
    plan, have = random_run(foon.units, kitchen, order)
    target = goal.satisfied_by(have)
    if target is None:
        return
    kept = justify(plan, kitchen, target)
    assert validate(TaskTree(kept, target), kitchen).ok
    positions = [plan.index(u) for u in kept]
    assert positions == sorted(positions)  # order of the plan is kept
    # every kept unit makes something a later kept unit (or the goal) needs, not already available
    for i, u in enumerate(kept):
        later_inputs = {n for v in kept[i + 1:] for n in v.inputs} | {target}
        assert set(u.outputs) & later_inputs


def test_justify_drops_steps_the_goal_does_not_need() -> None:
    a, b, c, d = (make_node(x) for x in "abcd")
    make_b = FunctionalUnit((a,), Motion("chop"), (b,))
    make_d = FunctionalUnit((a,), Motion("mix"), (d,))
    make_c = FunctionalUnit((b,), Motion("pour"), (c,))
    assert justify([make_b, make_d, make_c], {a}, c) == (make_b, make_c)
    assert justify([make_b, make_d, make_c], {a, c}, c) == ()


def test_validate_reports_missing_input_and_goal() -> None:
    a, b, c = (make_node(x) for x in "abc")
    tree = TaskTree((FunctionalUnit((b,), Motion("pour"), (c,)),), c)
    result = validate(tree, {a})
    assert not result.ok and "input not available: b" in result.problems[0]
    assert validate(TaskTree((), c), {a}).problems == ("goal not produced: c",)
