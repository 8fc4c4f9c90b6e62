"""The `relational` encoding: physical objects as in `instances`, plus which object holds which.

* **Objects and states** as in `encode_instances`: one PDDL object per physical
  object, `(is ?x ?s)` for its FOON node (`not-yet-made` before it exists,
  `consumed` after it became part of a mixture), `(occupied s)` for stable nodes
  (and, kept by a tally, for a role that only checks a node others leave: `tallies`),
  `(precedes ?a ?b)` to bind two roles of one state to two objects. Counts are
  derived as for `instances`, from the roles this encoding gives each unit
  (`relational_plan.count_roles`: a portion poured off is a new object); counted
  small with `EncodeOptions.narrow` (`relational_objects`: what `plan` tries first).
* **Relations** as facts between objects, holder first (the public converter's
  order): `(in ?holder ?obj)`, `(on ?surface ?obj)`. A container's contents are
  the objects in it; every action that puts an object somewhere removes it from
  where it was, so an object is in or on at most one holder.
* **Actions.** One schema per unit, from the unit's reading in the task (`relational_reading.read_units`:
  `relational_plan.plan_unit`, `holders.relational_roles`). Per role:
  - an object that stays where it is while it or its holder changes must be there: `(in ?bowl ?onion)`;
  - an object that moves must be in its source holder (deleted) and goes into its
    target (added); a source the unit does not name is left by a quantified delete
    `(forall (?h - physical-object) (when (in ?h ?x) (not (in ?h ?x))))`, never by one
    parameter per possible source (seven read-only bowls poured from are not 9^7 groundings); a target the unit
    does not name is one parameter of its label per unit (the planner picks the oven);
  - a portion (`SPLITS`) is a not-yet-made object that arrives at the target in
    the role's output node, while the object it was taken from stays;
  - a container FOON filled earlier and leaves out of the outputs is emptied of
    what leaves it (`relational_plan.without`), and says so as a role;
  - a consumed object goes to `consumed` and leaves its holder, with all of its
    label there when the holder's node no longer lists it, and with what is in
    or on it, two levels deep (`relational_sweep`); contents that are
    no role of the unit follow their container's list (`holders.Flow`), by one
    quantified conditional effect per node they can be in.
* **Init.** Kitchen objects start in the state of their node; an object whose node
  names a place starts in an object of that label whose node lists it (else one
  silent about its contents); when there is none, a holder of that label is added,
  listing what starts in it (`heavy cream (in [carton])` and no carton in any unit,
  or `egg (in [bowl])` while every bowl of the kitchen is `bowl (empty)`), and a
  kitchen container that lists an item holds one object of it.
* **Stitches** (`input_stitch`): an input no unit makes, read as the node the plan left it in; two nodes of a unit
  that list each other, read as one on the other (`mutual_lists`); a list's item no object of the unit is, taken
  there on the container's path in a node no unit makes, read as arriving with the unit (`list_arrivals`); a node
  a unit takes and leaves listing what it puts in, read before it as the node without that (`list_brought`); a
  container's node and what is in it, taken together and made together by no unit, as at hand (`kitchen_pairs`).
* **Reports.** Label readings and contradictions (`holder_words.mismatches`, `holders.list_gaps`), stitches, and
  every object the unit puts where its node does not say what the holder holds (a target the unit does not
  name: `sandwich (on [plate])` with no plate in the unit), once per task with the unit's file:line; the last
  two are the (container, content) pairs the replay does not check.

Requirements: `:strips :typing`, `:conditional-effects` when an action has a
quantified or conditional effect, `:action-costs` with costs.
"""

from __future__ import annotations

from dataclasses import replace

