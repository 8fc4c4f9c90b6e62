"""Which object holds which in one functional unit: the FOON evidence the `relational` encoding reads.

FOON writes relations into states: `onion (chopped, in [bowl])` names the onion's
place, `bowl (contains {onion, salt})` the bowl's contents. Per unit, for every
role (`pairing.unit_roles`) this module says what becomes of the object (its
`Fate`), where it is before the unit (`source`) and after it (`target`), as a
`Place`: the relation (`in`/`on`), the holder's label, and the unit's role that
is the holder, or None when the unit does not name it (the encoding binds it
late). FOON's explicit nodes are never rewritten: an object the unit gives an
output node ends in that node, and a container the unit leaves out of its
outputs keeps the node it has (FOON says nothing else of it).

Rules, in order (each reads only the unit itself):

0. **Names.** FOON's lists and places often name an object by another word than
   its label: `salad bowl (contains {salad})` beside `carrot salad (in [salad
   bowl])`, `oil (in [pan])` where the pan is a `cooking pan`. A name no role of
   the unit has is read as the one role whose label it is the head of, or whose
   head it is (last words; `unit_aliases`), and a place no label matches so, used
   by an output node and no ingredient list, as the one role whose node lists what
   is placed there (`lemonade (in [cup])` in the drinking glass that lists it);
   every such reading is reported
   (`holder_words.mismatches`), and the replay reads the task's lists through the same
   readings (`holder_words.task_aliases`).
1. **Places.** A node's place is its first `in [C]` / `on [C]` state (a bare `on`
   is an appliance switched on, not a place).
2. **Holder binding.** The holder of an object of label L at a place of label C (before the unit: read from the
   input nodes; after it: from the output nodes, or the input node of a role the unit leaves unchanged) is, among
   the unit's other roles of label C: the first whose node on that side lists L; else the only one; else none:
   bound late (the planner chooses which C). Before the unit, a C whose node lists its contents without L is no
   candidate: FOON's words disagree (`egg white and yolk (in [bowl])` beside the only `bowl (contains {egg white,
   egg yolk, flour})`), so it is bound late and reported (rule 6), unless that C's output node lists it and none of
   what it listed, which no role is (the cook's pan goes from `contains {egg mixture}` to `contains {omelette}`:
   the omelette made from it is in it). An object `in [C]` before and after a unit with
   one C that does not list it stays in that C (`white rice (in [pot])` beside `pot (contains {rice})`), unless
   that C's output node newly lists it (it came from another C). An object whose output node keeps its input
   node's place, in a holder whose output node no longer lists it, arrives in the one other container that newly
   lists it, if one: FOON left its place stale (the garlic butter scraped into the bowl that lists it, still `in
   [food processor bowl]`). An object placed at a C where the unit has no C is with the one other role whose output
   node lists both L and C: C is part of it (the club sandwich's bacon `on [bread]` beside the sandwich that lists
   bread and bacon; reported by rule 6). A second role of one label in the same holder is bound late too: a list names a label
   once (`plate (contains {bread})` under the sandwich's two breads, each brought on its own plate: the planner
   takes the second from where it is).
3. **Implied moves.** FOON often lists an ingredient only as an input: the pour of heavy cream gives `mixing bowl
   (contains {heavy cream})` as output but not the cream. A role of label L with no output node moves when another
   role's output node lists L and its input node does not: it arrives in that role, `on` it where the unit's nodes
   say `on` (an implied node: its input node with the place replaced, `heavy cream (in [mixing bowl])`), unless that role is a product the unit makes
   (`custard (contains {egg, milk})`): then it is an ingredient of it, `CONSUMED` (as in rule 5). Of two roles
   newly listing L, one in or on the other, it arrives in the inner one, which the outer holds (`takers`: the
   whipped cream the baking tray and the pudding in it list after the scoop, `0071-banana_pudding.txt:245`, is
   on the pudding; reported, `holder_words.mismatches`). An output node
   whose only place word is a bare `on`, beside the one role that newly lists it, is `on` that role (`avocado (on,
   sliced)` put on the bread that lists it).
4. **Fates.** An object whose holder changes `MOVES`, unless the holder it leaves still lists L afterwards (its
   output node does, or the unit gives it none and its node does) and no role is in or on the object (the blend's
   bowl, `0071-banana_pudding.txt:108`, leaves the mixer that stays `with [bowl]` whole, with the vanilla in it):
   FOON then says the holder keeps what it holds, so a portion `SPLITS` off: a new object of label L arrives where
   the role's output node says, and the object in the holder stays (the carton still holds cream after some is
   poured; the measuring cup FOON never empties keeps its cream too). A role with no output node whose holder's
   output node no longer lists L is `CONSUMED`: it became part of the mixture made there (the lettuce of a salad),
   and so is one sitting, with no output node, where the unit makes a new object (`garlic (in [bowl])` where `meat
   mix (in [bowl])` is made). A source the unit does not name is decided by the encoding, which knows the task's
   nodes (`Fate.MOVES` here).
5. **Contents that are not roles** (`holder_flows.unit_flows`). A container whose output node drops a label its
   input node lists, with no role of that label that may be in it (a role of the
   label taken from a holder of another label, or consumed from no place, is another
   object: the flour the cup lists beside the mix's `flour (in [bowl])`): what is of that label in it
   follows into the role whose output node newly lists it (`holder_flows.Flow`), or became
   part of the mixture (`into` None; also when that role is a product the unit makes).
   A container FOON leaves out of the outputs, or gives an output node silent about its
   contents (`bowl (dirty)`), whose contents another role's output node newly lists,
   was poured out whole (`bowl (contains {tuna})` into the bowl of mayonnaise): its
   contents follow, and the task empties it (`list_drops`: unless a later unit takes
   a label the list dropped from that container).
6. **Contradictions** (`holder_gaps.list_gaps`): an object in a C whose only C does not list it
   (rule 2), a product placed in a container whose output node describes its
   contents and does not list it, an object placed on a part of another role (rule 2),
   and a label an output node newly lists that no role of the unit is. No plan can satisfy both words, so the
   task reports them and its replay does not check that pair.

What stays ambiguous: several holders of one label that all list L (the first
is taken), a place FOON never names (the object stands free), and whether a
container FOON leaves out of the outputs was emptied (it is taken to keep what it
lists). O(r^2) for r roles; cached per unit.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from functools import lru_cache

from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode, make_node
from ..model.pairing import Role
from ..model.physical import Relation
from ..model.places import describes_contents, listed, moved_into, place_of, place_state, places
from .holder_words import UnitWords, newly_listed, part_of, renamed, takers, unit_words

__all__ = ["Fate", "Place", "RelRole", "held_elsewhere", "on_parts", "placed_products", "relational_roles", "still_holds",
           "unit_aliases"]


class Fate(StrEnum):
    """What a unit does to one of its objects (rule 4)."""

    STAYS = "stays"  # where it was (its state may change)
    MOVES = "moves"  # it leaves its holder, arrives at another, or both
    SPLITS = "splits"  # a portion of it goes to the target as a new object; it stays in its holder
    CONSUMED = "consumed"  # it became part of a mixture
    NEW = "new"  # the unit makes it


@dataclass(frozen=True)
class Place:
    """Where an object is: `relation` a `holder` label; `role`: the unit's role that is the holder (None: late)."""

    relation: Relation
    holder: str
    role: int | None = None


