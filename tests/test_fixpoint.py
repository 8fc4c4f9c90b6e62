"""The shared forward fixpoints (`analysis.fixpoint`) against brute-force oracles on random AND/OR graphs."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.fixpoint import UNREACHED, cheapest, fire

INF = math.inf


@st.composite
def graphs(draw):
    """(node count, per unit (inputs, outputs)) with up to 8 nodes and 9 units; units may have no inputs."""
    n = draw(st.integers(1, 8))
    nodes = st.integers(0, n - 1)
    units = draw(st.lists(st.tuples(st.frozensets(nodes, max_size=3), st.frozensets(nodes, min_size=1, max_size=3)),
                          max_size=9))
    return n, [(tuple(sorted(i)), tuple(sorted(o))) for i, o in units]


def consumers_of(n, units):
    out = [[] for _ in range(n)]
    for u, (ins, _) in enumerate(units):
        for i in ins:
            out[i].append(u)
    return out


def synchronous_rounds(n, units, given_nodes, scope, rank):
    """Oracle: round r fires every unit in scope, not fired yet, whose inputs all existed after round r - 1
    (in rank order); a node's round and achiever come from the first unit of the first round that makes it."""
    node_round = [0 if i in given_nodes else UNREACHED for i in range(n)]
    achiever = [-1] * n
    fired: set[int] = set()
    rounds = []
    while True:
        have = {i for i in range(n) if node_round[i] != UNREACHED}
        now = sorted((u for u in scope if u not in fired and set(units[u][0]) <= have), key=rank.__getitem__)
        if not now:
            return rounds, node_round, achiever
        rounds.append(now)
        fired.update(now)
        for u in now:
            for o in units[u][1]:
                if node_round[o] == UNREACHED:
                    node_round[o] = len(rounds)
                    achiever[o] = u
    return rounds, node_round, achiever


@settings(max_examples=300, deadline=None)
@given(graphs(), st.data())
def test_fire_matches_synchronous_rounds(graph, data):
    n, units = graph
    given_nodes = data.draw(st.frozensets(st.integers(0, n - 1)), label="given")
    scope = data.draw(st.frozensets(st.integers(0, max(len(units) - 1, 0)), max_size=len(units)), label="scope")
    scope = {u for u in scope if u < len(units)}
    rank = data.draw(st.permutations(range(len(units))), label="rank")
    use_rank = data.draw(st.booleans(), label="use rank")
    missing = [len([i for i in ins if i not in given_nodes]) if u in scope else -1 for u, (ins, _) in enumerate(units)]
    ready = [u for u in sorted(scope) if not missing[u]]
    node_round = [0 if i in given_nodes else UNREACHED for i in range(n)]
    achiever = [-1] * n
    rounds = fire(ready, missing, [o for _, o in units], consumers_of(n, units), node_round, achiever,
                  rank if use_rank else None)
    want_rounds, want_round, want_achiever = synchronous_rounds(n, units, given_nodes, scope, rank)
    assert node_round == want_round
    if use_rank:
        assert rounds == want_rounds
        assert achiever == want_achiever
    else:  # discovery order within a round: the same units per round, achievers among that round's makers
        assert [sorted(r) for r in rounds] == [sorted(r) for r in want_rounds]
        for i in range(n):
            if node_round[i] > 0:
                u = achiever[i]
                assert i in units[u][1] and u in rounds[node_round[i] - 1]
    # following first achievers back never meets a cycle: every input of an achiever is made earlier
    for i in range(n):
        if node_round[i] > 0:
            assert all(node_round[j] < node_round[i] for j in units[achiever[i]][0])


def bellman_ford(n, units, rc, additive):
    """Oracle: node costs by relaxing every unit until nothing changes (costs only decrease)."""
    cost = [INF] * n
    changed = True
    while changed:
        changed = False
        for u, (ins, outs) in enumerate(units):
            base = (sum(cost[i] for i in ins) if additive else max((cost[i] for i in ins), default=0.0)) if ins else 0.0
            for o in outs:
                if base + rc[u] < cost[o]:
                    cost[o] = base + rc[u]
                    changed = True
    return cost


@settings(max_examples=300, deadline=None)
@given(graphs(), st.data())
def test_cheapest_matches_bellman_ford(graph, data):
    n, units = graph
    rc = [float(x) if x >= 0 else INF for x in data.draw(st.lists(st.integers(-1, 4), min_size=len(units),
                                                                   max_size=len(units)), label="rc")]
    additive = data.draw(st.booleans(), label="additive")
    counts = [len(ins) for ins, _ in units]
    seeds = [u for u, c in enumerate(counts) if not c]
    outputs = [o for _, o in units]
    cost, base, sup, goal = cheapest(seeds, counts, outputs, consumers_of(n, units), rc, additive)
    assert goal == -1
    assert cost == bellman_ford(n, units, rc, additive)
    for u, (ins, _) in enumerate(units):
        combined = (sum(cost[i] for i in ins) if additive else max(cost[i] for i in ins)) if ins else 0.0
        assert base[u] == (combined if all(cost[i] < INF for i in ins) else INF)
    for i in range(n):
        if cost[i] < INF:  # the best supporter makes the node at its cost, and supporters never cycle
            u = sup[i]
            assert i in units[u][1] and base[u] + rc[u] == cost[i]
            assert all(cost[j] <= cost[i] for j in units[u][0])
        else:
            assert sup[i] == -1
    goals = data.draw(st.frozensets(st.integers(0, n - 1)), label="goals")
    _, _, _, goal = cheapest(seeds, counts, outputs, consumers_of(n, units), rc, additive, goals)
    reached = [cost[g] for g in goals if cost[g] < INF]
    if reached:  # a cheapest goal (on ties, the lowest id among those queued when it settles)
        assert goal in goals and cost[goal] == min(reached)
    else:
        assert goal == -1