from ..model.aliases import unit_aliases
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.pairing import Role
from ..model.physical import Relation
from ..model.places import describes_contents, place_of, places
from . import relational_touched
from .costs import unit_cost
from .encode_instances import (
    GOAL_OBJECT,
    IS,
    NOT_MADE,
    OCCUPIED,
    PRECEDES,
    ROOT_TYPE,
    STATE_TYPE,
    count_lines,
    goal_actions_over_objects,
    object_types,
    precedes_facts,
)
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, header, unit_comment
from .holder_words import mismatches, reported
from .holders import Fate, attached_gaps, held_elsewhere, list_gaps, on_parts
from .input_stitch import with_stitches
from .instance_counts import count_reasons
from .kitchen_pairs import read_pairs
from .list_arrivals import read_arrivals
from .list_brought import read_brought
from .live_holders import LIVE, with_live
from .mutual_lists import mutual_notes, read_mutual
from .names import NameTable
from .prune import restoring_units
from .registry import Compiled
from .relational_init import kitchen_implied
from .relational_objects import task_objects
from .relational_plan import UnitPlan
from .relational_stitch import stitch_notes, stitched
from .relational_sweep import CONSUMED, sweep_effects
from .restore import discards
from .tallies import tallied
from .task import Action, Atom, Conditional, PlanningTask, Predicate
from .untouched import set_aside

__all__ = ["CONSUMED", "IN", "ON", "encode_relational"]

IN, ON = "in", "on"
#: The note kinds of a relation FOON states that the encoding does not hold (`holders.attached_gaps`) and of a
#: pair of nodes no unit makes together, read as the kitchen's (`kitchen_pairs`).
UNHELD, AT_HAND = "relation not modelled", "assumed at hand"


