"""Property tests of native retrieval on random FOONs (hypothesis).

The networks are small (a pool of 8 nodes, up to 9 units) so that cycles,
several makers per node, shared subtrees and unreachable goals all occur, and
so that an exhaustive search over unit subsets can serve as the reference.
"""

from __future__ import annotations

import itertools
import math
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import foon2pddl.retrieval.greedy as greedy_module
from foon2pddl.model.dedupe import dedupe_units
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.tasktree import validate
from foon2pddl.retrieval import Rates, blockers, reachable, retrieve
from foon2pddl.retrieval.result import BUDGET_EXHAUSTED, UNREACHABLE, Retrieval

POOL = [make_node("a"), make_node("b"), make_node("b", [make_state("cut")]), make_node("c", [make_state("in", "b")]),
        make_node("d"), make_node("e", [make_state("mixed", "", ["a", "d"])]), make_node("f"), make_node("g")]
MOTIONS = ["chop", "mix", "pour", "stir"]
RATES = Rates({"chop": 0.5, "mix": 0.9, "pour": 0.8}, default=0.3)


@st.composite
def problems(draw):
    """(network, kitchen nodes, goal) with 1-3 goal candidates among the produced nodes.

    The kitchen holds the nodes no unit makes except up to two, plus up to three others,
    so that most goals are reachable, many in several ways; half of the goals have a
    candidate the reference closure (`naive_closure`) can make.
    """
    ins = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    outs = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    units = draw(st.lists(st.tuples(ins, st.sampled_from(MOTIONS), outs), min_size=4, max_size=9))
    foon = Foon(dedupe_units(FunctionalUnit(tuple(i), Motion(m), tuple(o)) for i, m, o in units))
    produced = sorted(foon.producers)
    starting = sorted(set(foon.nodes) - set(produced))
    missing = draw(st.lists(st.sampled_from(starting), max_size=2, unique=True)) if starting else []
    extra = draw(st.lists(st.sampled_from(POOL), max_size=3, unique=True))
    kitchen = frozenset(starting).difference(missing).union(extra)
    makeable = sorted(set(produced) & naive_closure(foon.units, kitchen))
    first = draw(st.sampled_from(makeable if makeable and draw(st.booleans()) else produced))
    cands = {first} | set(draw(st.lists(st.sampled_from(produced), max_size=2)))
    return foon, kitchen, Goal(GoalSpec("goal"), tuple(sorted(cands)), 3)


def naive_closure(units, kitchen):
    """Everything the units can make from the kitchen, by repeating passes until nothing changes."""
    have = set(kitchen)
    changed = True
    while changed:
        changed = False
        for u in units:
            if set(u.inputs) <= have and not set(u.outputs) <= have:
                have |= set(u.outputs)
                changed = True
    return have


def best_subset(foon, kitchen, goal, cost):
    """The cheapest set of units whose closure from the kitchen reaches a candidate (exhaustive)."""
    best = math.inf
    for k in range(len(foon.units) + 1):
        for subset in itertools.combinations(foon.units, k):
            if goal.satisfied_by(naive_closure(subset, kitchen)) is not None:
                best = min(best, cost(subset))
    return best


def unit_count(units):
    return len(units)


def neg_log(units):
    return math.fsum(RATES.cost(u.motion.label) for u in units)


@settings(max_examples=300, deadline=None)
@given(problems())
def test_fixpoint_matches_naive_closure(problem):
    foon, kitchen, _ = problem
    reach = reachable(foon, kitchen)
    closure = naive_closure(foon.units, kitchen)
    assert {n for n in foon.nodes if reach.can_make(n)} == {n for n in foon.nodes if n in closure}
    # rounds: a made node's first achiever fired in its round, with all inputs from earlier rounds
    for n in foon.nodes:
        u = reach.achiever_of(n)
        if u is not None:
            assert reach.round_of(n) == 1 + max((reach.round_of(i) for i in foon.units[u].inputs), default=0)



