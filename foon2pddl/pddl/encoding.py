"""What every encoding shares: inputs at one level, options, comments, goal actions.

An encoding is a pure function `(foon, kitchen, goal, level, options) -> PlanningTask`;
this module brings its inputs to one hierarchy level (`at_level`), picks the
units and nodes a node-proposition encoding compiles (`select`, pruned or not)
and writes the parts that do not depend on the encoding (header and per-action
comments, the auxiliary actions for a goal with several candidate nodes).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..analysis.index import FoonIndex, index_of
from ..errors import UsageError
from ..generalize.categories import CategoryIndex
from ..io.rates import Rates
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.levels import check_level, project, project_node
from ..model.where import short_path, source_where
from ..model.words import count, first_of
from .costs import check_costs, goal_cost, unit_cost
from .names import NameTable
from .prune import relevant_units
from .task import Action, Atom

#: Name of the 0-ary predicate (tree, state) auxiliary goal actions make true.
GOAL_REACHED = "goal-reached"

#: Longest unit description written into an action comment.
DESCRIBE_MAX = 240


@dataclass(frozen=True)
class EncodeOptions:
    """How to encode: relevance pruning, cost mode (None, `unit`, `success-rate`) and motion rates.

    The `instances` encoding also reads `instances` (label -> instances per starting place,
    overriding derived counts) and `categories` (label -> its category chain, most specific
    first, for PDDL supertypes; given as data, so the encoders need no category index).
    Lifted encodings also take the category index (`category_index`, None: the shipped one)
    and which categorized objects become parameters (`policy`, see `encode_lifted.generalizer`).
    The `relational` encoding counts its objects small when `narrow` (`relational_objects.task_objects`), from the
    plan through the stitches alone with `through`, with makers by holder reach with `placed`, and wide from FOON's
    own plan unfolded, no plan with another maker of a node, with `own` (what `plan` falls back on last); `memo`, a
    dict one caller passes to each encoding of one goal (`compile.compile_goal`'s), lets it read the network and
    derive each count once across them (None: nothing is shared).
    """

    prune: bool = True
    costs: str | None = None
    rates: Rates | None = None
    instances: tuple[tuple[str, int], ...] = ()
    categories: tuple[tuple[str, tuple[str, ...]], ...] = ()
    category_index: CategoryIndex | None = field(default=None, compare=False)
    policy: str = "absent"
    narrow: bool = False
    through: bool = False
    placed: bool = False
    memo: dict | None = field(default=None, compare=False, repr=False)
    own: bool = False

    def __post_init__(self) -> None:
        check_costs(self.costs, self.rates)


DEFAULT_OPTIONS = EncodeOptions()


@dataclass(frozen=True)
class LevelInputs:
    """Network, kitchen nodes and goal candidates, all at one level."""

    foon: Foon
    kitchen: frozenset[ObjectNode]
    candidates: tuple[ObjectNode, ...]
    level: int
    goal: Goal
    kitchen_source: str


def at_level(foon: Foon, kitchen: Kitchen, goal: Goal, level: int) -> LevelInputs:
    """Project network, kitchen and goal to `level` (none of them may be coarser than `level`)."""
    check_level(level)
    for what, have in (("network", foon.level), ("kitchen", kitchen.level), ("goal", goal.level)):
        if have < level:
            raise UsageError(f"the {what} is at level {have}, cannot encode it at level {level}")
    candidates = tuple(sorted({project_node(c, level) for c in goal.candidates}))
    if not candidates:
        raise UsageError(f"goal {goal.describe()!r} has no candidate node")
    projected = project(foon, level)
    ix = index_of(projected)
    missing = [c for c in candidates if c not in ix.node_id]
    if missing:
        raise UsageError(f"goal candidate {missing[0].describe()!r} is not a node of the network")
    return LevelInputs(projected, kitchen.project(level).nodes, candidates, level, goal, kitchen.source)


@dataclass(frozen=True)
class Selection:
    """What a node-proposition encoding compiles: unit indexes and node ids (`index` ids), sorted."""

    index: FoonIndex
    units: tuple[int, ...]
    nodes: tuple[int, ...]
    candidates: tuple[int, ...]
    kitchen: tuple[int, ...]  # kitchen nodes among `nodes`


def select(inp: LevelInputs, prune: bool) -> Selection:
    """The units to compile (all, or the relevant ones) and the nodes they and the goal mention."""
    ix = index_of(inp.foon)
    candidates = tuple(ix.ids(inp.candidates))
    if prune:
        units = relevant_units(inp.foon, inp.kitchen, inp.candidates)
        used = set(candidates)
        for u in units:
            used.update(ix.inputs[u])
            used.update(ix.outputs[u])
        nodes = tuple(sorted(used))
    else:
        units = tuple(range(len(inp.foon.units)))
        nodes = tuple(range(len(ix.nodes)))
    chosen = set(nodes)
    return Selection(ix, units, nodes, candidates, tuple(i for i in ix.ids(inp.kitchen) if i in chosen))


def unit_comment(unit: FunctionalUnit, index: int) -> tuple[str, ...]:
    """Comment lines of a unit's action: index, motion, source recipe files and lines, what it does."""
    places = first_of(unit.sources, 3, lambda s: source_where(s, short_path), sep=", ")
    motion = unit.motion.label + ("*" if unit.motion.composite else "")
    first = f"unit {index}: {motion}" + (f" from {places}" if places else "")
    text = unit.describe()
    if len(text) > DESCRIBE_MAX:
        text = text[: DESCRIBE_MAX - 3] + "..."
    return (first, text)


def goal_kitchen_lines(goal: str, candidates: int, kitchen_source: str | None, kitchen_nodes: int) -> tuple[str, str]:
    """The header's goal and kitchen lines (every encoding's): file names only, counts with their noun."""
    return (f"goal: {goal} ({count(candidates, 'candidate node')})",
            f"kitchen: {(short_path(kitchen_source) if kitchen_source else '') or 'given'} ({count(kitchen_nodes, 'node')})")


def units_kept(kept: int, total: int, prune: bool) -> str:
    """The header's words for the units compiled of the network's `total` (every encoding's)."""
    return f"{kept} of {count(total, 'unit')} after relevance pruning" if prune else f"all {count(total, 'unit')}"


def header(encoding: str, inp: LevelInputs, options: EncodeOptions, kept: int) -> tuple[str, ...]:
    """Header comment lines shared by the domain and problem files."""
    lines = [f"foon2pddl, encoding {encoding}, level {inp.level}: {units_kept(kept, len(inp.foon.units), options.prune)}",
             *goal_kitchen_lines(inp.goal.describe(), len(inp.candidates), inp.kitchen_source, len(inp.kitchen))]
    return (*lines, *cost_lines(options))


def cost_lines(options: EncodeOptions) -> tuple[str, ...]:
    """The header's action-costs line (none without costs), the rates file by its name."""
    if not options.costs:
        return ()
    costs = options.costs
    if options.costs == "success-rate" and options.rates is not None:
        costs += f" (rates: {short_path(options.rates.source) or 'given'})"
    return (f"action costs: {costs}",)


def goal_actions(
    table: NameTable, candidate_atoms: list[tuple[ObjectNode, tuple[Atom, ...]]], goal_atom: Atom,
    options: EncodeOptions,
) -> tuple[Action, ...]:
    """One auxiliary action per candidate: its atoms -> `goal_atom` (unit None, cost 0)."""
    actions = []
    for i, (node, atoms) in enumerate(candidate_atoms, start=1):
        name = table.name(f"reach-goal-{i}", key=("goal-action", i))
        actions.append(Action(name, atoms, (goal_atom,), cost=goal_cost(options.costs), unit=None,
                              comment=(f"goal candidate {i}: {node.describe()}",), candidate=node))
    return tuple(actions)


def unit_actions(foon: Foon, sel: Selection, atom: dict[int, Atom], name: Callable[[int, FunctionalUnit], str],
                 options: EncodeOptions) -> list[Action]:
    """One delete-free action per selected unit: its input nodes' atoms as precondition, its outputs' as effect.

    Shared by the node-proposition encodings (`tree`, `foon-compat`), which differ only in
    how a node becomes an atom and how an action is named (`name(index, unit)`, called in
    unit order so names are assigned deterministically).
    """
    ix = sel.index
    actions = []
    for i in sel.units:
        u = foon.units[i]
        actions.append(Action(
            name(i, u),
            pre=tuple(atom[n] for n in ix.inputs[i]),
            add=tuple(atom[n] for n in ix.outputs[i]),
            cost=unit_cost(u, options.costs, options.rates),
            unit=i,
            comment=unit_comment(u, i),
        ))
    return actions
