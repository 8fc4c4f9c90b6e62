"""A goal planned and decomposed into robot skills in one call: what `plan --skills` and the API run.

The robot's missing skills become `without-motion` bans for the macro planner
(`profile.robot_constraints`), so a robot without `pour` gets a plan without a
pouring motion or an unreachable goal with the blocking motion. The macro plan
comes from an encoding over physical objects (`relational` when it is
registered, else `instances`); its trace (`source.trace_of`) is decomposed
(`decompose`).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..model.constraints import Constraints, combine
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.physical import PhysicalTrace
from ..pddl.compile import ENCODINGS
from ..planners.solve import PlanOutcome, plan
from .decompose import SkillPlan, decompose
from .domain import SkillDomain, shipped_domain
from .profile import Robot, robot_constraints
from .source import trace_of
from .table import MotionTable, shipped_table

__all__ = ["SkillOutcome", "plan_skills", "robot_profile", "skills_encoding"]


def skills_encoding() -> str:
    """The encoding skill plans start from: `relational` (real holders) when registered, else `instances`."""
    return "relational" if "relational" in ENCODINGS else "instances"


@dataclass(frozen=True)
class SkillOutcome:
    """The macro plan's outcome, its physical trace, and its skill plan (None without a plan)."""

    outcome: PlanOutcome
    trace: PhysicalTrace | None
    skills: SkillPlan | None

    def json(self) -> dict | None:
        """The skill plan as `plan --skills --format json` gives it (None without a plan)."""
        from .report import skill_plan_json

        return skill_plan_json(self.skills) if self.skills is not None else None


def robot_profile(constraints: Constraints | None, hands: int = 1, without: tuple[str, ...] = ()) -> Robot:
    """The robot of a constraints file's `without_skills`/`skill_costs` plus flags."""
    c = constraints or Constraints()
    return Robot.of(hands, (*c.without_skills, *without), dict(c.skill_costs))


def plan_skills(foon: Foon, kitchen: Kitchen, goal: Goal, *, encoding: str | None = None,
                domain: SkillDomain | None = None, table: MotionTable | None = None, robot: Robot | None = None,
                constraints: Constraints | None = None, **options) -> SkillOutcome:
    """Plan `goal` (as `planners.solve.plan`, `options` passed on) and decompose the plan into skills.

    Raises `pddl.constraints.GoalExcluded` when the constraints (the robot's included) leave no way to the goal.
    """
    domain = domain or shipped_domain()
    table = table or shipped_table()
    robot = robot or robot_profile(constraints)
    cons = combine(constraints or Constraints(), robot_constraints(table, robot))
    outcome = plan(foon, kitchen, goal, encoding or skills_encoding(), constraints=cons if cons else None,
                   **options)
    trace = trace_of(outcome) if outcome.status == "solved" else None
    return SkillOutcome(outcome, trace, decompose(trace, table, domain, robot) if trace is not None else None)
