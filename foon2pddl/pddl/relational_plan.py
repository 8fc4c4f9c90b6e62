"""What a unit does to each object in a given task: `holders.relational_roles` plus the task-level decisions.

`holders` reads one unit; two questions need the task too:

* **A portion or the whole?** An object leaving a container that keeps what it lists `SPLITS` (a new object of its
  label arrives at the target; the one in the container stays). The task says which containers keep: a container
  FOON changes keeps what its output node lists. One FOON leaves out of the outputs is emptied of what leaves it,
  moved or consumed (GEN's garlic, consumed into the rice dish off the plate; not into what the unit makes in it:
  the omelette cooked from the egg mixture in the pan), and what the units put into that label (its node drops the labels,
  `without`: the syrup soaked into the cranberries) when the task's units fill
  containers of its label with that label (`holder_flows.gained`: the measuring cup the cream was poured into) and its node
  is no kitchen node, or one a unit of the task fills with that object's node (`filled_by_task`), a unit FOON's plan as
  counted fires, in a node it starts no kitchen object in (`relational_reading._moved_whole`: the eggs and bacon
  pizza's cup the faucet fills at `0085-mini_bacon_egg_breakfast_pizza.txt:231`, in the node another recipe's kitchen
  cup of water is in), unless it goes onto an object in that container (the lemon juice the carrot in the salad bowl is
  seasoned with: it is still in the bowl, and the bowl still lists it); else it keeps its contents (a carton, a bag, a
  packet: the kitchen stocks them), but one no other unit takes or takes from, fired once (`sole`:
  `relational_reading`), of what goes into a node like its own is emptied: the hamburger's salt `in [bowl]`
  (`0027-best_hamburger_ever.txt:167`). A holder the unit does not name is emptied likewise when the units fill its
  label with the object's (whichever holds it: `Slot.late_empties`), keeps its contents when they do not (it may be a
  carton; the kitchen adds one listing what it holds when the task has none), and the object simply moves when no node
  of the task says what a holder of its label holds (a stove, a table), or when its node names no place after the unit
  (the squeezer that ends `dirty`: it leaves the surface whole), or when a unit of the task made it and no node of
  the task lists its label in a holder of that label (`listings`: the loaf the attach made on a board, moved onto the
  foil, `0016-easy_garlic_bread-one-pot-chef.txt:157`; the garlic bread baked in an oven whose nodes list the loaf,
  taken out at `:221`): nothing says that holder keeps some (`lists`; a unit FOON's plan as counted fires again is
  read with none, `relational_reading._fired_again`). An object consumed out of a holder the unit does not
  name empties it likewise; all that leaves holders of one label in a unit leaves at once (the beef and the onion leave
  the pan together).
  A container poured out whole (`holder_flows.unit_flows`) is emptied of what it held.
  An ingredient consumed into a product made elsewhere,
  out of a kitchen container FOON leaves listing it, was only partly used: it stays
  (the bowl of sesame seeds sprinkled over the salad).
* **Counts.** `count_roles` turns the decisions into the object roles that
  `instance_counts.derive_counts` unfolds: a portion is a new object, a consumed
  object leaves its node, an emptied container changes node; so does a read-only role FOON leaves out of the
  outputs whose node a late emptying changes, read as the action reads it (`late_emptied`); and, counted in a
  kitchen that starts an object leaving a holder the unit does not name in such a holder alone, that holder, which
  is no role of the unit (`_late_holders`).

What the decisions do to the task's nodes beyond the unit's own roles (the contents poured out with a container,
the holder emptied late, the corn restated on the board, the flour on the floured board) is `relational_touched`.

Pure; O(r^2) per unit for r roles.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode, make_node, make_state
from ..model.pairing import Role
from ..model.places import describes_contents, head_of, listed, places
from .holder_flows import Flow, gained, unit_flows
from .holder_words import listed_as
from .holders import Fate, RelRole, relational_roles

__all__ = ["CONSUMED_STATE", "Slot", "UnitPlan", "called_fills", "consumed_node", "count_roles", "filled_by_task",
           "holding_labels", "late_emptied", "listings", "plan_unit", "quiet_places", "silent_labels", "taken_with",
           "without"]

#: The state label of the node a consumed object is counted as leaving to (never a FOON node of the task).
CONSUMED_STATE = "consumed into a mixture"


def consumed_node(label: str) -> ObjectNode:
    """The node `instance_counts` sees a consumed object of `label` go to (nothing demands it)."""
    return make_node(label, [make_state(CONSUMED_STATE)])


def without(node: ObjectNode, labels: Iterable[str], alias: dict[str, str] | None = None) -> ObjectNode:
    """A container after what left it: its `contains` list without `labels` (`empty` when nothing is left) and
    no `with [x]` of them (a name the node uses for one of `labels` through `alias` leaves with it)."""
    alias, labels = alias or {}, set(labels)

    def gone(x: str) -> bool:
        return x in labels or alias.get(x) in labels

    listing = any(s.label in ("contains", "empty") for s in node.states)
    rest = sorted(x for x in listed(node) if not gone(x) and any(
        s.label == "contains" and x in (*s.ingredients, s.related) for s in node.states))
    kept = [s for s in node.states if s.label not in ("contains", "empty") and not (s.label == "with" and gone(s.related))]
    if listing:
        kept.append(make_state("contains", "", rest) if rest else make_state("empty"))
    return make_node(node.label, kept)


@dataclass(frozen=True)
class Slot:
    """One role in a task: its reading (`rel`), its fate, the node its own object ends in (None: unchanged),
    and for `SPLITS` the new portion's node."""

    rel: RelRole
    fate: Fate
    after: ObjectNode | None
    portion: ObjectNode | None = None
    #: `MOVES` out of a holder the unit does not name, which the task's units fill with it: whichever holds
    #: it no longer lists it
    late_empties: bool = False
    #: with `late_empties`: what the task's units put into the object, which leaves that holder's list with it
    #: (the paprika kneaded into the kofta mix on the tray)
    along: frozenset[str] = frozenset()


