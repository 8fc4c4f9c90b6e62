"""One unit's action schema in the `relational` task (`encode_relational`): per role its state change and
its holder facts, from the unit's reading in the task (`relational_plan.UnitPlan`). Per role:

- an object that stays where it is while it or its holder changes must be there: `(in ?bowl ?onion)`;
- an object that moves must be in its source holder (deleted) and goes into its
  target (added); a source the unit does not name is left by a quantified delete
  `(forall (?h - physical-object) (when (in ?h ?x) (not (in ?h ?x))))`, never by one
  parameter per possible source (seven read-only bowls poured from are not 9^7 groundings); a target the unit
  does not name is one parameter of its label per unit (the planner picks the oven);
- a portion (`SPLITS`) is a not-yet-made object that arrives at the target in
  the role's output node, while the object it was taken from stays;
- a container FOON filled earlier and leaves out of the outputs is emptied of
  what leaves it (`relational_plan.without`), and says so as a role; so is a holder
  the unit does not name (`relational_touched.late_empties`); an object sitting in
  such a holder in a node of a label its new node drops becomes part of what
  leaves, consumed (`_with_it`: the water beside FOON-GEN's bulgur, stirred out of
  a bowl that becomes `bowls (empty)`);
- a consumed object goes to `consumed` and leaves its holder, with all of its
  label there when the holder's node no longer lists it, and with what is in
  or on it, two levels deep (`relational_sweep`); contents that are
  no role of the unit follow their container's list (`holder_flows.Flow`), by one
  quantified conditional effect per node they can be in.

Which roles are parameters: a role whose object changes or moves, the holders a bound object's facts name, what
sits in a changing holder, and an object in a holder role whose node does not say what it holds, with that holder
(`places.holds_unsaid`: level 2's `container (contains)`; no list ties the parmesan to the container the unit reads,
`0019-garlic-parmesan_chicken.txt:64`, so `(in ?container ?parmesan)` does) (to a fixpoint, O(r^2) for r roles); holders the unit does not name are one
parameter per label and unit, or a quantified conditional effect for a source, never a parameter per source.
"""

from __future__ import annotations

from ..model.foon import ObjectNode
from ..model.pairing import Role
from ..model.physical import Relation
from ..model.places import holds_unsaid
from . import relational_touched
from .costs import unit_cost
from .encode_instances import IS, NOT_MADE, OCCUPIED, PRECEDES, ROOT_TYPE
from .encoding import EncodeOptions, unit_comment
from .holders import Fate, held_elsewhere
from .live_holders import LIVE
from .names import NameTable
from .relational_plan import UnitPlan
from .relational_sweep import CONSUMED, sweep_effects
from .restore import discards
from .task import Action, Atom, Conditional

__all__ = ["IN", "ON", "unit_action"]

IN, ON = "in", "on"


