"""Lifted PDDL for FOON-GEN: categories are types, the planner grounds them to kitchen objects.

FOON-GEN on its own leaves a category-level task tree ("squeeze a citrus fruit")
that must be "de-generalized" before a robot can use it. Here the network stays
concrete and only its *parameters* are generalized:

* **Types.** Every category of the index used by an object becomes a PDDL type,
  a refined category a subtype of its parent (`object` for top-level ones).
  PDDL gives a type one parent, so an object listed in several categories is
  declared with its single chosen category (`CategoryIndex.choose`: the most
  specific, then file order); it is not also an instance of the others.
  Objects in no category are of type `kitchen-object`, the root of the category types.
* **Objects.** Every object label of the network and the kitchen is a PDDL
  object of its type; labels an action names as constants are domain constants.
* **Actions.** A functional unit becomes an action with one parameter per
  categorized object among its *inputs* (node labels, related objects and
  ingredients of input nodes), typed with that object's category; objects that
  only appear among its outputs (what it makes: `lemon juice`) stay constants.
  Units equal up to those parameters are one action (`lift`). Which objects
  become parameters is a policy (`generalizer`): by default (`absent`) those no
  kitchen node has (a `lemon` when the kitchen has a `lime`); `all`
  parameterizes every categorized input object, which FD's translator cannot
  ground on the universal FOON within a minute.
* **Facts.** Node identity is kept: a node is one atom whose predicate encodes
  its *shape* (its states with the objects they mention replaced by argument
  positions) and whose arguments are the node's object then the objects its
  states mention, ordered by (top-level category, label). The planner is
  delete-free like FOON itself (`tree` encoding).
* **Kitchen and goal** stay concrete. A kitchen node becomes every atom that
  reconstructs it under a shape some action needs (objects of one top-level
  category may appear in any order, as a grounded action may order them
  differently); the goal is any such atom of any goal candidate.

Soundness: an atom determines its node (`node_of`), the initial atoms are those
of kitchen nodes and an action adds the atoms of the output nodes of the
grounded unit, so a valid plan maps back (`lifted_plans.ground_unit`) to concrete units
whose inputs are each in the kitchen or made before: a task tree that
`tasktree.validate` accepts at the concrete level. The encoding is incomplete
where a grounded action orders two same-category objects of one node
differently from the action that needs the node.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from ..analysis.reachability import reachable
from ..errors import UsageError
from ..generalize.categories import CategoryIndex
from ..generalize.grounding import ground, input_labels
from ..generalize.relevance import Ordering, relevant, shared_grounding
from ..generalize.substitute import substitute_unit, unit_labels
from ..model.constraints import node_labels
from ..model.dedupe import dedupe_units
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.levels import project, project_node
from .arg_types import narrow_arguments
from .costs import unit_cost
from .encoding import (
    DEFAULT_OPTIONS,
    GOAL_REACHED,
    EncodeOptions,
    cost_lines,
    goal_actions,
    goal_kitchen_lines,
    unit_comment,
    units_kept,
)
from .lifted_atoms import Family, Shape, family_label, node_atom_labels, representations, shape_label
from .names import NameTable
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["POLICIES", "ROOT_TYPE", "LiftedTask", "LiftedUnit", "encode_lifted", "generalizer", "lift", "lift_unit"]

#: The root of the category types: objects in no category have it, predicates take it (some PDDL
#: parsers reject `object` written out as a parameter type).
ROOT_TYPE = "kitchen-object"


@dataclass(frozen=True)
class LiftedUnit:
    """A unit with some objects as typed parameters: `params` are (label in `unit`, category)."""

    unit: FunctionalUnit
    params: tuple[tuple[str, str], ...]

    @property
    def constants(self) -> frozenset[str]:
        """Labels the unit names that are not parameters."""
        return unit_labels(self.unit) - {label for label, _ in self.params}


def lift_unit(unit: FunctionalUnit, index: CategoryIndex,
              generalize: Callable[[str], bool] = lambda label: True) -> tuple[LiftedUnit, tuple]:
    """The lifted unit and its duplicate key (the unit with parameters renamed by category and rank).

    Categorized input labels for which `generalize` holds become parameters.
    """
    by_cat: dict[str, list[str]] = {}
    for label in sorted(input_labels(unit)):
        cat = index.choose(label)
        if cat is not None and generalize(label):
            by_cat.setdefault(cat, []).append(label)
    params = tuple((label, cat) for cat in sorted(by_cat) for label in by_cat[cat])
    rename = {label: f"\x00{cat}\x00{k}" for cat in by_cat for k, label in enumerate(by_cat[cat])}
    return LiftedUnit(unit, params), substitute_unit(unit, rename).key


def lift(foon: Foon, index: CategoryIndex,
         generalize: Callable[[str], bool] = lambda label: True) -> tuple[LiftedUnit, ...]:
    """Lifted units of `foon`, one per class of units equal up to their parameters (first kept, sources joined)."""
    units = dedupe_units(foon.units, key=lambda u: lift_unit(u, index, generalize)[1])
    return tuple(lift_unit(u, index, generalize)[0] for u in units)


@dataclass(frozen=True)
class LiftedTask:
    """The PDDL task and what decoding its plans needs."""

    task: PlanningTask
    lifted: tuple[LiftedUnit, ...]  # Action.unit indexes this
    level: int
    families: dict[str, Family]  # predicate name -> (shape, objects folded in at fixed positions)
    objects: dict[str, str]  # PDDL object/constant name -> label


def made_labels(foon: Foon) -> frozenset[str]:
    """Labels of objects some unit makes (an output node whose label none of the unit's inputs mentions)."""
    out: set[str] = set()
    for u in foon.units:
        seen = input_labels(u)
        out.update(n.label for n in u.outputs if n.label not in seen)
    return frozenset(out)


#: Which categorized objects become parameters (see `generalizer`).
POLICIES = ("absent", "missing", "blocked", "all")


def generalizer(policy: str, foon: Foon, kitchen_nodes: frozenset[ObjectNode]) -> Callable[[str], bool]:
    """Which categorized labels become parameters, by policy:

    - `absent` (default): objects no kitchen node has (a `lemon` when the kitchen has a
      `lime`; intermediate products such as `lemon juice`, so another juice may stand in);
    - `missing`: only the absent objects that no unit makes (raw ingredients and tools);
    - `blocked`: objects of input nodes the concrete network cannot make from the kitchen;
    - `all`: every categorized input object.

    A parameter that a kitchen object already fills only multiplies the ground actions:
    on the universal FOON with its default kitchen, FD's translator grounds `absent` and
    `missing` in about a second and times out (60 s) with `blocked` and `all`.
    """
    if policy not in POLICIES:
        raise UsageError(f"generalization policy must be one of {', '.join(POLICIES)}, not {policy!r}")
    if policy == "all":
        return lambda label: True
    if policy == "blocked":
        reach = reachable(foon, kitchen_nodes)
        blocked = {n.label for u in foon.units for n in u.inputs if not reach.can_make(n)}
        return lambda label: label in blocked
    have = {n.label for n in kitchen_nodes}
    if policy == "absent":
        return lambda label: label not in have
    made = made_labels(foon)
    return lambda label: label not in have and label not in made


class _Names:
    """PDDL names of the lifted task: types (categories), objects (labels) and predicates (families).

    A node atom's predicate is its shape with the objects at the positions no action binds to a
    parameter (`free`) folded in, so it keeps only the parameter positions as arguments."""

    def __init__(self, index: CategoryIndex, ordering: Ordering) -> None:
        self.index = index
        self.ordering = ordering
        self.table = NameTable()
        self.table.reserve(GOAL_REACHED, "goal reached")
        self.table.reserve(ROOT_TYPE, "any kitchen object")
        self.types: dict[str, str] = {}  # category -> type name
        self.families: dict[Family, str] = {}  # (shape, fixed objects) -> predicate name
        self.free: dict[Shape, tuple[int, ...]] = {}  # shape -> positions some action binds to a parameter

    def type_of(self, cat: str | None) -> str:
        """The type of a category (its ancestors named first), ROOT_TYPE for none."""
        if cat is None:
            return ROOT_TYPE
        if cat not in self.types:
            for c in (*reversed(self.index.ancestors(cat)), cat):
                if c not in self.types:
                    self.types[c] = self.table.name(c, key=("type", c))
        return self.types[cat]

    def obj(self, label: str) -> str:
        return self.table.name(label, key=("object", label))

    def predicate(self, shape: Shape, labels: tuple[str, ...]) -> tuple[str, tuple[int, ...]]:
        """The predicate of an atom of `shape` over `labels`, and the positions it keeps as arguments."""
        free = self.free.get(shape, ())
        family = (shape, tuple((i, x) for i, x in enumerate(labels) if i not in free))
        if family not in self.families:
            self.families[family] = self.table.name(family_label(*family), key=("shape", family))
        return self.families[family], free

    def atom(self, node: ObjectNode, var: dict[str, str]) -> Atom:
        """The atom of a unit's node: parameters for the labels in `var`, constants for the others."""
        shape, labels = node_atom_labels(node, self.ordering)
        name, free = self.predicate(shape, labels)
        return Atom(name, tuple(var.get(labels[i]) or self.obj(labels[i]) for i in free))

    def ground_atom(self, shape: Shape, labels: tuple[str, ...]) -> Atom:
        name, free = self.predicate(shape, labels)
        return Atom(name, tuple(self.obj(labels[i]) for i in free))

    def type_pairs(self) -> tuple[tuple[str, str], ...]:
        """(type, parent type) of every declared type, the root first."""
        parent = {name: self.types[self.index.get(cat).parent] if self.index.get(cat).parent else ROOT_TYPE
                  for cat, name in self.types.items()}
        return ((ROOT_TYPE, "object"), *parent.items())


def _unit_actions(lifted: tuple[LiftedUnit, ...], names: _Names, options: EncodeOptions
                  ) -> tuple[list[Action], set[str], set[Shape]]:
    """One action per lifted unit; the labels actions name as constants; the shapes preconditions use."""
    actions: list[Action] = []
    constants: set[str] = set()
    pre_shapes: set[Shape] = set()
    free: dict[Shape, set[int]] = {}
    for lu in lifted:
        bound = {label for label, _ in lu.params}
        for n in (*lu.unit.inputs, *lu.unit.outputs):
            shape, labels = node_atom_labels(n, names.ordering)
            free.setdefault(shape, set()).update(k for k, x in enumerate(labels) if x in bound)
    names.free = {shape: tuple(sorted(ks)) for shape, ks in free.items()}
    for i, lu in enumerate(lifted):
        vars_ = NameTable()
        var = {label: "?" + vars_.name(f"{cat} {k}", key=label) for k, (label, cat) in enumerate(lu.params, start=1)}
        constants |= lu.constants
        pre = tuple(dict.fromkeys(names.atom(n, var) for n in lu.unit.inputs))
        pre_shapes.update(node_atom_labels(n, names.ordering)[0] for n in lu.unit.inputs)
        add = tuple(dict.fromkeys(names.atom(n, var) for n in lu.unit.outputs))
        actions.append(Action(
            names.table.name(f"{lu.unit.motion.label} g{i}", key=("unit", i)), pre, add,
            params=tuple((var[label], names.type_of(cat)) for label, cat in lu.params),
            cost=unit_cost(lu.unit, options.costs, options.rates), unit=i, comment=unit_comment(lu.unit, i)))
    return actions, constants, pre_shapes


def _drop_static(actions: list[Action], init: frozenset[Atom]) -> list[Action]:
    """`actions` without ground preconditions true in `init` whose predicate no action deletes (O(atoms)).

    They always hold, so plans and their map back are unchanged; some planners (ENHSP) mishandle a
    parameterised action with such a variable-free precondition.
    """
    deleted = {d.predicate for a in actions for d in a.delete}

    def static(p: Atom) -> bool:
        return p in init and p.predicate not in deleted and not any(x.startswith("?") for x in p.args)

    return [replace(a, pre=tuple(p for p in a.pre if not static(p))) if any(map(static, a.pre)) else a
            for a in actions]


def encode_lifted(foon: Foon, kitchen: Kitchen, goal: Goal, index: CategoryIndex, level: int = 3, *,
                  prune: bool = True, policy: str = "absent", options: EncodeOptions = DEFAULT_OPTIONS) -> LiftedTask:
    """The lifted FOON-GEN task for `goal` from `kitchen` over the concrete network `foon` (see the module doc);
    `options` gives the action costs (`costs.unit_cost` of each lifted unit's first unit, goal actions 0)."""
    f = project(foon, level)
    total = len(f.units)
    kitchen_nodes = kitchen.project(level).nodes
    candidates = tuple(sorted({project_node(c, level) for c in goal.candidates}))
    ordering = Ordering(index)
    generalize = generalizer(policy, f, kitchen_nodes)
    if prune:
        grounded = shared_grounding(foon, level, kitchen_nodes, policy, index,
                                    lambda: ground(f, kitchen_nodes, generalize, index))
        f = Foon(tuple(f.units[i] for i in relevant(f, kitchen_nodes, candidates, generalize, index, grounded)),
                 level)
    lifted = lift(Foon(dedupe_units(f.units), level), index, generalize)
    names = _Names(index, ordering)
    actions, constants, pre_shapes = _unit_actions(lifted, names, options)
    add_shapes = {node_atom_labels(n, ordering)[0] for lu in lifted for n in lu.unit.outputs}

    held = {node_atom_labels(c, ordering)[0] for c in candidates if c in kitchen_nodes}  # no action need make them
    goal_reps = [(c, representations(c, ordering, add_shapes | pre_shapes | held)) for c in candidates]
    init_shapes = pre_shapes | {s for _, reps in goal_reps for s, _ in reps}
    atoms = [(c, (names.ground_atom(s, labels),)) for c, reps in goal_reps for s, labels in reps]
    wanted = {p.predicate for a in actions for p in a.pre} | {x.predicate for _, xs in atoms for x in xs}
    init = sorted(x for x in {names.ground_atom(s, labels) for n in kitchen_nodes
                              for s, labels in representations(n, ordering, init_shapes)} if x.predicate in wanted)
    actions = _drop_static(actions, frozenset(init))
    if len(atoms) == 1:
        goal_atoms: tuple[Atom, ...] = atoms[0][1]
    else:  # goal actions live in the domain: the objects they name must be constants
        constants |= {x for c, reps in goal_reps for _, labels in reps for x in labels}
        actions.extend(goal_actions(names.table, atoms, Atom(GOAL_REACHED), options))
        goal_atoms = (Atom(GOAL_REACHED),)

    labels = {x for lu in lifted for x in unit_labels(lu.unit)}
    labels |= {x for n in (*kitchen_nodes, *candidates) for x in node_labels(n)}
    declared = {label: (names.obj(label), names.type_of(index.choose(label))) for label in sorted(labels)}
    used = {x.predicate for x in (*init, *goal_atoms)} | {x.predicate for a in actions for x in (*a.pre, *a.add)}
    predicates = [Predicate(name, tuple((f"?x{k}", ROOT_TYPE) for k in names.free.get(family[0], ())),
                            comment=shape_label(family[0]))
                  for family, name in sorted(names.families.items(), key=lambda x: x[1]) if name in used]
    if len(atoms) != 1:
        predicates.insert(0, Predicate(GOAL_REACHED, comment="a goal candidate was made"))
    task = PlanningTask(
        domain="foon-gen-lifted",
        problem=names.table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="gen-lifted",
        level=level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=tuple(init),
        goal=goal_atoms,
        types=names.type_pairs(),
        objects=tuple(v for label, v in declared.items() if label not in constants),
        constants=tuple(v for label, v in declared.items() if label in constants),
        units=tuple(lu.unit for lu in lifted),
        labels=names.table.labels,
        comments=(f"foon2pddl, lifted FOON-GEN (categories as types), level {level}: "
                  f"{len(lifted)} lifted units from {units_kept(len(f.units), total, prune)}",
                  *goal_kitchen_lines(goal.describe(), len(candidates), kitchen.source, len(kitchen_nodes)),
                  *cost_lines(options)),
    )
    return LiftedTask(narrow_arguments(task), lifted, level, {n: s for s, n in names.families.items()},
                      {name: label for label, (name, _) in declared.items()})