@dataclass(frozen=True)
class UnitPlan:
    """A unit in a task: its slots (one per role), the read-only holders it empties (role index -> their new
    node), and the contents that are no role (`holder_flows.Flow`)."""

    unit: FunctionalUnit
    slots: tuple[Slot, ...]
    emptied: tuple[tuple[int, ObjectNode], ...] = ()
    flows: tuple[Flow, ...] = field(default=())

    def after_of(self, k: int) -> ObjectNode | None:
        """The node role `k`'s object ends in (None: unchanged)."""
        return dict(self.emptied).get(k, self.slots[k].after)


def silent_labels(nodes: Iterable[ObjectNode]) -> frozenset[str]:
    """Labels whose nodes (among `nodes`) never say what they hold: a stove, a table, `oven (on)`."""
    nodes = list(nodes)
    describing = {n.label for n in nodes if describes_contents(n)}
    return frozenset(n.label for n in nodes) - describing


def holding_labels(units: Iterable[FunctionalUnit]) -> frozenset[str]:
    """Labels of the objects the `units` place something in or on, as their roles read (`holders.relational_roles`:
    `butter (in [bread])`, the spread's butter the bread lists)."""
    return frozenset(c for u in units for r in relational_roles(u) for n in (r.role.before, r.after)
                     for _, c in places(n))


def quiet_places(nodes: Iterable[ObjectNode], units: Iterable[FunctionalUnit],
                 speakers: Iterable[FunctionalUnit]) -> frozenset[str]:
    """The holders that say nothing of what they hold: the labels no node of `nodes` (the task's) says the contents
    of (`silent_labels`), and the places the output nodes of `units` name that are no label of `nodes` nor the head
    of one, nor a name one of `speakers` (the units the task has objects for) reads as one of its objects
    (`unit_aliases`): the bread toast's plate; the onigiri's `surface`, which the grilled cheese's place reads as its
    table in a universal FOON, where the onigiri's task has no table to fire that unit with."""
    nodes = list(nodes)
    names = {n.label for n in nodes} | {c for u in speakers for c, _ in unit_aliases(u)}
    return silent_labels(nodes) | {c for u in units for n in u.outputs for _, c in places(n)
                                   if c not in names and not any(head_of(c, x) for x in names)}