@dataclass(frozen=True)
class RelRole:
    """A role with what becomes of it: `after` is its node after the unit (None: unchanged; for `SPLITS` the
    new portion's node, the role's own object keeping its input node), `source`/`target` where it is before
    and after (the same Place, or both None, when it stays)."""

    role: Role
    after: ObjectNode | None
    fate: Fate
    source: Place | None = None
    target: Place | None = None

    @property
    def changes(self) -> bool:
        """The role's own object leaves its input node (a new object is made, or moved, or consumed)."""
        return self.fate in (Fate.NEW, Fate.CONSUMED) or (
            self.fate is not Fate.SPLITS and self.after is not None and self.after != self.role.before)


def _relation(nodes: tuple[ObjectNode | None, ...], holder: str) -> Relation:
    """How the unit's nodes place things at `holder`: `on` when they say `on [holder]` more often than `in
    [holder]` (the onion and pepper poured onto the plate of tomato, `on [plate]` in the unit), else `in`."""
    said = [rel for node in nodes for rel, c in places(node) if c == holder]
    return Relation.ON if said.count(Relation.ON) > said.count(Relation.IN) else Relation.IN


def _holder(labels: list[str], nodes: list[ObjectNode | None], me: int, label: str,
            place: tuple[Relation, str] | None, strict: bool = False) -> Place | None:
    """Rule 2: the role holding role `me` (of `label`) at `place`, read from `nodes` (one side of the unit)."""
    if place is None:
        return None
    rel, holder = place
    mine = [k for k, lab in enumerate(labels) if k != me and lab == holder and nodes[k] is not None]
    listing = [k for k in mine if label in listed(nodes[k])]
    if not listing and strict:  # the only holder of its label lists what it holds, and not this: FOON's words
        mine = [k for k in mine if not describes_contents(nodes[k])]  # disagree, so bind it late
    pick = listing[0] if listing else (mine[0] if len(mine) == 1 else None)
    return Place(rel, holder, pick)


