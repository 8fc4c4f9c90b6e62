"""Integer index of a FOON for the retrieval searches.

Hashing an `ObjectNode` hashes its whole state tuple, so the searches work on
integer ids instead. Ids follow the sorted (content) order of nodes, and every
unit has a rank in a content order (motion label, sorted input ids, sorted
output ids): all tie-breaks use these orders, never file order. An index is
built once per `Foon` object and cached while that object lives.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Sequence
from dataclasses import dataclass, field
from functools import partial
from itertools import chain, repeat
from operator import attrgetter, itemgetter
from typing import TypeVar

from ..model.bulk import bulk, drain
from ..model.foon import Foon, ObjectNode
from ..model.memo import per_network
from ..model.node_table import NodeTable

T = TypeVar("T")


#: Kitchens whose node ids `FoonIndex.kitchen_ids` keeps (a trial's kitchen and the readings of it a goal's task makes).
KITCHENS_KEPT = 8


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
        """`ids(kitchen)`, remembered for the last `KITCHENS_KEPT` kitchens, by value (retrievals repeat one kitchen
        object; the relational encoding builds equal kitchens anew, several per goal)."""
        kept = self._memo.setdefault("kitchens", {})
        key = kitchen if isinstance(kitchen, frozenset) else frozenset(kitchen)
        ids = kept.get(key)
        if ids is None:
            ids = kept[key] = tuple(self.ids(key))
            while len(kept) > KITCHENS_KEPT:
                kept.pop(next(iter(kept)))
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
_LABEL = attrgetter("label")
_STATES = attrgetter("states")


def node_key(node: ObjectNode) -> tuple:
    """The nodes' sort order (that of the model's dataclass order) as plain tuples, compared in C."""
    return (node.label, tuple(map(_STATE_KEY, node.states)))


def _node_keys(nodes: Sequence[ObjectNode]) -> list[tuple]:
    """`node_key` of every node, built by C-level maps (no Python call per node)."""
    return list(zip(map(_LABEL, nodes), map(tuple, map(partial(map, _STATE_KEY), map(_STATES, nodes))),
                    strict=True))


def _flat(side: Sequence[Sequence[int]]):
    """One side of every unit (tuples of node numbers) as two arrays: each number's unit, and the number."""
    import numpy as np

    lengths = np.fromiter(map(len, side), np.int64, len(side))
    numbers = np.fromiter(chain.from_iterable(side), np.int64, int(lengths.sum()))
    return np.repeat(np.arange(len(side), dtype=np.int64), lengths), numbers


def _pairs(owner, member, size: int):
    """The distinct (owner, member) pairs as keys `owner * size + member`, sorted: by owner, then member."""
    import numpy as np

    keys = owner * size + member
    keys.sort()
    if len(keys):
        keys = keys[np.concatenate(([True], keys[1:] != keys[:-1]))]
    return keys