def listings(nodes: Iterable[ObjectNode], alias: Mapping[str, str] | None = None) -> frozenset[tuple[str, str]]:
    """(holder label, content label) for every label one of `nodes` lists (`places.listed`), a listed name read
    through the task's `alias` (`holder_words.task_aliases`, `listed_as`): the holders a task says hold that label."""
    return frozenset((x.label, c) for x in nodes for c in listed_as(x, alias or {}))


def _fills(holder: str, label: str, filled: frozenset[tuple[str, str]], labels: frozenset[str],
           called: frozenset[tuple[str, str]]) -> bool:
    """Whether the task's units fill holders named `holder` (or, when no object of the task has that label, a
    label it is the head of: `pan`, `cooking pan`; or holders they call `holder`, `called`: FOON-GEN's enchiladas
    fill the cookware with the ground meats they place `in [pan]`) with `label`. A `cup` in a task with cups is
    a cup, not the blender cup another recipe of a universal FOON fills."""
    return (holder, label) in called or any(
        x == label and (h == holder or (holder not in labels and h.endswith(" " + holder))) for h, x in filled)


def called_fills(units: Iterable[FunctionalUnit]) -> frozenset[tuple[str, str]]:
    """(name, content label) for every label a unit puts into a holder it calls by that name (`unit_aliases`: the
    pick-and-place that fills FOON-GEN's cookware with ground meats and leaves them `in [pan]`)."""
    return frozenset((name, x) for u in units for name, lab in unit_aliases(u) for h, x in gained(u) if h == lab)


def filled_by_task(units: Iterable[FunctionalUnit], kitchen: frozenset[ObjectNode]
                   ) -> frozenset[tuple[ObjectNode, ObjectNode]]:
    """(an object's node, a container's node listing its label) for every two output nodes one of `units` makes
    together, the object's no kitchen node: a container a unit of the task fills with that object (the faucet's turn
    on at `0085-mini_bacon_egg_breakfast_pizza.txt:231` makes `water (from [faucet], in [measuring cup])` with
    `measuring cup (contains {water})`, though a universal FOON's kitchen has that cup too, for the ramen's pour at
    `0054-quick_ramen_noodles.txt:180`). O(sum of outputs^2)."""
    return frozenset((a, h) for u in units for a in u.outputs for h in u.outputs
                     if h != a and a not in kitchen and a.label in listed(h))


