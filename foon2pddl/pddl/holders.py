"""Which object holds which in one functional unit: the FOON evidence the `relational` encoding reads.

FOON writes relations into states: `onion (chopped, in [bowl])`, `bowl (contains
{onion, salt})`. Per unit, for every role (`pairing.unit_roles`) this module says
where the object is before the unit (`source`) and after it (`target`), as a
`Place`: the relation (`in`/`on`), the holder's label, and the unit's role that is
the holder, or None when FOON does not say which object it is (the encoding then
binds it late: a parameter the planner chooses).

Rules, in order (each reads only the unit itself):

0. **Names.** FOON's lists and places often name an object by another word than
   its label: `salad bowl (contains {salad})` beside `carrot salad (in [salad
   bowl])`, `oil (in [pan])` where the pan is a `cooking pan`. A name no role of
   the unit has is read as the one role whose label it is the head of, or whose
   head it is (last words: `salad` / `carrot salad`, `black pepper` / `pepper`;
   `unit_aliases`); every such reading is reported (rule 5), and the replay reads
   the task's lists through the same readings (`task_aliases`).
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
   role of the unit has and that was not listed before is reported (`mismatches`):
   with its reading by rule 0 (`olive oil` listed, read as the object `green olive
   oil`), else as a name no object of the unit is (no object moves for it).

What stays ambiguous: several holders of one label that all list L (the first
is taken), and a place FOON never names (the object then stands free).
O(r^2) for r roles; cached per unit.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from functools import lru_cache

from ..model.foon import FunctionalUnit, ObjectNode, make_node, make_state
from ..model.physical import Relation
from ..model.places import describes_contents, listed, place_of, places
from .pairing import Role, unit_roles

__all__ = ["Place", "RelRole", "list_gaps", "mismatches", "relational_roles", "task_aliases", "unit_aliases", "without"]


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


def _head_of(name: str, label: str) -> bool:
    """`name` and `label` name one thing by the head-noun rule: one is the other's last words (`salad` /
    `carrot salad`, `pan` / `cooking pan`, `black pepper` / `pepper`)."""
    return label != name and (label.endswith(" " + name) or name.endswith(" " + label))


@lru_cache(maxsize=1 << 14)
def unit_aliases(unit: FunctionalUnit) -> tuple[tuple[str, str], ...]:
    """Rule 0: names the unit's lists and places use for one of its objects under another label.

    A name a `contains`/`with` list or an `in [C]`/`on [C]` place of the unit uses that is the label of no
    role of the unit, and that exactly one role's label matches by the head-noun rule (`_head_of`), means
    that role: `salad bowl (contains {salad})` beside `carrot salad (in [salad bowl])`, `oil (in [pan])` in a
    unit whose pan is `cooking pan`. Sorted (name, label) pairs; O(n r) for n names and r roles.
    """
    roles = unit_roles(unit)
    labels = {r.label for r in roles}
    names = {x for r in roles for n in (r.before, r.after) for x in (*listed(n), *(c for _, c in places(n)))}
    out = []
    for name in sorted(names - labels):
        match = [lab for lab in sorted(labels) if _head_of(name, lab)]
        if len(match) == 1:
            out.append((name, match[0]))
    return tuple(out)


def _aliased(node: ObjectNode | None, alias: dict[str, str]) -> ObjectNode | None:
    """`node` with the names of its lists and places read through `alias` (the node itself when none apply)."""
    if node is None or not alias:
        return node
    states = []
    for st in node.states:
        if st.label in ("in", "on", "with") and st.related in alias:
            st = make_state(st.label, alias[st.related], list(st.ingredients))
        elif st.label == "contains" and any(i in alias for i in (*st.ingredients, st.related)):
            st = make_state(st.label, alias.get(st.related, st.related),
                            sorted({alias.get(i, i) for i in st.ingredients}))
        states.append(st)
    return make_node(node.label, states)


@lru_cache(maxsize=1 << 14)
def relational_roles(unit: FunctionalUnit) -> tuple[RelRole, ...]:
    """The unit's roles with their completed output nodes and holders (see the module doc)."""
    roles = unit_roles(unit)
    alias = dict(unit_aliases(unit))
    read = [(_aliased(r.before, alias), _aliased(r.after, alias)) for r in roles]
    before = [b for b, _ in read]
    after = [a if a is not None else b for b, a in read]
    gained = {lab for k, r in enumerate(roles) for lab in listed(after[k]) - listed(before[k])}
    out_nodes = list(after)
    for k, r in enumerate(roles):
        if r.after is None and r.label in gained:
            into = [j for j, x in enumerate(roles) if j != k and r.label in listed(after[j]) - listed(before[j])]
            out_nodes[k] = _moved_into(r.before, roles[into[0]].label)
    places_ = [(_holder(roles, before, k, r.label, place_of(before[k])),
                _holder(roles, out_nodes, k, r.label, place_of(out_nodes[k]))) for k, r in enumerate(roles)]
    leaving: dict[int, set[str]] = {}
    for k, (src, dst) in enumerate(places_):
        if src is not None and src.role is not None and src != dst:
            leaving.setdefault(src.role, set()).add(roles[k].label)
    for j, labels in leaving.items():
        if roles[j].changes and listed(out_nodes[j]) & labels:
            out_nodes[j] = without(out_nodes[j], labels, alias)
    result = []
    for k, r in enumerate(roles):
        src, dst = places_[k]
        if out_nodes[k] == after[k]:  # nothing completed: FOON's own output node
            done = r.after
        else:
            done = out_nodes[k] if out_nodes[k] != before[k] else r.after
        result.append(RelRole(r, done, stays=src) if src == dst else RelRole(r, done, src, dst))
    return tuple(result)