def unit_action(u: int, plan: UnitPlan, table: NameTable, const: dict[ObjectNode, str], stable: set[ObjectNode],
                type_of: dict[str, str], options: EncodeOptions, precede: set[str], ways: dict[int, list[relational_touched.Way]],
                gaps: list, containers: set[str], inside: dict[str, list[tuple[ObjectNode, Relation]]],
                empties: dict[int, list[tuple[ObjectNode, ObjectNode]]], loose: frozenset[str],
                dust: frozenset[ObjectNode], entered: set[ObjectNode]) -> Action:
    """One unit's schema (see the module doc): per role its state change and its holder facts. Adds the labels
    whose objects it orders to `precede`, and to `gaps` a (container, content, message, unit) note for each object
    it puts in a holder the unit does not name, which nothing says lists it."""
    slots, unit = plan.slots, plan.unit
    # Containers FOON filled earlier and leaves out of the outputs are emptied of what leaves them. One of a
    # label is a parameter (it must be in its node); several of one label (seven bowls poured into the salad
    # bowl) are emptied by a conditional effect on whichever holds the object, else 9^7 groundings, unless what
    # leaves one may be in another node of its label (`holders.held_elsewhere`): then each is a parameter.
    emptied = dict(plan.emptied)
    per_label = [slots[k].rel.role.label for k in emptied]
    emptied = {k: n for k, n in emptied.items() if per_label.count(slots[k].rel.role.label) > 1
               and not held_elsewhere([s.rel for s in slots], k, const)}
    bound = [s.fate in (Fate.NEW, Fate.MOVES, Fate.CONSUMED)
             or s.after not in (None, s.rel.role.before) or (s.rel.role.before not in stable and k not in emptied)
             for k, s in enumerate(slots)]
    for f in plan.flows:
        bound[f.holder] = True
        if f.into is not None:
            bound[f.into] = True
    changes = [plan.after_of(k) not in (None, s.rel.role.before) or s.fate is not Fate.STAYS
               for k, s in enumerate(slots)]
    grew = True
    while grew:  # the holders a bound object's facts name are parameters; so is what sits in a changing holder
        grew = False
        for k, s in enumerate(slots):
            src, dst = s.rel.source, s.rel.target
            need = []
            if bound[k] and src is not None and src.role is not None and src.role not in emptied:
                need.append(src.role)
            if dst is not None and dst.role is not None and (bound[k] or s.fate is Fate.SPLITS):
                need.append(dst.role)
            if src is not None and src.role is not None and not bound[k] and (s.fate is Fate.STAYS and changes[src.role]
                    or s.fate is Fate.SPLITS and (bound[src.role] or s.rel.role.before in entered)):
                need.append(k)  # it stays in that holder, or a portion comes out of it (of a node an action fills)
            if src is not None and src.role is not None and holds_unsaid(slots[src.role].rel.role.before):
                need += [k, src.role]  # no list says which object that holder holds: the holder fact does
            for j in need:
                if not bound[j]:
                    bound[j] = grew = True
    names = NameTable()
    var = [f"?{names.name(s.rel.role.label, key=k)}" for k, s in enumerate(slots)]
    params = [(var[k], type_of[s.rel.role.label]) for k, s in enumerate(slots) if bound[k]]
    pre: list[Atom] = []
    add: list[Atom] = []
    delete: list[Atom] = []
    cond: list[Conditional] = []
    first: dict[tuple[str, str], str] = {}
    late: dict[tuple[Relation, str, int], str] = {}

    def fresh(label: str, key, word: str = "") -> str:
        v = f"?{names.name(f'{label} {word}'.strip(), key=key)}"
        params.append((v, type_of[label]))
        return v

    def state(v: str, label: str, node: ObjectNode | None) -> None:
        s_ = const[node] if node is not None else NOT_MADE
        pre.append(Atom(IS, (v, s_)))
        same = (label, s_)
        if same in first:
            pre.append(Atom(PRECEDES, (first[same], v)))
            precede.add(label)
        first[same] = v

    def becomes(v: str, old: ObjectNode | None, new: ObjectNode | str) -> None:
        delete.append(Atom(IS, (v, const[old] if old is not None else NOT_MADE)))
        add.append(Atom(IS, (v, CONSUMED if isinstance(new, str) else const[new])))
        if not isinstance(new, str) and new in stable:
            add.append(Atom(OCCUPIED, (const[new],)))

    def holder_var(place, label: str, k: int, source: bool = False) -> str | None:
        if place.role is not None:
            return var[place.role]
        key = (place.relation, place.holder, k if source else -1)  # a source per object (two breads, two boards)
        if key not in late:
            if place.holder not in type_of:
                return None
            taken = [h for (rel, c, _), h in late.items() if (rel, c) == key[:2] and not source]  # the first's
            late[key] = taken[0] if taken else fresh(place.holder, ("late", key), "here")
            pre.extend(() if taken or source else [Atom(LIVE, (late[key],)), *(  # a target that exists (`live_holders`),
                Atom(x.rel.source.relation.value, (late[key], var[j])) for j, x in enumerate(slots)  # the one a bound
                if j != k and bound[j] and x.rel.source is not None and x.rel.source.role is None  # role is at under
                and x.rel.source.holder == place.holder)])  # that name: one word, one stove (docs/pddl.md)
        if place.holder in containers:
            gaps.append((place.holder, label, f"{label} is {place.relation} [{place.holder}], a {place.holder} "
                         "the unit does not name: nothing says that it lists it", unit))
        return late[key]

    moving = {s.rel.role.before for s in slots if s.fate is Fate.MOVES}
    for k, s in enumerate(slots):
        r = s.rel
        label, before = r.role.label, r.role.before
        v = var[k]
        if s.fate is Fate.SPLITS:  # the portion: a new object where the role's output node says
            portion = fresh(label, ("portion", k), "portion")
            state(portion, label, None)
            becomes(portion, None, s.portion)
            if r.target is not None and (h := holder_var(r.target, label, k)) is not None:
                add.append(Atom(r.target.relation.value, (h, portion)))
        if not bound[k]:
            if before in stable:  # else a container emptied by a conditional effect: whichever holds the object
                pre.append(Atom(OCCUPIED, (const[before],)))
            continue
        state(v, label, before)
        after = plan.after_of(k) if bound[k] else s.after
        # what is in or on a consumed object became part of the mixture too, and so did all of its label in its
        # holder; what is in or on a container a restoring unit empties is thrown away; a role that moves out of it
        # goes where its node says (the gyoza filling folded from the wrapper into the dumpling)
        sweep = [(v, node, rel, f"{node.label} in {label}", ("inside", k, node.label)) for node, rel in
                 inside.get(label, ()) if node not in moving] if s.fate is Fate.CONSUMED or (
                     k == 0 and discards(unit)) else []
        if s.fate is Fate.CONSUMED:
            becomes(v, before, CONSUMED)
            if r.source is not None and r.source.role is not None and bound[r.source.role]:
                sweep += [(var[r.source.role], node, rel, f"{label} alike", ("alike", k, node))
                          for node, rel in relational_touched.alike_nodes(plan, s, inside)]
        elif after is not None and after != before:
            becomes(v, before, after)
        sweep += [(v, node, rel, f"{node.label} on {label}", ("dust", k, node))  # went into what is put there
                  for node, rel in relational_touched.dusted_nodes(plan, k, inside, dust)]
        if s.fate is Fate.NEW:  # what FOON restates as made was there: it becomes part of the one made
            sweep += [(var[r.target.role], node, rel, f"{label} there", ("there", k, node))
                      for node, rel in relational_touched.restated_nodes(plan, s, inside)]
        cond += sweep_effects(sweep, lambda word, key: names.name(word, key=key), const, type_of, inside)
        src, dst = r.source, r.target
        if s.fate in (Fate.STAYS, Fate.SPLITS) and src is not None and src.role is not None and bound[src.role]:
            pre.append(Atom(src.relation.value, (var[src.role], v)))
            if s.fate is Fate.STAYS and dst is not None and dst.relation != src.relation:
                delete.append(Atom(src.relation.value, (var[src.role], v)))
                add.append(Atom(dst.relation.value, (var[src.role], v)))
        if s.fate in (Fate.MOVES, Fate.CONSUMED) and src is not None:
            h = None
            if (src.role is not None and bound[src.role]) or (src.role is None and s.fate is Fate.CONSUMED
                                                               and not s.late_empties):
                h = holder_var(src, label, k, source=True)
            fact = Atom(src.relation.value, (h, v)) if h is not None else None
            dropped = dict(relational_touched.emptied_sources(plan, k, empties.get(k, [])))
            if fact is not None:
                pre.append(fact)
                delete.append(fact)
                for old, new in dropped.items():  # what the emptied holder's new node drops goes with it (once)
                    cond += [c for c in _with_it(h, (), old, new, plan, k, inside, const, type_of, names)
                             if c not in cond]
            else:
                if src.role in emptied:  # a container FOON filled earlier: emptied of it, whichever it is
                    f_ = f"?{names.name(f'{src.holder} {k}', key=('emptied', k))}"
                    there = Atom(src.relation.value, (f_, v))
                    old, new = slots[src.role].rel.role.before, emptied[src.role]
                    was = Atom(IS, (f_, const[old]))
                    now = [Atom(IS, (f_, const[new]))] + ([Atom(OCCUPIED, (const[new],))] if new in stable else [])
                    hold = type_of[slots[src.role].rel.role.label]
                    cond.append(Conditional((there, was), add=tuple(now), delete=(was,), var=f_, type=hold))
                    if old in dropped:
                        cond += _with_it(f_, (there, was), old, new, plan, k, inside, const, type_of, names, hold)
                f_ = f"?{names.name(f'from {k}', key=('from', k))}"
                leave = Atom(src.relation.value, (f_, v))
                cond.append(Conditional((leave,), delete=(leave,), var=f_, type=ROOT_TYPE))
                for old, new in empties.get(k, ()):  # whichever holder the units filled with it: emptied of it,
                    if any(bound[j] and changes[j] and x.rel.role.before == old for j, x in enumerate(slots)):
                        continue  # but not one the unit itself changes out of that state: it says how
                    was = Atom(IS, (f_, const[old]))
                    now = [Atom(IS, (f_, const[new]))] + ([Atom(OCCUPIED, (const[new],))] if new in stable else [])
                    cond.append(Conditional((leave, was), add=tuple(now), delete=(was,), var=f_, type=ROOT_TYPE))
                    if old in dropped:  # and of what its new node drops with it
                        cond += _with_it(f_, (leave, was), old, new, plan, k, inside, const, type_of, names,
                                         ROOT_TYPE)
        elif s.fate in (Fate.MOVES, Fate.CONSUMED) and label in loose:  # it leaves the holder FOON does not name
            f_ = f"?{names.name(f'from {k}', key=('from', k))}"
            for rel in Relation:
                leave = Atom(rel.value, (f_, v))
                cond.append(Conditional((leave,), delete=(leave,), var=f_, type=ROOT_TYPE))
        if s.fate in (Fate.MOVES, Fate.NEW) and dst is not None:
            h = holder_var(dst, label, k)
            if h is not None:
                add.append(Atom(dst.relation.value, (h, v)))
    for i, flow in enumerate(plan.flows):
        label = ways[i][0][0].label if ways.get(i) else flow.label  # the object label the list's name reads as
        if label not in type_of:
            continue
        y = f"?{names.name(f'{label} in it', key=('flow', i))}"
        for node, rel, new in ways.get(i, ()):
            there, was = Atom(rel.value, (var[flow.holder], y)), Atom(IS, (y, const[node]))
            now = [Atom(IS, (y, CONSUMED if new is None else const[new]))]
            if flow.into is not None:
                now.append(Atom(IN, (var[flow.into], y)))
            cond.append(Conditional((there, was), add=tuple(now), delete=(there, was), var=y, type=type_of[label]))
    # a role the unit leaves as it is ends in the node a late empty turns its node into (the oven the tray leaves), by
    # the emptied node's label (the name the unit uses may be another, FOON-GEN's `pan` for the cookware)
    emptied_by = {(old.label, old): new for j, s in enumerate(slots) if s.late_empties for old, new in empties.get(j, ())}
    expected = [Role(s.rel.role.label, s.rel.role.before, None if s.fate in (Fate.SPLITS, Fate.CONSUMED) else
                     plan.after_of(k) or emptied_by.get((s.rel.role.label, s.rel.role.before)))
                for k, s in enumerate(slots)]
    return Action(table.name(f"{unit.motion.label} u{u}", key=("unit", u)), pre=tuple(dict.fromkeys(pre)),
                  add=tuple(dict.fromkeys(add)), delete=tuple(d for d in dict.fromkeys(delete) if d not in add),
                  params=tuple(params), conditional=tuple(cond), cost=unit_cost(unit, options.costs, options.rates),
                  unit=u, comment=unit_comment(unit, u), roles=tuple(zip(expected, bound, strict=True)))