def plan_unit(unit: FunctionalUnit, kitchen: frozenset[ObjectNode], silent: frozenset[str],
              filled: frozenset[tuple[str, str]], labels: frozenset[str] = frozenset(),
              holding: frozenset[str] = frozenset(), called: frozenset[tuple[str, str]] = frozenset(),
              sole: frozenset[ObjectNode] = frozenset(),
              lists: frozenset[tuple[str, str]] | None = None, names: Mapping[str, str] | None = None,
              task_filled: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset()) -> UnitPlan:
    """The unit's slots in a task whose kitchen nodes are `kitchen`, in which the labels `silent` are holders
    no node says the contents of (`silent_labels`), whose units put contents into holders as `filled`
    says ((holder label, content label), `holder_flows.gained`; module doc), whose nodes have `labels` and place
    objects in or on objects of the labels `holding`, fill holders by the names `called` (`called_fills`); `sole`;
    `lists`: (holder label, content label) for every label a node of the task lists (`listings`; None: not known,
    every holder the unit does not name may keep a portion); `names`: the task's aliases
    (`holder_words.task_aliases`), through which a place's holder is read against `lists` (`pan`, the cooking pan),
    as the count reads a late emptying (`late_emptied`); `task_filled`: the (object node, container node)
    pairs a unit of the task fills (`filled_by_task`), a unit the plan as counted fires, in a node it starts no
    kitchen object in (`relational_reading._moved_whole`): the whole of the object leaves the container, though the
    kitchen has that container's node too."""
    names = names or {}
    rels = relational_roles(unit)
    alias = dict(unit_aliases(unit))
    slots: list[Slot] = []
    drops: dict[int, set[str]] = {}
    made_at = {(x.target.relation, x.target.holder) for x in rels
               if x.fate is Fate.NEW and x.target is not None and x.target.role is None}
    for r in rels:
        fate, after, portion, late_empties = r.fate, r.after, None, False
        src = r.source
        if fate in (Fate.SPLITS, Fate.CONSUMED) and src is not None and src.role is not None:
            holder = rels[src.role].role
            made_in = any(x.fate is Fate.NEW and x.target is not None and x.target.role == src.role for x in rels)
            whole = (holder.before not in kitchen or (r.role.before, holder.before) in task_filled  # (a unit filled it)
                     or (holder.before in sole and r.after == r.role.before))  # (a split)
            if holder.after is None and whole and (holder.label, r.role.label) in filled and not (
                    fate is Fate.CONSUMED and made_in):  # (consumed into what the unit makes there: still in it)
                fate = Fate.MOVES if fate is Fate.SPLITS else fate  # a container an earlier unit filled, which FOON
                # never empties: the whole leaves it (or is consumed out of it: GEN's garlic rice)
                into = rels[r.target.role].target if r.target is not None and r.target.role is not None else None
                restated = any(x.fate is Fate.NEW and x.role.label == r.role.label and x.target is not None
                               and x.target.role == src.role for x in rels)  # the unit's own output leaves one there
                if (into is None or into.role != src.role) and not restated:  # onto the carrot in that bowl: still in it
                    # with what the task's units put into it (the syrup soaked into the cranberries)
                    drops.setdefault(src.role, set()).update({r.role.label} | {x for h, x in filled if h == r.role.label})
            elif (fate is Fate.CONSUMED and holder.after is None and holder.before in kitchen
                  and r.role.label in listed(holder.before)
                  and not made_in):
                fate, after = Fate.STAYS, None  # some of what a kitchen bowl holds went into a product made elsewhere
        elif (fate is Fate.CONSUMED and src is not None and src.role is None and _fills(src.holder, r.role.label, filled, labels, called)
              and (src.relation, src.holder) not in made_at):
            late_empties = True  # consumed out of a container the unit does not name (and makes nothing in)
        elif fate is Fate.MOVES and src is not None and src.role is None and src.holder not in silent:
            if (_fills(src.holder, r.role.label, filled, labels, called) or r.target is None
                    or (r.role.label in holding and listed(r.role.before))):
                # whichever container holds it is emptied of it (it ends in no place; it holds objects a portion
                # would leave behind: the buttered bread leaves the plate whole, the butter in it with it)
                late_empties = True
            elif lists is None or r.role.before in kitchen or (names.get(src.holder, src.holder), r.role.label) in lists:
                fate = Fate.SPLITS  # a holder the unit does not name may be a carton: it keeps what it lists
            else:  # made by a unit of the task, in a holder no node of the task lists it in: nothing says that
                # holder keeps some, so the whole leaves whichever holds it (the loaf off the board,
                # `0016-easy_garlic_bread-one-pot-chef.txt:157`)
                late_empties = True
        if fate is Fate.SPLITS and _into_one_staying(rels, r):
            fate = Fate.MOVES  # into a mixture that stays in the holder: still in it, so the holder's list holds
        if fate is Fate.SPLITS:
            after, portion = None, r.after
        elif fate is Fate.CONSUMED:
            after = None
        along = frozenset(x for h, x in filled if h == r.role.label) if late_empties else frozenset()
        slots.append(Slot(r, fate, after, portion, late_empties, along))
    flows = unit_flows(unit)
    for f in flows:  # a container FOON leaves out of the outputs, poured out whole, is emptied of what left it
        if rels[f.holder].role.after is None and not _stays_in(rels, f):
            drops.setdefault(f.holder, set()).add(f.label)
    emptied = tuple((k, without(rels[k].role.before, labels, alias)) for k, labels in sorted(drops.items()))
    return UnitPlan(unit, tuple(slots), emptied, flows)


