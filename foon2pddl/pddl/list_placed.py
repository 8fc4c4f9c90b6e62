"""A product whose node names no place, read in the one container the unit leaves listing it (a relational reading).

The apple turnover's pour and stir (`0086-apple_turnover.txt:291`) makes `filling (contains {butter, apple, ...})`
and `cooking pan (contains {filling})`; the pour at `:307` takes `filling (contains {...}, in [cooking pan])`, a
node no unit makes. Over objects the filling made was in nothing while the pan listed it, and the pour took a
filling out of a pan by a stitch (`input_stitch`) that read the placeless node as in the pan: on FOON-GEN (trial 7
goal 14) the task admitted a plan pouring the filling the kitchen's pan holds out of the pan that made another,
which the replay rejects (`claimed-twice`).

Rule (`holders.placed_products`): a unit's output node M of label L that names no place, where exactly one role of
the unit that exists before it has an output node newly listing L, is read as M placed in (or on) that role, M'. The
unit's own words tie them, nothing else. When every unit making M reads it as the same M', the network is read with
M' for M wherever a unit makes or takes M, and in the goal's candidates (the kitchen keeps its own M): the pour
takes the filling the pour and stir made, from the pan it is in. FOON's tree keeps FOON's units and is checked with
the M' nodes as given (`Compiled.placed`); the reading is reported with the maker's file:line. O(units x roles^2).
"""

from __future__ import annotations

from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.memo import per_network_reading
from .encoding import LevelInputs
from .holders import placed_products

__all__ = ["placed_nodes", "read_placed"]


def placed_nodes(foon: Foon) -> dict[ObjectNode, ObjectNode]:
    """M -> M' for every node of `foon` that every unit making it reads as placed alike (module doc)."""
    readings: dict[ObjectNode, set[ObjectNode | None]] = {}
    for unit in foon.units:
        placed = dict(placed_products(unit))
        for o in unit.outputs:
            readings.setdefault(o, set()).add(placed.get(o))
    return {m: next(iter(r)) for m, r in readings.items() if len(r) == 1 and None not in r}


def _network(foon: Foon, placed: dict[ObjectNode, ObjectNode]) -> Foon:
    """The network with every node of `placed` read as placed, in inputs and outputs."""
    return Foon(tuple(replace(x, inputs=tuple(placed.get(i, i) for i in x.inputs),
                              outputs=tuple(placed.get(o, o) for o in x.outputs)) for x in foon.units), foon.level)


_placed_network = per_network_reading(placed_nodes, _network)


def read_placed(inp: LevelInputs) -> tuple[LevelInputs, dict[int, tuple[FunctionalUnit, str]],
                                           frozenset[ObjectNode]]:
    """`inp` read with `placed_nodes`; unit index -> (unit, note) per maker of one, for the notes of a task with
    that unit; and the placed nodes (the tree's check takes them as given)."""
    foon, placed = _placed_network(inp.foon)
    if foon is None:
        return inp, {}, frozenset()
    notes = {u: (x, f"{x.motion.label} makes {m.describe()}, which names no place, beside the one container it "
                    f"leaves listing it: read as {placed[m].describe()}")
             for u, x in enumerate(inp.foon.units) for m in x.outputs if m in placed}
    return (replace(inp, foon=foon, candidates=tuple(placed.get(c, c) for c in inp.candidates)), notes,
            frozenset(placed.values()))
