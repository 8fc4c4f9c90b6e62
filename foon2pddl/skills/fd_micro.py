"""Fast Downward on micro tasks: the translator run in this process, the search binary as `planners.fd` runs it.

A micro task is tiny (a handful of objects, five skills), so starting an interpreter
for the translator would cost more than translating. The installed translator
(`fast_downward.translate`, shipped in the wheel's `builds/release/bin`) takes its
options through `options.set_options`, so it is called in-process, its output
captured; calls are serialized (the translator keeps its options in a module
global). If the in-process translator cannot be imported, the translator
subprocess of `planners.fd` is used.

Search (`fd.search`): A* with h_max, so a skill plan is one of least cost (a robot
profile's skill costs count; no detours: lama-first, greedy, would carry the jars to
the workspace and back). A* on a task with many objects to move can take long (the
orders of independent moves), so a task with more than `OPTIMAL_MAX_GRASPABLE`
graspable objects, or whose A* search does not end within `OPTIMAL_SECONDS`, is
planned with `lama-first` (the only case in which the time a search takes, and so the
load of the host, can change a plan). On the 20 relational dish plans of the shared
subgraphs, A* searched 201 micro tasks (up to 7 graspable objects) in at most 0.13 s
each, none timed out, and 8 tasks (8 to 18 graspable objects) went to `lama-first`.
"""

from __future__ import annotations

import contextlib
import io
import sys
import tempfile
import threading
import time
from pathlib import Path

from ..planners import fd
from ..planners.process import ProcessRun
from ..planners.result import PlanResult

__all__ = ["solve_micro"]

_LOCK = threading.Lock()
NAME = "fd (lama-first)"
OPTIMAL_NAME = "fd (astar hmax)"
OPTIMAL_SEARCH = ("--search", "astar(hmax())")
OPTIMAL_MAX_GRASPABLE = 7
OPTIMAL_SECONDS = 5.0


def optimal_first(problem_text: str) -> bool:
    """Whether a micro task is small enough for A* first: at most OPTIMAL_MAX_GRASPABLE graspable objects."""
    return problem_text.count("(graspable ") <= OPTIMAL_MAX_GRASPABLE


def _translator():
    """The translator's (set_options, main), or None when it cannot be imported in-process."""
    try:
        path = str(fd.bin_dir())
        if path not in sys.path:
            sys.path.append(path)
        from fast_downward.translate.main import main
        from fast_downward.translate.options import set_options
    except Exception:  # noqa: BLE001 - any import failure falls back to the subprocess
        return None
    return set_options, main


def _translate(work: Path) -> ProcessRun:
    found = _translator()
    args = [str(work / "domain.pddl"), str(work / "problem.pddl"), "--sas-file", str(work / "output.sas")]
    if found is None:
        return fd.translate(work / "domain.pddl", work / "problem.pddl", work / "output.sas", work, None)
    set_options, main = found
    out = io.StringIO()
    t0 = time.perf_counter()
    code = 0
    with _LOCK, contextlib.redirect_stdout(out):
        try:
            set_options(args)
            main()
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 1
        except Exception as exc:  # noqa: BLE001 - a translator failure is a result, never a crash
            print(f"{type(exc).__name__}: {exc}")
            code = 30
    return ProcessRun(code, out.getvalue(), time.perf_counter() - t0)


def solve_micro(domain_text: str, problem_text: str, time_limit: float | None = 10.0) -> PlanResult:
    """Plan one micro task; the result's timings have `translate` and `search` (seconds)."""
    with tempfile.TemporaryDirectory(prefix="foon2pddl-skill-") as tmp:
        work = Path(tmp)
        (work / "domain.pddl").write_text(domain_text)
        (work / "problem.pddl").write_text(problem_text)
        run = _translate(work)
        failed = fd.translation_failure(run, NAME)
        if failed is not None:
            return failed
        try:
            result = None
            if optimal_first(problem_text):
                limit = OPTIMAL_SECONDS if time_limit is None else min(time_limit, OPTIMAL_SECONDS)
                result = fd.search(work, OPTIMAL_SEARCH, limit, OPTIMAL_NAME, sas_path=work / "output.sas")
            if result is None or result.status == "timeout":
                spent = result.timings.get("search", 0.0) if result is not None else 0.0
                left = None if time_limit is None else max(0.0, time_limit - spent)
                result = fd.search(work, fd.search_options(), left, NAME, sas_path=work / "output.sas")
                result = result.with_timings(search=result.timings.get("search", 0.0) + spent)
        except (fd.FastDownwardMissing, OSError) as exc:
            return PlanResult("error", (), NAME, str(exc), {"translate": run.seconds})
        return result.with_timings(translate=run.seconds)
