"""Robot profiles: how many hands, which skills a robot lacks, what each skill costs.

A robot without a skill cannot carry out the motions that map to it, so the macro
planner is told so with the existing `without-motion` constraints
(`robot_constraints`): a robot that cannot pour gets a recipe without a pour, or
the dish is reported unreachable with the blocking motion, as native retrieval
says under `--without-motion pour`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from ..model.constraints import Constraint, Constraints, Kind, make_constraints
from .table import MotionTable

__all__ = ["Robot", "robot_constraints"]


@dataclass(frozen=True)
class Robot:
    """`hands` (>= 1), skills it lacks (sorted), and per-skill costs (sorted pairs; others cost 1)."""

    hands: int = 1
    without: tuple[str, ...] = ()
    costs: tuple[tuple[str, int], ...] = ()

    def __post_init__(self) -> None:
        if self.hands < 1:
            raise ValueError("a robot needs at least one hand")
        for skill, cost in self.costs:
            if cost < 0:
                raise ValueError(f"cost of skill {skill!r} must be >= 0, not {cost}")

    @classmethod
    def of(cls, hands: int = 1, without: Iterable[str] = (), costs: Mapping[str, int] | None = None) -> Robot:
        return cls(hands, tuple(sorted({s.strip().lower() for s in without if s.strip()})),
                   tuple(sorted((k.strip().lower(), int(v)) for k, v in (costs or {}).items())))

    @property
    def cost_table(self) -> dict[str, int]:
        return dict(self.costs)

    def lacks(self, skill: str) -> bool:
        return skill in self.without


def robot_constraints(table: MotionTable, robot: Robot, source: str = "<robot>") -> Constraints:
    """`without-motion M` for every motion whose skill the robot lacks, marked with the skill so that
    messages name the option the user gave (`without-skill pour`)."""
    return make_constraints(Constraint(Kind.WITHOUT_MOTION, m, source, s) for m, s in sorted(table.pairs)
                            if robot.lacks(s))
