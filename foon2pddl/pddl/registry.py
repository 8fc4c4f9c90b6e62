"""What an encoding returns and how it is registered: a task plus the map from plan steps back to units.

In the spirit of unified-planning's compilers (a compiled problem plus a map
back to the original), every encoding turns (network, kitchen, goal, level,
options) into a `Compiled`: the `PlanningTask`, how a plan step (an action with
its arguments) maps back to a functional unit, and whether the task has FOON's
semantics (then a valid plan is also a task tree that FOON simulation accepts).
`compile.ENCODINGS` is the one registry of encodings by name. An encoding over
physical objects also carries its hooks: `replay` (plan steps ->
`model.physical.PhysicalTrace`, the plan object by object) and `view` (how that
trace is printed, `trace_view.TraceView`); `planners.decode` and the CLI call
them and never test an encoding's name.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from ..errors import PlanDecodeError
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.physical import PhysicalTrace
from ..model.tasktree import TaskTree
from .encoding import EncodeOptions
from .task import Action, PlanningTask
from .trace_view import TraceView

__all__ = ["Compiled", "Encoder", "Encoding", "Ground", "PlanDecodeError", "Replay"]

#: (unit index of an action, the plan step's arguments) -> the functional unit the step stands for.
Ground = Callable[[int, tuple[str, ...]], FunctionalUnit]


#: (task, plan steps) -> the plan as a physical trace (PlanDecodeError for a step that does not fit).
Replay = Callable[[PlanningTask, Sequence[str]], PhysicalTrace]


@dataclass(frozen=True)
class Compiled:
    """A planning task and how its plans map back to functional units.

    `ground(unit, args)` gives the unit of an action whose `Action.unit` is `unit`
    applied to the PDDL objects `args`; None means the actions are ground, and the
    unit is `task.units[unit]` (`ground` raises PlanDecodeError for arguments that
    do not fit). `foon_semantics`: a valid plan is a FOON task tree. `every_step`:
    every plan step is a real firing (a unit may fire again on other objects), so the
    tree keeps them all instead of justifying it down to what the goal needs.
    `replay`, `view`, `holders`: the encoding's trace hooks (`Encoding`), None for encodings
    with no physical objects.
    """

    task: PlanningTask
    foon_semantics: bool = True
    ground: Ground | None = None
    #: (tree, plan steps, kitchen nodes) -> the tree to report (the lifted encoding renames what a
    #: substituted object made after it); None: the tree as decoded.
    finish: Callable[[TaskTree, Sequence[str], frozenset[ObjectNode]], TaskTree] | None = None
    every_step: bool = False
    notes: tuple[str, ...] = ()  # what the encoder reports once per task (label mismatches)
    replay: Replay | None = None
    view: TraceView | None = None
    holders: bool = False
    #: nodes the encoding starts objects in that the kitchen's own nodes imply: a kitchen node where a kitchen
    #: holder says it is (`skillet (empty, on [stove])` for `skillet (empty)` and `stove (off, with
    #: [skillet])`), and a holder a kitchen node is in (`stove (on, with [pot])` under `pot (heated, on
    #: [stove])`); the kitchen the tree is checked from includes them
    placed: frozenset[ObjectNode] = frozenset()
    #: what the encoder counted small, as a note (`EncodeOptions.narrow`); empty when its counts are the wide
    #: ones: then no wider task has more objects (`planners.solve.plan` plans the wide one when this has no plan)
    narrowed: str = ""
    #: the units of the plan the encoder counted its objects from (`relational`: FOON's own plan unfolded, as
    #: `Action.unit` indexes); `planners.solve.plan` plans with them alone first. Empty: not known
    counted: frozenset[int] = frozenset()

    def unit_of(self, action: Action, args: tuple[str, ...] = ()) -> FunctionalUnit | None:
        """The functional unit a plan step of `action` with `args` stands for (None for auxiliary actions)."""
        if action.unit is None:
            return None
        if self.ground is None:
            return self.task.units[action.unit]
        return self.ground(action.unit, args)


#: An encoder: (network, kitchen, goal, level, options) -> the task, or the compiled task when its
#: plans need more than `Action.unit` to map back (parameters bound to objects).
Encoder = Callable[[Foon, Kitchen, Goal, int, EncodeOptions], "PlanningTask | Compiled"]


@dataclass(frozen=True)
class Encoding:
    """A registered encoding: its name, its encoder and what it promises and supports.

    `foon_semantics`: its valid plans are FOON task trees; `costs`: it honours
    `EncodeOptions.costs`; `lifted`: objects are typed parameters over categories
    (from `EncodeOptions.categories`, or the shipped index), so plans name the
    objects the planner chose; `every_step`: see `Compiled`. `replay`: plan steps -> the
    plan's `PhysicalTrace` (None: the encoding has no physical objects); `view`: how the
    trace is printed; `holders`: the trace's holders are modelled (not all None), so the
    relational replay applies to it. `complete`: it solves every goal FOON's delete-free
    semantics solves (an encoding with more physical rules can fail where FOON's data has gaps).
    `kitchen_init`: unpruned, the kitchen changes only the initial state, which holds each kitchen
    node's goal atoms (so a task compiled from one kitchen serves any kitchen within it with its
    initial state cut down: `planners.goal_replanner.GoalReplanner.for_kitchen`).
    """

    name: str
    encode: Encoder
    description: str
    foon_semantics: bool = True
    costs: bool = True
    lifted: bool = False
    every_step: bool = False
    replay: Replay | None = None
    view: TraceView | None = None
    holders: bool = False
    complete: bool = True
    kitchen_init: bool = False

    @property
    def physical(self) -> bool:
        """Its tasks are over physical objects (it reads `EncodeOptions.instances` and `categories`)."""
        return self.replay is not None

    def compile(self, foon: Foon, kitchen: Kitchen, goal: Goal, level: int, options: EncodeOptions) -> Compiled:
        """The compiled task (an encoder's bare `PlanningTask` has parameterless actions, one per unit)."""
        return self.wrap(self.encode(foon, kitchen, goal, level, options))

    def wrap(self, out: PlanningTask | Compiled) -> Compiled:
        """`out` with this encoding's promises and hooks."""
        hooks = {"replay": self.replay, "view": self.view, "holders": self.holders}
        if isinstance(out, Compiled):
            return replace(out, **hooks)
        return Compiled(out, self.foon_semantics, every_step=self.every_step, **hooks)
