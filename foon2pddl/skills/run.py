"""A goal planned and decomposed into robot skills in one call: what `plan --skills` and the API run.

The robot's missing skills become `without-motion` bans for the macro planner
(`profile.robot_constraints`), so a robot without `pour` gets a plan without a
pouring motion or an unreachable goal with the blocking motion. The macro plan
comes from an encoding over physical objects (`relational` when it is
registered, else `instances`); its trace (`source.trace_of`) is decomposed
(`decompose`).

When no encoding is asked for, the relational task gets `FIRST_SHARE` of the time limit and,
should it end without a plan (time limit, a search that gave up, or `unsolvable`, which the
incomplete relational encoding does not prove) where FOON's semantics makes the goal (one fixpoint; where it
does not, no encoding has a plan), the `instances` encoding plans with the rest:
holders read from FOON's words rather than planned (the black bean dish of the merged shared
subgraphs times out under `relational` and solves under `instances` in ~2 s). The outcome says so
(`SkillOutcome.first`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

from ..analysis.constraints import removal
from ..model.constraints import Constraints, combine
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.physical import PhysicalTrace
from ..pddl.compile import ENCODINGS
from ..planners.solve import EXCLUDED, PlanOutcome, plan
from ..status import PlanStatus
from .decompose import SkillPlan, decompose
from .domain import SkillDomain, shipped_domain
from .profile import Robot, robot_constraints
from .source import trace_of
from .table import MotionTable, shipped_table

__all__ = ["FALLBACK_ENCODING", "FIRST_SHARE", "SkillOutcome", "plan_skills", "robot_profile", "skills_encoding"]

#: The encoding a default skill plan falls back to when the relational one finds no plan.
FALLBACK_ENCODING = "instances"
#: The share of the time limit the relational task gets when a fallback may follow: its solved dish plans take
#: at most ~5 s (the 89 solvable shared dishes), so a quarter of the default 300 s leaves it a wide margin.
FIRST_SHARE = 0.25
#: Outcomes the fallback follows: no plan and no proof that there is none under every encoding.
_NO_PLAN = (PlanStatus.TIMEOUT, PlanStatus.GAVE_UP, PlanStatus.UNSOLVABLE)


def skills_encoding() -> str:
    """The encoding skill plans start from: `relational` (real holders) when registered, else `instances`."""
    return "relational" if "relational" in ENCODINGS else "instances"


@dataclass(frozen=True)
class SkillOutcome:
    """The macro plan's outcome, its physical trace, and its skill plan (None without a plan)."""

    outcome: PlanOutcome
    trace: PhysicalTrace | None
    skills: SkillPlan | None
    #: The default (relational) encoding's outcome without a plan, when `outcome` is the fallback's.
    first: PlanOutcome | None = None

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
                constraints: Constraints | None = None, on_fallback: Callable[[PlanOutcome], None] | None = None,
                **options) -> SkillOutcome:
    """Plan `goal` (as `planners.solve.plan`, `options` passed on) and decompose the plan into skills.

    `encoding` None: the default one, with the fallback of the module doc (`on_fallback(first outcome)` is
    called as the fallback starts). Raises `pddl.constraints.GoalExcluded` when the constraints (the robot's
    included) leave no way to the goal.
    """
    domain = domain or shipped_domain()
    table = table or shipped_table()
    robot = robot or robot_profile(constraints)
    cons = combine(constraints or Constraints(), robot_constraints(table, robot))
    chosen = encoding or skills_encoding()
    fallback = encoding is None and chosen != FALLBACK_ENCODING and FALLBACK_ENCODING in ENCODINGS
    limit = options.pop("time_limit", None)
    finite = limit is not None and math.isfinite(limit)
    t0 = time.monotonic()
    outcome = plan(foon, kitchen, goal, chosen, constraints=cons if cons else None,
                   time_limit=limit * FIRST_SHARE if fallback and finite else limit, **options)
    first = None
    if fallback and outcome.status in _NO_PLAN and outcome.result.planner != EXCLUDED \
            and removal(foon, cons).solvable(kitchen.nodes, goal):  # else no encoding has a plan: FOON's reason
        first = outcome
        if on_fallback is not None:
            on_fallback(first)
        rest = max(limit - (time.monotonic() - t0), 1.0) if finite else limit
        outcome = plan(foon, kitchen, goal, FALLBACK_ENCODING, constraints=cons if cons else None, time_limit=rest,
                       **options)
    trace = trace_of(outcome) if outcome.status == "solved" else None
    return SkillOutcome(outcome, trace, decompose(trace, table, domain, robot) if trace is not None else None, first)
