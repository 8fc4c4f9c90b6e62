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
grounded unit, so a valid plan maps back (`degeneralize.py`) to concrete units
whose inputs are each in the kitchen or made before: a task tree that
`tasktree.validate` accepts at the concrete level. The encoding is incomplete
where a grounded action orders two same-category objects of one node
differently from the action that needs the node.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass

from ..analysis.reachability import reachable
from ..errors import UsageError
from ..model.foon import Foon, FunctionalUnit, ObjectNode, dedupe_units, make_node, make_state
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.levels import project, project_node
from ..pddl.encoding import GOAL_REACHED, EncodeOptions, goal_actions, unit_comment
from ..pddl.names import NameTable
from ..pddl.task import Action, Atom, PlanningTask, Predicate
from .categories import CategoryIndex
from .relevance import Ordering, coarse_network, input_labels, mentioned, relevant, shared_coarse
from .substitute import substitute_unit, unit_labels

#: The root of the category types: objects in no category have it, predicates take it (some PDDL
#: parsers reject `object` written out as a parameter type).
ROOT_TYPE = "kitchen-object"

#: Most atoms written for one kitchen node or goal candidate (orderings of same-category objects).
MAX_REPRESENTATIONS = 24

# A node shape: arity, then per state (label, related position or -1, ingredient positions).
Shape = tuple[int, tuple[tuple[str, int, tuple[int, ...]], ...]]


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
    """Lifted units of `foon`, one per class of units equal up to their parameters (first kept)."""
    kept: dict[tuple, LiftedUnit] = {}
    for u in foon.units:
        lifted, key = lift_unit(u, index, generalize)
        first = kept.get(key)
        if first is None:
            kept[key] = lifted
        else:
            merged = FunctionalUnit(first.unit.inputs, first.unit.motion, first.unit.outputs,
                                    first.unit.sources + u.sources)
            kept[key] = LiftedUnit(merged, first.params)
    return tuple(kept.values())


def shape_with(node: ObjectNode, order: list[str]) -> Shape:
    """The shape of `node` when its mentioned labels take positions 1.. in `order`."""
    pos = {node.label: 0, **{label: i for i, label in enumerate(order, start=1)}}
    states = tuple(sorted((s.label, pos[s.related] if s.related else -1, tuple(sorted(pos[i] for i in s.ingredients)))
                          for s in node.states))
    return (len(order) + 1, states)


def node_atom_labels(node: ObjectNode, ordering: Ordering) -> tuple[Shape, tuple[str, ...]]:
    """The canonical (shape, argument labels) of `node`."""
    order = sorted(mentioned(node), key=ordering.key)
    return shape_with(node, order), (node.label, *order)


def representations(node: ObjectNode, ordering: Ordering, shapes: set[Shape]) -> list[tuple[Shape, tuple[str, ...]]]:
    """Every (shape in `shapes`, argument labels) that reconstructs `node`, same-category objects in any order."""
    order = sorted(mentioned(node), key=ordering.key)
    groups = [list(g) for _, g in itertools.groupby(order, key=ordering.root)]
    out: list[tuple[Shape, tuple[str, ...]]] = []
    for combo in itertools.islice(itertools.product(*(itertools.permutations(g) for g in groups)),
                                  MAX_REPRESENTATIONS):
        labels = [x for part in combo for x in part]
        shape = shape_with(node, labels)
        if shape in shapes:
            out.append((shape, (node.label, *labels)))
    return out


def node_of(shape: Shape, labels: tuple[str, ...]) -> ObjectNode:
    """The node an atom of `shape` with argument `labels` stands for."""
    states = [make_state(s, labels[r] if r >= 0 else "", (labels[i] for i in ings)) for s, r, ings in shape[1]]
    return make_node(labels[0], states)


def shape_label(shape: Shape) -> str:
    """Readable text naming a shape (`contains {1} in [2]`), the base of its predicate name."""
    parts = []
    for s, r, ings in shape[1]:
        text = s + (f" [{r}]" if r >= 0 else "") + (" {" + " ".join(map(str, ings)) + "}" if ings else "")
        parts.append(text)
    return "node " + (", ".join(parts) if parts else "plain") + f" /{shape[0]}"


@dataclass(frozen=True)
class LiftedTask:
    """The PDDL task and what decoding its plans needs."""

    task: PlanningTask
    lifted: tuple[LiftedUnit, ...]  # Action.unit indexes this
    level: int
    shapes: dict[str, Shape]  # predicate name -> shape
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


