"""Kitchen containers the relational task reads as a unit's output: FOON gives their contents only as what units
make (module doc of `encode_relational`, "Init").

A kitchen container node K (a starting node: no unit makes it) whose list names contents that the units taking
K take in nodes only units make (`mixing bowl (contains {instant coffee, sugar, hot water})`, whose beat takes
`water (in [mixing bowl])`, which only the pour makes) would start holding objects in those nodes: the plan
then skips the units FOON makes them with, and its task tree does not validate from FOON's kitchen. When
exactly one unit output P of K's label is K by another wording, the relational task reads K as P: K is no
kitchen object, and the units taking K take P. "Another wording": K's states but lists and places among P's
(P may add one: the cook leaves the bacon macaroni's pot `hot`, which the scoop's kitchen pot does not say), K's
places among P's, K's list (read through the task's aliases, `holder_words.task_aliases`) within P's, and
whatever else P lists no object of P's unit is and its input nodes of that label do not list (the onigiri's
`bowl (contains {rice, water})` for the kitchen's `bowl (contains {rice})`: no water is poured). FOON's tree
keeps K, which FOON's kitchen has; each reading is reported with the unit's file:line.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.places import CONTENT_STATES, listed, place_of, place_state, places
from .encoding import LevelInputs
from .holder_words import task_aliases
from .relational_init import kitchen_placed

__all__ = ["kitchen_stitches", "stitch_notes", "stitched"]


def _rest(node: ObjectNode) -> frozenset:
    """The node's states but its lists and places."""
    return frozenset(s for s in node.states if place_state(s) is None and s.label not in CONTENT_STATES)


def kitchen_stitches(units: Sequence[FunctionalUnit], kitchen: Iterable[ObjectNode],
                     makers: Sequence[FunctionalUnit] | None = None) -> dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]:
    """K -> (P, the unit making P) for each kitchen container a task of `units` reads as an output of one of
    `makers` (the network's units; default `units`; module doc). Names are read as in that task: a universal
    FOON's `sugar` is a label of its own, a dish's task may read it as `refined sugar`. O(kitchen containers x
    units x outputs)."""
    kitchen, makers = frozenset(kitchen), units if makers is None else makers
    made = {o for u in makers for o in u.outputs}
    full = sorted(k for k in kitchen if listed(k) and k not in made)
    if not full:
        return {}
    labels = {n.label for u in units for n in (*u.inputs, *u.outputs)}
    alias = dict(task_aliases(units, labels, full))

    def read(names: Iterable[str]) -> frozenset[str]:
        return frozenset(alias.get(x, x) for x in names)

    out = {}
    for k in full:
        items = read(listed(k))
        taken = {x for u in units if k in u.inputs for x in u.inputs
                 if (p := place_of(x)) is not None and alias.get(p[1], p[1]) == k.label and x.label in items}
        if not {x for x in taken if x not in kitchen and x in made} - kitchen_placed(taken, kitchen):
            continue  # what K holds the kitchen has, or nothing of it is taken
        found = {}
        for u in makers:
            roles = {n.label for n in (*u.inputs, *u.outputs)}
            before = frozenset().union(*(read(listed(i)) for i in u.inputs if i.label == k.label))
            for p in u.outputs:
                if (p.label == k.label and _rest(k) <= _rest(p) and set(places(k)) <= set(places(p))
                        and items <= read(listed(p)) and not (read(listed(p)) - items) & (roles | before)):
                    found.setdefault(p, u)
        if len(found) == 1:
            out[k] = next(iter(found.items()))
    return out


def stitched(inp: LevelInputs, units: Iterable[int]) -> tuple[LevelInputs, dict[ObjectNode, tuple[ObjectNode,
                                                                                                FunctionalUnit]]]:
    """`inp` with each kitchen node K that a task of the `units` (indexes) reads as a unit output P
    (`kitchen_stitches`) read so: out of the kitchen, and P in every unit taking K; and the readings."""
    stitches = kitchen_stitches([inp.foon.units[u] for u in units], inp.kitchen, inp.foon.units)
    if not stitches:
        return inp, stitches

    def unit(u: FunctionalUnit) -> FunctionalUnit:
        if not any(n in stitches for n in u.inputs):
            return u
        ins = tuple(dict.fromkeys(stitches[n][0] if n in stitches else n for n in u.inputs))
        return FunctionalUnit(ins, u.motion, u.outputs, u.sources)

    foon = Foon(tuple(map(unit, inp.foon.units)), inp.foon.level)
    return replace(inp, foon=foon, kitchen=inp.kitchen - stitches.keys()), stitches


def stitch_notes(stitches: Mapping[ObjectNode, tuple[ObjectNode, FunctionalUnit]]) -> list[tuple[FunctionalUnit, str]]:
    """(the unit making P, what is read) per reading, for the task's notes with the unit's file:line."""
    return [(u, f"the kitchen's {k.describe()} is read as {p.describe()}, which this {u.motion.label} makes: FOON "
             "gives what it holds only as what units make") for k, (p, u) in sorted(stitches.items())]