@lru_cache(maxsize=1 << 14)
def on_parts(unit: FunctionalUnit) -> tuple[tuple[ObjectNode, str], ...]:
    """(output node, holder label) for each object the unit places at a part of another role (rule 2: the bacon
    `on [bread]` is on the sandwich)."""
    read, rels = unit_words(unit), relational_roles(unit)
    labels, given = [r.label for r in read.roles], _given(read)
    return tuple((r.after, labels[x.target.role]) for j, (r, x) in enumerate(zip(read.roles, rels, strict=True))
                 if r.after is not None and x.target is not None and x.target.role is not None and place_of(given[j])
                 and part_of(labels, read.before, given, j, place_of(given[j])[1]) == x.target.role)


def _given(read: UnitWords) -> list[ObjectNode | None]:
    """The output nodes of the unit's roles, read through its names (None: the unit gives the role none)."""
    return [read.after[k] if r.after is not None else None for k, r in enumerate(read.roles)]


def still_holds(node: ObjectNode | None, label: str) -> bool:
    """Whether a holder in `node` still holds something of `label` by FOON's words (rule 4)."""
    return node is not None and describes_contents(node) and label in listed(node)


@lru_cache(maxsize=1 << 14)
def relational_roles(unit: FunctionalUnit) -> tuple[RelRole, ...]:
    """The unit's roles with their fates, output nodes and holders (see the module doc)."""
    read = unit_words(unit)
    roles, before, after = read.roles, read.before, read.after
    labels = [r.label for r in roles]
    newly = newly_listed(unit)
    out_nodes: list[ObjectNode | None] = [r.after for r in roles]
    implied: dict[int, int] = {}
    mixed: set[int] = set()  # roles listed by a product the unit makes: ingredients of it
    for k, r in enumerate(roles):  # rule 3
        if r.after is None and r.before is not None:
            into = takers(unit, r.label, k)
            if into and roles[into[0]].before is None:
                mixed.add(k)
            elif into:
                implied[k] = into[0]
    how = {k: _relation((*before, *after), labels[j]) for k, j in implied.items()}
    for k, j in implied.items():
        out_nodes[k] = moved_into(roles[k].before, labels[j], how[k])
    read_after = [moved_into(before[k], labels[implied[k]], how[k]) if k in implied else after[k]
                  for k in range(len(roles))]
    for k, r in enumerate(roles):  # rule 3: a bare `on` beside the one role newly listing it is on that role
        bare = [st for st in (r.after.states if r.after is not None else ()) if st.label == "on" and not place_state(st)]
        into = [j for j in takers(unit, r.label, k) if roles[j].before is not None]
        if bare and r.before is not None and place_of(after[k]) is None and place_of(before[k]) and len(into) == 1:
            out_nodes[k], read_after[k] = (moved_into(make_node(r.label, [st for st in node.states if st not in bare]),
                                                      labels[into[0]], Relation.ON) for node in (r.after, after[k]))
    made_in = {place_of(after[k]) for k, r in enumerate(roles) if r.before is None and place_of(after[k])}
    result = []
    sources = [_holder(labels, list(before), k, r.label, place_of(before[k]), True) if r.before is not None else None
               for k, r in enumerate(roles)]
    held = {s.role for s in sources if s is not None}  # the roles others are in or on: they leave whole (rule 4)
    for k, r in enumerate(roles):
        src = sources[k]
        if src is not None and src.role is None and place_of(after[k]) == place_of(before[k]):
            mine = [j for j in range(len(roles)) if j != k and labels[j] == src.holder and before[j] is not None]
            if len(mine) == 1 and renamed(before[mine[0]], after[mine[0]], r.label, labels):
                src = Place(src.relation, src.holder, mine[0])  # its list had it by the name it was made from
        if src is not None and src.role is not None and any(
                labels[j] == r.label and sources[j] == src for j in range(k)):
            src = Place(src.relation, src.holder)  # a list names a label once: the second is bound late (rule 2)
        dst = (Place(how[k], labels[implied[k]], implied[k]) if k in implied  # the role it moves into
               else _holder(labels, read_after, k, r.label, place_of(read_after[k])))
        if (src is not None and src == dst and src.role is not None and r.after is not None
                and place_of(after[k]) == place_of(before[k]) and r.label not in listed(after[src.role])):
            taking = [j for j in takers(unit, r.label, k) if roles[j].before is not None]
            if len(taking) == 1:  # a stale place (the unit left it as it was): the one role taking it in holds it
                dst = Place(dst.relation, labels[taking[0]], taking[0])
        if r.after is not None and dst is not None and dst.role is None and (
                part := part_of(labels, before, _given(read), k, dst.holder)) is not None:
            dst = Place(dst.relation, labels[part], part)  # placed on a part of the one role taking it in
        if r.before is None:
            result.append(RelRole(r, r.after, Fate.NEW, None, dst))
            continue
        if r.after is None and k not in implied:
            holder_drops = (src is not None and src.role is not None and roles[src.role].after is not None
                            and describes_contents(after[src.role]) and r.label not in listed(after[src.role]))
            absorbed = k in mixed or (src is not None and (src.relation, src.holder) in made_in)
            if holder_drops or absorbed:
                result.append(RelRole(r, None, Fate.CONSUMED, src, None))
            else:
                result.append(RelRole(r, None, Fate.STAYS, src, src))
            continue
        if src is not None and dst is not None and src.role is None and (src.relation, src.holder) == (
                dst.relation, dst.holder) and dst.role is not None and labels.count(dst.holder) == 1 \
                and r.label not in newly[dst.role]:
            src = dst  # in [pot] before and after, the unit's one pot not taking it in: it stays there
        same = (src == dst) or (src is not None and dst is not None and src.holder == dst.holder
                                and src.role is not None and src.role == dst.role)
        if same:
            result.append(RelRole(r, out_nodes[k], Fate.STAYS, src, dst))
            continue
        keeps = src is not None and src.role is not None and still_holds(after[src.role], r.label) and k not in held
        result.append(RelRole(r, out_nodes[k], Fate.SPLITS if keeps else Fate.MOVES, src, dst))
    return tuple(result)


