"""Complete solvability: which nodes a kitchen can make, by an AND/OR fixpoint.

A unit fires when all its inputs are available; its outputs become available
(the counter fixpoint of `fixpoint.fire`). Every node and unit is handled once:
O(nodes + sum of unit sizes).

The fixpoint runs in rounds (round 0 = the kitchen; a unit fires in round
1 + the latest round of its inputs) and, within a round, in the units' content
order (`index.FoonIndex.order`). A node's *first achiever* is the first unit in
that firing order that outputs it: following first achievers back from a node
never meets a cycle, and gives a tree whose depth is the node's round, the
fewest sequential rounds that can make it.
"""

from __future__ import annotations

import weakref
from collections.abc import Container, Iterable, Sequence
from dataclasses import dataclass
from itertools import chain, repeat

from ..model.bulk import drain
from ..model.foon import Foon, ObjectNode
from ..model.memo import per_network
from ..model.words import first_of
from .fixpoint import UNREACHED, fire
from .index import FoonIndex, index_of


@dataclass(frozen=True, eq=False)
class Reachability:
    """The fixpoint of a network from a kitchen.

    `node_round[id]` is 0 for kitchen nodes, the round a unit first made it, or
    UNREACHED; `achiever[id]` is the node's first achiever (unit index) or -1;
    `fired` lists the units that fire, in firing order; `unit_round[u]` is the
    round unit u fires in, or UNREACHED. When `targets` is set, only the units
    that can contribute to them were run: the answers hold for the targets and
    the nodes they depend on (for those they equal the full fixpoint's).
    """

    foon: Foon
    index: FoonIndex
    kitchen: frozenset[ObjectNode]
    node_round: tuple[int, ...]
    achiever: tuple[int, ...]
    fired: tuple[int, ...]
    unit_round: tuple[int, ...]
    targets: frozenset[ObjectNode] | None = None

    def can_make(self, node: ObjectNode) -> bool:
        """Whether `node` is in the kitchen or some sequence of units makes it."""
        i = self.index.node_id.get(node)
        return node in self.kitchen if i is None else self.node_round[i] != UNREACHED

    def makes_any(self, nodes: Iterable[ObjectNode]) -> bool:
        """Whether the kitchen can make at least one of `nodes` (a goal's candidates): the goal test of
        retrieval, planning and the reasons. O(len(nodes)), stops at the first makeable one."""
        return any(map(self.can_make, nodes))

    def round_of(self, node: ObjectNode) -> int | None:
        """0 for a kitchen node, the round a unit first makes it, or None when it cannot be made."""
        i = self.index.node_id.get(node)
        if i is None:
            return 0 if node in self.kitchen else None
        r = self.node_round[i]
        return None if r == UNREACHED else r

    def achiever_of(self, node: ObjectNode) -> int | None:
        """Index of the node's first achiever (None for kitchen or unreachable nodes)."""
        i = self.index.node_id.get(node)
        if i is None or self.achiever[i] < 0:
            return None
        return self.achiever[i]


def relevant_units(ix: FoonIndex, targets: Iterable[int], in_kitchen: bytearray) -> list[int]:
    """The units that can contribute to the target node ids, in discovery order: backwards over
    makers (depth-first, O(units + edges)), not past kitchen nodes (those need no making)."""
    return walk_back(ix.makers, ix.inputs, targets, bytearray(in_kitchen))


def walk_back(makers: Sequence[Sequence[int]], inputs: Sequence[Sequence[int]], targets: Iterable[int],
              seen: bytearray) -> list[int]:
    """The units met walking back from the `targets` (node ids) over `makers` (node -> units) and
    `inputs` (unit -> nodes), depth-first, in discovery order, O(units + edges). Nodes marked in
    `seen` are not walked past; every node met gets marked."""
    taken = bytearray(len(inputs))
    units: list[int] = []
    stack = list(targets)
    while stack:
        n = stack.pop()
        if seen[n]:
            continue
        seen[n] = 1
        for u in makers[n]:
            if not taken[u]:
                taken[u] = 1
                units.append(u)
                stack.extend(inputs[u])
    return units


