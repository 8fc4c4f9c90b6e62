"""What moves with a unit's containers' contents, beside its roles: holders' rule 5 (`unit_flows`), and the
(holder, content) pairs the unit fills (`gained`).

Rule 5 of `holders` (its module doc): a container whose output node drops a label its input node lists, with no
role of that label that may be in it, lets what is of that label in it follow into the role whose output node newly
lists it, or become part of the mixture; a container poured out whole lets its contents follow. Read from the unit
alone, names through its aliases (`holder_words`); cached per unit.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from ..model.foon import FunctionalUnit
from ..model.pairing import unit_roles
from ..model.places import describes_contents, listed
from .holder_words import newly_listed, takers, unit_words
from .holders import Fate, relational_roles

__all__ = ["Flow", "gained", "unit_flows"]


@dataclass(frozen=True)
class Flow:
    """Rule 5: what is of `label` in the container role `holder` (and is no role of the unit) goes into role
    `into`, or is consumed (`into` None)."""

    label: str
    holder: int
    into: int | None


@lru_cache(maxsize=1 << 14)
def gained(unit: FunctionalUnit) -> frozenset[tuple[str, str]]:
    """(holder label, content label) for every label a role's output node lists and its input node does not:
    what the unit puts into something (names read through the unit's aliases)."""
    return frozenset((r.label, x) for r, new in zip(unit_roles(unit), newly_listed(unit), strict=True) for x in new)


@lru_cache(maxsize=1 << 14)
def unit_flows(unit: FunctionalUnit) -> tuple[Flow, ...]:
    """Rule 5: for every container role whose output node drops a label no role of the unit has, where what is
    of that label in it goes. O(r^2)."""
    read = unit_words(unit)
    roles, before, after = read.roles, read.before, read.after
    labels = {r.label for r in roles}
    rels = relational_roles(unit)
    out = []
    for h, r in enumerate(roles):
        if r.before is None or not (describes_contents(after[h]) or describes_contents(before[h])):
            continue
        if r.after is None or not describes_contents(after[h]):  # poured out whole (no output node, or one silent
            # about its contents: `bowl (dirty)`): what another role's output node newly lists follows
            for lab in sorted(listed(before[h]) - labels):
                into = [j for j in takers(unit, lab, h) if roles[j].before is not None]
                if into:
                    out.append(Flow(lab, h, into[0]))
            continue
        # a role of the label taken from a holder of another label, or consumed from no place, is another
        # object: what is of that label in this one goes too (the flour the cup lists, beside the mix's `flour
        # (in [bowl])`; the lemon in the glass, beside the lemon squeezed into it)
        elsewhere = {x.role.label for x in rels if (x.source.holder != r.label if x.source is not None
                                                     else x.fate is Fate.CONSUMED)}
        for lab in sorted(listed(before[h]) - listed(after[h]) - (labels - elsewhere)):
            into = takers(unit, lab, h)
            out.append(Flow(lab, h, into[0] if into and roles[into[0]].before is not None else None))
    return tuple(out)
