"""Property tests of the search bounds (`retrieval.lmcut`) and of greedy's bookkeeping, on random inputs.

The oracles are independent of the code under test: a from-scratch h_max for
the incremental one, an exhaustive search over unit subsets for LM-cut's
admissibility, and the seed paper's plain greedy loop (every maker's inputs
scanned on every visit) for the bookkeeping `greedy` adds.
"""

from __future__ import annotations

import itertools
import math
from collections import deque

from hypothesis import assume, given, settings
from hypothesis import strategies as st
from test_retrieval_properties import problems

from foon2pddl.analysis.index import index_of
from foon2pddl.retrieval.extract import ordered_units
from foon2pddl.retrieval.greedy import greedy
from foon2pddl.retrieval.improve import improve, relaxed_plan
from foon2pddl.retrieval.lmcut import Cone

NODES = 7  # node ids 0..6 (none in the kitchen: a unit without inputs fires from the kitchen)


@st.composite
def cones(draw):
    """A cone of up to 8 units over 7 nodes (unit k: inputs, outputs disjoint from them) with weights,
    so that several makers per node, cycles and nodes no unit makes all occur."""
    count = draw(st.integers(1, 8))
    deps, outputs = {}, []
    for u in range(count):
        ins = draw(st.lists(st.integers(0, NODES - 1), max_size=3, unique=True))
        outs = draw(st.lists(st.integers(0, NODES - 1).filter(lambda n, ins=ins: n not in ins),
                             min_size=1, max_size=2, unique=True))
        deps[u] = tuple(sorted(ins))
        outputs.append(tuple(sorted(outs)))
    makers = {n: tuple(u for u in range(count) if n in outputs[u]) for n in range(NODES)}
    weight = draw(st.lists(st.sampled_from([1.0, 2.0, 0.5, 3.25]), min_size=count, max_size=count))
    return Cone.of(range(count), deps, outputs, makers, weight), deps, outputs, weight


def cheapest(deps, outputs, weight, free, goal):
    """Least cost of a unit set whose closure from the kitchen makes every goal node (free units cost 0)."""
    units = range(len(outputs))
    best = math.inf
    for k in range(len(outputs) + 1):
        for subset in itertools.combinations(units, k):
            have: set[int] = set()
            changed = True
            while changed:
                changed = False
                for u in subset:
                    if set(deps[u]) <= have and not set(outputs[u]) <= have:
                        have |= set(outputs[u])
                        changed = True
            if set(goal) <= have:
                best = min(best, math.fsum(weight[u] for u in subset if u not in free))
    return best


def snapshot(state):
    return (state.free, list(state.rc), list(state.cost), list(state.ucost), list(state.pcf))


@settings(max_examples=300, deadline=None)
@given(cones(), st.lists(st.integers(0, 7), max_size=4), st.lists(st.integers(0, 7), max_size=4))
def test_incremental_hmax_equals_a_fresh_one(cone_case, first, more):
    """h_max grown from a base state (a search parent's) is the fresh h_max: costs and dearest inputs."""
    cone = cone_case[0]
    small = frozenset(first)
    large = small | frozenset(more)
    grown = cone.state(large, base=cone.state(small))
    assert snapshot(grown) == snapshot(cone.state(large))


@settings(max_examples=300, deadline=None)
@given(cones(), st.lists(st.integers(0, 7), max_size=3), st.lists(st.integers(0, NODES - 1), min_size=1,
                                                                   max_size=3, unique=True))
def test_lmcut_is_admissible_and_at_least_hmax(cone_case, free, goal):
    """h_max <= LM-cut <= the exhaustive optimum (free units cost 0), and the state is left as it was."""
    cone, deps, outputs, weight = cone_case
    state = cone.state(frozenset(free))
    before = snapshot(state)
    bound = cone.lmcut(state, goal)
    assert snapshot(state) == before
    best = cheapest(deps, outputs, weight, set(free), goal)
    hmax = max(state.cost[cone.local_n[n]] for n in goal)
    assert hmax <= bound + 1e-9
    assert bound <= best + 1e-9
    assert (bound == math.inf) == (best == math.inf)