def encode_relational(foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3,
                      options: EncodeOptions = DEFAULT_OPTIONS) -> Compiled:
    """The relational task of `goal` over `foon` (see the module doc), with its reports as notes."""
    inp = at_level(foon, kitchen, goal, level)
    given = inp.foon.units  # FOON's own: the plan's tree is made of them
    inp, mutual = read_mutual(inp)  # two nodes listing each other: one is on the other
    inp, arrived = read_arrivals(inp)  # a list's item no object of the unit is, taken there later: put in too
    inp, brought = read_brought(inp)  # a node a unit takes and leaves, listing what it puts in: before it, less that
    inp, reads, units = stitched(inp, lambda i: restoring_units(i.foon, i.kitchen, i.candidates) if options.prune
                                 else tuple(range(len(given))))
    inp, at_hand = read_pairs(inp, units)  # a container's node and what is in it that no unit makes together: the kitchen's
    f = inp.foon
    def relevant(net: Foon) -> tuple[int, ...]:
        return restoring_units(net, inp.kitchen, inp.candidates) if options.prune else tuple(range(len(net.units)))
    st = with_stitches(f, relevant)  # inputs no unit makes, read as the node the plan left that object in
    f, units, origin, sewn = st.foon, st.units, st.origin, st.found
    scene = kitchen.project(level).scene
    ob = task_objects(inp, st, scene, kitchen.project(level).stated_counts(), dict(options.instances), (
        IS, IN, ON, OCCUPIED, NOT_MADE, CONSUMED, PRECEDES, GOAL_REACHED, GOAL_OBJECT, STATE_TYPE, ROOT_TYPE, LIVE),
        options.narrow)
    rd, table, instances, alias, placed, nodes = ob.reading, ob.table, list(ob.instances), ob.alias, ob.placed, set(ob.nodes)
    units, plans, drops, counts = rd.units, rd.plans, rd.drops, rd.counts
    why = tuple(f"objects: {w}" for w in (*count_reasons(inp.foon, counts, ob.kitchen, rd.roles_of),
                                          *((ob.narrowed,) if ob.narrowed else ())))
    # labels of objects held where their node names no place (a scene's onion in the fridge): moving one
    # leaves whatever holds it
    loose = frozenset(x.label for x in instances if x.holder is not None and place_of(x.start) is None)
    nodes.update(x.start for x in instances if x.start is not None)
    readings = frozenset(pair for u in units for pair in unit_aliases(f.units[u]))
    ways = {u: relational_touched.flow_ways(plans[u], nodes, alias, readings) for u in units}
    nodes.update(n for w in ways.values() for lst in w.values() for _, _, n in lst if n is not None)
    empties = relational_touched.every_late_empty({u: plans[u] for u in units}, nodes, alias)
    type_of, types = object_types(table, sorted({x.label for x in instances} | {c.label for c in inp.candidates}),
                            dict(options.categories))
    const = {n: table.name(n.describe() if n.states else f"{n.label} plain", key=("node", n)) for n in sorted(nodes)}
    init = [Atom(IS, (x.name, const[x.start] if x.start is not None else NOT_MADE)) for x in instances]
    init.extend(Atom(x.relation.value, (x.holder, x.name)) for x in instances if x.holder is not None)

    inside: dict[str, list[tuple[ObjectNode, Relation]]] = {}  # label -> nodes placed in or on one
    for n in sorted(nodes):
        for rel, c in places(n)[:1]:
            inside.setdefault(alias.get(c, c), []).append((n, rel))
    for n, holder in sorted({x for u in units for x in on_parts(f.units[u])}):  # the bacon `on [bread]`: on the
        inside.setdefault(holder, []).extend((n, rel) for rel, _ in places(n)[:1])  # sandwich (`holders` rule 2)
    dust = relational_touched.dustings(plans[u] for u in units)
    left = relational_touched.left_nodes([(plans[u], ways[u], empties[u]) for u in units], inside, dust)
    stable = {n for n in const if n not in left}
    entered = {n for u in units for k, s in enumerate(plans[u].slots) if s.fate is not Fate.CONSUMED  # an action puts
               for n in (s.portion, plans[u].after_of(k)) if n not in (None, s.rel.role.before)}  # an object there
    init.extend(Atom(OCCUPIED, (const[x.start],)) for x in instances if x.start in stable)

    gaps: list[tuple[str, str, str, object]] = list(drops)  # (container, content, message, unit)
    precede: set[str] = set()
    container_labels = {n.label for n in nodes if describes_contents(n)} & placed
    actions = [replace(_unit_action(u, plans[u], table, const, stable, type_of, options, precede, ways[u], gaps,
                                    container_labels, inside, empties[u], loose, dust, entered), unit=origin.get(u, u))
               for u in units]
    live = {origin[u] for u in units if u in origin}  # the stitched units the task has (objects for their labels)
    # what the kitchen implies (its objects where its holders say, the holders its objects are in): the tree
    # check's kitchen too; a candidate an object starts in beyond it is reached only by what units make
    moved = (kitchen_implied((x.start for x in instances), inp.kitchen) | ob.implied | {x.node for x in sewn if x.unit in live}
             | {n for x in at_hand for n in (x.box, x.held)})
    early = {c for c in inp.candidates if c not in moved and c not in inp.kitchen
             and any(x.start == c for x in instances)}
    actions.extend(goal_actions_over_objects(inp.candidates, stable, table, const, type_of, options, early))
    init.extend(Atom(GOAL_OBJECT, (x.name,)) for x in instances if any(x.label == c.label and x.start != c
                                                                      for c in early))
    init.extend(precedes_facts(precede, instances))
    hold = (("?h", ROOT_TYPE), ("?x", ROOT_TYPE))
    predicates = [Predicate(IS, (("?x", ROOT_TYPE), ("?s", STATE_TYPE)), "?x is in the state of FOON node ?s"),
                  Predicate(IN, hold, "?x is in ?h"), Predicate(ON, hold, "?x is on ?h"),
                  Predicate(OCCUPIED, (("?s", STATE_TYPE),), "some object is in state ?s, which no action leaves"),
                  Predicate(GOAL_REACHED, comment="a goal candidate was made")]
    if precede:
        predicates.append(Predicate(PRECEDES, hold, "static order of the objects of a label"))
    if early:
        predicates.append(Predicate(GOAL_OBJECT, (("?x", ROOT_TYPE),), "?x may reach the goal: no kitchen object"))
    unheld = [(f.units[u], g) for u in units for _, _, g in attached_gaps(f.units[u])]  # FOON's labels agree there
    found = [(f.units[u], m) for u in units for m in (*mismatches(f.units[u]), *(g for _, _, g in list_gaps(f.units[u])))
             if (f.units[u], m) not in unheld]
    found += [(unit, msg) for _, _, msg, unit in gaps] + stitch_notes(reads) + mutual_notes(
        mutual, {n for u in units for n in (*f.units[u].inputs, *f.units[u].outputs)})
    found += [(x.taker, x.describe()) for x in sewn if x.unit in live] + [x[u] for x in (arrived, brought) for u in units if u in x]
    found += rd.renamed + rd.portions + ob.init_notes
    told = [(kind, reported(x)) for kind, x in (("label mismatch", found), (UNHELD, unheld),
                                                (AT_HAND, [(x.taker, x.describe()) for x in at_hand]))]
    notes, commented = ([f"{kind}: {m}" for kind, both in told for m in both[i]] for i in (0, 1))
    pairs = {(c, x) for u in (*units, *ob.beside) for c, x, _ in list_gaps(f.units[u])} | {(c, x) for c, x, _, _ in gaps}
    task = PlanningTask(
        domain="foon-relational", problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="relational", level=inp.level, predicates=tuple(predicates), actions=tuple(actions),
        init=tuple(sorted(set(init))), goal=(Atom(GOAL_REACHED),), types=tuple(types),
        constants=tuple((name, STATE_TYPE) for name in (NOT_MADE, CONSUMED, *const.values())),
        objects=tuple((x.name, type_of[x.label]) for x in instances), units=given, labels=table.labels,
        comments=header("relational", inp, options, len(units) - len(live)) + count_lines(counts) + why
        + tuple(commented),
        instances=tuple(instances), nodes=tuple(sorted((name, n) for n, name in const.items())),
        gaps=tuple(sorted(pairs)))
    task = with_live(task)  # late-bound targets exist: (live x), made to consumed
    task = set_aside(task) if options.prune else task  # untouched objects: out of the problem, not the replay
    task = tallied(task)  # a role that only checks a state other actions leave: (occupied s), kept by a tally
    return Compiled(task, every_step=True, placed=moved, notes=tuple(notes) + why, narrowed=ob.narrowed,
                    counted=frozenset(u for u, _ in rd.counts.firings))  # the units of the plan counted from


