"""The `instances` encoding: physical object instances whose states change.

* **Types.** Flat: `physical-object` and `object-state` (UP's FLAT_TYPING, the
  only typing Tamer reads: a label type under `physical-object` as the argument
  of `(is ?x - physical-object ...)` is a TypeCheckingError there). An object's
  label (`bowl`), and its category chain when one is given
  (`EncodeOptions.categories`, e.g. `lemon - citrus_fruits - fruit`), are static
  unary predicates (`(type_bowl bowl_1)`, `untyped.flat_typed`), and a role's
  parameter requires its label's (`(type_lemon ?lemon)`), so a lemon never stands
  in for a lime; categories only group.
* **Instances.** `bowl_1 ... bowl_k`, of label `bowl`, with counts from
  `instance_counts` (derived per goal, stated by the kitchen, or overridden).
* **State.** Every FOON node of a label is a domain constant of type
  `object-state`; `(is ?x ?s)` says instance `?x` is in the state of node `?s`,
  `(is ?x not-yet-made)` that it does not exist yet. Every instance is in
  exactly one state at any time (init gives one, every action that adds a
  state deletes the old one), so Fast Downward's invariant synthesis makes
  one multi-valued variable per instance. A *stable* node, one that no action
  of the task moves an instance out of, also has `(occupied s)`: true once an
  instance is there, and then forever, so it is exactly "some instance is in
  state s".
* **Actions.** One lifted schema per functional unit, with one parameter per
  role (`pairing.unit_roles`): a moved object must be in its input node's
  state and goes to its output node's state (delete + add); kept and
  read-only objects must be in their input node's state and stay there (when
  that node is stable and no other role of the unit is in it, they are no parameter: `(occupied s)` is checked
  instead,
  which keeps grounding small: seven read-only bowls of a salad would be 9^7
  groundings with nine bowls, and the plan's instance for them is
  chosen when the plan is replayed, `instance_replay`); a new
  object must be not yet made and comes into its output node's state. Two
  roles of one label that require the same state (a node listed twice, two
  new objects) must bind different instances: `(precedes ?a ?b)`, a static
  strict order on the instances of a label, says so in plain STRIPS (and
  halves the symmetric groundings). A unit whose labels have no instances
  is dropped.
* **Lanes.** With derived counts, static facts (`instance_lanes.lanes`) say
  what the unfolded plan does with each instance when run on these
  instances: `(lane ?x s t)` per state change (`(lane ?x s s)` for the states
  it is in) and `(together ?a ?b)` for instances changed by one firing. Every
  bound role requires its instance's lane to make the unit's change (or pass
  through the state it reads), and a unit's changing instances must have
  changed together. The unfolded plan still runs, so solvability is
  unchanged, and a unit grounds over the bindings the plan uses instead of
  the product of its labels' counts (71,796 -> 1,227 operators on the slowest
  universal-FOON goal). Off for stated, overridden or extra counts.
* **Goal.** `(goal-reached)`, added by one `reach-goal-<i>` action per goal
  candidate: "some instance is in the candidate's state".
* **Pruning.** With pruning on (default), only the goal's relevant units
  become schemas (`prune.restoring_units`: FOON's relevant units plus those that
  can restore a kitchen state they use up, such as washing a knife): any plan
  here maps to units that fire in FOON's delete-free semantics.

Not modelled: which instance holds which (`in [bowl]` is part of a node's
state, so the bowl holding the onion is *a* bowl; FOON's nodes rarely name
the holding object in the same unit, see docs/pddl.md), quantities, and what
becomes of read-only objects. `Action.roles` and `PlanningTask.instances` let
a plan map back to units with instance bindings, and to a `model.physical.PhysicalTrace`
with no holders (`instance_replay`, the encoding's replay hook).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Collection, Mapping
from itertools import pairwise

from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.pairing import unit_roles
from .costs import goal_cost, unit_cost
from .count_reasons import count_reasons
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, header, unit_comment
from .instance_counts import InstanceCounts, derive_counts
from .instance_lanes import lanes
from .instance_names import counted_objects
from .names import NameTable
from .prune import restoring_units
from .task import Action, Atom, Instance, PlanningTask, Predicate
from .untyped import flat_typed

IS = "is"
OCCUPIED = "occupied"
NOT_MADE = "not-yet-made"
PRECEDES = "precedes"
LANE = "lane"
TOGETHER = "together"
GOAL_OBJECT = "goal-object"
STATE_TYPE = "object-state"
ROOT_TYPE = "physical-object"

#: Most labels listed in the header's count line.
HEADER_LABELS = 40


def object_types(table: NameTable, labels: list[str], categories: Mapping[str, tuple[str, ...]]) -> tuple[dict, list]:
    """Label -> type name, and the (type, parent) declarations (categories first, then labels)."""
    decl: dict[str, str] = {}
    cat_name: dict[str, str] = {}
    for label in labels:
        chain = categories.get(label, ())
        for k in range(len(chain) - 1, -1, -1):
            if chain[k] not in cat_name:
                cat_name[chain[k]] = table.name(chain[k], key=("category", chain[k]))
                decl[cat_name[chain[k]]] = cat_name[chain[k + 1]] if k + 1 < len(chain) else ROOT_TYPE
    type_of = {}
    for label in labels:
        chain = categories.get(label, ())
        type_of[label] = table.name(label, key=("type", label))
        decl[type_of[label]] = cat_name[chain[0]] if chain else ROOT_TYPE
    return type_of, [(ROOT_TYPE, "object"), (STATE_TYPE, "object"), *decl.items()]


def encode_instances(
    foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3, options: EncodeOptions = DEFAULT_OPTIONS,
    *, extra: int = 0,
) -> PlanningTask:
    """The object-instance task of `goal` over `foon` (see the module doc); `extra` adds instances everywhere."""
    inp = at_level(foon, kitchen, goal, level)
    f = inp.foon
    units = (restoring_units(f, inp.kitchen, inp.candidates) if options.prune else tuple(range(len(f.units))))
    counts = derive_counts(f, units, inp.kitchen, inp.candidates, stated=kitchen.project(level).stated_counts(),
                           overrides=dict(options.instances), extra=extra)
    have = counts.labels()
    units = tuple(u for u in units if all(r.label in have for r in unit_roles(f.units[u])))

    table = NameTable()
    for name in (IS, OCCUPIED, NOT_MADE, PRECEDES, LANE, TOGETHER, GOAL_REACHED, STATE_TYPE, ROOT_TYPE):
        table.reserve(name)
    type_of, types = object_types(table, sorted(set(have) | {c.label for c in inp.candidates}), dict(options.categories))
    nodes = set(inp.candidates) | {n for n, _ in counts.at_node}
    for u in units:
        nodes.update(x for r in unit_roles(f.units[u]) for x in (r.before, r.after) if x is not None)
    # A node without states would take its label's name, which its type has: call it `<label> plain`.
    const = {n: table.name(n.describe() if n.states else f"{n.label} plain", key=("node", n)) for n in sorted(nodes)}
    instances, init, precede = _instances(table, counts, const)
    lane = lanes(f, counts, [(x.name, x.label, x.start) for x in instances]) if set(counts.unfolded) <= set(units) \
        else None
    if lane is not None:
        init.extend(Atom(LANE, (x, NOT_MADE if a is None else const[a], const[b])) for x, a, b in lane.steps)
        init.extend(Atom(TOGETHER, pair) for pair in lane.together)
    # Stable nodes: no kept unit moves an instance out of them, so "some instance is there" never
    # becomes false again; roles that only need one there check `(occupied s)` instead of a parameter.
    left = {r.before for u in units for r in unit_roles(f.units[u]) if r.changes}
    stable = {n for n in const if n not in left}
    init.extend(Atom(OCCUPIED, (const[n],)) for n, _ in counts.at_node if n in stable)

    actions: list[Action] = []
    for u in units:
        unit = f.units[u]
        roles = unit_roles(unit)
        twice = {n for n, k in Counter(r.before for r in roles).items() if k > 1}  # two bowls at level 2: two objects
        bound = tuple(r.changes or r.before not in stable or r.before in twice for r in roles)
        params_table = NameTable()
        params = [f"?{params_table.name(r.label, key=k)}" for k, r in enumerate(roles)]
        pre, add, delete = [], [], []
        first: dict[tuple[str, str], str] = {}
        changing = [var for var, r in zip(params, roles, strict=True) if r.changes]
        if lane is not None:  # the instances one firing changes changed together in the unfolded plan
            pre.extend(Atom(TOGETHER, pair) for pair in pairwise(changing))
        for var, r, b in zip(params, roles, bound, strict=True):
            state = const[r.before] if r.before is not None else NOT_MADE
            if not b:
                pre.append(Atom(OCCUPIED, (state,)))
                continue
            pre.append(Atom(IS, (var, state)))
            if lane is not None:
                pre.append(Atom(LANE, (var, state, const[r.after] if r.changes else state)))
            if r.changes:
                delete.append(Atom(IS, (var, state)))
                add.append(Atom(IS, (var, const[r.after])))
                if r.after in stable:
                    add.append(Atom(OCCUPIED, (const[r.after],)))
            same = (r.label, state)
            if same in first:
                pre.append(Atom(PRECEDES, (first[same], var)))
                precede.add(r.label)
            first[same] = var
        actions.append(Action(
            table.name(f"{unit.motion.label} u{u}", key=("unit", u)),
            pre=tuple(pre), add=tuple(add), delete=tuple(delete),
            params=tuple((var, type_of[r.label]) for var, r, b in zip(params, roles, bound, strict=True) if b),
            cost=unit_cost(unit, options.costs, options.rates), unit=u, comment=unit_comment(unit, u),
            roles=tuple(zip(roles, bound, strict=True)),
        ))
    actions.extend(goal_actions_over_objects(inp.candidates, stable, table, const, type_of, options))
    init.extend(precedes_facts(precede, instances))
    predicates = [Predicate(IS, (("?x", ROOT_TYPE), ("?s", STATE_TYPE)), "?x is in the state of FOON node ?s"),
                  Predicate(OCCUPIED, (("?s", STATE_TYPE),), "some instance is in state ?s, which no action leaves"),
                  Predicate(GOAL_REACHED, comment="a goal candidate was made")]
    if precede:
        predicates.append(Predicate(PRECEDES, (("?a", ROOT_TYPE), ("?b", ROOT_TYPE)),
                                    "static order of the instances of a label: binds two roles to two instances"))
    if lane is not None:
        predicates.append(Predicate(LANE, (("?x", ROOT_TYPE), ("?s", STATE_TYPE), ("?t", STATE_TYPE)),
                                    "static: ?x's path in the unfolded plan goes from state ?s to ?t (or is in ?s=?t)"))
        predicates.append(Predicate(TOGETHER, (("?a", ROOT_TYPE), ("?b", ROOT_TYPE)),
                                    "static: ?a and ?b change state in one firing of the unfolded plan"))
    return flat_typed(PlanningTask(
        domain="foon-instances",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="instances",
        level=inp.level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=tuple(sorted(init)),
        goal=(Atom(GOAL_REACHED),),
        types=tuple(types),
        constants=tuple((name, STATE_TYPE) for name in (NOT_MADE, *const.values())),
        objects=tuple((x.name, type_of[x.label]) for x in instances),
        units=f.units,
        labels=table.labels,
        comments=header("instances", inp, options, len(units)) + count_lines(counts)
        + tuple(f"objects: {w}" for w in count_reasons(f, counts, inp.kitchen, given=kitchen.project(level),
                                                        instances=dict(options.instances), encoding="instances"))
        + (("lanes: each instance changes state only as in the unfolded plan",) if lane is not None else ()),
        instances=tuple(instances),
    ))


def _instances(table: NameTable, counts: InstanceCounts,
               const: dict[ObjectNode, str]) -> tuple[list[Instance], list[Atom], set[str]]:
    """Instance objects numbered per label (`instance_names.counted_objects`), their initial states."""
    instances = counted_objects(table, counts)
    return instances, [Atom(IS, (x.name, NOT_MADE if x.start is None else const[x.start])) for x in instances], set()


def count_lines(counts: InstanceCounts) -> tuple[str, ...]:
    labels = counts.labels()
    shown = ", ".join(f"{label} {k}" for label, k in list(labels.items())[:HEADER_LABELS])
    more = f", +{len(labels) - HEADER_LABELS} more labels" if len(labels) > HEADER_LABELS else ""
    return (f"instances: {counts.total} ({shown}{more})",)


def goal_actions_over_objects(candidates, stable, table: NameTable, const, type_of, options: EncodeOptions,
                              made_by_units: Collection[ObjectNode] = ()) -> list[Action]:
    """One `reach-goal-<i>` action per goal candidate: "some object is in the candidate's state" (through
    `(occupied s)` when the candidate's node is stable, else a parameter). Shared by the encodings over
    physical objects; kept even when no object can reach a candidate.

    `made_by_units`: the candidates some object starts in without the kitchen holding them (`relational`: a
    closed packet's chipotle starts as the `chipotle (dried, in [packet])` FOON makes by opening the packet):
    their actions also need `(goal-object ?x)`, a static fact the task gives the objects that do not start in
    it, so only a unit's product reaches the goal."""
    out = []
    for i, c in enumerate(candidates, start=1):
        stable_goal = c in stable and c not in made_by_units
        pre = (Atom(OCCUPIED, (const[c],)),) if stable_goal else (Atom(IS, ("?x", const[c])),)
        out.append(Action(
            table.name(f"reach-goal-{i}", key=("goal-action", i)),
            pre=pre + ((Atom(GOAL_OBJECT, ("?x",)),) if c in made_by_units else ()),
            add=(Atom(GOAL_REACHED),), params=() if stable_goal else (("?x", type_of[c.label]),),
            cost=goal_cost(options.costs), comment=(f"goal candidate {i}: {c.describe()}",), candidate=c,
        ))
    return out


def precedes_facts(labels, instances) -> list[Atom]:
    """`(precedes a b)` for every ordered pair of objects of each label in `labels` (instance order)."""
    out = []
    for label in sorted(labels):
        mine = [x.name for x in instances if x.label == label]
        out.extend(Atom(PRECEDES, (a, b)) for k, a in enumerate(mine) for b in mine[k + 1:])
    return out
