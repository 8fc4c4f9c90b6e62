"""Plan with the lifted FOON-GEN task and map the plan back to a concrete, validated task tree.

Each plan step names a lifted unit's action and the kitchen objects the planner
bound its parameters to; substituting those objects into the unit (`lifted.ground_unit`)
gives a concrete functional unit. The units in plan order, with the first goal
candidate they make, form the task tree, checked by simulation from the concrete
kitchen (`tasktree.validate`) exactly like a native retrieval.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree, Validation, validate
from ..pddl.render import render
from ..planners import DEFAULT_PLANNER, PlanResult, run_planner
from ..planners.decode import PlanDecodeError, goal_node
from .categories import CategoryIndex
from .lifted import LiftedTask, encode_lifted, ground_unit
from .substitute import rename_derived, substitute_node, substitute_unit


@dataclass(frozen=True)
class LiftedOutcome:
    """The planner's result on the lifted task, the concrete tree of its plan and that tree's validation."""

    lifted: LiftedTask
    result: PlanResult
    tree: TaskTree | None = None
    validation: Validation | None = None
    decode_error: str = ""
    timings: dict[str, float] = field(default_factory=dict, compare=False, hash=False)

    @property
    def task(self):
        """The lifted PDDL task (as `pddl.solve.PlanOutcome.task`)."""
        return self.lifted.task

    @property
    def status(self) -> str:
        """The planner's status, or `error` when its plan does not map back to a valid tree."""
        if self.result.solved and (self.validation is None or not self.validation.ok):
            return "error"
        return self.result.status

    @property
    def message(self) -> str:
        if self.decode_error:
            return self.decode_error
        if self.result.solved and self.validation is not None and not self.validation.ok:
            return "plan does not validate: " + "; ".join(self.validation.problems[:3])
        return "" if self.result.solved else self.result.message


def plan_units(lt: LiftedTask, steps: Sequence[str]) -> tuple[FunctionalUnit, ...]:
    """The concrete units of a plan's steps (auxiliary goal actions skipped); PlanDecodeError on a bad step."""
    units = []
    for n, step in enumerate(steps, start=1):
        name, *args = step.split()
        action = lt.task.action_for(name)
        if action is None:
            raise PlanDecodeError(f"plan step {n} ({step}) names no action of the task")
        if action.unit is None:
            continue
        try:
            units.append(ground_unit(lt, action.unit, tuple(args)))
        except (KeyError, ValueError) as exc:
            raise PlanDecodeError(f"plan step {n} ({step}): {exc}") from None
    return tuple(units)


def plan_bindings(lt: LiftedTask, steps: Sequence[str]) -> dict[str, str]:
    """Recipe object -> kitchen object, for every parameter a plan bound to another object."""
    out: dict[str, str] = {}
    for step in steps:
        name, *args = step.split()
        action = lt.task.action_for(name)
        if action is None or action.unit is None or len(args) != len(lt.lifted[action.unit].params):
            continue
        for (label, _), a in zip(lt.lifted[action.unit].params, args, strict=True):
            if lt.objects.get(a, label) != label:
                out.setdefault(label, lt.objects[a])
    return out


def plan_tree(lt: LiftedTask, steps: Sequence[str], goal: Goal, kitchen_nodes: frozenset[ObjectNode]) -> TaskTree:
    """The concrete task tree a plan of the lifted task stands for.

    What the plan made from a substituted object is renamed with it (`substitute.rename_derived`:
    a lime squeezed where the recipe squeezed a lemon gives `lime juice`), in every unit and in
    the goal node, as FOON-EXP names it; when the renamed tree would not validate (a new name
    colliding with another object), the recipe's names are kept.
    """
    units = plan_units(lt, steps)
    tree = TaskTree(units, goal_node(goal, lt.level, kitchen_nodes, units), lt.level)
    fixed = frozenset(x for n in kitchen_nodes for x in (n.label, *(y for s in n.states
                                                                    for y in (s.related, *s.ingredients))) if x)
    renames = rename_derived(units, plan_bindings(lt, steps), fixed)
    if not renames:
        return tree
    renamed = TaskTree(tuple(substitute_unit(u, renames) for u in units), substitute_node(tree.goal, renames),
                       lt.level)
    return renamed if validate(renamed, kitchen_nodes).ok else tree


def plan_lifted(foon: Foon, kitchen: Kitchen, goal: Goal, index: CategoryIndex, level: int = 3, *,
                planner: str = DEFAULT_PLANNER, planner_cmd: str | None = None, optimal: bool = False,
                time_limit: float | None = None, prune: bool = True, policy: str = "absent",
                search=None) -> LiftedOutcome:
    """Encode, plan, ground the plan back to concrete units and validate them against the concrete kitchen."""
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    lt = encode_lifted(foon, kitchen, goal, index, level, prune=prune, policy=policy)
    timings["encode"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    domain, problem = render(lt.task)
    timings["write"] = time.perf_counter() - t0
    result = run_planner(lt.task, domain, problem, planner=planner, planner_cmd=planner_cmd, optimal=optimal,
                         time_limit=time_limit, search=search)
    timings.update({k: v for k, v in result.timings.items() if k in ("translate", "search")})
    if not result.solved:
        return LiftedOutcome(lt, result, timings=timings)
    kitchen_nodes = kitchen.project(level).nodes
    t0 = time.perf_counter()
    try:
        tree = plan_tree(lt, result.plan, goal, kitchen_nodes)
    except PlanDecodeError as exc:
        return LiftedOutcome(lt, result, decode_error=str(exc), timings=timings)
    timings["decode"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    check = validate(tree, kitchen_nodes)
    timings["validate"] = time.perf_counter() - t0
    return LiftedOutcome(lt, result, tree, check, timings=timings)
