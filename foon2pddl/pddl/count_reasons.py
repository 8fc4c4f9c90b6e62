"""Why a task has the objects it has: per kitchen state given several objects, the units of FOON's plan unfolded that
take one out of it (`count_reasons`), from the counts `instance_counts.derive_counts` gives.

Kept apart from the counting: the counts never read these sentences, and the encodings that report them
(`encode_instances`, `encode_relational`) add them to their notes.
"""

from __future__ import annotations

from ..model.foon import Foon, ObjectNode
from ..model.pairing import unit_roles
from ..model.where import short_path, source_where
from ..model.words import first_of
from .instance_counts import InstanceCounts, RolesOf

__all__ = ["count_reasons"]


def count_reasons(foon: Foon, counts: InstanceCounts, kitchen: frozenset[ObjectNode],
                  roles_of: RolesOf = unit_roles, shown: int = 4, through: bool = False) -> tuple[str, ...]:
    """Why the task has several objects in one kitchen state: per kitchen node given k > 1 objects, the
    units of the unfolded plan that take one out of that state (file:line, x firings), and whether a
    unit that only reads the state keeps one there. FOON's units never return an object to a kitchen
    state unless the network has a unit that does (a wash, an emptying): each taking needs its own object.
    O(units x roles). Stated and overridden counts, and those restoring units set, are said to be given. `through`:
    the counts unfolded the plan through the stitched units (the relational encoding's, where FOON's own plan is
    none), which the sentences name."""
    plan = " through its stitched units" if through else ""
    given = dict(counts.at_node)
    takers: dict[ObjectNode, list[tuple[int, int]]] = {}
    readers: set[ObjectNode] = set()
    for u, times in counts.firings:
        for r in roles_of(foon.units[u]):
            if r.before is None or r.before not in kitchen:
                continue
            if r.changes:
                takers.setdefault(r.before, []).append((u, times))
            else:
                readers.add(r.before)

    def taking(ut: tuple[int, int]) -> str:  # a unit that takes one, where, how many times
        unit, t = foon.units[ut[0]], ut[1]
        src = f" at {source_where(unit.source, short_path)}" if unit.source else ""
        return f"{unit.motion.label}{src}" + (f" x{t}" if t > 1 else "")

    out = []
    for node, k in sorted(given.items(), key=lambda x: (x[0].label, x[0])):
        if k < 2:
            continue
        taken = sum(t for _, t in takers.get(node, ()))
        if taken + (node in readers) != k and not (counts.reused and k < taken + (node in readers)):
            out.append(f"{k} x {node.describe()}: {k} given, where FOON's unfolded plan{plan} takes {taken} (a stated count, "
                       "restoring units' peak, or the relational encoding's own counting)")
            continue
        again = taken + (node in readers) - k
        out.append(f"{k} x {node.describe()}: FOON's plan{plan}, unfolded, takes one out of that state each time it fires "
                   + first_of(takers.get(node, []), shown, taking, sep=", ")
                   + (f"; {again} of those takings use one a unit put back in it" if again > 0
                      else ", and no unit puts one back")
                   + ("; one more stays for a unit that only reads it" if node in readers else ""))
    return tuple(out)