def _groups(keys, size: int, groups: int, values=None) -> tuple[tuple[int, ...], ...]:
    """Sorted keys `group * size + value` -> per group 0 .. groups-1 the tuple of its values (`values[value]` when
    given), in key order."""
    import numpy as np

    ends = np.cumsum(np.bincount(keys // size, minlength=groups)).tolist()
    found = keys % size
    flat = tuple((found if values is None else values[found]).tolist())
    return tuple(map(flat.__getitem__, map(slice, [0, *ends[:-1]], ends)))


def _by_node(keys, size: int, order, rank):
    """Sorted (unit, node) keys `unit * size + node` -> sorted (node, rank of the unit) keys `node * units + rank`."""
    by_node = (keys % size) * len(order) + rank[keys // size]
    by_node.sort()
    return by_node


def _padded(keys, size: int, count: int):
    """Sorted (unit, node) keys `unit * size + node` as a matrix, row u the node ids of unit u padded with -1
    (below every id): its rows compare as the units' id tuples do."""
    import numpy as np

    owner = keys // size
    lengths = np.bincount(owner, minlength=count)
    matrix = np.full((count, int(lengths.max(initial=0))), -1, dtype=np.int64)
    starts = np.cumsum(lengths) - lengths
    matrix[owner, np.arange(len(keys)) - starts[owner]] = keys % size
    return matrix


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


#: Networks of at least this many units are indexed on numpy arrays (`_array_fields`); smaller ones by plain
#: C-level loops over tuples (`_tuple_fields`), faster than numpy's import (~0.15 s) on the networks users
#: mostly load (a universal FOON of the public subgraphs has ~2,400 units). Both give the same fields.
ARRAYS_FROM = 20_000


@bulk
def build_index(foon: Foon) -> FoonIndex:
    """Build the index on the network's node numbers (`Foon.table`): one sort of nodes (by `node_key`), renumbered
    in that order, then each unit's distinct ids sorted, the units' content order, consumers and makers; no node
    is hashed but in `node_id`, and no loop over units or nodes runs in Python."""
    table = foon.table
    first = table.nodes
    keys = _node_keys(first)
    by_key = sorted(range(len(first)), key=keys.__getitem__)
    del keys
    nodes = tuple(map(first.__getitem__, by_key))
    node_id = dict(zip(nodes, range(len(nodes)), strict=True))
    motions = tuple(map(_MOTION_LABEL, foon.units))
    fields = (_array_fields if len(motions) >= ARRAYS_FROM else _tuple_fields)(table, by_key, motions)
    return FoonIndex(nodes, node_id, *fields, motions)


def _tuple_fields(table: NodeTable, by_key: list[int], motions: tuple[str, ...]) -> tuple:
    """inputs, outputs, consumers, makers, rank and order by loops over tuples: O(P log P) for P (unit, node)
    pairs, but with a large network's millions of small objects scattered in memory, slower than arrays."""
    renumber = [0] * len(by_key)
    drain(map(renumber.__setitem__, by_key, range(len(by_key))))
    inputs = _sorted_ids(renumber.__getitem__, table.inputs)
    outputs = _sorted_ids(renumber.__getitem__, table.outputs)
    order = tuple(map(itemgetter(3), sorted(zip(motions, inputs, outputs, range(len(motions)), strict=True))))
    rank = [0] * len(order)
    drain(map(rank.__setitem__, order, range(len(order))))
    consumers = _listing(len(by_key), order, map(inputs.__getitem__, order))
    # a unit makes the outputs it does not also take as inputs
    makes = map(set.difference, map(set, map(outputs.__getitem__, order)), map(inputs.__getitem__, order))
    makers = _listing(len(by_key), order, makes)
    return inputs, outputs, consumers, makers, tuple(rank), order


def _array_fields(table: NodeTable, by_key: list[int], motions: tuple[str, ...]) -> tuple:
    """`_tuple_fields` on numpy arrays of (unit, node) pairs: each unit's distinct ids by one sort of pair keys,
    the content order by one lexicographic sort of (motion, inputs, outputs) rows padded with -1, consumers
    and makers by one sort of (node, rank) keys each; O(P log P) for P pairs, in contiguous arrays."""
    import numpy as np

    size, count = len(by_key), len(motions)
    renumber = np.empty(size, dtype=np.int64)
    renumber[np.array(by_key, dtype=np.int64)] = np.arange(size, dtype=np.int64)
    in_keys, out_keys = (_pairs(owner, renumber[member], size) for owner, member in map(_flat, (table.inputs,
                                                                                                   table.outputs)))
    labels = sorted(set(motions))
    motion_rank = np.fromiter(map(dict(zip(labels, range(len(labels)), strict=True)).__getitem__, motions),
                              np.int64, count)
    columns = np.hstack([motion_rank[:, None], _padded(in_keys, size, count), _padded(out_keys, size, count)])
    order = np.lexsort(columns.T[::-1])  # the first column is the first key; stable: unit index breaks ties
    del columns
    rank = np.empty(count, dtype=np.int64)
    rank[order] = np.arange(count, dtype=np.int64)
    # a unit makes the outputs it does not also take as inputs
    found = np.searchsorted(in_keys, out_keys)
    made = np.ones(len(out_keys), dtype=bool)
    inside = found < len(in_keys)
    made[inside] = in_keys[found[inside]] != out_keys[inside]
    consumers, makers = (_groups(_by_node(keys, size, order, rank), count, size, order)
                         for keys in (in_keys, out_keys[made]))
    return (_groups(in_keys, size, count), _groups(out_keys, size, count), consumers, makers,
            tuple(rank.tolist()), tuple(order.tolist()))


_MOTION_LABEL = attrgetter("motion.label")


@per_network
def index_of(foon: Foon) -> FoonIndex:
    """The cached index of `foon`; the entry is dropped when `foon` is garbage-collected."""
    return build_index(foon)
