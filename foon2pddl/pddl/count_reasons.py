"""Why a task has the objects it has: per kitchen state given several objects, the units of FOON's plan unfolded that
take one out of it (`count_reasons`), from the counts `instance_counts.derive_counts` gives.

Kept apart from the counting: the counts never read these sentences, and the encodings that report them
(`encode_instances`, `encode_relational`) add them to their notes.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.foon import Foon, ObjectNode
from ..model.kitchen import Kitchen
from ..model.pairing import unit_roles
from ..model.where import short_path, source_where
from ..model.words import first_of
from .instance_counts import InstanceCounts, RolesOf

__all__ = ["count_reasons", "given_by"]


def given_by(node: ObjectNode, given: Kitchen | None, instances: Mapping[str, int]) -> str | None:
    """Who gave `node` its count, in words (None: nobody; the encoding counted it): the instances stated per label
    (`--instances`), which win over the kitchen's; the restoring units (`--restore`); the scene; the kitchen file's
    line. Checked in the order `derive_counts` reads them. No flag is named (flags are the CLI's words): the label's
    `label=N` and "the restoring units' peak" are."""
    if node.label in instances:
        return f"given by `{node.label}={instances[node.label]}` (the instances stated per label)"
    if given is None or node not in given.stated_counts():
        return None
    if node in given.restored:
        return "set by the restoring units' peak"
    if given.scene:
        return "given by the scene"
    line = given.line_numbers().get(node)
    where = f"{short_path(given.source)}:{line}" if given.source and line else short_path(given.source)
    return "given by the kitchen file" + (f" ({where})" if where else "")


def count_reasons(foon: Foon, counts: InstanceCounts, kitchen: frozenset[ObjectNode],
                  roles_of: RolesOf = unit_roles, shown: int = 4, through: bool = False, *,
                  given: Kitchen | None = None, instances: Mapping[str, int] | None = None,
                  encoding: str = "relational") -> tuple[str, ...]:
    """Why the task has several objects in one kitchen state: per kitchen node given k > 1 objects, the
    units of the unfolded plan that take one out of that state (file:line, x firings), and whether a
    unit that only reads the state keeps one there. FOON's units never return an object to a kitchen
    state unless the network has a unit that does (a wash, an emptying): each taking needs its own object.
    O(units x roles). A count the plan does not take is said with who gave it (`given_by`: `given`, the kitchen
    as the encoding read it, and `instances`, the `--instances` counts), else as the `encoding`'s own. `through`:
    the counts unfolded the plan through the stitched units (the relational encoding's, where FOON's own plan is
    none), which the sentences name."""
    plan = " through its stitched units" if through else ""
    at_node = dict(counts.at_node)
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
    for node, k in sorted(at_node.items(), key=lambda x: (x[0].label, x[0])):
        if k < 2:
            continue
        taken = sum(t for _, t in takers.get(node, ()))
        if taken + (node in readers) != k and not (counts.reused and k < taken + (node in readers)):
            who = (given_by(node, given, instances or {})
                   or f"counted by the {encoding} encoding itself (no count was given)")
            out.append(f"{k} x {node.describe()}: {k} {who}, where FOON's unfolded plan{plan} takes {taken}")
            continue
        again = taken + (node in readers) - k
        out.append(f"{k} x {node.describe()}: FOON's plan{plan}, unfolded, takes one out of that state each time it fires "
                   + first_of(takers.get(node, []), shown, taking, sep=", ")
                   + (f"; {again} of those takings use one a unit put back in it" if again > 0
                      else ", and no unit puts one back")
                   + ("; one more stays for a unit that only reads it" if node in readers else ""))
    return tuple(out)
