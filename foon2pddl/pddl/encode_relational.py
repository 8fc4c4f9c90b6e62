"""The `relational` encoding: physical objects as in `instances`, plus which object holds which.

* **Objects and states** as in `encode_instances`: one PDDL object per physical
  object (counts from `instance_counts`), `(is ?x ?s)` for its FOON node,
  `(occupied s)` for stable nodes, `(precedes ?a ?b)` to bind two roles of one
  state to two objects.
* **Relations** as facts between objects, holder first (the public converter's
  order): `(in ?holder ?obj)`, `(on ?surface ?obj)`. A container's contents are
  the objects in it; an object is in or on at most one holder (init gives one,
  every action that adds a holder fact deletes the old one).
* **Actions.** One schema per unit. Per role (`holders.relational_roles`): the
  state change of `instances`; an object that stays at a place whose holder the
  unit names must be there (`(in ?bowl ?onion)`: nothing is cut on another board);
  an object that moves must be in its source holder (deleted) and goes into its
  target holder (added). A holder FOON does not identify is bound late: one
  parameter of the holder's label per moving object (the planner picks the bowl),
  never one per read-only object; an object leaving a holder the unit does not
  change leaves whatever holds it, by a quantified delete `(forall (?h -
  physical-object) (when (in ?h ?x) (not (in ?h ?x))))` instead of one parameter
  per possible source. Products are new objects in the holder FOON
  names; FOON's implied moves (an ingredient listed only as an input, whose
  receiving container lists it after) are completed with an implied node.
* **Consumption** is read from the containers' lists when the plan is replayed
  (`relational_replay`): an object in a container whose new node no longer lists
  its label became part of the mixture.
* **Init.** Kitchen objects start in the state of their node; an object whose
  node names a place starts in an object of that label whose node lists it, else
  in the first of that label. A holder the kitchen names but the task has no
  object of (`heavy cream (in [carton])`, no carton in any unit) is added, listing
  what starts in it (`implied_holders`), and so is what a kitchen container lists
  but the task has no object of (`pot (contains {water})`: `water (in [pot])`,
  `implied_contents`).

Not modelled: emptiness as a derived predicate (it stays a FOON state), quantities,
scene kitchens with object ids, generic restoring actions. Requirements: `:strips
:typing`, `:conditional-effects` when some object leaves a holder by a quantified
delete, `:action-costs` with costs.
"""

from __future__ import annotations

from ..model.foon import Foon, ObjectNode, make_node, make_state
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.places import describes_contents, listed, place_of, places
from .costs import unit_cost
from .encode_instances import (
    IS,
    NOT_MADE,
    OCCUPIED,
    PRECEDES,
    ROOT_TYPE,
    STATE_TYPE,
    _count_lines,
    _instances,
    _types,
    goal_actions_over_objects,
    precedes_facts,
)
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, header, short_path, unit_comment
from .holders import Place, RelRole, list_gaps, mismatches, relational_roles, task_aliases
from .instance_counts import derive_counts
from .names import NameTable
from .prune import restoring_units
from .registry import Compiled
from .task import Action, Atom, Instance, PlanningTask, Predicate

__all__ = ["IN", "ON", "encode_relational", "holder_init"]

IN, ON = "in", "on"


def holder_init(instances: list[Instance], alias: dict[str, str] | None = None) -> list[Instance]:
    """Instances with their starting holders: an object whose node names `in [C]` goes into an object of label C
    whose node lists its label (the first not yet given one of that label), else the first of label C (names
    read through the task's `alias`es)."""
    alias = alias or {}
    by_label: dict[str, list[Instance]] = {}
    for x in instances:
        by_label.setdefault(x.label, []).append(x)
    used: set[tuple[str, str]] = set()
    out = []
    for x in instances:
        place = place_of(x.start)
        if place is None or alias.get(place[1], place[1]) not in by_label:
            out.append(x)
            continue
        rel, label = place[0], alias.get(place[1], place[1])
        pool = [h for h in by_label[label] if h.name != x.name]
        listing = [h for h in pool if x.label in _read(listed(h.start), alias)]
        free = [h for h in listing if (h.name, x.label) not in used]
        silent = [h for h in pool if h.start is not None and not describes_contents(h.start)]
        pick = (free or listing or silent or pool or [None])[0]
        if pick is None:
            out.append(x)
            continue
        used.add((pick.name, x.label))
        out.append(Instance(x.name, x.label, x.start, pick.name, rel))
    return out


