"""Planners: Fast Downward (fresh or reusing one translation), unified-planning engines, external commands.

`run_planner` is the one entry point: it picks the planner and returns a
`PlanResult` whatever happens (statuses `solved`, `unsolvable`, `timeout`,
`error`); it never raises for a planner's failure.

The package itself imports nothing: `planners.cleanup` (which every CLI call enters) must not pull in
the PDDL task model, so `PlanResult` and friends load from `result` on first access.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from ..pddl.task import PlanningTask
    from .result import PlanResult

__all__ = ["STATUSES", "PlanResult", "parse_plan_text", "run_planner", "step_action", "cleanup", "commands", "decode",
           "copies", "executable", "external", "fd", "fd_reuse", "fd_speedups", "foon_places", "goal_replanner", "instance_physical",
           "physical_replay", "process", "registry", "replay_findings", "replay_where", "result", "sas", "solve", "trace_check", "translate_server", "translator", "up_engine"]

#: The default planner (`planners.registry.PLANNERS`); unregistered names are unified-planning engines.
DEFAULT_PLANNER = "fd"

#: Names re-exported from `result`, loaded on first access (module `__getattr__`).
_FROM_RESULT = ("STATUSES", "PlanResult", "parse_plan_text", "step_action")


def __getattr__(name: str) -> object:
    if name in _FROM_RESULT:
        from . import result

        return getattr(result, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


def run_planner(task: PlanningTask, domain_text: str, problem_text: str, *, planner: str = DEFAULT_PLANNER,
                planner_cmd: str | None = None, optimal: bool = False,
                time_limit: float | None = None, search=None, cpu_limit: float | None = None) -> PlanResult:
    """Solve a rendered task with the registered planner `planner` (`planners.registry`): Fast Downward
    (`fd`), a unified-planning engine by name, or, given `planner_cmd`, an external command.

    `search` (an `fd.SearchConfig`: a driver alias or --search/--evaluator) configures Fast Downward.
    `cpu_limit`: CPU seconds besides the wall-clock `time_limit` (`PlanRequest.cpu_limit`).
    """
    from .registry import PlanRequest, lookup

    request = PlanRequest(task, domain_text, problem_text, planner, optimal, time_limit, search, planner_cmd,
                          cpu_limit)
    return lookup(planner, planner_cmd).solve(request)