def without(node: ObjectNode, labels: set[str], alias: dict[str, str] | None = None) -> ObjectNode:
    """Rule 2b: a source container after what left it (`contains` without `labels`, or `empty`); a name
    the list uses for one of `labels` (`alias`) leaves with it."""
    alias = alias or {}
    rest = sorted(x for x in listed(node) if x not in labels and alias.get(x) not in labels)
    kept = [s for s in node.states if s.label not in ("contains", "empty")]
    return make_node(node.label, [*kept, make_state("contains", "", rest) if rest else make_state("empty")])


def mismatches(unit: FunctionalUnit) -> tuple[str, ...]:
    """Rule 5: names an output node newly lists that no role of the unit has: `bowl lists olive oil, read as
    green olive oil` when rule 0 reads it as a role (`unit_aliases`), else `..., which no object of the unit is`."""
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
    return tuple(dict.fromkeys(out))


def list_gaps(unit: FunctionalUnit) -> tuple[tuple[str, str, str], ...]:
    """Rule 6: where the unit's own output nodes contradict each other about a container's contents.

    (container label, content label, message) for: an output node placed `in [C]`/`on [C]` while C's output
    node describes its contents and does not list it (`salad (in [salad bowl])` and `carrot salad (in [salad
    bowl])` made, the bowl `contains {salad}`); and a label C's output node newly lists that no role of the
    unit is, nor is read as (rule 0). No plan can satisfy both words, so the task reports them and its replay
    does not check that pair. Names read through the unit's aliases; O(r^2) for r roles.
    """
    roles = unit_roles(unit)
    alias = dict(unit_aliases(unit))
    labels = {r.label for r in roles}
    out = []
    outs = [(r.label, _aliased(r.after, alias)) for r in roles if r.after is not None]
    for label, node in outs:
        place = place_of(node)
        if place is None:
            continue
        holders = [n for lab, n in outs if lab == place[1] and describes_contents(n)]
        if holders and not any(label in listed(n) for n in holders):
            out.append((place[1], label, f"{label} is {place[0]} [{place[1]}], whose output node does not list it"))
    for r in roles:
        if r.after is None:
            continue
        new = listed(_aliased(r.after, alias)) - listed(_aliased(r.before, alias))
        out += [(r.label, x, f"{r.label} lists {x}, which no object of the unit is") for x in sorted(new - labels)]
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
            match = [lab for lab in sorted(have) if _head_of(name, lab)]
            if name not in have and len(match) == 1:
                seen.setdefault(name, set()).add(match[0])
    return tuple((n, next(iter(ls))) for n, ls in sorted(seen.items()) if len(ls) == 1 and n not in have)