def reachable(foon: Foon, kitchen_nodes: Iterable[ObjectNode],
              targets: Iterable[ObjectNode] | None = None, skip: Container[int] = ()) -> Reachability:
    """Run the fixpoint of `foon` from `kitchen_nodes` (nodes at the network's level).

    With `targets`, run it only over the units that can contribute to them (a
    node's round and first achiever depend only on such units, so the answers
    for the targets are the same; used per goal, it is much faster). Units whose
    index is in `skip` never fire (the units constraints remove, `constraints.py`).
    The whole fixpoint (no `targets`, no `skip`) is remembered per network object for its last
    `FIXPOINTS_KEPT` kitchens (`_fixpoints`): a Reachability is immutable, and the relational encoding
    asks for one kitchen's fixpoint several times per goal, for every goal of a trial.
    """
    kitchen = frozenset(kitchen_nodes)
    if targets is not None or skip:
        return _fixpoint(foon, kitchen, targets, skip)
    kept = _fixpoints(foon)
    if (hit := kept.get(kitchen)) is None:
        reach = _fixpoint(foon, kitchen, None, ())
        kept[kitchen] = (reach.node_round, reach.achiever, reach.fired, reach.unit_round)
        while len(kept) > FIXPOINTS_KEPT:
            kept.pop(next(iter(kept)))
        return reach
    return Reachability(foon, index_of(foon), kitchen, *hit)


#: Whole fixpoints `reachable` keeps per network object, by kitchen (a trial's kitchen and its readings).
FIXPOINTS_KEPT = 4


@per_network
def _fixpoints(foon: Foon) -> dict[frozenset[ObjectNode], tuple[tuple[int, ...], ...]]:
    """The whole fixpoints of `foon` `reachable` keeps, by kitchen, oldest first: their rounds, achievers, fired
    units and unit rounds (not the Reachability, which holds the network: the cache would keep it alive)."""
    return {}


def _fixpoint(foon: Foon, kitchen: frozenset[ObjectNode], targets: Iterable[ObjectNode] | None,
              skip: Container[int]) -> Reachability:
    """`reachable`, computed."""
    ix = index_of(foon)
    scope = None if targets is None else frozenset(targets)
    kitchen_ids = ix.kitchen_ids(kitchen)
    in_kitchen = bytearray(len(ix.nodes))
    for k in kitchen_ids:
        in_kitchen[k] = 1
    inputs = ix.inputs
    units = ix.order if scope is None else relevant_units(ix, ix.ids(scope), in_kitchen)
    if skip:
        units = [u for u in units if u not in skip]
    missing = [-1] * len(inputs)  # inputs still missing; -1 (never 0) for units outside the scope
    ready: list[int] = []
    for u in units:
        left = 0
        for i in inputs[u]:
            if not in_kitchen[i]:
                left += 1
        missing[u] = left
        if not left:
            ready.append(u)
    node_round = [UNREACHED] * len(ix.nodes)
    for k in kitchen_ids:
        node_round[k] = 0
    achiever = [-1] * len(ix.nodes)
    rounds = fire(ready, missing, ix.outputs, ix.consumers, node_round, achiever, ix.rank)
    unit_round = [UNREACHED] * len(inputs)
    for rnd, now in enumerate(rounds, start=1):
        drain(map(unit_round.__setitem__, now, repeat(rnd)))  # a C-level loop
    fired = tuple(chain.from_iterable(rounds))
    return Reachability(foon, ix, kitchen, tuple(node_round), tuple(achiever), fired, tuple(unit_round),
                        scope)


