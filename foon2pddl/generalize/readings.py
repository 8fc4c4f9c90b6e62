"""FOON-GEN's reading of a name a node uses for one of its unit's objects under another word.

FOON often names a holder or an ingredient by a shorter word than the object's label: the
apple turnover's pour (`0086-apple_turnover.txt:195`) takes `butter (melted, in [pan])`
beside the `cooking pan (contains {butter})`. The relational encoding reads such a name as
the object (rule 0, `model/aliases.py`). A name with no category of its own
(`pan`) would stay as it is under FOON-GEN, beside `cookware (contains {dairy})`: no object
of the GEN unit is a `pan`. So a name a node uses (a place, a list item) that has no category,
and that exactly one object label of its unit matches by the head-noun rule
(`model.places.head_of`; not a label whose own node lists the name: `fried rice (contains
{rice})`), takes that label's category in the node. A node is one thing wherever it appears:
the readings of all the units it is in are joined, and a name read as two categories is not
read (`pan` is a `cooking pan` in some units and a `skillet` in others, but never both for one
node). Each reading is reported at its unit's file:line.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from ..model.constraints import node_labels
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.places import head_of, listed
from ..model.where import unit_where

__all__ = ["node_readings", "unit_readings"]


def unit_readings(unit: FunctionalUnit, mapping: Mapping[str, str]) -> dict[str, str]:
    """Name -> the label it is read as, for the names the unit's nodes use that `mapping` (label -> category)
    has no category for, read as the one object label of the unit with one (head-noun rule)."""
    nodes = (*unit.inputs, *unit.outputs)
    labels = {n.label for n in nodes}
    out = {}
    for name in sorted(set().union(*(node_labels(n) for n in nodes)) - labels - mapping.keys()):
        listers = {n.label for n in nodes if name in listed(n)}
        match = [lab for lab in sorted(labels) if head_of(name, lab) and lab not in listers]
        if len(match) == 1 and match[0] in mapping:
            out[name] = match[0]
    return out


def node_readings(units: Iterable[FunctionalUnit], mapping: Mapping[str, str],
                  ) -> tuple[dict[ObjectNode, dict[str, str]], tuple[str, ...]]:
    """Node -> {name: category} for the names its units read (`unit_readings`) as one category, and the
    readings as notes (`FILE:LINE: pan read as cooking pan, so cookware`, sorted)."""
    seen: dict[ObjectNode, dict[str, set[str]]] = {}
    notes: dict[tuple[ObjectNode, str], set[str]] = {}
    for u in units:
        read = unit_readings(u, mapping)
        if not read:
            continue
        where = unit_where(u)
        for n in (*u.inputs, *u.outputs):
            for name in node_labels(n) & read.keys():
                seen.setdefault(n, {}).setdefault(name, set()).add(mapping[read[name]])
                notes.setdefault((n, name), set()).add(f"{where}: {name} read as {read[name]}, so "
                                                       f"{mapping[read[name]]}")
    names = {n: {x: next(iter(cats)) for x, cats in by.items() if len(cats) == 1} for n, by in seen.items()}
    said = {s for (n, name), ss in notes.items() if name in names[n] for s in ss}
    return {n: m for n, m in names.items() if m}, tuple(sorted(said))
