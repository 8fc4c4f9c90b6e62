"""Integer index of a FOON for the retrieval searches.

Hashing an `ObjectNode` hashes its whole state tuple, so the searches work on
integer ids instead. Ids follow the sorted (content) order of nodes, and every
unit has a rank in a content order (motion label, sorted input ids, sorted
output ids): all tie-breaks use these orders, never file order. An index is
built once per `Foon` object and cached while that object lives.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Hashable, Iterable
from dataclasses import dataclass, field
from typing import TypeVar

from ..model.bulk import bulk
from ..model.foon import Foon, ObjectNode

T = TypeVar("T")


@dataclass(frozen=True, eq=False)
class FoonIndex:
    """Node ids, unit inputs/outputs as id tuples, consumers and makers per node, unit ranks."""

    nodes: tuple[ObjectNode, ...]          # id -> node, sorted
    node_id: dict[ObjectNode, int]
    inputs: tuple[tuple[int, ...], ...]    # unit index -> distinct input ids (sorted)
    outputs: tuple[tuple[int, ...], ...]   # unit index -> distinct output ids (sorted)
    consumers: tuple[tuple[int, ...], ...]  # node id -> units taking it as input, by rank
    makers: tuple[tuple[int, ...], ...]    # node id -> units outputting it without consuming it, by rank
    rank: tuple[int, ...]                  # unit index -> position in the content order
    order: tuple[int, ...]                 # unit indexes in content order
    motions: tuple[str, ...]               # unit index -> motion label
    _memo: dict = field(default_factory=dict, repr=False)

    def ids(self, nodes: Iterable[ObjectNode]) -> list[int]:
        """Sorted ids of the given nodes that occur in the network (others are ignored)."""
        get = self.node_id.get
        return sorted({i for i in map(get, nodes) if i is not None})

    def kitchen_ids(self, kitchen: frozenset[ObjectNode]) -> tuple[int, ...]:
        """`ids(kitchen)`, remembered for the last kitchen object seen (retrievals repeat it)."""
        hit = self._memo.get("kitchen")
        if hit is not None and hit[0] is kitchen:
            return hit[1]
        ids = tuple(self.ids(kitchen))
        self._memo["kitchen"] = (kitchen, ids)
        return ids

    def positions(self, foon: Foon) -> dict[int, int]:
        """id(unit) -> unit index, for the units of `foon` (the network of this index), remembered."""
        hit = self._memo.get("positions")  # keyed by id: holding `foon` here would keep it alive
        if hit is None or hit[0] != id(foon):
            hit = self._memo["positions"] = (id(foon), {id(x): i for i, x in enumerate(foon.units)})
        return hit[1]

    def remember(self, name: str, key: Hashable, make: Callable[[], T]) -> T:
        """`make()` for `key`, remembered under `name` while this index lives (the last key per name)."""
        hit = self._memo.get(name)
        if hit is not None and hit[0] == key:
            return hit[1]
        value = make()
        self._memo[name] = (key, value)
        return value


def node_key(node: ObjectNode) -> tuple:
    """The nodes' sort order (that of the model's dataclass order) as plain tuples, compared in C."""
    return (node.label, tuple((s.label, s.related, s.ingredients) for s in node.states))


@bulk
def build_index(foon: Foon) -> FoonIndex:
    """Build the index (linear after one sort of nodes and one of units)."""
    nodes = tuple(sorted(foon.nodes, key=node_key))
    node_id = {n: i for i, n in enumerate(nodes)}
    inputs = tuple(tuple(sorted({node_id[n] for n in u.inputs})) for u in foon.units)
    outputs = tuple(tuple(sorted({node_id[n] for n in u.outputs})) for u in foon.units)
    motions = [u.motion.label for u in foon.units]
    order = tuple(sorted(range(len(foon.units)), key=lambda u: (motions[u], inputs[u], outputs[u], u)))
    rank = [0] * len(order)
    for r, u in enumerate(order):
        rank[u] = r
    consumers: list[list[int]] = [[] for _ in nodes]
    makers: list[list[int]] = [[] for _ in nodes]
    for u in order:
        ins = inputs[u]
        for n in ins:
            consumers[n].append(u)
        for n in outputs[u]:
            if n not in ins:
                makers[n].append(u)
    return FoonIndex(nodes, node_id, inputs, outputs, tuple(map(tuple, consumers)),
                     tuple(map(tuple, makers)), tuple(rank), order, tuple(motions))


_CACHE: dict[int, tuple[weakref.ref, FoonIndex]] = {}


def index_of(foon: Foon) -> FoonIndex:
    """The cached index of `foon`; the entry is dropped when `foon` is garbage-collected."""
    hit = _CACHE.get(id(foon))
    if hit is not None and hit[0]() is foon:
        return hit[1]
    ix = build_index(foon)
    key = id(foon)
    _CACHE[key] = (weakref.ref(foon, lambda _r, key=key: _CACHE.pop(key, None)), ix)
    return ix