@settings(max_examples=300, deadline=None)
@given(problems(), st.lists(st.sampled_from(POOL), max_size=4))
def test_makes_any_is_the_goal_test_of_the_closure(problem, others):
    """`makes_any` holds exactly when the closure holds one of the nodes: the goal's candidates, others (some
    outside the network), none; read once, as a generator, and on the goal's own cone (`targets`)."""
    foon, kitchen, goal = problem
    closure = naive_closure(foon.units, kitchen)
    whole, cone = reachable(foon, kitchen), reachable(foon, kitchen, goal.candidates)
    for nodes in (goal.candidates, others, [*others, *goal.candidates], ()):
        assert whole.makes_any(n for n in nodes) == bool(closure & set(nodes)), nodes
    assert cone.makes_any(goal.candidates) == bool(closure & set(goal.candidates))

def naive_blockers(foon, kitchen, nodes):
    """Unmakeable nodes without a maker that the unmakeable `nodes` depend on (plain search on the units)."""
    made = naive_closure(foon.units, kitchen)
    makers = {}
    for u in foon.units:
        for o in u.outputs:
            if o not in u.inputs:
                makers.setdefault(o, []).append(u)
    seen, found, stack = set(), set(), [n for n in nodes if n not in made]
    while stack:
        n = stack.pop()
        if n in seen:
            continue
        seen.add(n)
        if n not in makers:
            found.add(n)
        for u in makers.get(n, ()):
            stack.extend(i for i in u.inputs if i not in made)
    return sorted(found)


@settings(max_examples=300, deadline=None)
@given(problems(), st.lists(st.sampled_from(POOL), min_size=1, max_size=8), st.integers(1, 12))
def test_blockers_remembered_per_fixpoint_match_a_plain_search(problem, queries, limit):
    """Repeated queries on one fixpoint (answers remembered per component) give the plain search's answer."""
    foon, kitchen, goal = problem
    reach = reachable(foon, kitchen)
    for nodes in [goal.candidates, *([q] for q in queries), queries]:
        nodes = [n for n in nodes if n in foon.nodes]
        assert list(blockers(reach, nodes, limit)) == naive_blockers(foon, kitchen, nodes)[:limit]


@settings(max_examples=300, deadline=None)
@given(problems())
def test_complete_and_greedy_find_a_valid_tree_iff_reachable(problem):
    foon, kitchen, goal = problem
    reach = reachable(foon, kitchen)
    can = any(reach.can_make(c) for c in goal.candidates)
    for method in ("complete", "greedy"):
        result = retrieve(foon, kitchen, goal, method)
        assert (result.tree is not None) == can, (method, result)
        if result.tree is None:
            assert result.reason == UNREACHABLE and result.detail
        else:
            assert result.tree.goal in goal.candidates
            assert validate(result.tree, kitchen).ok, validate(result.tree, kitchen).problems
            # pruned: every unit makes something a later unit or the goal needs
            for k, unit in enumerate(result.tree.units):
                later = {n for u in result.tree.units[k + 1:] for n in u.inputs} | {result.tree.goal}
                assert set(unit.outputs) & later


@settings(max_examples=200, deadline=None)
@given(problems(), st.integers(1, 4))
def test_greedy_fixpoint_shortcut_changes_no_answer(problem, check_after):
    """Greedy given a fixpoint, or checking one after a few iterations, answers as the plain search does."""
    foon, kitchen, goal = problem
    plain = greedy_module.greedy(foon, kitchen, goal)
    given_reach = greedy_module.greedy(foon, kitchen, goal, reach=reachable(foon, kitchen))
    saved = greedy_module.FIXPOINT_CHECK_AFTER
    greedy_module.FIXPOINT_CHECK_AFTER = check_after
    try:
        lazy = greedy_module.greedy(foon, kitchen, goal)
    finally:
        greedy_module.FIXPOINT_CHECK_AFTER = saved
    for other in (given_reach, lazy):
        assert other.reason == plain.reason
        assert (other.tree is None) or other.tree.units == plain.tree.units


