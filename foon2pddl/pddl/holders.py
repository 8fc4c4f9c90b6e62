"""Which object holds which in one functional unit: the FOON evidence the `relational` encoding reads.

FOON writes relations into states: `onion (chopped, in [bowl])`, `bowl (contains
{onion, salt})`. Per unit, for every role (`pairing.unit_roles`) this module says
where the object is before the unit (`source`) and after it (`target`), as a
`Place`: the relation (`in`/`on`), the holder's label, and the unit's role that is
the holder, or None when FOON does not say which object it is (the encoding then
binds it late: a parameter the planner chooses).

Rules, in order (each reads only the unit itself):

1. **Places.** A node's place is its first `in [C]` / `on [C]` state (a bare `on`
   is an appliance switched on, not a place); a read-only or kept role keeps its
   input node, so its place.
2. **Completion.** FOON often lists an ingredient only as an input: the pour of
   heavy cream into a bowl gives `bowl (contains {heavy cream})` as output but not
   the cream. A read-only role of label L moves when some other role's output
   node lists L and its input node does not: its output node is its input node
   with the place replaced by `in [that role's label]` (a node FOON implies,
   marked in the trace by the state `in [C]`). Likewise a source container that
   the unit changes and that the moving object leaves, but whose output node
   still lists it: its output node lists the rest, or is `empty` (2b). A read-only
   source keeps its node here; the plan's replay empties it (`relational_replay`).
3. **Holder binding.** The holder of an object of label L at a place of label C
   (before: from the input nodes, after: from the output nodes) is, among the
   unit's other roles of label C: the one whose node on that side lists L; else
   the only one; else (none, or several and none lists L) the first one that lists
   it, else none: bound late. Ambiguous cases are rare (under 0.2 % of arriving
   objects in the shared data).
4. **Moves.** An object moves when its place changes (another label or relation,
   or another role of the same label), or it leaves a place, or arrives at one.
5. **Label mismatches.** A label listed by an output node's `contains` that no
   role of the unit has and that was not listed before (`olive oil` listed, the
   object is `green olive oil`) is reported (`mismatches`): no object moves for it.

What stays ambiguous: several holders of one label that all list L (the first
is taken), and a place FOON never names (the object then stands free).
O(r^2) for r roles; cached per unit.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from ..model.foon import FunctionalUnit, ObjectNode, make_node, make_state
from ..model.physical import Relation
from .pairing import Role, unit_roles

__all__ = ["Place", "RelRole", "listed", "mismatches", "place_of", "relational_roles", "without"]


@dataclass(frozen=True)
class Place:
    """Where an object is: `relation` a `holder` label; `role`: the unit's role that is the holder (None: late)."""

    relation: Relation
    holder: str
    role: int | None = None


@dataclass(frozen=True)
class RelRole:
    """A role with its holders: `after` is the completed output node (None: unchanged), `source`/`target` the
    place it leaves / arrives at (None: it does not move; `stays` is where an unmoved object must be)."""

    role: Role
    after: ObjectNode | None
    source: Place | None = None
    target: Place | None = None
    stays: Place | None = None

    @property
    def changes(self) -> bool:
        return self.after is not None and self.after != self.role.before

    @property
    def moves(self) -> bool:
        return self.source != self.target


def place_of(node: ObjectNode | None) -> tuple[Relation, str] | None:
    """The node's first place: `(in, bowl)` for `in [bowl]`; None when it names none."""
    if node is None:
        return None
    return next(((Relation(s.label), s.related) for s in node.states if s.label in ("in", "on") and s.related), None)


def listed(node: ObjectNode | None) -> frozenset[str]:
    """The labels a container node lists (its `contains` states' ingredients and related objects)."""
    if node is None:
        return frozenset()
    items = {i for s in node.states if s.label == "contains" for i in (*s.ingredients, s.related) if i}
    return frozenset(items - {node.label})


def _moved_into(node: ObjectNode, holder: str) -> ObjectNode:
    """`node` with its place replaced by `in [holder]` (rule 2)."""
    kept = [s for s in node.states if not (s.label in ("in", "on") and s.related)]
    return make_node(node.label, [*kept, make_state("in", holder)])


def _holder(roles: tuple[Role, ...], nodes: list[ObjectNode | None], me: int, label: str,
            place: tuple[Relation, str] | None) -> Place | None:
    """Rule 3: the role holding role `me` (of `label`) at `place`, read from `nodes` (one side of the unit)."""
    if place is None:
        return None
    rel, holder = place
    mine = [k for k, r in enumerate(roles) if k != me and r.label == holder and nodes[k] is not None]
    listing = [k for k in mine if label in listed(nodes[k])]
    pick = listing[0] if listing else (mine[0] if len(mine) == 1 else None)
    return Place(rel, holder, pick)


@lru_cache(maxsize=1 << 14)
def relational_roles(unit: FunctionalUnit) -> tuple[RelRole, ...]:
    """The unit's roles with their completed output nodes and holders (see the module doc)."""
    roles = unit_roles(unit)
    before = [r.before for r in roles]
    after = [r.after if r.after is not None else r.before for r in roles]
    gained = {lab for k, r in enumerate(roles) for lab in listed(after[k]) - listed(before[k])}
    out_nodes = list(after)
    for k, r in enumerate(roles):
        if r.after is None and r.label in gained:
            into = [j for j, x in enumerate(roles) if j != k and r.label in listed(after[j]) - listed(before[j])]
            out_nodes[k] = _moved_into(r.before, roles[into[0]].label)
    places = [(_holder(roles, before, k, r.label, place_of(r.before)),
               _holder(roles, out_nodes, k, r.label, place_of(out_nodes[k]))) for k, r in enumerate(roles)]
    leaving: dict[int, set[str]] = {}
    for k, (src, dst) in enumerate(places):
        if src is not None and src.role is not None and src != dst:
            leaving.setdefault(src.role, set()).add(roles[k].label)
    for j, labels in leaving.items():
        if roles[j].changes and listed(out_nodes[j]) & labels:
            out_nodes[j] = without(out_nodes[j], labels)
    result = []
    for k, r in enumerate(roles):
        src, dst = places[k]
        done = r.after if r.after is not None and out_nodes[k] == r.after else (
            out_nodes[k] if out_nodes[k] != r.before else r.after)
        result.append(RelRole(r, done, stays=src) if src == dst else RelRole(r, done, src, dst))
    return tuple(result)


def without(node: ObjectNode, labels: set[str]) -> ObjectNode:
    """Rule 2b: a source container after what left it (`contains` without `labels`, or `empty`)."""
    rest = sorted(listed(node) - labels)
    kept = [s for s in node.states if s.label not in ("contains", "empty")]
    return make_node(node.label, [*kept, make_state("contains", "", rest) if rest else make_state("empty")])


def mismatches(unit: FunctionalUnit) -> tuple[str, ...]:
    """Rule 5: labels an output node newly lists that no role of the unit has, as `bowl lists olive oil`."""
    roles = unit_roles(unit)
    labels = {r.label for r in roles}
    out = []
    for r in roles:
        if r.after is None:
            continue
        new = listed(r.after) - (listed(r.before) if r.before is not None else frozenset())
        out += [f"{r.label} lists {x}, which no object of the unit is" for x in sorted(new - labels)]
    return tuple(dict.fromkeys(out))