def _unit_action(u: int, plan: UnitPlan, table: NameTable, const: dict[ObjectNode, str], stable: set[ObjectNode],
                 type_of: dict[str, str], options: EncodeOptions, precede: set[str], ways: dict[int, list[relational_touched.Way]],
                 gaps: list, containers: set[str], inside: dict[str, list[tuple[ObjectNode, Relation]]],
                 empties: dict[int, list[tuple[ObjectNode, ObjectNode]]], loose: frozenset[str],
                 dust: frozenset[ObjectNode], entered: set[ObjectNode]) -> Action:
    """One unit's schema (see the module doc): per role its state change and its holder facts."""
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
            if fact is not None:
                pre.append(fact)
                delete.append(fact)
            else:
                if src.role in emptied:  # a container FOON filled earlier: emptied of it, whichever it is
                    f_ = f"?{names.name(f'{src.holder} {k}', key=('emptied', k))}"
                    there = Atom(src.relation.value, (f_, v))
                    old, new = slots[src.role].rel.role.before, emptied[src.role]
                    was = Atom(IS, (f_, const[old]))
                    now = [Atom(IS, (f_, const[new]))] + ([Atom(OCCUPIED, (const[new],))] if new in stable else [])
                    cond.append(Conditional((there, was), add=tuple(now), delete=(was,), var=f_,
                                            type=type_of[slots[src.role].rel.role.label]))
                f_ = f"?{names.name(f'from {k}', key=('from', k))}"
                leave = Atom(src.relation.value, (f_, v))
                cond.append(Conditional((leave,), delete=(leave,), var=f_, type=ROOT_TYPE))
                for old, new in empties.get(k, ()):  # whichever holder the units filled with it: emptied of it,
                    if any(bound[j] and changes[j] and x.rel.role.before == old for j, x in enumerate(slots)):
                        continue  # but not one the unit itself changes out of that state: it says how
                    was = Atom(IS, (f_, const[old]))
                    now = [Atom(IS, (f_, const[new]))] + ([Atom(OCCUPIED, (const[new],))] if new in stable else [])
                    cond.append(Conditional((leave, was), add=tuple(now), delete=(was,), var=f_, type=ROOT_TYPE))
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
