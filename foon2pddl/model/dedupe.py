"""Networks without duplicate units: units equal by motion label and node sets are merged, provenance joined.

A parser's or a merge's units often repeat a unit of another recipe; `deduped` keeps the first of each group and
compares units by node numbers (`node_table.NodeTable`), so no node is hashed per occurrence.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable
from itertools import compress
from operator import attrgetter, ne

from .bulk import bulk
from .foon import Foon, FunctionalUnit
from .node_table import NodeTable, node_table

_MOTION_LABEL = attrgetter("motion.label")


def dedupe_units(units: Iterable[FunctionalUnit],
                 key: Callable[[FunctionalUnit], Hashable] | None = None) -> tuple[FunctionalUnit, ...]:
    """Keep the first of each group of units with the same key (default `FunctionalUnit.key`); join their sources."""
    if key is None:
        return deduped(units).units
    kept: dict[Hashable, FunctionalUnit] = {}
    for u in units:
        k = key(u)
        first = kept.get(k)
        if first is None:
            kept[k] = u
        else:
            kept[k] = FunctionalUnit(first.inputs, first.motion, first.outputs, first.sources + u.sources)
    return tuple(kept.values())


@bulk
def deduped(units: Iterable[FunctionalUnit], level: int = 3, table: NodeTable | None = None) -> Foon:
    """The network of `units` without duplicates (`dedupe_units` with `FunctionalUnit.key`), with its `table`
    (`table`: `node_table(units)` when already known): units are compared by motion label and node numbers,
    in C-level loops (no node is hashed per occurrence)."""
    units = tuple(units)
    table = table if table is not None else node_table(units)
    kept: dict[Hashable, int] = {}
    keys = zip(map(_MOTION_LABEL, units), map(frozenset, table.inputs), map(frozenset, table.outputs), strict=True)
    first = list(map(kept.setdefault, keys, range(len(units))))
    joined: dict[int, FunctionalUnit] = {}
    for i in compress(range(len(units)), map(ne, first, range(len(units)))):  # the duplicates
        base = joined.get(first[i], units[first[i]])
        joined[first[i]] = FunctionalUnit(base.inputs, base.motion, base.outputs, base.sources + units[i].sources)
    order = list(kept.values())
    if len(order) == len(units):
        return network_with_table(units, level, table)
    # a duplicate lists the same nodes as the unit kept before it, so the numbering does not change
    return network_with_table(tuple(joined.get(i) or units[i] for i in order), level,
                              NodeTable(table.nodes, tuple(map(table.inputs.__getitem__, order)),
                                        tuple(map(table.outputs.__getitem__, order))))


def network_with_table(units: tuple[FunctionalUnit, ...], level: int, table: NodeTable) -> Foon:
    """`Foon(units, level)` whose `table` is already known (it must be `node_table(units)`)."""
    foon = Foon(units, level)
    foon.__dict__["table"] = table  # what the cached property would store
    return foon
