"""The planner registry: each backend is an entry with a `solve` and a `check` callable.

Like unified-planning's engine factory, a planner is looked up by name and
nothing else in the package branches on which one it is: `run_planner` calls
`lookup(name).solve(request)`, the CLI calls `lookup(name).check(name)` before
loading anything. Built-in entries (`PLANNERS`):

- `fd`: Fast Downward's two components run directly (`planners.fd`); it also
  has `translate_once`, the reuse of one translation for many goals (`planners.fd_reuse`);
- `command`: an external command or a preset (`planners.external`, `planners.commands.PRESETS`),
  chosen by giving a command (the CLI's `--planner-cmd`), whatever the name.

Any other name is a unified-planning engine: `lookup` accepts exactly the one-shot
planners of UP's own factory (`get_environment().factory.engines`, public API), so an
engine added with `factory.add_engine` is accepted like a built-in one. Importing UP
costs seconds, so built-in names are checked without it. `register` adds an entry.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import UsageError
from ..pddl.task import PlanningTask
from .result import PlanResult

__all__ = ["PLANNERS", "PlanRequest", "Planner", "UnknownPlanner", "lookup", "register"]


@dataclass(frozen=True)
class PlanRequest:
    """One planner run: the task and its rendered PDDL, and how to search.

    `name` is the planner name asked for (a UP engine entry serves many names);
    `command` the external command when one is given; `search` a Fast Downward
    `fd.SearchConfig` (None: the default for `optimal`); `cpu_limit` the CPU seconds the planner's processes may
    use besides the wall-clock `time_limit` (a planner that cannot bound CPU takes it as a wall-clock limit:
    `wall_limit`).
    """

    task: PlanningTask
    domain_text: str
    problem_text: str
    name: str
    optimal: bool = False
    time_limit: float | None = None
    search: Any = None
    command: str | None = None
    cpu_limit: float | None = None

    @property
    def wall_limit(self) -> float | None:
        """The time limit of a planner that cannot bound CPU time: the shorter of `time_limit` and `cpu_limit`
        (a one-thread planner's CPU time never runs ahead of the wall clock)."""
        limits = [x for x in (self.time_limit, self.cpu_limit) if x is not None]
        return min(limits) if limits else None


@dataclass(frozen=True)
class Planner:
    """A planner backend: `solve(request) -> PlanResult` (never raises for the planner's failure) and
    `check(name)` (raises UsageError when `name` cannot run here: unknown, not installed).

    `configurable`: it takes a search configuration (`PlanRequest.search`);
    `translate_once`: None, or `(task, optimal, time_limit, search, cache, forgettable) -> ` a translated
    task whose `solve(alternatives, time_limit)` plans for any of many goals (reuse across goals) and, built
    `forgettable`, whose `at_init(task)` starts from any subset of its initial state (reuse across kitchens).
    """

    name: str
    description: str
    solve: Callable[[PlanRequest], PlanResult]
    check: Callable[[str], None]
    configurable: bool = False
    translate_once: Callable[..., Any] | None = None


def _fd_solve(request: PlanRequest) -> PlanResult:
    from . import fd

    config = request.search
    if config is None and request.optimal:  # LM-cut takes no conditional effects: A* with h^max then
        config = fd.optimal_config(request.task)
    return fd.solve(request.domain_text, request.problem_text, optimal=request.optimal,
                    time_limit=request.time_limit, translate_options=fd.translate_options_for(request.task),
                    config=config, cpu_limit=request.cpu_limit)


def _fd_translate_once(task: PlanningTask, *, optimal: bool = False, time_limit: float | None = None,
                       search: tuple[str, ...] | None = None, cache: Path | None = None,
                       forgettable: bool = False) -> Any:
    from .fd_reuse import TranslatedTask

    return TranslatedTask.build(task, optimal=optimal, time_limit=time_limit, search=search, cache=cache,
                                forgettable=forgettable)


def _no_check(name: str) -> None:
    """Built-in backends are always present (a missing wheel is reported by their run)."""


def _command_solve(request: PlanRequest) -> PlanResult:
    from . import external

    return external.solve(request.command or "", request.domain_text, request.problem_text,
                          time_limit=request.wall_limit)


def _command_check(command: str) -> None:
    from .commands import resolve_command

    try:
        resolve_command(command)
    except ValueError as exc:
        raise UsageError(str(exc)) from None


class UnknownPlanner(UsageError):
    """A planner name that no entry and no unified-planning engine answers to."""


def _up_solve(request: PlanRequest) -> PlanResult:
    from . import up_engine

    return up_engine.solve(request.task, request.name, optimal=request.optimal, time_limit=request.wall_limit)


def _up_check(name: str) -> None:
    """Raise UsageError unless UP's factory has a one-shot planner `name` (imports unified-planning)."""
    import difflib

    from .up_engine import engine_names

    try:
        from ..pddl.up_problem import quiet_environment

        factory = quiet_environment().factory
        installed, known = set(factory.engines), engine_names()
    except ImportError:
        installed, known = set(), []
    if name in known:
        return
    try:  # the engines UP knows of by default, installed or not (a public module constant)
        from unified_planning.engines.factory import DEFAULT_ENGINES
    except ImportError:
        DEFAULT_ENGINES = {}
    if name in DEFAULT_ENGINES and name not in installed:
        package = DEFAULT_ENGINES[name][0].split(".")[0].replace("_", "-")
        raise UsageError(f"planner {name!r} is a unified-planning engine that is not installed "
                         f"(pip install {package})")
    choices = [*PLANNERS, *known]
    choices.remove("command")
    close = difflib.get_close_matches(name, choices, n=1)
    hint = f"did you mean {close[0]!r}? " if close else ""
    raise UnknownPlanner(f"unknown planner {name!r}; {hint}planners here: {', '.join(choices)}")


#: Any name not registered: a unified-planning engine, checked against UP's factory.
UP_ENGINE = Planner("up", "a unified-planning one-shot engine, by its factory name", _up_solve, _up_check)

PLANNERS: dict[str, Planner] = {p.name: p for p in (
    Planner("fd", "Fast Downward (lama-first; A* with LM-cut when optimal), translator and search run directly",
            _fd_solve, _no_check, configurable=True, translate_once=_fd_translate_once),
    Planner("command", "an external planner command or preset, run without a shell; its plan file read back",
            _command_solve, _command_check),
)}


def register(planner: Planner) -> Planner:
    """Add (or replace) a planner entry; returns it."""
    PLANNERS[planner.name] = planner
    return planner


def lookup(name: str, command: str | None = None) -> Planner:
    """The entry that runs `name`: the `command` entry when a command is given, a registered entry, or
    else UP's engine entry (whose `check` says whether UP knows `name`)."""
    if command is not None:
        return PLANNERS["command"]
    return PLANNERS.get(name, UP_ENGINE)
