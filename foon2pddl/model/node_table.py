"""A network's nodes numbered (`NodeTable`): what network-sized passes (indexes, kitchens, duplicate units) work on
instead of hashing nodes, and a network's units by node (`unit_index`: `foon.Foon.producers` and `consumers`).

The numbering reads a unit only as the nodes it takes and makes (`Listing`: a `foon.FunctionalUnit`), so this
module sits below `foon`, which numbers its networks with it.
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Sequence
from dataclasses import dataclass
from itertools import chain
from operator import attrgetter
from typing import Generic, Protocol, TypeVar

from .bulk import drain

__all__ = ["Listing", "NodeTable", "first_objects", "node_table", "unit_index"]

N = TypeVar("N", bound=Hashable)
N_co = TypeVar("N_co", bound=Hashable, covariant=True)


class Listing(Protocol[N_co]):
    """What the numbering reads of a unit: the nodes it takes and those it makes, in its order."""

    @property
    def inputs(self) -> tuple[N_co, ...]: ...

    @property
    def outputs(self) -> tuple[N_co, ...]: ...


@dataclass(frozen=True, eq=False)
class NodeTable(Generic[N]):
    """A network's distinct nodes numbered 0.. in order of first appearance (inputs, then outputs, unit by
    unit), and each unit's inputs and outputs as those numbers, in the order the unit lists them.

    Network-sized passes (indexes, kitchens, duplicate units) look nodes up by number instead of
    hashing them: an `ObjectNode`'s hash is a Python-level call, a number's is not.
    """

    nodes: tuple[N, ...]
    inputs: tuple[tuple[int, ...], ...]
    outputs: tuple[tuple[int, ...], ...]


def node_table(units: Iterable[Listing[N]]) -> NodeTable[N]:
    """Number the nodes of `units` (`NodeTable`). Linear: node objects recur across units (a parser shares
    them), so each distinct object is hashed once and every occurrence is found by identity, in C loops."""
    units = tuple(units)
    objects: dict[int, N] = {}  # id(object) -> object, in order of first appearance
    for u in units:
        objects.update(zip(map(id, u.inputs), u.inputs, strict=True))
        objects.update(zip(map(id, u.outputs), u.outputs, strict=True))
    number: dict[N, int] = {}  # equal objects share a number: the first one seen stands for them
    setdefault = number.setdefault
    by_object = dict(zip(objects, [setdefault(n, len(number)) for n in objects.values()], strict=True))
    look = by_object.__getitem__
    return NodeTable(tuple(number),
                     tuple(tuple(map(look, map(id, u.inputs))) for u in units),
                     tuple(tuple(map(look, map(id, u.outputs))) for u in units))


def first_objects(units: Sequence[Listing[N]], ids: tuple[tuple[int, ...], ...], side: str) -> dict[int, N]:
    """Node number -> the first object listed for it on `side` (`inputs` or `outputs`, with `ids` the table's
    numbers of that side), in order of first appearance there. Equal nodes may differ in what is not their
    identity (motion flag, goal and dish marks); the first one listed stands for them, as in a set or dict of
    nodes built by going through the units. One C-level pass of `dict.setdefault` (the first write wins)."""
    first: dict[int, N] = {}
    drain(map(first.setdefault, chain.from_iterable(ids), chain.from_iterable(map(attrgetter(side), units))))
    return first


def unit_index(side: tuple[tuple[int, ...], ...], objects: dict[int, N]) -> dict[N, tuple[int, ...]]:
    """Node -> indexes of the units listing it on `side`, for the nodes some unit lists there (first appearance;
    `objects`: `first_objects` of that side)."""
    acc: dict[int, list[int]] = {}
    for i, ids in enumerate(side):
        for n in ids:
            got = acc.get(n)
            if got is None:
                acc[n] = [i]
            elif got[-1] != i:  # a node listed twice on one side counts once
                got.append(i)
    return {objects[n]: tuple(v) for n, v in acc.items()}
