"""Universal FOON: merge many files into one network with duplicate units removed.

Files are read in sorted path order so the result never depends on the file
system; duplicates are found with hashed keys in one pass (linear time).
"""

from __future__ import annotations

from collections.abc import Iterable

from .dedupe import deduped
from .foon import Foon
from .levels import project


def merge(foons: Iterable[Foon], level: int = 3) -> Foon:
    """Merge networks (projected to `level`) into one, removing duplicate units.

    A network already at a lower level (e.g. a level-1 JSON export) lowers the
    result's level, so that all nodes are compared at one level.
    """
    foons = list(foons)
    level = min([level, *(f.level for f in foons)])
    if len(foons) == 1:  # its node numbering carries over (a parser's, or built once here)
        one = project(foons[0], level)
        return deduped(one.units, level, one.table)
    return deduped((u for f in foons for u in project(f, level).units), level)