@lru_cache(maxsize=1 << 14)
def placed_products(unit: FunctionalUnit) -> tuple[tuple[ObjectNode, ObjectNode], ...]:
    """(output node, that node placed) per product whose output node names no place, beside the one role there
    before the unit whose output node newly lists it (rule 3; `list_placed`): in that role, `on` it where the unit's
    nodes say `on` (0086's `filling (contains {...})` beside `cooking pan (contains {filling})`). O(r^2)."""
    read, out = unit_words(unit), []
    for k, r in enumerate(read.roles):
        into = [j for j in takers(unit, r.label, k) if read.roles[j].before is not None]
        if r.before is None and r.after is not None and place_of(read.after[k]) is None and len(into) == 1:
            holder = read.roles[into[0]].label
            out.append((r.after, moved_into(r.after, holder, _relation((*read.before, *read.after), holder))))
    return tuple(out)


def held_elsewhere(rels: Sequence[RelRole], k: int, nodes: Iterable[ObjectNode]) -> bool:
    """Whether an object leaving role `k`'s container (`rels`: the unit's roles) may be in a holder of its label
    in another node of `nodes` (a task's) that lists it: a scrape made the plate of alliums the omelette pour
    takes `contains {alliums, peppers}` (`0042-perfect_omelette.txt:79`), and a pour emptying whichever plate held
    the alliums, in no node it names, took them off that plate and left it listing both. O(nodes x roles)."""
    before = rels[k].role.before
    leaving = {r.role.label for r in rels if r.source is not None and r.source.role == k}
    return any(n.label == before.label and n != before and leaving & listed(n) for n in nodes)
