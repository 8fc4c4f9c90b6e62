"""Retrieval under constraints on small random FOONs, against brute force (hypothesis).

The oracle re-implements the rules independently on the single-word labels of the
pool: a unit is banned by a motion ban when its motion equals it, by an object ban
when a node's label, related object or ingredient equals it; must-use X is met when
a unit with an input mentioning X can fire from the kitchen with the allowed units.
"""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st
from test_retrieval_properties import MOTIONS, RATES, naive_closure, problems

from foon2pddl.analysis.blocking import minimal_blocking_set
from foon2pddl.analysis.constraints import removal
from foon2pddl.model.constraints import Constraint, Kind, make_constraints
from foon2pddl.model.tasktree import validate
from foon2pddl.retrieval.constrained import retrieve_constrained
from foon2pddl.retrieval.result import UNREACHABLE

OBJECTS = ["a", "b", "d", "e", "g"]


def names(node):
    return {node.label} | {s.related for s in node.states if s.related} | {i for s in node.states for i in s.ingredients}


def banned(unit, items):
    for c in items:
        if c.kind is Kind.WITHOUT_MOTION and unit.motion.label == c.value:
            return True
        if c.kind is Kind.WITHOUT and any(c.value in names(n) for n in (*unit.inputs, *unit.outputs)):
            return True
    return False


def oracle(foon, kitchen, goal, items) -> bool:
    """Whether the goal can be made under `items` (brute force, see the module doc)."""
    objects = {c.value for c in items if c.kind is Kind.WITHOUT}
    allowed = [u for u in foon.units if not banned(u, items)]
    have = naive_closure(allowed, kitchen)
    cands = [c for c in goal.candidates if not names(c) & objects]
    if not any(c in have for c in cands):
        return False
    for c in items:
        if c.kind is Kind.MUST_USE and not any(set(u.inputs) <= have and any(c.value in names(n) for n in u.inputs)
                                               for u in allowed):
            return False
    return True


constraint_sets = st.lists(st.one_of(
    st.builds(Constraint, st.just(Kind.WITHOUT_MOTION), st.sampled_from(MOTIONS)),
    st.builds(Constraint, st.just(Kind.WITHOUT), st.sampled_from(OBJECTS)),
    st.builds(Constraint, st.just(Kind.MUST_USE), st.sampled_from(OBJECTS)),
), max_size=4).map(make_constraints)


@settings(max_examples=300, deadline=None)
@given(problems(), constraint_sets)
def test_every_method_finds_a_tree_iff_the_oracle_says_so_and_honours_the_constraints(problem, cons):
    foon, kitchen, goal = problem
    expected = oracle(foon, kitchen, goal, cons.items)
    assert removal(foon, cons).solvable(kitchen, goal) == expected
    banned_objects = {c.value for c in cons.items if c.kind is Kind.WITHOUT}
    for method in ("complete", "greedy", "optimal", "weighted"):
        done = retrieve_constrained(foon, kitchen, goal, cons, method, rates=RATES)
        tree = done.result.tree
        assert (tree is not None) == expected, (method, done.result)
        if tree is None:
            assert done.result.reason == UNREACHABLE and done.blocking is not None
            continue
        assert tree.goal in goal.candidates and validate(tree, kitchen).ok
        assert not any(banned(u, cons.items) for u in tree.units)
        assert not names(tree.goal) & banned_objects
        for x in cons.must_use:
            assert any(x in names(n) for u in tree.units for n in u.inputs), (method, x)


@settings(max_examples=300, deadline=None)
@given(problems(), constraint_sets)
def test_minimal_blocking_set_is_smallest_against_brute_force(problem, cons):
    foon, kitchen, goal = problem
    relax, minimum, _ = minimal_blocking_set(removal(foon, cons), kitchen, goal)
    works = [s for k in range(len(cons.items) + 1) for s in itertools.combinations(cons.items, k)
             if oracle(foon, kitchen, goal, [c for c in cons.items if c not in s])]
    if not works:
        assert relax is None
        return
    assert minimum and relax is not None
    # relaxing it makes the goal reachable, and no smaller subset does
    assert oracle(foon, kitchen, goal, [c for c in cons.items if c not in relax])
    assert len(relax) == min(len(s) for s in works)


@settings(max_examples=100, deadline=None)
@given(problems(), constraint_sets)
def test_optimal_under_constraints_is_no_larger_than_complete(problem, cons):
    foon, kitchen, goal = problem
    best = retrieve_constrained(foon, kitchen, goal, cons, "optimal").result
    if best.tree is not None:
        assert len(best.tree) <= len(retrieve_constrained(foon, kitchen, goal, cons, "complete").result.tree)
        assert best.cost == len(best.tree) and best.bound <= best.cost  # the auxiliary goal unit is not counted
