"""What a coarser level takes from the encodings that read holders: units whose reading differs from level 3's.

Levels 1 and 2 leave out the ingredient lists (`bowl (contains {milk})` is `bowl (contains)` at level 2). The
`relational` encoding reads from those lists which container of a unit holds an object and whether a pour leaves a
portion behind (`holders.relational_roles`, rules 2 and 4): the measuring cup that still lists milk after the pour
at `0004-pancake_batter.txt:46` keeps some (a portion is poured); at level 2 nothing says so, and the milk leaves it
whole. `lost_readings` names, per unit, the objects read otherwise at `level` than at level 3: the cause `plan
--level 2` gives where FOON's semantics makes the goal and the planner finds no plan. O(sum of r^2) over the units
for r roles (`relational_roles` is cached per unit).
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import FunctionalUnit
from ..model.levels import project_unit
from ..model.where import unit_where
from .holders import Fate, Place, RelRole, relational_roles

__all__ = ["lost_readings"]

_FATE = {Fate.STAYS: "stays", Fate.MOVES: "moves whole", Fate.SPLITS: "leaves a portion", Fate.CONSUMED: "is consumed",
         Fate.NEW: "is made"}


def _place(word: str, place: Place | None) -> str:
    if place is None:
        return ""
    which = "the unit's" if place.role is not None else "whichever"
    return f" {word} {which} {place.holder}"


def _reading(rel: RelRole) -> str:
    """`leaves a portion out of the unit's measuring cup into the unit's bowl`; `stays in whichever bowl`."""
    if rel.fate is Fate.STAYS:
        return _FATE[rel.fate] + _place("in", rel.source)
    return _FATE[rel.fate] + _place("out of", rel.source) + _place("into", rel.target)


def lost_readings(units: Iterable[FunctionalUnit], level: int, shown: int = 3) -> tuple[str, ...]:
    """For the first `shown` of `units` (level 3, in order) whose objects `level` reads otherwise: `pour at
    FILE:LINE: milk leaves a portion out of the unit's measuring cup ... at level 3, moves whole ... at level 2`
    (the first such object of the unit); () at level 3. An object is compared with the role at its position in the
    projected unit (`levels.project_unit` keeps a node per node), and only when that role is of its label: a unit
    paired otherwise at the level (an output left unpaired) shifts the roles after it, and another object's reading
    is not its own."""
    if level >= 3:
        return ()
    out: list[str] = []
    for unit in units:
        for a, b in zip(relational_roles(unit), relational_roles(project_unit(unit, level)), strict=False):
            if a.role.label != b.role.label:  # not one object (roles paired otherwise at the level): not compared
                continue
            said = _reading(a), _reading(b)
            if said[0] != said[1]:
                out.append(f"{unit.motion.label} at {unit_where(unit)}: {a.role.label} {said[0]} at level 3, "
                           f"{said[1]} at level {level}")
                break
        if len(out) == shown:
            break
    return tuple(out)
