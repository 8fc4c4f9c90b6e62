"""Assumed transfer units (`plan`'s fallback, issue 21): a cook pours an ingredient into the holder a unit makes its
product in, where FOON's own words leave it in another.

FOON's unit U can consume an ingredient X `in [C]` while U's one role of label C that holds what U makes (B) does not
list X before U (the pancake batter's mix at `0004-pancake_batter.txt:58` takes `egg white and yolk (in [bowl])`, its
bowl `contains {flour, egg white, egg yolk, milk}`): the encoding binds X's holder late, and every plan consumes X in
the bowl the crack left it in while it makes the batter in another (`consumed-elsewhere`). `transfer_network` adds,
for each such (U, X) pair, one unit T beyond FOON: motion `pour`, source `assumed-transfer:K` (K numbers them) with
U's `file:line` as its url, taking B's node as U takes it and X's node, giving B's node listing X as well and X's node
(X moves from whichever C holds it into B); U then takes B's node listing X, so X is bound to B. The replay checks T
as any pour (X must be in the holder it leaves). O(units x roles).

>>> from foon2pddl.model.foon import make_node, make_state
>>> with_listed(make_node("bowl", [make_state("contains", "", ["flour"])]), "milk").describe()
'bowl (contains {flour, milk})'
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, Source, make_node, make_state
from ..model.places import describes_contents, listed
from ..model.where import TRANSFER_SOURCE, unit_where
from .holders import Fate, relational_roles

__all__ = ["transfer_network", "transfer_pairs", "with_listed"]


def with_listed(node: ObjectNode, label: str) -> ObjectNode | None:
    """`node` listing `label` in its `contains` (an `empty` node: containing only it); None when it says nothing
    of its contents (`bowl (clean)`)."""
    if not describes_contents(node):
        return None
    spot = next((j for j, s in enumerate(node.states) if s.label in ("contains", "empty")), None)
    if spot is None:
        return None
    s = node.states[spot]
    items = (*s.ingredients, label) if s.label == "contains" else (label,)
    added = make_state("contains", s.related if s.label == "contains" else "", items)
    return make_node(node.label, [*node.states[:spot], added, *node.states[spot + 1:]])


def transfer_pairs(unit: FunctionalUnit) -> tuple[tuple[int, int], ...]:
    """(role of X, role of B) for each ingredient the unit consumes in a holder bound late while it makes its
    product in its one role B of that holder's label, before the unit not listing X (module doc)."""
    rels = relational_roles(unit)
    made = {(r.target.relation, r.target.holder, r.target.role) for r in rels
            if r.fate is Fate.NEW and r.target is not None and r.target.role is not None}
    out = []
    for k, r in enumerate(rels):
        src = r.source
        if r.fate is not Fate.CONSUMED or src is None or src.role is not None:
            continue
        mine = [b for rel, holder, b in made if (rel, holder) == (src.relation, src.holder)]
        if len(set(mine)) == 1 and rels[mine[0]].role.before is not None \
                and r.role.label not in listed(rels[mine[0]].role.before):
            out.append((k, mine[0]))
    return tuple(out)


def transfer_network(foon: Foon, wheres: Iterable[str]) -> tuple[Foon, int]:
    """`foon` with, for each unit whose `unit_where` is one of `wheres` and each of its `transfer_pairs`, an assumed
    transfer unit appended and the unit taking its holder as the transfers leave it; and how many were added."""
    wheres = frozenset(wheres)
    units, added = list(foon.units), []
    for i, u in enumerate(foon.units):
        if unit_where(u) not in wheres:
            continue
        rels = relational_roles(u)
        holder: dict[ObjectNode, ObjectNode] = {}  # B's node as U takes it -> as the transfers leave it
        for k, b in transfer_pairs(u):
            x, before = rels[k].role.before, rels[b].role.before
            now = holder.get(before, before)
            after = with_listed(now, x.label)
            if after is None:
                continue
            added.append(FunctionalUnit((now, x), Motion("pour"), (after, x),
                                        (Source(TRANSFER_SOURCE, len(added) + 1, unit_where(u)),)))
            holder[before] = after
        if holder:
            units[i] = FunctionalUnit(tuple(holder.get(n, n) for n in u.inputs), u.motion, u.outputs, u.sources)
    return Foon(tuple(units) + tuple(added)), len(added)