def _read(names: frozenset[str], alias: dict[str, str]) -> frozenset[str]:
    return frozenset(alias.get(x, x) for x in names)


def implied_holders(instances: list[Instance], alias: dict[str, str] | None = None) -> tuple[ObjectNode, ...]:
    """Holders the kitchen's objects start in but the task has no object of (`heavy cream (in [carton])` and no
    carton in any unit): one per label, listing what starts in it (`carton (contains {heavy cream})`), sorted by
    label (names read through the task's `alias`es). A holder of the label whose node contradicts it (`egg (in
    [bowl])` while the only bowl is `bowl (empty)`) is still used: a new bowl the units never name would leave
    the egg where no unit can reach it (measured: four more unsolvable dishes of the shared subgraphs)."""
    alias = alias or {}
    by_label: dict[str, list[Instance]] = {}
    for h in instances:
        if h.start is not None:
            by_label.setdefault(h.label, []).append(h)
    wanted: dict[str, set[str]] = {}
    for x in instances:
        place = place_of(x.start)
        if place is None:
            continue
        label = alias.get(place[1], place[1])
        pool = [h for h in by_label.get(label, ()) if h.name != x.name]
        if not pool:
            wanted.setdefault(label, set()).add(x.label)
    return tuple(make_node(label, [make_state("contains", "", sorted(items))]) for label, items in sorted(wanted.items()))


def implied_contents(instances: list[Instance], alias: dict[str, str] | None = None,
                     placed: frozenset[str] = frozenset()) -> tuple[ObjectNode, ...]:
    """What kitchen containers list but the task has too few objects in (`pot (contains {water})`, no water in
    any unit; three bowls of `contains {water}` and one `water (in [bowl])`): for every container (a label of
    `placed`, the labels nodes name as a place) that starts listing a label, one object of that label placed
    in it, counting the task's objects that start placed in a container of that label first. A new object
    starts in the node of such an object, else `water (in [pot])`. In container-name order; O(n^2)."""
    alias = alias or {}
    out = []
    fits: dict[tuple[str, str], list[ObjectNode]] = {}  # (item, container label) -> start nodes placed there
    for x in instances:
        place = place_of(x.start)
        if place is not None:
            fits.setdefault((x.label, alias.get(place[1], place[1])), []).append(x.start)
    spare = {k: len(v) for k, v in fits.items()}
    for h in sorted(instances, key=lambda x: x.name):
        if h.start is None or h.label not in placed:
            continue
        for item in sorted(_read(listed(h.start), alias)):
            if spare.get((item, h.label), 0) > 0:
                spare[(item, h.label)] -= 1
                continue
            known = fits.get((item, h.label))
            out.append(known[0] if known else make_node(item, [make_state("in", h.label)]))
    return tuple(out)