def _with_it(h: str, when: tuple[Atom, ...], old: ObjectNode, new: ObjectNode, plan: UnitPlan, k: int,
             inside: dict[str, list[tuple[ObjectNode, Relation]]], const: dict[ObjectNode, str],
             type_of: dict[str, str], names: NameTable, hold: str | None = None) -> list[Conditional]:
    """Role `k` of `plan` moves or is consumed out of holder `h`, which goes from `old` to `new` (`when` it is in
    `old` and holds the role's object, for a holder quantified over `hold`; always for a bound one): every object
    in it in a node `relational_touched.dropped_nodes` gives (a label `new` drops, not the role's own) becomes part
    of what leaves (consumed), so the holder holds nothing its new node does not list (GEN's kofta: the water beside
    the bulgur stirred out of the bowl; the units put water into grains, so the bowl's list dropped it with the
    bulgur)."""
    label = plan.slots[k].rel.role.label
    out = []
    for node, rel in relational_touched.dropped_nodes(plan, k, old, new, inside):
        if node.label not in type_of:
            continue
        y = f"?{names.name(f'{node.label} with {label}', key=('with', k if when else -1, h, node))}"  # one per holder
        there, was = Atom(rel.value, (h, y)), Atom(IS, (y, const[node]))
        out.append(Conditional((*when, there, was), add=(Atom(IS, (y, CONSUMED)),), delete=(there, was), var=y,
                               type=type_of[node.label], more=((h, hold),) if hold is not None else ()))
    return out
