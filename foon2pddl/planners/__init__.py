"""Planners: Fast Downward (fresh or reusing one translation), unified-planning engines, external commands.

`run_planner` is the one entry point: it picks the planner and returns a
`PlanResult` whatever happens (statuses `solved`, `unsolvable`, `timeout`,
`error`); it never raises for a planner's failure.
"""

from __future__ import annotations

from ..pddl.task import PlanningTask
from .result import STATUSES, PlanResult, parse_plan_text, step_action

__all__ = ["STATUSES", "PlanResult", "parse_plan_text", "run_planner", "step_action"]

#: The built-in planner; any other name is looked up among unified-planning engines.
DEFAULT_PLANNER = "fd"


def run_planner(task: PlanningTask, domain_text: str, problem_text: str, *, planner: str = DEFAULT_PLANNER,
                planner_cmd: str | None = None, optimal: bool = False,
                time_limit: float | None = None, search=None) -> PlanResult:
    """Solve a rendered task with Fast Downward (`fd`), a UP engine by name, or an external command.

    `search` (an `fd.SearchConfig`: a driver alias or --search/--evaluator) configures Fast Downward.
    """
    if planner_cmd is not None:
        from . import external

        return external.solve(planner_cmd, domain_text, problem_text, time_limit=time_limit)
    if planner == DEFAULT_PLANNER:
        from . import fd

        return fd.solve(domain_text, problem_text, optimal=optimal, time_limit=time_limit,
                        translate_options=fd.translate_options_for(task), config=search)
    from . import up_engine

    return up_engine.solve(task, planner, optimal=optimal, time_limit=time_limit)
