"""Any unified-planning engine by name (`pyperplan`, `fast-downward`, `symk`, ...).

Each solve runs in a child process (forked where possible) that starts its own
process group and works in its own temporary directory: the time limit holds
even for engines that ignore UP's `timeout` (pyperplan runs in-process), the
whole group is killed when it runs out, and engines that write into the
current directory (Fast Downward through UP writes `output.sas` there) never
share one. The child builds the UP problem with `to_up_problem` and sends back
plain data: status, plan steps and a message.
"""

from __future__ import annotations

import multiprocessing
import os
import tempfile
import time
from typing import Any

from ..io.interrupts import signals_deferred
from ..pddl.task import PlanningTask
from .cleanup import MARK, kill_group, kill_marked, new_token
from .process import bounded_timeout
from .result import PlanResult

#: UP's PlanGenerationResultStatus names -> our statuses.
UP_STATUS = {
    "SOLVED_SATISFICING": "solved",
    "SOLVED_OPTIMALLY": "solved",
    "INTERMEDIATE": "solved",
    "UNSOLVABLE_PROVEN": "unsolvable",
    "UNSOLVABLE_INCOMPLETELY": "gave up",
    "TIMEOUT": "timeout",
    "MEMOUT": "error",
    "INTERNAL_ERROR": "error",
    "UNSUPPORTED_PROBLEM": "error",
}


def engine_names(env: Any = None) -> list[str]:
    """Names of the one-shot planning engines UP can find (imports unified-planning)."""
    if env is None:
        from ..pddl.up_problem import quiet_environment

        env = quiet_environment()
    return sorted(n for n in env.factory.engines
                  if getattr(env.factory.engine(n), "is_oneshot_planner", lambda: False)())


def _pick_engine(env: Any, name: str, optimal: bool) -> tuple[str, str | None]:
    """The engine name to use, or an error message."""
    from unified_planning.engines import OptimalityGuarantee

    known = engine_names(env)
    if name not in known:
        return name, f"unknown planner {name!r}; planners here: fd, {', '.join(known)} (unified-planning engines)"
    if optimal:
        for candidate in (name, f"{name}-opt"):
            if candidate in known and env.factory.engine(candidate).satisfies(OptimalityGuarantee.SOLVED_OPTIMALLY):
                return candidate, None
        return name, f"engine {name!r} gives no optimality guarantee (and there is no {name}-opt)"
    return name, None


def _read_pddl(texts: tuple[str, str]) -> tuple[Any, Any]:
    """(UP problem, plan step of an action instance) of PDDL (domain, problem) text, as UP's reader reads it."""
    from unified_planning.io import PDDLReader

    problem = PDDLReader().parse_problem_string(*texts)
    return problem, lambda ai: " ".join((ai.action.name, *map(str, ai.actual_parameters))).lower()


def _solve_here(task: PlanningTask | tuple[str, str], name: str, optimal: bool
                ) -> tuple[str, tuple[str, ...], str, str]:
    """Build the UP problem (from the task, or read from PDDL (domain, problem) text) and solve it in this
    process: (status, steps, message, engine used: `--optimal` may pick `NAME-opt`)."""
    from unified_planning.shortcuts import OneshotPlanner

    from ..pddl.untyped import untyped
    from ..pddl.up_problem import build_up, quiet_environment

    env = quiet_environment()
    engine, problem_msg = _pick_engine(env, name, optimal)
    if problem_msg:
        return "error", (), problem_msg, name
    if isinstance(task, tuple):
        problem, step = _read_pddl(task)
    else:
        up = build_up(task)
        problem, step = up.problem, up.step
    with OneshotPlanner(name=engine) as planner:
        if not planner.supports(problem.kind) and not isinstance(task, tuple) and task.uses_types:
            up = build_up(untyped(task))  # an engine without subtypes (Tamer): the same task, types as predicates
            problem, step = up.problem, up.step
        if not planner.supports(problem.kind):
            return "error", (), f"engine {engine!r} does not support this task's features", engine
        res = planner.solve(problem)  # the parent enforces the time limit
    status = UP_STATUS.get(res.status.name, "error")
    steps: tuple[str, ...] = ()
    if res.plan is not None and status == "solved":
        steps = tuple(step(ai) for ai in res.plan.actions)
    log = " ".join(str(m.message) for m in (res.log_messages or []))[-500:]
    return (status, steps, f"{engine}: {res.status.name.lower()}" + (f" ({log})" if status == "error" and log else ""),
            engine)


def _child(conn: Any, task: PlanningTask | tuple[str, str], name: str, optimal: bool, work: str, token: str) -> None:
    os.setsid()
    os.environ[MARK] = token  # processes the engine starts inherit the mark
    try:
        os.chdir(work)
        conn.send(_solve_here(task, name, optimal))
    except BaseException as exc:  # report, never hang the parent
        conn.send(("error", (), f"{type(exc).__name__}: {exc}", name))
    finally:
        conn.close()


def _context() -> Any:
    methods = multiprocessing.get_all_start_methods()
    return multiprocessing.get_context("fork" if "fork" in methods else "spawn")


def solve(task: PlanningTask | tuple[str, str], engine: str, *, optimal: bool = False,
          time_limit: float | None = None) -> PlanResult:
    """Plan with a UP engine in a child process, killed (with its process group and every process
    carrying its mark) when it answers or at the time limit; its work directory is removed here.
    `task` may be PDDL (domain, problem) text, read by UP's PDDL reader in the child (as a user's files)."""
    name = f"up:{engine}"
    ctx = _context()
    token = new_token()
    t0 = time.perf_counter()
    data = None
    with tempfile.TemporaryDirectory(prefix="foon2pddl-up-") as work:
        recv, send = ctx.Pipe(duplex=False)
        proc = ctx.Process(target=_child, args=(send, task, engine, optimal, work, token), daemon=True)
        try:
            proc.start()  # not under signals_deferred: the fork would inherit the blocked mask
            send.close()
            if recv.poll(bounded_timeout(time_limit)):
                data = recv.recv()
        except EOFError:
            data = ("error", (), f"engine process died (exit code {proc.exitcode})", engine)
        finally:
            with signals_deferred():
                if proc.is_alive():
                    kill_group(proc.pid, proc.kill)
                kill_marked(token)
                if proc.pid is not None:
                    proc.join()
                recv.close()
    seconds = time.perf_counter() - t0
    if data is None:
        return PlanResult("timeout", (), name, "time limit reached", {"search": seconds})
    status, steps, message, used = data
    return PlanResult(status, tuple(steps), f"up:{used}", message, {"search": seconds})
