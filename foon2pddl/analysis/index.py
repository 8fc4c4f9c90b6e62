"""Integer index of a FOON for the retrieval searches.

Hashing an `ObjectNode` hashes its whole state tuple, so the searches work on
integer ids instead. Ids follow the sorted (content) order of nodes, and every
unit has a rank in a content order (motion label, sorted input ids, sorted
output ids): all tie-breaks use these orders, never file order. An index is
built once per `Foon` object and cached while that object lives.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable
from dataclasses import dataclass, field
from functools import partial
from itertools import chain, repeat
from operator import attrgetter, itemgetter
from typing import TypeVar

from ..model.bulk import bulk, drain
from ..model.foon import Foon, ObjectNode
from ..model.memo import per_network

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


#: A state's sort key, read in C (the dataclass order of `State`).
_STATE_KEY = attrgetter("label", "related", "ingredients")


def node_key(node: ObjectNode) -> tuple:
    """The nodes' sort order (that of the model's dataclass order) as plain tuples, compared in C."""
    return (node.label, tuple(map(_STATE_KEY, node.states)))


def _sorted_ids(look: Callable[[int], int], side: tuple[tuple[int, ...], ...]) -> tuple[tuple[int, ...], ...]:
    """Each unit's node numbers on one side mapped by `look`, deduplicated and sorted (C-level loops)."""
    return tuple(map(tuple, map(sorted, map(set, map(partial(map, look), side)))))


def _listing(size: int, owners: Iterable[int], members: Iterable[Iterable[int]]) -> tuple[tuple[int, ...], ...]:
    """Per node id (0 .. size-1), the owners listing it among their members, in `owners` order."""
    lists: list[list[int]] = [[] for _ in range(size)]
    members = list(members)
    drain(map(list.append, map(lists.__getitem__, chain.from_iterable(members)),
              chain.from_iterable(map(repeat, owners, map(len, members)))))
    return tuple(map(tuple, lists))


@bulk
def build_index(foon: Foon) -> FoonIndex:
    """Build the index: one sort of nodes (by `node_key`) and one of units, the rest linear, on the
    network's node numbers (`Foon.table`) renumbered in sorted order; no node is hashed per occurrence,
    and the loops over units and nodes run in C (`map`)."""
    table = foon.table
    first = table.nodes
    keys = list(map(node_key, first))
    by_key = sorted(range(len(first)), key=keys.__getitem__)
    del keys
    nodes = tuple(map(first.__getitem__, by_key))
    renumber = [0] * len(first)
    drain(map(renumber.__setitem__, by_key, range(len(by_key))))
    del by_key
    node_id = dict(zip(nodes, range(len(nodes)), strict=True))
    inputs = _sorted_ids(renumber.__getitem__, table.inputs)
    outputs = _sorted_ids(renumber.__getitem__, table.outputs)
    motions = tuple(map(_MOTION_LABEL, foon.units))
    order = tuple(map(itemgetter(3), sorted(zip(motions, inputs, outputs, range(len(motions)), strict=True))))
    rank = [0] * len(order)
    drain(map(rank.__setitem__, order, range(len(order))))
    consumers = _listing(len(nodes), order, map(inputs.__getitem__, order))
    # a unit makes the outputs it does not also take as inputs
    makes = map(set.difference, map(set, map(outputs.__getitem__, order)), map(inputs.__getitem__, order))
    makers = _listing(len(nodes), order, makes)
    return FoonIndex(nodes, node_id, inputs, outputs, consumers, makers, tuple(rank), order, motions)


_MOTION_LABEL = attrgetter("motion.label")


@per_network
def index_of(foon: Foon) -> FoonIndex:
    """The cached index of `foon`; the entry is dropped when `foon` is garbage-collected."""
    return build_index(foon)
