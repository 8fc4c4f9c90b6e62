"""The status vocabularies of planners, native retrieval and experiment cells, and the one map between them.

Every status is a `StrEnum`, so it compares equal to (and prints, formats and
serializes to JSON as) its old string: `PlanStatus.SOLVED == "solved"`.

- `PlanStatus`: what a planner run ends in (`planners.result.PlanResult.status`);
- `RetrievalStatus`: what a native retrieval ends in (`retrieval.result.Retrieval.status`;
  its `reason` is one of the non-`FOUND` members);
- `BatchStatus`: one goal of a batch (`retrieve`, `compile`, `plan` with several goals;
  plan rows carry their `PlanStatus`, or `unmatched`); `batch_status` maps a retrieval's into it;
- `CellStatus`: one experiment cell (a solver on a goal), covering both (and
  `lost` cells); `cell_status` is the one explicit mapping into it.
"""

from __future__ import annotations

from enum import StrEnum

__all__ = ["BatchStatus", "CellStatus", "PlanStatus", "RetrievalStatus", "batch_status", "cell_status"]


class PlanStatus(StrEnum):
    """A planner run: a plan was found, the planner proved (or, for an external command, said) there is none,
    its search stopped without a plan and without a proof (an incomplete search exhausted, a cost bound: `gave
    up`), it ran out of time, it failed."""

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    GAVE_UP = "gave up"
    TIMEOUT = "timeout"
    ERROR = "error"


class RetrievalStatus(StrEnum):
    """A native retrieval: a tree was found, the goal cannot be made, or the method's budget ran out first."""

    FOUND = "found"
    UNREACHABLE = "unreachable"
    BUDGET_EXHAUSTED = "budget exhausted"


class BatchStatus(StrEnum):
    """One goal of a batch: a tree was found, the goal cannot be made, the budget ran out, the goal names no
    node any unit produces, a found tree does not validate (a bug: reported, never hidden), its PDDL was written."""

    SOLVED = "solved"
    UNREACHABLE = "unreachable"
    BUDGET_EXHAUSTED = "budget exhausted"
    UNMATCHED = "unmatched"
    INVALID = "invalid"
    COMPILED = "compiled"


class CellStatus(StrEnum):
    """How an experiment cell ended, whichever kind of solver ran it (`solved`: a task tree was found).

    `unsolvable`: proven (the fixpoint, a planner's proof); `gave up`: a planner's search
    stopped without a plan or a proof; `budget exhausted`: a native search's budget ran out.
    `rejected`: a planner found a plan and the physical replay rejects it, and no count had a physically right
    one (FOON's own words contradict each other where the plan works: docs/pddl.md, "Plans the replay rejects"); no
    tree is returned, and a rerun gives the same answer. `lost`: its worker died or its task was killed (no
    answer; a rerun redoes it).
    """

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    GAVE_UP = "gave up"
    BUDGET_EXHAUSTED = "budget exhausted"
    TIMEOUT = "timeout"
    ERROR = "error"
    REJECTED = "rejected"
    LOST = "lost"


_CELL: dict[PlanStatus | RetrievalStatus, CellStatus] = {
    PlanStatus.SOLVED: CellStatus.SOLVED,
    PlanStatus.UNSOLVABLE: CellStatus.UNSOLVABLE,
    PlanStatus.GAVE_UP: CellStatus.GAVE_UP,
    PlanStatus.TIMEOUT: CellStatus.TIMEOUT,
    PlanStatus.ERROR: CellStatus.ERROR,
    RetrievalStatus.FOUND: CellStatus.SOLVED,
    RetrievalStatus.UNREACHABLE: CellStatus.UNSOLVABLE,
    RetrievalStatus.BUDGET_EXHAUSTED: CellStatus.BUDGET_EXHAUSTED,
}


_BATCH: dict[RetrievalStatus, BatchStatus] = {
    RetrievalStatus.FOUND: BatchStatus.SOLVED,
    RetrievalStatus.UNREACHABLE: BatchStatus.UNREACHABLE,
    RetrievalStatus.BUDGET_EXHAUSTED: BatchStatus.BUDGET_EXHAUSTED,
}


def batch_status(status: RetrievalStatus) -> BatchStatus:
    """The batch row status of a retrieval's status.

    >>> batch_status(RetrievalStatus.FOUND)
    <BatchStatus.SOLVED: 'solved'>
    """
    return _BATCH[status]


def cell_status(status: PlanStatus | RetrievalStatus) -> CellStatus:
    """The experiment cell status of a planner's or a retrieval's status.

    >>> cell_status(RetrievalStatus.UNREACHABLE)
    <CellStatus.UNSOLVABLE: 'unsolvable'>
    >>> cell_status(PlanStatus.TIMEOUT) == "timeout"
    True
    """
    return _CELL[status]