def encode_relational(foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3,
                      options: EncodeOptions = DEFAULT_OPTIONS) -> Compiled:
    """The relational task of `goal` over `foon` (see the module doc), with its label mismatches as notes."""
    inp = at_level(foon, kitchen, goal, level)
    f = inp.foon
    units = restoring_units(f, inp.kitchen, inp.candidates) if options.prune else tuple(range(len(f.units)))
    counts = derive_counts(f, units, inp.kitchen, inp.candidates, stated=kitchen.project(level).stated_counts(),
                           overrides=dict(options.instances))
    have = counts.labels()
    units = tuple(u for u in units if all(r.role.label in have for r in relational_roles(f.units[u])))

    table = NameTable()
    for name in (IS, IN, ON, OCCUPIED, NOT_MADE, PRECEDES, GOAL_REACHED, STATE_TYPE, ROOT_TYPE):
        table.reserve(name)
    type_of, types = _types(table, sorted(set(have) | {c.label for c in inp.candidates}), dict(options.categories))
    nodes = set(inp.candidates) | {n for n, _ in counts.at_node}
    for u in units:
        nodes.update(x for r in relational_roles(f.units[u]) for x in (r.role.before, r.after) if x is not None)
    const = {n: table.name(n.describe() if n.states else f"{n.label} plain", key=("node", n)) for n in sorted(nodes)}
    instances, init, precede = _instances(table, counts, const)
    alias = dict(task_aliases([f.units[u] for u in units], have, [x.start for x in instances]))
    extra = implied_holders(instances, alias)
    placed = frozenset(alias.get(c, c) for n in nodes | {x.start for x in instances} for _, c in places(n))
    extra += implied_contents([*instances, *(Instance("", x.label, x) for x in extra)], alias, placed)
    for node in extra:
        if node not in const:
            const[node] = table.name(node.describe(), key=("node", node))
        if node.label not in type_of:
            type_of[node.label] = table.name(node.label, key=("type", node.label))
            types.append((type_of[node.label], ROOT_TYPE))
        k = 1 + sum(x.label == node.label for x in instances)
        name = table.name(f"{node.label} {k}", key=("instance", node.label, k))
        instances.append(Instance(name, node.label, node))
        init.append(Atom(IS, (name, const[node])))
    instances = holder_init(instances, alias)
    init.extend(Atom(x.relation.value, (x.holder, x.name)) for x in instances if x.holder is not None)
    left = {r.role.before for u in units for r in relational_roles(f.units[u]) if r.changes}
    stable = {n for n in const if n not in left}
    init.extend(Atom(OCCUPIED, (const[n],)) for n, _ in counts.at_node if n in stable)

    actions = [_unit_action(u, f.units[u], table, const, stable, type_of, options, precede) for u in units]
    actions.extend(goal_actions_over_objects(inp.candidates, stable, table, const, type_of, options))
    init.extend(precedes_facts(precede, instances))
    hold = (("?h", ROOT_TYPE), ("?x", ROOT_TYPE))
    predicates = [Predicate(IS, (("?x", ROOT_TYPE), ("?s", STATE_TYPE)), "?x is in the state of FOON node ?s"),
                  Predicate(IN, hold, "?x is in ?h"), Predicate(ON, hold, "?x is on ?h"),
                  Predicate(OCCUPIED, (("?s", STATE_TYPE),), "some object is in state ?s, which no action leaves"),
                  Predicate(GOAL_REACHED, comment="a goal candidate was made")]
    if precede:
        predicates.append(Predicate(PRECEDES, hold, "static order of the objects of a label"))
    found = [(f.units[u], m) for u in units for m in (*mismatches(f.units[u]), *(g for _, _, g in list_gaps(f.units[u])))]
    notes = sorted({f"{_where(unit)}: {m}" for unit, m in found})
    commented = sorted({f"{_where(unit, short_path)}: {m}" for unit, m in found})  # no checkout path in files
    task = PlanningTask(
        domain="foon-relational", problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="relational", level=inp.level, predicates=tuple(predicates), actions=tuple(actions),
        init=tuple(sorted(set(init))), goal=(Atom(GOAL_REACHED),), types=tuple(types),
        constants=tuple((name, STATE_TYPE) for name in (NOT_MADE, *const.values())),
        objects=tuple((x.name, type_of[x.label]) for x in instances), units=f.units, labels=table.labels,
        comments=header("relational", inp, options, len(units)) + _count_lines(counts)
        + tuple(f"label mismatch: {m}" for m in commented),
        instances=tuple(instances),
    )
    return Compiled(task, every_step=True, notes=tuple(f"label mismatch: {m}" for m in notes))


