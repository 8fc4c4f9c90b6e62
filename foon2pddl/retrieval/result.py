"""What every retrieval method returns: a task tree or the reason there is none."""

from __future__ import annotations

from dataclasses import dataclass

from ..model.tasktree import TaskTree
from ..status import RetrievalStatus

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
    or weighted search proved its tree optimal, False when it returns the best
    tree found within its budget, None for the other methods. `probability` is
    the product of the tree's motion success rates when rates were given.

    Anytime optimal/weighted retrieval also sets `cost`, the tree's objective
    (optimal: its units; weighted: the sum of -log(rate) of its motions), and
    `bound`, a proven lower bound on the cost of every tree for the goal.
    Checked on construction: both are set together and only with a tree,
    `bound <= cost`, and `proven_optimal` is exactly `bound == cost` (a search
    that proves its tree optimal reports the bound equal to the cost).
    """

    tree: TaskTree | None
    reason: RetrievalStatus | None
    method: str
    detail: str = ""
    expansions: int = 0
    proven_optimal: bool | None = None
    probability: float | None = None
    cost: float | None = None
    bound: float | None = None

    def __post_init__(self) -> None:
        if (self.tree is None) == (self.reason is None):
            raise ValueError("a Retrieval has either a tree or a reason")
        if self.reason is not None:
            object.__setattr__(self, "reason", RetrievalStatus(self.reason))
            if self.reason == RetrievalStatus.FOUND:
                raise ValueError("a Retrieval without a tree needs a reason other than 'found'")
        if (self.cost is None) != (self.bound is None):
            raise ValueError("a Retrieval's cost and bound are set together")
        if self.bound is not None:
            if self.tree is None:
                raise ValueError("a bound needs a tree")
            if not self.bound <= self.cost:
                raise ValueError(f"bound {self.bound} exceeds the tree's cost {self.cost}")
            if self.proven_optimal is not (self.bound == self.cost):
                raise ValueError("proven_optimal must be exactly bound == cost")

    @property
    def status(self) -> RetrievalStatus:
        """`found`, or the reason there is no tree."""
        return RetrievalStatus.FOUND if self.reason is None else self.reason

    @property
    def gap(self) -> float | None:
        """cost - bound (0 when proven optimal), None without a bound."""
        return None if self.bound is None else self.cost - self.bound

    @property
    def found(self) -> bool:
        return self.tree is not None