def count_roles(plan: UnitPlan, alias: Mapping[str, str] | None = None, kitchen: frozenset[ObjectNode] = frozenset(),
                started: frozenset[ObjectNode] = frozenset(),
                taken: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset()) -> tuple[Role, ...]:
    """The object roles `instance_counts.derive_counts` unfolds for this unit (module doc), names read through the
    task's `alias` (`holder_words.task_aliases` of its units: the pour's plate it calls `sheet`), counted in
    `kitchen`, whose objects are where it started them in the nodes `started` (`relational_init.placed_since_start`),
    in a task whose units take the pairs `taken` (an object's node, a node listing it: `taken_with`): the holders it
    starts them in that the unit empties without naming (`_late_holders`)."""
    out: list[Role] = []
    alias = alias or {}
    emptied = dict(plan.emptied)
    for k, s in enumerate(plan.slots):
        if k not in emptied and s.after is None and s.fate is Fate.STAYS and s.rel.role.before is not None:
            if (late := late_emptied(plan, s.rel.role.before, alias)) is not None:
                emptied[k] = late  # whichever holder of its node the objects leave: the action empties it so
        label, before = s.rel.role.label, s.rel.role.before
        if s.fate is Fate.NEW:
            out.append(Role(label, None, s.rel.after))
        elif s.fate is Fate.CONSUMED:
            out.append(Role(label, before, consumed_node(label)))
        elif s.fate is Fate.SPLITS:
            out += [Role(label, before, None), Role(label, None, s.portion)]
        elif k in emptied:
            out.append(Role(label, before, emptied[k]))
        else:
            out.append(Role(label, before, s.after))
    return tuple(out) + _late_holders(plan, alias, kitchen, started, taken)


def _late_holders(plan: UnitPlan, alias: Mapping[str, str], kitchen: frozenset[ObjectNode],
                  started: frozenset[ObjectNode], taken: frozenset[tuple[ObjectNode, ObjectNode]]) -> tuple[Role, ...]:
    """A role per holder the unit empties without naming it (`Slot.late_empties`, out of the holder it is in), of
    an object whose node is where the kitchen started it (`started`: no unit put it there): the one node of
    `kitchen` of that holder's label that names no place and lists that object alone, where the completion starts it
    (`relational_init.holder_init`), goes to the node the action empties it to (`late_emptied`: names read through the
    task's `alias`, as the action reads them), when that is a kitchen node too (a later taker of it takes that
    holder again, `count_reuse`; a node no kitchen has would credit the unit with making it). Uncounted, that holder
    is added after the count, and a later taker of it empty gets a holder of its own: the eggs and bacon pizza's
    onion leaves `bowl (contains {onion})` at `0085-mini_bacon_egg_breakfast_pizza.txt:12`, and the pick-and-place
    at `:104` takes `bowl (empty)`. A kitchen with no such node (the wide count's, before the completion adds it),
    or two, counts none; nor does a unit that names an object of the holder's label, nor one whose object's node a
    unit of the task takes with that holder node (`taken`): its takers count it, and the completion starts the
    object in theirs (`holder_init`'s `paired`: the chocolate cake's flour, sprinkled at `0058-chocolate_cake.txt:17`
    out of a bowl the unit does not name, is in the bowl the pour at `:49` takes with it: one bowl of flour, two
    counted so). O(slots x kitchen)."""
    out: list[Role] = []
    for s in plan.slots:
        src, label = s.rel.source, s.rel.role.label
        if not s.late_empties or src is None or src.role is not None or s.rel.role.before not in started:
            continue
        holder = alias.get(src.holder, src.holder)
        if any(t.rel.role.label == holder for t in plan.slots):
            continue  # the unit names one of that label: which holds the object is the unit's reading (two breads
            # on [cutting board] and one board listing bread, `0061-club_sandwich.txt:180`), no holder to add
        homes = [x for x in kitchen if x.label == holder and listed_as(x, alias) == {label}
                 and not places(x) and (s.rel.role.before, x) not in taken]
        if len(homes) == 1 and (emptied := late_emptied(plan, homes[0], alias)) in kitchen:
            out.append(Role(holder, homes[0], emptied))
    return tuple(out)