def encode_lifted(foon: Foon, kitchen: Kitchen, goal: Goal, index: CategoryIndex, level: int = 3, *,
                  prune: bool = True, policy: str = "absent") -> LiftedTask:
    """The lifted FOON-GEN task for `goal` from `kitchen` over the concrete network `foon` (see the module doc)."""
    f = project(foon, level)
    kitchen_nodes = kitchen.project(level).nodes
    candidates = tuple(sorted({project_node(c, level) for c in goal.candidates}))
    ordering = Ordering(index)
    generalize = generalizer(policy, f, kitchen_nodes)
    if prune:
        coarse = shared_coarse(foon, level, kitchen_nodes, policy, index,
                                lambda: coarse_network(f, kitchen_nodes, generalize, index, ordering))
        f = Foon(tuple(f.units[i] for i in relevant(f, kitchen_nodes, candidates, generalize, index, ordering,
                                                     coarse)), level)
    lifted = lift(Foon(dedupe_units(f.units), level), index, generalize)

    table = NameTable()
    table.reserve(GOAL_REACHED, "goal reached")
    table.reserve(ROOT_TYPE, "any kitchen object")
    types: dict[str, str] = {}  # category -> type name

    def type_of(cat: str | None) -> str:
        if cat is None:
            return ROOT_TYPE
        if cat not in types:
            for c in (*reversed(index.ancestors(cat)), cat):
                if c not in types:
                    types[c] = table.name(c, key=("type", c))
        return types[cat]

    def obj(label: str) -> str:
        return table.name(label, key=("object", label))

    shape_names: dict[Shape, str] = {}

    def predicate(shape: Shape) -> str:
        if shape not in shape_names:
            shape_names[shape] = table.name(shape_label(shape), key=("shape", shape))
        return shape_names[shape]

    def atom(node: ObjectNode, var: dict[str, str]) -> Atom:
        """The atom of a unit's node: parameters for the labels in `var`, constants for the others."""
        shape, labels = node_atom_labels(node, ordering)
        return Atom(predicate(shape), tuple(var.get(x) or obj(x) for x in labels))

    actions: list[Action] = []
    constants: set[str] = set()
    pre_shapes: set[Shape] = set()
    for i, lu in enumerate(lifted):
        vars_ = NameTable()
        var = {label: "?" + vars_.name(f"{cat} {k}", key=label)
               for k, (label, cat) in enumerate(lu.params, start=1)}
        constants |= lu.constants
        pre = tuple(dict.fromkeys(atom(n, var) for n in lu.unit.inputs))
        pre_shapes.update(node_atom_labels(n, ordering)[0] for n in lu.unit.inputs)
        add = tuple(dict.fromkeys(atom(n, var) for n in lu.unit.outputs))
        actions.append(Action(
            table.name(f"{lu.unit.motion.label} g{i}", key=("unit", i)), pre, add,
            params=tuple((var[label], type_of(cat)) for label, cat in lu.params),
            unit=i, comment=unit_comment(lu.unit, i)))
    add_shapes = {node_atom_labels(n, ordering)[0] for lu in lifted for n in lu.unit.outputs}

    goal_reps = [(c, representations(c, ordering, add_shapes | pre_shapes)) for c in candidates]
    init_shapes = pre_shapes | {s for _, reps in goal_reps for s, _ in reps}
    init = sorted({Atom(predicate(s), tuple(obj(x) for x in labels))
                   for n in kitchen_nodes for s, labels in representations(n, ordering, init_shapes)})
    atoms = [(c, (Atom(predicate(s), tuple(obj(x) for x in labels)),)) for c, reps in goal_reps for s, labels in reps]
    if len(atoms) == 1:
        goal_atoms: tuple[Atom, ...] = atoms[0][1]
    else:  # goal actions live in the domain: the objects they name must be constants
        constants |= {x for c, reps in goal_reps for _, labels in reps for x in labels}
        actions.extend(goal_actions(table, atoms, Atom(GOAL_REACHED), EncodeOptions(prune=False)))
        goal_atoms = (Atom(GOAL_REACHED),)

    labels = {x for lu in lifted for x in unit_labels(lu.unit)}
    labels |= {x for n in (*kitchen_nodes, *candidates) for x in (n.label, *mentioned(n))}
    declared = {label: (obj(label), type_of(index.choose(label))) for label in sorted(labels)}
    predicates = [Predicate(name, tuple((f"?x{k}", ROOT_TYPE) for k in range(shape[0])), comment=shape_label(shape))
                  for shape, name in sorted(shape_names.items(), key=lambda x: x[1])]
    if len(atoms) != 1:
        predicates.insert(0, Predicate(GOAL_REACHED, comment="a goal candidate was made"))
    task = PlanningTask(
        domain="foon-gen-lifted",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="gen-lifted",
        level=level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=tuple(init),
        goal=goal_atoms,
        types=((ROOT_TYPE, "object"),) + tuple((name, types[index.get(cat).parent] if index.get(cat).parent
                                                 else ROOT_TYPE) for cat, name in types.items()),
        objects=tuple(v for label, v in declared.items() if label not in constants),
        constants=tuple(v for label, v in declared.items() if label in constants),
        units=tuple(lu.unit for lu in lifted),
        labels=table.labels,
        comments=(f"foon2pddl, lifted FOON-GEN (categories as types), level {level}: "
                  f"{len(lifted)} lifted units from {len(f.units)} units",
                  f"goal: {goal.describe()} ({len(candidates)} candidate nodes)",
                  f"kitchen: {kitchen.source or 'given'} ({len(kitchen_nodes)} nodes)"),
    )
    return LiftedTask(task, lifted, level, {n: s for s, n in shape_names.items()},
                      {name: label for label, (name, _) in declared.items()})


def ground_unit(lt: LiftedTask, action_index: int, args: tuple[str, ...]) -> FunctionalUnit:
    """The concrete unit of lifted unit `action_index` with its parameters bound to the objects `args` (PDDL names)."""
    lu = lt.lifted[action_index]
    if len(args) != len(lu.params):
        raise ValueError(f"action of unit {action_index} takes {len(lu.params)} arguments, got {len(args)}")
    binding = {label: lt.objects[a] for (label, _), a in zip(lu.params, args, strict=True)}
    changed = {k: v for k, v in binding.items() if k != v}
    if not changed:
        return lu.unit
    note = "gen: " + ", ".join(f"{k} -> {v}" for k, v in sorted(changed.items()))
    return substitute_unit(lu.unit, binding, note=note)

