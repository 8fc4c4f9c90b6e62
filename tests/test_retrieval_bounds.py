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

from hypothesis import given, settings
from hypothesis import strategies as st
from test_retrieval_properties import problems

from foon2pddl.analysis.index import index_of
from foon2pddl.retrieval.greedy import greedy
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
    """The paper's loop without bookkeeping: the units fired, in order, or None (nothing more can be made)."""
    ix = index_of(foon)
    available = {ix.node_id[n] for n in kitchen if n in ix.node_id}
    cands = sorted(ix.node_id[c] for c in goal.candidates)
    if any(c in available for c in cands):
        return []
    queue, seen, fired = deque(cands), set(cands), []
    since_progress, window = 0, len(queue)
    while queue:
        obj = queue.popleft()
        progress = False
        if obj not in available:
            for u in ix.makers[obj]:
                if all(i in available for i in ix.inputs[u]):
                    fired.append(u)
                    available.update(ix.outputs[u])
                    if any(c in available for c in cands):
                        return fired
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
    """greedy's missing-input counts and skipped retries change nothing: same units fired, same answer."""
    foon, kitchen, goal = problem
    fired = plain_greedy(foon, kitchen, goal)
    result = greedy(foon, kitchen, goal)
    assert (result.tree is None) == (fired is None)
    if fired is not None and result.tree is not None and fired:
        assert result.detail.startswith(f"{len(fired)} units fired")
        position = index_of(foon).positions(foon)
        assert {position[id(u)] for u in result.tree.units} <= set(fired)
