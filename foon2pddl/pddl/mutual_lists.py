"""Two nodes of one unit that list each other, read as one placed on the other (a relational-task reading).

FOON's annotators sometimes write the relation between two objects both ways: garlic bread's pick-and-place gives
`baking tray (contains {bread})` beside `bread (sliced, contains {baking tray})`. A tray holds the bread; a bread
cannot also hold the tray that holds it. When a unit has a node of label C that lists L and a node of label L
that lists C, the relational task reads the L node without C in its list and, when it names no place, `on [C]`
(`bread (on [baking tray], sliced)`): C is the holder, as the relational encoding's contents are. Which of the two
is the holder: the one whose node on the unit's other side (or a later unit's) says so: a node of L placed at C
(`bread (on [baking tray])` elsewhere in the network); with no such evidence, nothing is read. The same reading
applies to every node of the network and the kitchen (the put-inside's `bread (on [baking tray], contains {baking
tray})`). FOON's tree keeps its own nodes; each reading is reported with the unit's file:line. O(u n^2).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode, make_node, make_state
from ..model.memo import per_network_reading
from ..model.places import listed, places
from .encoding import LevelInputs

__all__ = ["mutual_notes", "mutual_readings", "read_mutual"]


def _read(node: ObjectNode, holder: str) -> ObjectNode:
    """`node` without `holder` in its lists and, when it names no place, `on [holder]`."""
    states = []
    for s in node.states:
        if s.label == "contains" and holder in (*s.ingredients, s.related):
            rest = [i for i in s.ingredients if i != holder]
            if rest or (s.related and s.related != holder):
                states.append(make_state("contains", s.related if s.related != holder else "", rest))
            continue
        states.append(s)
    if not places(node):
        states.append(make_state("on", holder))
    return make_node(node.label, states, motion_flag=node.motion_flag, goal=node.goal, dish=node.dish)


def mutual_readings(foon: Foon) -> dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]:
    """Node -> (its reading, the first unit that shows the pair) for every node listing a label C that a node of
    label C in one unit lists back, where some node of the network places an object of the node's label at C."""
    placed = {(n.label, c) for u in foon.units for n in (*u.inputs, *u.outputs) for _, c in places(n)}
    pairs: dict[tuple[str, str], FunctionalUnit] = {}
    for u in foon.units:
        for side in (u.inputs, u.outputs):
            for x in side:
                for c in listed(x):
                    if (x.label, c) in placed and any(y.label == c and x.label in listed(y) for y in side):
                        pairs.setdefault((x.label, c), u)
    out = {}
    for u in foon.units:
        for n in (*u.inputs, *u.outputs):
            for (label, c), shown in sorted(pairs.items(), key=lambda kv: kv[0]):
                if n.label == label and c in listed(n) and n not in out:
                    out[n] = (_read(n, c), shown)
    return out


def _network(foon: Foon, reads: dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]) -> Foon:
    """The network with every node of `reads` read so (a unit given one node twice keeps it once)."""

    def unit(u: FunctionalUnit) -> FunctionalUnit:
        ins = tuple(dict.fromkeys(reads[n][0] if n in reads else n for n in u.inputs))
        outs = tuple(dict.fromkeys(reads[n][0] if n in reads else n for n in u.outputs))
        return FunctionalUnit(ins, u.motion, outs, u.sources)

    return Foon(tuple(map(unit, foon.units)), foon.level)


#: `_network` of `mutual_readings`, and the readings: once per network object (an experiment encodes a hundred
#: goals over one network).
_mutual_network = per_network_reading(mutual_readings, _network)


def read_mutual(inp: LevelInputs) -> tuple[LevelInputs, dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]]:
    """`inp` with every node of `mutual_readings` read so, in the units and the kitchen; and the readings."""
    foon, reads = _mutual_network(inp.foon)
    if foon is None:
        return inp, reads
    kitchen = frozenset(reads[n][0] if n in reads else n for n in inp.kitchen)
    return replace(inp, foon=foon, kitchen=kitchen), reads


def mutual_notes(reads: dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]],
                 task: Collection[ObjectNode]) -> list[tuple[FunctionalUnit, str]]:
    """(the unit showing the pair, what is read) per reading whose node the `task`'s units have, for the task's
    notes with the unit's file:line (a universal FOON's garlic bread reading is no note of the dalgona coffee)."""
    return [(u, f"{n.describe()} is read as {m.describe()}: this unit lists {n.label} and {places(m)[0][1]} each in "
             "the other") for n, (m, u) in sorted(reads.items()) if m in task]