@settings(max_examples=200, deadline=None)
@given(problems())
def test_greedy_terminates_within_any_budget(problem):
    foon, kitchen, goal = problem
    for budget in (1, 3, 50):
        result = retrieve(foon, kitchen, goal, "greedy", budget=budget)
        assert result.expansions <= budget
        assert result.reason in (None, UNREACHABLE, BUDGET_EXHAUSTED)
        if result.tree is not None:
            assert validate(result.tree, kitchen).ok


@settings(max_examples=200, deadline=None)
@given(problems())
def test_optimal_is_minimal_and_never_worse_than_complete_or_greedy(problem):
    foon, kitchen, goal = problem
    result = retrieve(foon, kitchen, goal, "optimal")
    best = best_subset(foon, kitchen, goal, unit_count)
    if best == math.inf:
        assert result.tree is None and result.reason == UNREACHABLE
        return
    assert result.proven_optimal
    assert validate(result.tree, kitchen).ok
    assert len(result.tree) == best
    for other in ("complete", "greedy"):
        assert len(result.tree) <= len(retrieve(foon, kitchen, goal, other).tree)


@settings(max_examples=200, deadline=None)
@given(problems())
def test_optimal_at_its_node_limit_returns_the_best_tree_so_far(problem):
    foon, kitchen, goal = problem
    full = retrieve(foon, kitchen, goal, "optimal")
    cut = retrieve(foon, kitchen, goal, "optimal", node_limit=1)
    assert (cut.tree is None) == (full.tree is None)
    if cut.tree is not None:
        assert validate(cut.tree, kitchen).ok
        assert len(cut.tree) <= len(retrieve(foon, kitchen, goal, "complete").tree)
        assert cut.expansions <= 1
        if cut.proven_optimal:
            assert len(cut.tree) == len(full.tree)
        else:
            assert "not proven optimal" in cut.detail


@settings(max_examples=300, deadline=None)
@given(problems(), st.sampled_from([1, 2, 5, None]), st.sampled_from([None, 1e-9]), st.booleans())
def test_anytime_bound_is_a_true_lower_bound_and_exact_search_is_optimal(problem, node_limit, time_limit, weighted):
    """Within any budget: a valid tree, its cost, and a bound <= the brute-force optimum <= cost;
    proven exactly when bound == cost; without a budget the brute-force optimum, proven."""
    foon, kitchen, goal = problem
    method, cost = ("weighted", neg_log) if weighted else ("optimal", unit_count)
    result = retrieve(foon, kitchen, goal, method, rates=RATES, node_limit=node_limit, time_limit=time_limit)
    best = best_subset(foon, kitchen, goal, cost)
    if best == math.inf:
        assert result.tree is None and result.bound is None
        return
    assert validate(result.tree, kitchen).ok
    assert math.isclose(result.cost, cost(result.tree.units), abs_tol=1e-9)
    assert result.bound <= best + 1e-9 and best <= result.cost + 1e-9
    assert result.proven_optimal == (result.bound == result.cost) == (result.gap == 0)
    if result.proven_optimal:
        assert math.isclose(result.cost, best, abs_tol=1e-9)
    if node_limit is None and time_limit is None:
        assert result.proven_optimal
    assert result.expansions <= (node_limit or math.inf)


def test_retrieval_bound_invariants_are_checked_on_construction():
    tree = retrieve(*_cover(), "complete").tree
    Retrieval(tree, None, "optimal", proven_optimal=False, cost=4.0, bound=2.0)
    Retrieval(tree, None, "optimal", proven_optimal=True, cost=4.0, bound=4.0)
    for bad in (dict(proven_optimal=True, cost=4.0, bound=2.0), dict(proven_optimal=False, cost=4.0, bound=4.0),
                dict(proven_optimal=False, cost=4.0, bound=5.0), dict(proven_optimal=False, cost=4.0)):
        with pytest.raises(ValueError):
            Retrieval(tree, None, "optimal", **bad)
    with pytest.raises(ValueError):
        Retrieval(None, UNREACHABLE, "optimal", proven_optimal=True, cost=1.0, bound=1.0)


