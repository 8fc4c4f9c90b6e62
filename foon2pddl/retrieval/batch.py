"""Many goals against one loaded network: one row per goal (status, units, time, reason, tree).

The network, its index and the reachability fixpoint from the kitchen are built
once and shared by every goal (the fixpoint answers unreachable goals and seeds
every method), so a goal costs its own search only: the 25 goals of the search
inputs take milliseconds, where one process per goal spent ~0.85 s loading.
Each found tree is validated by simulation under the same containment rule. An
unreachable goal's reason names the smallest kitchen additions that make it
(`explain.explain_unreachable`): the words `retrieve` and `plan` give one goal.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from ..analysis.reachability import reachable
from ..errors import FoonError
from ..io.goal_lists import GoalEntry
from ..io.rates import Rates
from ..model.containment import Containment, containment_of, count_inference
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec
from ..model.tasktree import TaskTree, validate
from ..model.words import first_of
from ..status import BatchStatus, batch_status
from .api import retrieve
from .explain import explain_unreachable
from .greedy import DEFAULT_BUDGET
from .optimal import DEFAULT_NODE_LIMIT, DEFAULT_TIME_LIMIT
from .result import UNREACHABLE


@dataclass(frozen=True)
class GoalRow:
    """One goal's result. `units` counts functional units (inference steps not included);
    `inferred` lists the containers the containment rule made available for the tree."""

    goal: str
    source: str
    status: BatchStatus
    seconds: float
    reason: str = ""
    units: int | None = None
    inferred: tuple[str, ...] = ()
    probability: float | None = None
    tree: TaskTree | None = None

    def as_dict(self) -> dict:
        """The JSON-lines record (the tree itself is written to its own file)."""
        return {"goal": self.goal, "status": str(self.status), "units": self.units,
                "inferred": list(self.inferred), "seconds": round(self.seconds, 6), "reason": self.reason,
                "probability": self.probability, "source": self.source}


def solve_goals(foon: Foon, kitchen_nodes: Iterable[ObjectNode], entries: Sequence[GoalEntry],
                resolve: Callable[[GoalSpec], Goal], *, method: str = "complete", rates: Rates | None = None,
                budget: int = DEFAULT_BUDGET, node_limit: int | None = DEFAULT_NODE_LIMIT,
                time_limit: float | None = DEFAULT_TIME_LIMIT, clock: Callable[[], float] = time.perf_counter) -> list[GoalRow]:
    """Retrieve a tree for every goal of `entries` (resolved by `resolve`) from one kitchen, in order.

    `foon` is the network as searched (with inference units under `--containment infer`,
    `containment.with_containment`); trees are validated under the matching semantics.
    """
    kitchen = frozenset(kitchen_nodes)
    mode = containment_of(foon.units)
    reach = reachable(foon, kitchen)
    rows = []
    for entry in entries:
        t0 = clock()
        limits = {"budget": budget, "node_limit": node_limit, "time_limit": time_limit}
        rows.append(_one(foon, kitchen, entry, resolve, mode, reach, method, rates, limits, t0, clock))
    return rows


def _one(foon, kitchen, entry: GoalEntry, resolve, mode: Containment, reach, method, rates, limits: dict,
         t0: float, clock) -> GoalRow:
    where = f"{entry.path}:{entry.line}"
    try:
        goal = resolve(entry.spec)
    except FoonError as exc:  # no node matches the goal
        return GoalRow(entry.spec.describe(), where, BatchStatus.UNMATCHED, clock() - t0, exc.message)
    result = retrieve(foon, kitchen, goal, method, rates=rates, reach=reach, **limits)
    if result.tree is None:  # unreachable: the smallest kitchen additions, in the words `retrieve` gives one goal
        detail = explain_unreachable(foon, kitchen, goal) if result.reason == UNREACHABLE else result.detail
        return GoalRow(goal.describe(), where, batch_status(result.reason), clock() - t0,
                       f"{result.reason}: {detail}")
    check = validate(result.tree, kitchen, mode)
    units = len(result.tree.units) - count_inference(result.tree.units)
    inferred = tuple(n.describe() for n in check.inferred)
    if not check.ok:
        return GoalRow(goal.describe(), where, BatchStatus.INVALID, clock() - t0, first_of(check.problems, 3),
                       units, inferred, result.probability, result.tree)
    return GoalRow(goal.describe(), where, BatchStatus.SOLVED, clock() - t0, result.detail, units, inferred,
                   result.probability, result.tree)