@settings(max_examples=300, deadline=None)
@given(cones(), st.lists(st.integers(0, NODES - 1), min_size=1, max_size=3, unique=True))
def test_a_restricted_cone_is_the_cone_built_from_its_units(cone_case, goals):
    """`restrict` (a goal's cone cut out of a wider one, h_max included) equals the cone built from
    scratch over the units lying backwards from the goals, and its h_max a fresh one."""
    wide, deps, outputs, weight = cone_case
    nodes, units, stack = set(), set(), list(goals)
    while stack:  # the backward closure, plainly
        n = stack.pop()
        if n not in nodes:
            nodes.add(n)
            for u in range(len(outputs)):
                if n in outputs[u] and u not in units:
                    units.add(u)
                    stack.extend(deps[u])
    fresh = Cone.of(units, deps, outputs, {n: tuple(u for u in sorted(units) if n in outputs[u]) for n in nodes},
                    weight)
    sub, top = wide.restrict([wide.local_n[g] for g in goals], wide.state(frozenset()))
    fields = ("unit_ids", "node_ids", "deps", "outs", "makers", "consumers", "weight", "seeds", "dep_counts")
    assert {f: getattr(sub, f) for f in fields} == {f: getattr(fresh, f) for f in fields}
    assert snapshot(top) == snapshot(fresh.state(frozenset()))


def plain_greedy(foon, kitchen, goal):
    """The paper's loop without bookkeeping (every maker's inputs scanned on every visit): the units of the
    tree it extracts (`ordered_units`, first achievers, earlier firings reused) and its iterations, or None
    when nothing more can be made."""
    ix = index_of(foon)
    in_kitchen = {ix.node_id[n] for n in kitchen if n in ix.node_id}
    available = set(in_kitchen)
    order = [ix.node_id[c] for c in goal.candidates]
    done = next((c for c in order if c in available), None)
    if done is not None:
        return (), 0
    queue = deque(sorted(order))
    seen, achiever, fired_at = set(queue), {}, {}
    since_progress, window, iterations = 0, len(queue), 0
    while queue:
        obj = queue.popleft()
        iterations += 1
        progress = False
        if obj not in available:
            for u in ix.makers[obj]:
                if all(i in available for i in ix.inputs[u]):
                    fired_at[u] = len(fired_at)
                    for n in ix.outputs[u]:
                        if n not in available:
                            available.add(n)
                            achiever[n] = u
                    done = next((c for c in order if c in available), None)
                    if done is not None:
                        units = ordered_units(ix, done, achiever.__getitem__, in_kitchen.__contains__,
                                              fired_at.__getitem__)
                        return units, iterations
                    progress = True
                    break
            else:
                for u in ix.makers[obj]:
                    for i in ix.inputs[u]:
                        if i not in available and i not in seen:
                            seen.add(i)
                            queue.append(i)
                            progress = True
                if ix.makers[obj]:
                    queue.append(obj)
        if progress:
            since_progress, window = 0, len(queue)
        else:
            since_progress += 1
            if since_progress >= window:
                return None
    return None


@settings(max_examples=300, deadline=None)
@given(problems())
def test_greedy_fires_what_the_plain_loop_fires(problem):
    """greedy's missing-input counts and skipped retries change nothing: the same tree after the same
    number of iterations, or no tree."""
    foon, kitchen, goal = problem
    plain = plain_greedy(foon, kitchen, goal)
    result = greedy(foon, kitchen, goal)
    assert (result.tree is None) == (plain is None)
    if plain is not None:
        units, iterations = plain
        position = index_of(foon).positions(foon)
        assert tuple(position[id(u)] for u in result.tree.units) == tuple(units)
        assert result.expansions == iterations


@settings(max_examples=300, deadline=None)
@given(cones(), st.integers(0, NODES - 1), st.floats(0.0, 1.0))
def test_local_search_that_stops_at_a_lower_bound_finds_the_same_plan(cone_case, goal, fraction):
    """`improve` with a floor at or below the optimum returns the plan it returns without one (it only
    skips attempts that cannot find anything cheaper), after no more attempts."""
    cone, deps, outputs, weight = cone_case
    found = relaxed_plan(cone, cone.weight, {cone.local_n[goal]})
    assume(found is not None)
    g, plan = found
    best = cheapest(deps, outputs, weight, set(), [goal])
    plain = improve(cone, plan, g, {g}, 25)
    for floor in (best, best * fraction):
        floored = improve(cone, plan, g, {g}, 25, floor=floor)
        assert floored[:2] == plain[:2]
        assert floored[2] <= plain[2]
    if math.isclose(math.fsum(weight[u] for u in plan), best):
        assert improve(cone, plan, g, {g}, 25, floor=best)[2] == 0