#: Blockers a reason names (the smallest ids); one more is remembered per node, enough for
#: `blockers(..., limit <= SUMMARY + 1)`: `blocker_words` learns from it whether any are left out.
SUMMARY = 10
_KEPT = SUMMARY + 1
_SUMMARIES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def blockers(reach: Reachability, nodes: Iterable[ObjectNode], limit: int = SUMMARY) -> tuple[ObjectNode, ...]:
    """Why `nodes` cannot be made: the unmakeable nodes they depend on that no unit makes.

    Walks back from each unreachable node through every maker's unreachable
    inputs; the nodes met that have no maker at all are what the kitchen lacks.
    Returns up to `limit` of them in sorted order.

    The goals of a batch share one fixpoint and mostly the same unreachable region,
    so each node's answer (its `SUMMARY` + 1 smallest blockers) is remembered per fixpoint:
    the region is condensed into strongly connected components (Tarjan, iterative) and
    a component's answer is the smallest of its own unmakeable nodes and its successors'
    answers (the smallest k of a union are among the smallest k of its parts). Each node
    and edge of the region is walked once per fixpoint instead of once per goal.
    """
    ix = reach.index
    rounds = reach.node_round
    starts = [i for i in ix.ids(nodes) if rounds[i] == UNREACHED]
    if limit > _KEPT:
        found = _walk(reach, starts)
    else:
        memo = _summaries(reach, starts)
        found = set().union(*(memo[s] for s in starts))
    return tuple(ix.nodes[i] for i in sorted(found)[:limit])


def blocker_words(reach: Reachability, nodes: Iterable[ObjectNode]) -> str:
    """`blockers` of `nodes` in words: the first `SUMMARY` in node order, then `; ... (N more)` ("" when none).

    A cut list must not read as the whole: the remembered answers (`SUMMARY` + 1 per node) tell whether any
    are left out; only then does the plain search count them (O(unreachable region)).
    """
    found = blockers(reach, nodes, _KEPT)
    if len(found) > SUMMARY:
        found = blockers(reach, nodes, len(reach.index.nodes))
    return first_of(found, SUMMARY, ObjectNode.describe)


def _walk(reach: Reachability, starts: list[int]) -> set[int]:
    """Every unmakeable node met walking back from `starts` (the plain search)."""
    ix = reach.index
    rounds, makers, inputs = reach.node_round, ix.makers, ix.inputs
    seen = bytearray(len(ix.nodes))
    stack = list(starts)
    found: set[int] = set()
    while stack:
        n = stack.pop()
        if seen[n]:
            continue
        seen[n] = 1
        if not makers[n]:
            found.add(n)
            continue
        for u in makers[n]:
            for i in inputs[u]:
                if not seen[i] and rounds[i] == UNREACHED:
                    stack.append(i)
    return found


def _summaries(reach: Reachability, starts: list[int]) -> dict[int, tuple[int, ...]]:
    """The remembered answers of this fixpoint, extended to cover `starts` (module doc of `blockers`)."""
    memo = _SUMMARIES.get(reach)
    if memo is None:
        memo = _SUMMARIES[reach] = {}
    rounds, makers, inputs = reach.node_round, reach.index.makers, reach.index.inputs

    def succ(n: int) -> list[int]:
        return [i for u in makers[n] for i in inputs[u] if rounds[i] == UNREACHED]

    index: dict[int, int] = {}
    low: dict[int, int] = {}
    stack: list[int] = []
    on_stack: set[int] = set()
    for s in starts:
        if s in memo or s in index:
            continue
        index[s] = low[s] = len(index)
        stack.append(s)
        on_stack.add(s)
        work = [(s, iter(succ(s)))]
        while work:
            v, it = work[-1]
            for w in it:
                if w in memo:
                    continue
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(succ(w))))
                    break
                if w in on_stack:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    low[parent] = min(low[parent], low[v])
                if low[v] == index[v]:
                    comp: list[int] = []
                    while True:
                        w = stack.pop()
                        on_stack.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    members = set(comp)
                    found = {w for w in comp if not makers[w]}
                    for w in comp:
                        for x in succ(w):
                            if x not in members:
                                found.update(memo[x])
                    answer = tuple(sorted(found)[:_KEPT])
                    for w in comp:
                        memo[w] = answer
    return memo
