"""FOON's words about a unit's holders read by another name (rule 0 of `holders`), as the relational task reports
and reads them: per unit (`mismatches`, the `label mismatch:` notes) and across a task (`task_aliases`, which its
replay reads)."""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import FunctionalUnit, ObjectNode
from ..model.places import listed, places
from .holders import head_of, unit_aliases
from .pairing import unit_roles

__all__ = ["mismatches", "task_aliases"]


def mismatches(unit: FunctionalUnit) -> tuple[str, ...]:
    """Names an output node newly lists that no role has (`bowl lists olive oil, read as green olive oil` by
    rule 0, else `..., which no object of the unit is`), or places by another: `oil is in [pan], read as ...`."""
    roles = unit_roles(unit)
    labels = {r.label for r in roles}
    alias = dict(unit_aliases(unit))
    out = []
    for r in roles:
        if r.after is None:
            continue
        new = listed(r.after) - (listed(r.before) if r.before is not None else frozenset())
        out += [f"{r.label} lists {x}, " + (f"read as {alias[x]}" if x in alias else "which no object of the unit is")
                for x in sorted(new - labels)]
        out += [f"{r.label} is {rel} [{c}], read as {alias[c]}" for rel, c in places(r.after) if c in alias]
    return tuple(dict.fromkeys(out))


def task_aliases(units: Iterable[FunctionalUnit], labels: Iterable[str],
                 starts: Iterable[ObjectNode | None] = ()) -> tuple[tuple[str, str], ...]:
    """The units' aliases (rule 0) for a whole task, for its replay, plus those of the objects' start nodes
    (`starts`: `bowl (contains {rice})` in a kitchen whose only rice is `white rice`, read against all the
    task's `labels`). A name that is itself the label of an object of the task, or that is read as different
    labels, is no alias. Sorted pairs."""
    have = set(labels)
    seen: dict[str, set[str]] = {}
    for u in units:
        for name, label in unit_aliases(u):
            seen.setdefault(name, set()).add(label)
    for node in starts:
        for name in (*listed(node), *(c for _, c in places(node))):
            match = [lab for lab in sorted(have) if head_of(name, lab)]
            if name not in have and len(match) == 1:
                seen.setdefault(name, set()).add(match[0])
    return tuple((n, next(iter(ls))) for n, ls in sorted(seen.items()) if len(ls) == 1 and n not in have)
