"""The forward AND/OR fixpoint with missing-input counters, unweighted and costed, written once.

A unit (action) fires once all its inputs are available; its outputs become
available. Each unit keeps a counter of the inputs it still misses; a node
becoming available decrements the counters of the units that consume it, and a
unit whose counter reaches 0 is ready. The callers build the counters (which
inputs count as missing: not in the kitchen, not in the initial state, not in a
plan's cone) and read the answers; the loops are here:

* `fire`, unweighted: which units fire and which nodes get made, in rounds
  (round 1 fires the units ready at the start; a unit fires in the round after
  the one that made its last missing input), with each node's first achiever.
  Used by `reachability.reachable` (rounds sorted by content rank) and the STRIPS
  relaxed reachability of `pddl.prune.prune_task` (discovery order).
* `cheapest`, costed: Knuth's generalization of Dijkstra's algorithm (superior
  functions) over the same counters: a unit's cost is its own `rc` plus the
  max (h_max) or the sum (h_add) of its inputs' costs, a node's cost the
  cheapest unit making it. Used by `retrieval.lmcut` (h_max) and the relaxed
  plans of `retrieval.improve` (h_add, stopping at the first goal settled).

The two differ in their queue (round lists versus a heap keyed by cost): one
loop for both would put a heap, and its log factor, under the unweighted
callers, whose answers (firing order, first achievers) are defined by rounds.
The demand-driven counters of `retrieval.greedy` (counters only for the units
its queue looks at, updated as a side effect of its search) are not a forward
fixpoint and stay there; so does the plan-pruning test of `retrieval.improve`,
run once per unit of a plan inside a much larger cone, whose marks are sparse
sets over the plan where `fire`'s are arrays over all nodes (measured slower
there).
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Collection, Sequence

INF = math.inf

#: `node_round` of a node not made (yet).
UNREACHED = -1


def fire(ready: list[int], missing: list[int] | dict[int, int], outputs: Sequence[Sequence[int]],
         consumers: Sequence[Sequence[int]], node_round: list[int], achiever: list[int],
         rank: Sequence[int] | None = None) -> list[list[int]]:
    """Fire units forward from `ready` until nothing more fires; the rounds, in firing order.

    Nodes and units are ids: `outputs[u]` the nodes unit u makes, `consumers[n]` the units with input n
    (each once per counted input). `ready`: the units whose inputs are all available (round 1; the list
    is kept as the first round). `missing[u]`: inputs unit u still misses, decremented in place; a unit
    whose count starts below 0 never fires (a unit outside the scope). `node_round[n]`: `UNREACHED` for
    a node not available yet, 0 for one available beforehand (the kitchen, the initial state); set in
    place to the round that makes it, and `achiever[n]` to the unit that first made it. `rank[u]`: with
    it, each round fires in increasing rank, else in the order its units became ready.

    Tie-breaks: a node's first achiever is the first unit in firing order that outputs it, so following
    first achievers back never meets a cycle and a node's round is the fewest sequential rounds that make
    it. O(units fired + their input and output edges), plus sorting each round when `rank` is given.
    """
    rounds: list[list[int]] = []
    rnd = 0
    while ready:
        rnd += 1
        if rank is not None:
            ready.sort(key=rank.__getitem__)
        rounds.append(ready)
        nxt: list[int] = []
        for u in ready:
            for n in outputs[u]:
                if node_round[n] == UNREACHED:
                    node_round[n] = rnd
                    achiever[n] = u
                    for c in consumers[n]:
                        missing[c] -= 1
                        if not missing[c]:
                            nxt.append(c)
        ready = nxt
    return rounds


def cheapest(seeds: Sequence[int], counts: Sequence[int], outputs: Sequence[Sequence[int]],
             consumers: Sequence[Sequence[int]], rc: Sequence[float], additive: bool,
             goals: Collection[int] = ()) -> tuple[list[float], list[float], list[int], int]:
    """(node cost, unit input cost, best supporter per node, goal settled or -1) of the costed fixpoint.

    Nodes and units are dense ids: `counts[u]` the inputs of unit u to wait for, `seeds` the units with
    none, `outputs[u]` and `consumers[n]` as in `fire`, `rc[u] >= 0` the unit's own cost (`INF`: it never
    makes anything). A unit's input cost is the max (h_max) or, with `additive`, the sum (h_add) of its
    inputs' costs, summed in the order the inputs settle; seeds' is 0. A node's cost is the least input
    cost + rc over the units making it (INF if none fires), its best supporter that unit (-1 if none).
    With `goals`, it stops at the first goal node settled (the answers then hold for the nodes settled).

    Nodes settle in increasing cost from a heap of (cost, node id) pushed only when a cost strictly
    drops, so a popped entry dearer than its node's cost is stale and every node settles once, at its
    final cost; a unit completes when its last input settles. Ties: lower node id first among the
    nodes queued, then each node's consumers in their order; a node keeps the first supporter reaching
    its least cost. The input costs of units that never complete stay INF. O((nodes + edges) log nodes).
    """
    n_nodes = len(consumers)
    cost = [INF] * n_nodes
    sup = [-1] * n_nodes
    base = [INF] * len(counts)
    acc = [0.0] * len(counts) if additive else base
    missing = list(counts)
    heap: list[tuple[float, int]] = []
    push, pop = heapq.heappush, heapq.heappop
    for u in seeds:
        base[u] = 0.0
        c = rc[u]
        for o in outputs[u]:
            if c < cost[o]:
                cost[o] = c
                sup[o] = u
                push(heap, (c, o))
    while heap:
        c, n = pop(heap)
        if c > cost[n]:
            continue
        if n in goals:
            return cost, base, sup, n
        for u in consumers[n]:
            if additive:
                acc[u] += c
            missing[u] -= 1
            if not missing[u]:
                b = base[u] = acc[u] if additive else c
                uc = b + rc[u]
                for o in outputs[u]:
                    if uc < cost[o]:
                        cost[o] = uc
                        sup[o] = u
                        push(heap, (uc, o))
    return cost, base, sup, -1
