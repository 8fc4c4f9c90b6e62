"""Universal FOON: merge many files into one network with duplicate units removed.

Files are read in sorted path order so the result never depends on the file
system; duplicates are found with hashed keys in one pass (linear time).
"""

from __future__ import annotations

from collections.abc import Iterable

from .foon import Foon, dedupe_units
from .levels import project


def merge(foons: Iterable[Foon], level: int = 3) -> Foon:
    """Merge networks (projected to `level`) into one, removing duplicate units.

    A network already at a lower level (e.g. a level-1 JSON export) lowers the
    result's level, so that all nodes are compared at one level.
    """
    foons = list(foons)
    level = min([level, *(f.level for f in foons)])
    return Foon(dedupe_units(u for f in foons for u in project(f, level).units), level)
