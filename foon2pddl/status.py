"""The status vocabularies of planners, native retrieval and experiment cells, and the one map between them.

Every status is a `StrEnum`, so it compares equal to (and prints, formats and
serializes to JSON as) its old string: `PlanStatus.SOLVED == "solved"`.

- `PlanStatus`: what a planner run ends in (`planners.result.PlanResult.status`);
- `RetrievalStatus`: what a native retrieval ends in (`retrieval.result.Retrieval.status`;
  its `reason` is one of the non-`FOUND` members);
- `CellStatus`: one experiment cell (a solver on a goal), covering both (and
  `lost` cells); `cell_status` is the one explicit mapping into it.
"""

from __future__ import annotations

from enum import StrEnum

__all__ = ["CellStatus", "PlanStatus", "RetrievalStatus", "cell_status"]


class PlanStatus(StrEnum):
    """A planner run: a plan was found, the planner proved or concluded there is none, it ran out of time, it failed."""

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    TIMEOUT = "timeout"
    ERROR = "error"


class RetrievalStatus(StrEnum):
    """A native retrieval: a tree was found, the goal cannot be made, or the method's budget ran out first."""

    FOUND = "found"
    UNREACHABLE = "unreachable"
    BUDGET_EXHAUSTED = "budget exhausted"


class CellStatus(StrEnum):
    """How an experiment cell ended, whichever kind of solver ran it (`solved`: a task tree was found).

    `lost`: its worker died or its task was killed (no answer; a rerun redoes it).
    `node limit` is kept as a report column; no solver produces it today.
    """

    SOLVED = "solved"
    UNSOLVABLE = "unsolvable"
    BUDGET_EXHAUSTED = "budget exhausted"
    NODE_LIMIT = "node limit"
    TIMEOUT = "timeout"
    ERROR = "error"
    LOST = "lost"


_CELL: dict[PlanStatus | RetrievalStatus, CellStatus] = {
    PlanStatus.SOLVED: CellStatus.SOLVED,
    PlanStatus.UNSOLVABLE: CellStatus.UNSOLVABLE,
    PlanStatus.TIMEOUT: CellStatus.TIMEOUT,
    PlanStatus.ERROR: CellStatus.ERROR,
    RetrievalStatus.FOUND: CellStatus.SOLVED,
    RetrievalStatus.UNREACHABLE: CellStatus.UNSOLVABLE,
    RetrievalStatus.BUDGET_EXHAUSTED: CellStatus.BUDGET_EXHAUSTED,
}


def cell_status(status: PlanStatus | RetrievalStatus) -> CellStatus:
    """The experiment cell status of a planner's or a retrieval's status.

    >>> cell_status(RetrievalStatus.UNREACHABLE)
    <CellStatus.UNSOLVABLE: 'unsolvable'>
    >>> cell_status(PlanStatus.TIMEOUT) == "timeout"
    True
    """
    return _CELL[status]