def _where(unit, path=str) -> str:
    src = unit.source
    return f"{path(src.path)}:{src.line}" if src is not None else "?"


def _unit_action(u: int, unit, table: NameTable, const: dict[ObjectNode, str], stable: set[ObjectNode],
                 type_of: dict[str, str], options: EncodeOptions, precede: set[str]) -> Action:
    """One unit's schema (see the module doc): per role its state change and its holder facts."""
    rels = relational_roles(unit)
    # A source holder is a parameter only when the unit changes it; else the object leaves whatever holds it
    # (a quantified delete): seven read-only bowls poured from are no 9^7 groundings.
    held = [p for r in rels for p in (r.target, _checked(r, rels)) + ((r.source,) if r.moves else ())
            if p is not None and p.role is not None and (p is not r.source or rels[p.role].changes)]
    holders = {p.role for p in held}
    bound = tuple(r.changes or r.moves or k in holders or r.role.before not in stable
                  or _checked(r, rels) is not None for k, r in enumerate(rels))
    names = NameTable()
    var = [f"?{names.name(r.role.label, key=k)}" for k, r in enumerate(rels)]
    params = [(v, type_of[r.role.label]) for v, r, b in zip(var, rels, bound, strict=True) if b]
    pre, add, delete, release = [], [], [], []
    first: dict[tuple[str, str], str] = {}
    for k, (v, r, b) in enumerate(zip(var, rels, bound, strict=True)):
        state = const[r.role.before] if r.role.before is not None else NOT_MADE
        if not b:
            pre.append(Atom(OCCUPIED, (state,)))
            continue
        pre.append(Atom(IS, (v, state)))
        if r.changes:
            delete.append(Atom(IS, (v, state)))
            add.append(Atom(IS, (v, const[r.after])))
            if r.after in stable:
                add.append(Atom(OCCUPIED, (const[r.after],)))
        same = (r.role.label, state)
        if same in first:
            pre.append(Atom(PRECEDES, (first[same], v)))
            precede.add(r.role.label)
        first[same] = v
        if (place := _checked(r, rels)) is not None:
            pre.append(Atom(place.relation.value, (var[place.role], v)))
        for place, side in ((r.source, "from"), (r.target, "into")):
            if place is None or not r.moves:
                continue
            if side == "from" and (place.role is None or not rels[place.role].changes):
                release.append((f"?{names.name(f'from {k}', key=('from', k))}", ROOT_TYPE, None, place.relation, v))
                continue
            if place.role is not None:
                h = var[place.role]
            elif place.holder in type_of:
                h = f"?{names.name(f'{side} {place.holder} {k}', key=(side, k))}"
                params.append((h, type_of[place.holder]))
            else:
                continue
            fact = Atom(place.relation.value, (h, v))
            if side == "from":
                pre.append(fact)
                delete.append(fact)
            else:
                add.append(fact)
    return Action(table.name(f"{unit.motion.label} u{u}", key=("unit", u)), pre=tuple(pre), add=tuple(add),
                  delete=tuple(d for d in delete if d not in add), params=tuple(params),
                  release=tuple((h, t, Atom(rel.value, (h, x))) for h, t, _, rel, x in release),
                  cost=unit_cost(unit, options.costs, options.rates), unit=u, comment=unit_comment(unit, u),
                  roles=tuple((r.role, b) for r, b in zip(rels, bound, strict=True)))


def _checked(r: RelRole, rels: tuple[RelRole, ...]) -> Place | None:
    """Where an unmoved object must be, checked by a precondition: its holder is a role of the unit and the
    unit changes the object or the holder (a read-only salt in a read-only bowl is checked by neither)."""
    place = r.stays
    if place is None or place.role is None or not (r.changes or rels[place.role].changes):
        return None
    return place