def taken_with(units: Iterable[FunctionalUnit],
               alias: Mapping[str, str] | None = None) -> frozenset[tuple[ObjectNode, ObjectNode]]:
    """(an object's node, a node listing its label, names read through the task's `alias` as `_late_holders` reads
    them) for every two inputs one of `units` takes together: the holder that unit reads the object in. O(sum of
    inputs^2)."""
    alias = alias or {}
    return frozenset((a, h) for u in units for a in u.inputs for h in u.inputs
                     if h != a and a.label in listed_as(h, alias))


def _late_leaving(plan: UnitPlan, alias: Mapping[str, str]) -> dict[str, frozenset[str]]:
    """Holder label (a name read through `alias`) -> all that leaves holders of it late in the unit, at once
    (`Slot.late_empties`): the objects' labels and what the task's units put into them (`Slot.along`: the paprika
    kneaded into the kofta mix; the beef and the onion leave the pan together). O(r)."""
    out: dict[str, set[str]] = {}
    for s in plan.slots:
        if s.late_empties:
            out.setdefault(alias.get(s.rel.source.holder, s.rel.source.holder), set()).update({s.rel.role.label,
                                                                                               *s.along})
    return {h: frozenset(x) for h, x in out.items()}


def late_emptied(plan: UnitPlan, node: ObjectNode, alias: Mapping[str, str]) -> ObjectNode | None:
    """The node a holder in `node` ends in when the unit's objects leave holders the unit does not name
    (`Slot.late_empties`): `without` all that leaves holders of its label (`_late_leaving`), when `node` says what it
    holds and lists one of those objects (names read through `alias`); else None. The one reading of a late emptying,
    for the action (`relational_touched.late_empties`: whichever holder of that node holds the object is emptied) and
    for the count (`count_roles`: a role FOON leaves out of the outputs ends so). O(r + l) for l listed names."""
    left = [s.rel.role.label for s in plan.slots
            if s.late_empties and alias.get(s.rel.source.holder, s.rel.source.holder) == node.label]
    if not left or not describes_contents(node) or listed_as(node, alias).isdisjoint(left):
        return None
    return without(node, _late_leaving(plan, alias)[node.label], dict(alias))


def _stays_in(rels: Sequence[RelRole], f: Flow) -> bool:
    """Whether flow `f` goes into a role that stays in the flow's holder (the flip's bacon onto the omelette in
    the pan, `0050-scrambled_eggs_with_bacon-cheese.txt:255`): it is still in the holder, on the other, so the
    holder's list keeps it (the cook at `:269` takes the pan listing both)."""
    if f.into is None:
        return False
    into = rels[f.into]
    return (into.fate is Fate.STAYS and into.source is not None and into.source.role == f.holder
            and into.target is not None and into.target.role == f.holder)


def _into_one_staying(rels: Sequence[RelRole], r: RelRole) -> bool:
    """Whether `r` leaves its holder role for a role that stays in that holder (the fold's chips into the batter
    in the bowl, which lists both after the unit): it is still in the holder, inside the other, so all of it goes
    and none is left beside the mixture."""
    src, dst = r.source, r.target
    if src is None or src.role is None or dst is None or dst.role is None:
        return False
    into = rels[dst.role]
    return (into.fate is Fate.STAYS and into.source is not None and into.source.role == src.role
            and into.target is not None and into.target.role == src.role)