def _cover():
    """Set cover: the goal needs a, b, c; `add` makes one, `mix` two; LM-cut proves 2, the optimum is 3."""
    k, a, b, c, g = (make_node(s) for s in ("k", "a", "b", "c", "goal"))
    units = [FunctionalUnit((k,), Motion("add"), (x,)) for x in (a, b, c)]
    units += [FunctionalUnit((k,), Motion("mix"), pair) for pair in ((a, b), (b, c), (a, c))]
    units.append(FunctionalUnit((a, b, c), Motion("serve"), (g,)))
    return Foon(tuple(units)), {k}, Goal(GoalSpec("goal"), (g,), 3)


def test_anytime_search_raises_its_bound_until_it_proves_the_optimum():
    bounds = []
    for limit in (1, 3, 6, 12, None):
        result = retrieve(*_cover(), "optimal", node_limit=limit, time_limit=None)
        bounds.append((result.bound, result.cost, result.proven_optimal))
    assert len(retrieve(*_cover(), "complete").tree) == 4
    assert bounds[0] == (2.0, 3.0, False)  # the local search found the optimum; LM-cut proves only 2
    assert all(a[0] <= b[0] and a[1] >= b[1] for a, b in itertools.pairwise(bounds))
    assert bounds[-1] == (3.0, 3.0, True)


@settings(max_examples=200, deadline=None)
@given(problems())
def test_weighted_maximizes_the_success_probability(problem):
    foon, kitchen, goal = problem
    result = retrieve(foon, kitchen, goal, "weighted", rates=RATES)
    best = best_subset(foon, kitchen, goal, neg_log)
    if best == math.inf:
        assert result.tree is None
        return
    assert validate(result.tree, kitchen).ok
    assert math.isclose(result.probability, math.exp(-best), rel_tol=1e-9)
    for other in ("complete", "greedy", "optimal"):
        assert result.probability >= retrieve(foon, kitchen, goal, other, rates=RATES).probability - 1e-12


@settings(max_examples=100, deadline=None)
@given(problems(), st.randoms(use_true_random=False))
def test_results_do_not_depend_on_unit_order(problem, rnd: random.Random):
    foon, kitchen, goal = problem
    units = list(foon.units)
    rnd.shuffle(units)
    shuffled = Foon(tuple(units))
    for method in ("complete", "greedy", "optimal", "weighted"):
        a = retrieve(foon, kitchen, goal, method, rates=RATES)
        b = retrieve(shuffled, kitchen, goal, method, rates=RATES)
        assert (a.tree is None) == (b.tree is None)
        if a.tree is not None:
            assert [u.key for u in a.tree.units] == [u.key for u in b.tree.units], method


def test_optimal_shares_a_unit_that_complete_and_greedy_duplicate():
    """x is made in round 1 by `chop`, but `mix` (needed for y anyway) also makes it."""
    k1, k2, w, x, y, z, goal = (make_node(s) for s in ("k1", "k2", "w", "x", "y", "z", "goal"))
    units = [FunctionalUnit((k1,), Motion("chop"), (x,)), FunctionalUnit((z,), Motion("mix"), (x, y)),
             FunctionalUnit((k2,), Motion("pour"), (z,)), FunctionalUnit((w,), Motion("zest"), (y,)),
             FunctionalUnit((k1,), Motion("wash"), (w,)), FunctionalUnit((x, y), Motion("serve"), (goal,))]
    foon, kitchen, target = Foon(tuple(units)), {k1, k2}, Goal(GoalSpec("goal"), (goal,), 3)
    best = retrieve(foon, kitchen, target, "optimal")
    assert [u.motion.label for u in best.tree.units] == ["pour", "mix", "serve"]
    assert best.proven_optimal
    for method in ("complete", "greedy"):
        assert len(retrieve(foon, kitchen, target, method).tree) == 4
