"""The nodes beyond a unit's own roles that its plan in a task (`relational_plan.UnitPlan`) changes.

`relational_plan` decides what becomes of each object a unit names; the unit's action also reaches nodes of the
task it does not name, and the relational encoding needs them to move, empty or consume the objects there:

* **Flows** (`flow_ways`): the contents poured out with a container (`holder_flows.unit_flows`), every node of the
  flow's label placed in a container of the holder's label, moved into the flow's target or consumed.
* **Late empties** (`late_empties`, `every_late_empty`): a holder the unit does not name, which the task's units
  fill with the object leaving it (`Slot.late_empties`), no longer lists what leaves holders of its label.
* **Alike** (`alike_nodes`): consumed out of a holder whose node after no longer lists the label, any other
  object of that label in such a holder is consumed too.
* **Dropped** (`dropped_nodes`, `emptied_sources`): moved or consumed out of a holder the unit empties (a container
  an earlier unit filled, or one the unit does not name), whose new node drops labels with it (what the task's units
  put into the object that leaves, `Slot.along`), every object of a dropped label sitting in that holder itself
  becomes part of what leaves (consumed; not the object's own label, nor the nodes of the unit's roles): FOON-GEN's kofta stirs the bulgur out of `bowls (contains {grains, water
  and ice})`, which becomes `bowls (empty)` because units put water into grains, while the kitchen's water sits in
  the bowl beside the bulgur (`ACT-0053-lentil_kofta-1.txt:150`).
* **Restated** (`restated_nodes`): an object a unit makes in a holder whose node lists it before and after
  restates what is there, which becomes part of it (the corn on the board).
* **Dust** (`dustings`, `dusted_nodes`): what a unit puts on a holder it leaves silent about its contents (the
  flour on the floured board), or what a unit's node lists on a holder some unit leaves silent (the spray's olive
  oil on the bread the flip leaves `toasted`), goes into what a later unit puts there when its list leaves it out
  (the melted cheese scooped onto that bread).

`left_nodes` gathers the nodes some unit's action moves an object out of (all others are stable).

Pure. Per slot or flow of a unit, a function reads the task's nodes of the labels concerned (O(n) for n nodes);
`dustings` compares the nodes each unit makes with the nodes turned silent (O(m h)); `every_late_empty` repeats
`late_empties` until no new node appears. Nodes are visited sorted, so results do not depend on set order.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import ObjectNode
from ..model.physical import Relation
from ..model.places import describes_contents, listed, moved_into, places
from .holder_words import listed_as
from .holders import Fate
from .relational_plan import Slot, UnitPlan, late_emptied

__all__ = ["Way", "alike_nodes", "dropped_nodes", "dusted_nodes", "dustings", "emptied_sources", "every_late_empty",
           "flow_ways", "late_empties", "left_nodes", "restated_nodes"]


#: One way a flow (`holder_flows.Flow`) meets an object: its node, the relation to the container, its node after
#: (None: consumed).
Way = tuple[ObjectNode, Relation, "ObjectNode | None"]


def flow_ways(plan: UnitPlan, nodes: Iterable[ObjectNode], alias: dict[str, str],
              readings: frozenset[tuple[str, str]] = frozenset()) -> dict[int, list[Way]]:
    """Per flow of the unit (by position): every node of its label (read through the task's `alias`: the
    measuring cup's `pepper` is the black pepper ground into it) placed in a container of the holder's label,
    or of a name some unit of the task reads as that label (`readings`, its units' `unit_aliases`:
    `strawberry (in [cup])` poured into the blender cup, in a task that has a cup too), with the node it
    ends in (moved into the flow's target, or None: consumed)."""
    out: dict[int, list[Way]] = {}
    labels = [s.rel.role.label for s in plan.slots]
    for i, flow in enumerate(plan.flows):
        ways = []
        for n in sorted(x for x in nodes if x.label == alias.get(flow.label, flow.label)):
            for rel, c in places(n)[:1]:
                if alias.get(c, c) == labels[flow.holder] or (c, labels[flow.holder]) in readings:
                    ways.append((n, rel, moved_into(n, labels[flow.into]) if flow.into is not None else None))
        out[i] = ways
    return out


def late_empties(plan: UnitPlan, nodes: Iterable[ObjectNode],
                 alias: dict[str, str]) -> dict[int, list[tuple[ObjectNode, ObjectNode]]]:
    """Per slot that empties a holder the unit does not name (`Slot.late_empties`): every node of the holder's
    label that lists the object's label, with the node it becomes (`relational_plan.late_emptied`, which the count
    reads too: without all that leaves holders of that label in the unit, the beef and the onion leave the pan at
    once, and what was put into them, `Slot.along`)."""
    out = {}
    for k, s in enumerate(plan.slots):
        if s.late_empties:
            label, holder = s.rel.role.label, alias.get(s.rel.source.holder, s.rel.source.holder)
            out[k] = [(n, new) for n in sorted(x for x in nodes if x.label == holder and label in listed_as(x, alias))
                      if (new := late_emptied(plan, n, alias)) is not None]
    return out


def every_late_empty(plans: dict[int, UnitPlan], nodes: set[ObjectNode],
                     alias: dict[str, str]) -> dict[int, dict[int, list[tuple[ObjectNode, ObjectNode]]]]:
    """`late_empties` of every unit, to a fixpoint: a holder emptied of one thing (salt) may then be emptied
    of the next (pepper). Adds the nodes holders become to `nodes`."""
    while True:
        empties = {u: late_empties(p, nodes, alias) for u, p in plans.items()}
        grown = {n for e in empties.values() for lst in e.values() for _, n in lst} - nodes
        if not grown:
            return empties
        nodes.update(grown)


def alike_nodes(plan: UnitPlan, s: Slot,
                inside: dict[str, list[tuple[ObjectNode, Relation]]]) -> list[tuple[ObjectNode, Relation]]:
    """For a slot consumed out of a holder role whose node after the unit no longer lists its label: the nodes
    of that label placed in holders of that label (any other such object in that holder is consumed too)."""
    src = s.rel.source
    if s.fate is not Fate.CONSUMED or src is None or src.role is None:
        return []
    after = plan.after_of(src.role)
    label = s.rel.role.label
    if after is None or not describes_contents(after) or label in listed(after):
        return []
    return [(n, rel) for n, rel in inside.get(plan.slots[src.role].rel.role.label, ()) if n.label == label]


def dropped_nodes(plan: UnitPlan, k: int, old: ObjectNode, new: ObjectNode,
                  inside: dict[str, list[tuple[ObjectNode, Relation]]]) -> list[tuple[ObjectNode, Relation]]:
    """For slot `k` leaving a holder that goes from `old` to `new` (`emptied_sources`): the nodes placed in or on a
    holder of `old`'s label whose label `old` lists and `new` no longer does, but the slot's own label (another rice
    in the bowl is no part of the rice that leaves) and the nodes of the unit's roles (the unit says what becomes
    of them): an object in one, left there, would sit in a holder whose list drops it."""
    gone = listed(old) - listed(new) - {plan.slots[k].rel.role.label}
    roles = {s.rel.role.before for s in plan.slots}
    return [(n, rel) for n, rel in inside.get(old.label, ()) if n.label in gone and n not in roles]


def emptied_sources(plan: UnitPlan, k: int,
                    empties: list[tuple[ObjectNode, ObjectNode]]) -> list[tuple[ObjectNode, ObjectNode]]:
    """For a slot moved or consumed out of a holder the unit empties: (node before, node after) of each node that
    holder may be in, the late empties `empties` of a holder the unit does not name, or the emptied holder role's
    (none when the slot stays, splits or is made, or its holder stays as it is)."""
    s = plan.slots[k]
    if s.fate not in (Fate.MOVES, Fate.CONSUMED) or s.rel.source is None:
        return []
    src = s.rel.source.role
    if src is None:
        return list(empties)
    new = dict(plan.emptied).get(src)
    old = plan.slots[src].rel.role.before
    return [(old, new)] if new is not None and old is not None else []


def restated_nodes(plan: UnitPlan, s: Slot,
                   inside: dict[str, list[tuple[ObjectNode, Relation]]]) -> list[tuple[ObjectNode, Relation]]:
    """For a slot the unit makes (its only role of that label, or the others of the label move out of that holder)
    in a holder role whose node lists the label before and after the unit: the nodes of that label placed in
    holders of the holder's label, but those the others leave. FOON restates what is already there (the scoop's
    output-only `corn (shaved, on [cutting board])` beside the board's `contains {corn}`; the mix's new `potato
    mixture` in the bowl that lists one; FOON-GEN's scoop and pour takes the corn kernels off the board and
    restates the shaved corn, both `fruit vegetables`): the object there becomes part of the one made, so the
    holder never holds two."""
    dst, label = s.rel.target, s.rel.role.label
    if s.fate is not Fate.NEW or dst is None or dst.role is None:
        return []
    others = [x for x in plan.slots if x.rel.role.label == label]
    others.remove(s)
    if not all(x.fate is Fate.MOVES and x.rel.source is not None and x.rel.source.role == dst.role
               and (x.rel.target is None or x.rel.target.role != dst.role) for x in others):
        return []
    holder = plan.slots[dst.role].rel.role
    after = plan.after_of(dst.role) or holder.before
    if holder.before is None or label not in listed(holder.before) or label not in listed(after):
        return []
    leave = {x.rel.role.before for x in others}
    return [(n, rel) for n, rel in inside.get(holder.label, ()) if n.label == label and n not in leave]


def dustings(plans: Iterable[UnitPlan]) -> frozenset[ObjectNode]:
    """The nodes units put in or on a role they leave silent about its contents (the sprinkle's `flour (powder, on
    [cutting board])` beside its `cutting board (floured)`), and the nodes units make of a label L placed at a
    label C when some unit turns a node of C listing L into one silent about its contents (0012's spray makes
    `olive oil (on [bread])` and `bread (contains {olive oil})`, the flip leaves `bread (toasted)`), made by the
    unit that made the node of C turned silent (not every L at a C: other recipes of a universal FOON): what FOON
    stops counting as the holder's contents."""
    out, made, hushed = set(), [], {}
    for p in plans:
        made.append({n for s in p.slots for n in (s.after, s.portion) if n is not None})
        for k, s in enumerate(p.slots):
            into = s.rel.target.role if s.rel.target is not None else None
            after = p.after_of(into) if into is not None else None
            if after is not None and not describes_contents(after) and s.fate in (Fate.NEW, Fate.MOVES, Fate.SPLITS):
                out.add(s.portion if s.fate is Fate.SPLITS else s.after)
            new, old = p.after_of(k), s.rel.role.before
            if new is not None and old is not None and describes_contents(old) and not describes_contents(new):
                hushed[old] = s.rel.role.label
    # only what the unit that made the hushed node made beside it: the spray's oil, not every L at C
    out.update(n for nodes in made for old, c in hushed.items() if old in nodes
               for n in nodes for _, at in places(n)[:1] if at == c and n.label in listed(old))
    return frozenset(out - {None})


def dusted_nodes(plan: UnitPlan, k: int, inside: dict[str, list[tuple[ObjectNode, Relation]]],
                 dust: frozenset[ObjectNode]) -> list[tuple[ObjectNode, Relation]]:
    """For a container role whose input node is silent about what it holds and whose node after the unit lists
    it (`cutting board (floured)` -> `cutting board (contains {dough})`): the nodes among `dust` (`dustings`)
    placed in holders of its label, of a label that list leaves out and no role of the unit has. What was put
    there as FOON stopped listing it (the flour sprinkled onto the board) went into what the unit puts there (the
    dough laid on the flour)."""
    before, after = plan.slots[k].rel.role.before, plan.after_of(k)
    if before is None or after is None or describes_contents(before) or not describes_contents(after):
        return []
    labels = {s.rel.role.label for s in plan.slots} | listed(after)
    return [(n, rel) for n, rel in inside.get(plan.slots[k].rel.role.label, ()) if n in dust and n.label not in labels]


def left_nodes(units: Iterable[tuple[UnitPlan, dict[int, list[Way]], dict[int, list[tuple[ObjectNode, ObjectNode]]]]],
               inside: dict[str, list[tuple[ObjectNode, Relation]]], dust: frozenset[ObjectNode]) -> set[ObjectNode]:
    """The nodes some unit's action moves an object out of (all others are stable), from each unit's plan, flow
    ways (`flow_ways`) and late empties (`late_empties`); `inside`: per label, the nodes placed in one; `dust`:
    the task's `dustings`."""
    left: set[ObjectNode] = set()
    for p, ways, empties in units:
        for k, s in enumerate(p.slots):
            after = p.after_of(k) if s.fate is not Fate.CONSUMED else None
            if s.rel.role.before is not None and (s.fate is Fate.CONSUMED or (after is not None
                                                                              and after != s.rel.role.before)):
                left.add(s.rel.role.before)
        left.update(n for lst in ways.values() for n, _, _ in lst)
        left.update(n for lst in empties.values() for n, _ in lst)
        left.update(n for s in p.slots if s.fate is Fate.CONSUMED for n, _ in inside.get(s.rel.role.label, ()))
        left.update(n for s in p.slots for n, _ in (*alike_nodes(p, s, inside), *restated_nodes(p, s, inside)))
        left.update(n for k in range(len(p.slots)) for n, _ in dusted_nodes(p, k, inside, dust))
        left.update(n for k in range(len(p.slots)) for old, new in emptied_sources(p, k, empties.get(k, []))
                    for n, _ in dropped_nodes(p, k, old, new, inside))
    return left
