"""A solver's answer for one goal (`Outcome`, a record without its key) and how a native retrieval's or a planner
run's result becomes one: its tree validated from the kitchen the solver was given (a tree that fails is an
`error`) and scheduled over that kitchen's physical objects (`planners.executable`), or a physical plan's trace
held against them.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

from ..model.tasktree import validate
from ..model.words import first_of
from ..status import cell_status
from .records import CellStatus

__all__ = ["Outcome", "native_outcome", "physical", "physical_plan", "plan_outcome"]


@dataclass(frozen=True)
class Outcome:
    """What a solver says about one goal (a record without its key)."""

    status: CellStatus
    reason: str = ""
    times: dict[str, float] = field(default_factory=dict)
    units: int | None = None
    plan_length: int | None = None
    validated: bool | None = None
    proven_optimal: bool | None = None
    foon_valid: bool | None = None
    bound: float | None = None  # anytime optimal search: proven lower bound on the tree's units
    gap: float | None = None  # (units - bound) / units
    executable: str | None = None  # the tree scheduled over the kitchen's objects (`physical`)
    executable_reason: str | None = None
    extra_objects: int | None = None
    repeated: int | None = None  # a physical plan: unit steps firing a unit it fired before


def native_outcome(result, kitchen_nodes, seconds: float, per_item: int = 1) -> Outcome:
    """Outcome of a `Retrieval`, its tree validated from `kitchen_nodes` and scheduled over their objects."""
    times = {"retrieve": seconds}
    if result.tree is None:
        return Outcome(cell_status(result.status), result.detail or result.reason, times)
    t0 = time.perf_counter()
    check = validate(result.tree, kitchen_nodes)
    times["validate"] = time.perf_counter() - t0
    if not check.ok:
        return Outcome(CellStatus.ERROR, "tree does not validate: " + first_of(check.problems, 3), times,
                       len(result.tree), None, False, result.proven_optimal, False, *_bound(result))
    return Outcome(CellStatus.SOLVED, result.detail, times, len(result.tree), None, True, result.proven_optimal,
                   True, *_bound(result), **physical(result.tree, kitchen_nodes, per_item, times))


def physical(tree, kitchen_nodes, per_item: int, times: dict[str, float]) -> dict:
    """The Outcome fields of `tree` scheduled over `per_item` objects per kitchen node
    (`planners.executable.schedule`, its time in `times["schedule"]`): the verdict, why not, and for a
    tree the kitchen runs short for, the objects it needs beyond the kitchen's (None when more objects
    would not do: a unit must fire again)."""
    from ..planners.executable import Verdict, needed, schedule

    t0 = time.perf_counter()
    verdict = schedule(tree, kitchen_nodes, per_item=per_item)
    extra = None
    if verdict.verdict is Verdict.SHORT:
        unlimited = needed(tree, kitchen_nodes)
        if unlimited.ok:
            extra = sum(max(0, n - per_item) for _, n in unlimited.drawn)
    times["schedule"] = time.perf_counter() - t0
    return {"executable": str(verdict.verdict), "executable_reason": verdict.message or None, "extra_objects": extra}


def physical_plan(trace, kitchen_nodes, per_item: int, times: dict[str, float]) -> dict:
    """The Outcome fields of a physical plan (its `trace`, replayed when decoded) against `per_item` objects
    per kitchen node (`planners.executable.drawn_by_plan`, its time in `times["schedule"]`): `short` when
    the planner, given as many objects as the goal may need, used more than the kitchen has (how many more),
    and how many of its unit steps fire a unit the plan fired before."""
    from ..planners.executable import Verdict, drawn_by_plan

    t0 = time.perf_counter()
    verdict = drawn_by_plan(trace, kitchen_nodes, per_item)
    extra = sum(max(0, n - per_item) for _, n in verdict.drawn) if verdict.verdict is Verdict.SHORT else None
    fired: set = set()
    repeated = 0
    for step in trace.steps:
        repeated += step.unit in fired
        fired.add(step.unit)
    times["schedule"] = time.perf_counter() - t0
    return {"executable": str(verdict.verdict), "executable_reason": verdict.message or None, "extra_objects": extra,
            "repeated": repeated}


def _bound(result) -> tuple[float | None, float | None]:
    """(bound, gap) of an anytime retrieval that reports a lower bound (None, None otherwise)."""
    bound = getattr(result, "bound", None)
    if bound is None or result.tree is None or not len(result.tree):
        return None, None
    return float(bound), max(0.0, (len(result.tree) - bound) / len(result.tree))


def plan_outcome(outcome, steps: tuple[str, ...], kitchen_nodes=None, per_item: int = 1) -> Outcome:
    """Outcome of a planner run mapped back to a tree (`PlanOutcome`). A plan over physical objects (its
    `trace`) is executable when it decodes (decoding replays it: `planners.decode.check_trace`, with
    holders the relational replay: a plan it rejects is `rejected`, with no tree); another valid tree is scheduled over the objects of `kitchen_nodes`
    when given (`physical`)."""
    times = dict(outcome.timings)
    if outcome.rejected:  # a plan found and physically wrong: no tree, and not a bug (`CellStatus.REJECTED`)
        return Outcome(CellStatus.REJECTED, outcome.message, times, None, len(steps) if steps else None)
    tree = outcome.tree
    units = len(tree) if tree is not None else None
    status = cell_status(outcome.status)  # `error` when a plan was found that does not decode or validate
    foon_valid = outcome.validation.ok if outcome.validation is not None else None
    validated = None if tree is None else status == CellStatus.SOLVED
    if status == CellStatus.SOLVED:
        reason = "" if foon_valid is not False else "tree fails FOON simulation: " + first_of(
            outcome.validation.problems, 2)
        if outcome.trace is not None:  # a plan over physical objects: decoding replayed it object by object
            scheduled: dict = physical_plan(outcome.trace, kitchen_nodes or frozenset(), per_item, times)
        elif kitchen_nodes is not None and foon_valid:
            scheduled = physical(tree, kitchen_nodes, per_item, times)
        else:
            scheduled = {}
        return Outcome(status, reason, times, units, len(steps), validated, None, foon_valid, **scheduled)
    return Outcome(status, outcome.message, times, units, len(steps) if steps else None, validated, None,
                   foon_valid)
