"""What a solver is prepared for (`Setting`: a network view, a trial's kitchen, a time limit) and what a prepared
solver does (`Prepared`: answer the goals of one batch, after a `setup` the batch shares).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..model.foon import ObjectNode
from ..model.kitchen import Kitchen
from .networks import NetworkView
from .outcomes import Outcome

__all__ = ["DEFAULT_TIME_LIMIT", "Prepared", "Setting"]

#: Default time limit (seconds) of one planner run.
DEFAULT_TIME_LIMIT = 60.0


@dataclass(frozen=True)
class Setting:
    """What a solver is prepared for: a network view, the trial's concrete kitchen, a planner time limit;
    `cache`, a directory where Fast Downward translations are shared between the run's processes
    (`fd-tree` and `fd-tree-opt` translate the same task; None: each translates its own); `per_item`,
    the physical objects per kitchen item with which returned trees are scheduled (`physical`)."""

    view: NetworkView
    kitchen: Kitchen
    time_limit: float = DEFAULT_TIME_LIMIT
    cache: Path | None = None
    per_item: int = 1  # physical objects per kitchen item when a returned tree is scheduled


class Prepared:
    """A solver ready for the goals of one batch; `setup` is the preparation time in seconds."""

    setup: float = 0.0

    def solve(self, node: ObjectNode) -> Outcome:  # pragma: no cover - interface
        raise NotImplementedError
