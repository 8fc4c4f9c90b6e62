"""What every retrieval method returns: a task tree or the reason there is none."""

from __future__ import annotations

from dataclasses import dataclass

from ..model.tasktree import TaskTree
from ..status import RetrievalStatus

METHODS = ("greedy", "complete", "optimal", "weighted")

#: Reasons for returning no tree.
UNREACHABLE = RetrievalStatus.UNREACHABLE
BUDGET_EXHAUSTED = RetrievalStatus.BUDGET_EXHAUSTED


@dataclass(frozen=True)
class Retrieval:
    """Outcome of one retrieval.

    Exactly one of `tree` and `reason` is set. `detail` explains the reason (or
    notes about the tree) in words. `expansions` counts the method's basic
    steps (greedy: objects taken from its queue; optimal/weighted: search nodes
    expanded; complete: units fired). `proven_optimal` is True when an optimal
    or weighted search finished within its node limit, False when it returns the
    best tree found so far, None for the other methods. `probability` is the
    product of the tree's motion success rates when rates were given.
    """

    tree: TaskTree | None
    reason: RetrievalStatus | None
    method: str
    detail: str = ""
    expansions: int = 0
    proven_optimal: bool | None = None
    probability: float | None = None

    def __post_init__(self) -> None:
        if (self.tree is None) == (self.reason is None):
            raise ValueError("a Retrieval has either a tree or a reason")
        if self.reason is not None:
            object.__setattr__(self, "reason", RetrievalStatus(self.reason))
            if self.reason == RetrievalStatus.FOUND:
                raise ValueError("a Retrieval without a tree needs a reason other than 'found'")

    @property
    def status(self) -> RetrievalStatus:
        """`found`, or the reason there is no tree."""
        return RetrievalStatus.FOUND if self.reason is None else self.reason

    @property
    def found(self) -> bool:
        return self.tree is not None
