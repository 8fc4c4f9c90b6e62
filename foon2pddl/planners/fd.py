"""Fast Downward from the `up-fast-downward` wheel, run as its driver runs it.

The driver (`downward/fast-downward.py`) runs two components: the Python
translator (`python -m fast_downward.translate`, with the wheel's
`builds/release/bin` first on PYTHONPATH) and the `downward` search binary,
fed the translated SAS task on stdin. We run the same two commands ourselves:
it saves one interpreter start per plan, times translation and search
separately, and lets `fd_reuse` search a translated task many times. Search
configurations come from the driver's own `aliases.py` (`lama-first` by
default; `seq-opt-lmcut`, A* with LM-cut, for `optimal=True`).

Every run works in its own temporary directory: the translator writes its
SAS file there, so concurrent solves never read each other's files.
The package is located without importing it (importing `up_fast_downward`
imports unified-planning, ~1.5 s).
"""

from __future__ import annotations

import importlib.util
import os
import signal
import sys
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from functools import cache, lru_cache
from pathlib import Path

from ..errors import MissingDependencyError, UsageError
from .process import ProcessRun, remaining, run_process
from .result import PlanResult, parse_plan_text, tail

SATISFICING_ALIAS = "lama-first"
OPTIMAL_ALIAS = "seq-opt-lmcut"
#: `optimal` on a task with conditional effects, which LM-cut refuses: A* with h^max, admissible and takes them.
OPTIMAL_CONDITIONAL_SEARCH = "astar(hmax())"

#: Exit codes of the FD components (driver/returncodes.py) -> (status, meaning).
EXIT_CODES: dict[int, tuple[str, str]] = {
    0: ("solved", "plan found"),
    1: ("solved", "plan found, then out of memory"),
    2: ("solved", "plan found, then out of time"),
    3: ("solved", "plan found, then out of memory and time"),
    10: ("unsolvable", "translator proved the task unsolvable"),
    11: ("unsolvable", "search proved the task unsolvable"),
    12: ("gave up", "search space exhausted without a plan (incomplete search)"),
    13: ("gave up", "no plan within the cost bound"),
    20: ("error", "translator out of memory"),
    21: ("timeout", "translator time limit"),
    22: ("error", "search out of memory"),
    23: ("timeout", "search time limit"),
    24: ("error", "search out of memory and time"),
    30: ("error", "translator critical error"),
    31: ("error", "translator input error (PDDL not accepted)"),
    32: ("error", "search critical error"),
    33: ("error", "search input error"),
    34: ("error", "search does not support this task"),
    35: ("error", "driver critical error"),
    36: ("error", "driver input error"),
    37: ("error", "driver unsupported"),
}


def exit_status(code: int) -> tuple[str, str]:
    """(status, meaning) of a Fast Downward exit code; unknown codes and signals are errors."""
    if code in EXIT_CODES:
        return EXIT_CODES[code]
    if code < 0:
        return "error", f"killed by signal {-code}"
    return "error", f"unexpected exit code {code}"


#: How to install Fast Downward (the wheel ships the translator and the search binary).
INSTALL_HINT = "pip install 'up-fast-downward' (make install does)"
#: A fresh translator's script: FD's translator with rewrites of its own, the same SAS file (`planners.fd_speedups`).
SPEEDUPS = Path(__file__).with_name("fd_speedups.py")


class FastDownwardMissing(MissingDependencyError):
    """The up-fast-downward wheel (or its search binary) is not installed."""

    def __init__(self, message: str) -> None:
        super().__init__(message, INSTALL_HINT)


@lru_cache(maxsize=1)
def downward_dir() -> Path:
    """`up_fast_downward/downward` inside the installed wheel."""
    spec = importlib.util.find_spec("up_fast_downward")
    if spec is None or not spec.submodule_search_locations:
        raise FastDownwardMissing("the up-fast-downward package is not installed")
    path = Path(next(iter(spec.submodule_search_locations))) / "downward"
    if not (path / "fast-downward.py").is_file():
        raise FastDownwardMissing(f"no Fast Downward driver under {path}")
    return path


def bin_dir() -> Path:
    return downward_dir() / "builds" / "release" / "bin"


def search_binary() -> Path:
    """The `downward` search executable."""
    path = bin_dir() / "downward"
    if not os.access(path, os.X_OK):
        raise FastDownwardMissing(f"Fast Downward search binary missing or not executable: {path}")
    return path


@cache
def driver_aliases() -> dict[str, tuple[str, ...]]:
    """The driver's alias table (`driver/aliases.py`: `ALIASES`), as the driver builds it.

    Some aliases are computed (`seq-sat-lama-2011` and `lama` call a helper), so the file
    is run on its own, with its one import (`DRIVER_DIR`) supplied, not imported as part
    of the driver package. Portfolios (run by the driver's portfolio runner) are not
    aliases of the search binary and are left out.
    """
    path = downward_dir() / "driver" / "aliases.py"
    source = path.read_text().replace("from .util import DRIVER_DIR", "")
    namespace: dict = {"DRIVER_DIR": path.parent, "__name__": "fd_driver_aliases"}
    exec(compile(source, str(path), "exec"), namespace)  # noqa: S102 - the installed FD's own table
    # The driver strips blanks the same way (aliases.set_options_for_alias).
    return {name: tuple(x.replace(" ", "").replace("\n", "") for x in options)
            for name, options in namespace["ALIASES"].items()}


class UnknownAlias(UsageError, KeyError):
    """An alias the installed driver does not define (a KeyError too, for callers that look it up)."""

    def __str__(self) -> str:  # KeyError would quote the message
        return self.message


def alias_options(alias: str) -> tuple[str, ...]:
    """Search options of a driver alias."""
    table = driver_aliases()
    if alias not in table:
        raise UnknownAlias(f"no Fast Downward alias {alias!r} in the driver's aliases.py")
    return table[alias]


def alias_names() -> tuple[str, ...]:
    """Every alias of the driver's table, sorted."""
    return tuple(sorted(driver_aliases()))


#: Translator options for tasks without delete effects: with nothing deleted there are no
#: mutexes to find, so invariant synthesis is skipped (~30 % of translation at 1,800 actions).
DELETE_FREE_OPTIONS = ("--invariant-generation-max-candidates", "0")


def translate_options_for(task) -> tuple[str, ...]:
    """Translator options suited to a PlanningTask."""
    return DELETE_FREE_OPTIONS if not any(a.delete or a.conditional for a in task.actions) else ()


def search_options(optimal: bool = False) -> tuple[str, ...]:
    return alias_options(OPTIMAL_ALIAS if optimal else SATISFICING_ALIAS)


@dataclass(frozen=True)
class SearchConfig:
    """A search configuration as Fast Downward's driver takes it: `--alias NAME`, or `--search S` with
    `--evaluator E` definitions (passed to the search binary verbatim, in the driver's order)."""

    label: str
    options: tuple[str, ...]

    @property
    def name(self) -> str:
        return f"fd ({self.label})"


def search_config(alias: str | None = None, search: str | None = None, evaluators: Sequence[str] = (),
                  optimal: bool = False) -> SearchConfig:
    """The configuration for the driver-style options; neither given: lama-first (seq-opt-lmcut when
    `optimal`). Raises ValueError for an unknown alias or options that do not go together."""
    if alias is not None and search is not None:
        raise ValueError("give --alias or --search, not both (as Fast Downward's driver)")
    if evaluators and search is None:
        raise ValueError("--evaluator defines an evaluator for --search; give --search too")
    if optimal and (alias is not None or search is not None):
        raise ValueError("--optimal chooses an optimal search itself (seq-opt-lmcut, or astar(hmax()) on a task with "
                         "conditional effects such as the relational encoding's); drop it or --alias/--search")
    if search is not None:
        if not search.strip():
            raise ValueError("empty --search")
        return SearchConfig("custom", (*(x for e in evaluators for x in ("--evaluator", e)), "--search", search))
    name = alias if alias is not None else (OPTIMAL_ALIAS if optimal else SATISFICING_ALIAS)
    try:
        return SearchConfig(name, alias_options(name))
    except KeyError:
        import difflib

        known = alias_names()
        close = difflib.get_close_matches(name, known, n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        raise ValueError(f"unknown Fast Downward alias {name!r}; {hint}aliases: {', '.join(known)}") from None


def optimal_config(task) -> SearchConfig | None:
    """The admissible search for `optimal` when `task` (a PlanningTask) has conditional effects, which
    `seq-opt-lmcut`'s LM-cut refuses: A* with h^max (`OPTIMAL_CONDITIONAL_SEARCH`); None otherwise (the alias)."""
    if not any(a.conditional for a in task.actions):
        return None
    return SearchConfig(OPTIMAL_CONDITIONAL_SEARCH, ("--search", OPTIMAL_CONDITIONAL_SEARCH))


def planner_name(optimal: bool) -> str:
    return f"fd ({OPTIMAL_ALIAS if optimal else SATISFICING_ALIAS})"


def translate(domain: Path, problem: Path, sas: Path, cwd: Path, timeout: float | None,
              options: tuple[str, ...] = (), memory_limit_mb: int | None = None,
              cpu: float | None = None) -> ProcessRun:
    """Run FD's translator on PDDL files, writing the SAS task to `sas`: in a child of the warm
    translator server (`planners.translator`) when it is free, else in a fresh interpreter. `cpu`: a CPU
    budget (seconds; past it the translator exits with its time limit's code)."""
    from . import translator

    args = [str(domain), str(problem), "--sas-file", str(sas), *options]
    warm = translator.run(args, cwd, timeout, bin_dir(), memory_limit_mb, cpu)
    if warm is not None:
        return warm
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(bin_dir()), env.get("PYTHONPATH", "")) if p)
    cmd = [sys.executable, str(SPEEDUPS), *args]  # `python -m fast_downward.translate`, sped up (same SAS file)
    return run_process(cmd, cwd, timeout, env=env, memory_limit_mb=memory_limit_mb, cpu=cpu)


def prestart_translator() -> None:
    """Start the warm translator now (see `planners.translator`), when Fast Downward is installed."""
    from . import translator

    try:
        translator.prestart(bin_dir())
    except FastDownwardMissing:
        pass


def translation_failure(run: ProcessRun, name: str) -> PlanResult | None:
    """The result to report when a translator run did not produce a usable task, else None."""
    timings = {"translate": run.seconds}
    if run.timed_out:
        return PlanResult("timeout", (), name, "time limit reached during translation", timings)
    if run.returncode != 0:
        status, meaning = exit_status(30 if run.returncode == 1 else run.returncode)
        return PlanResult(status, (), name, f"{meaning}: {tail(run.output)}", timings)
    for line in run.output.splitlines():
        if "Generating unsolvable task" in line:  # e.g. "No relaxed solution! Generating unsolvable task..."
            reason = line.split("!", 1)[0].strip().lower() or "goal unreachable"
            return PlanResult("unsolvable", (), name, f"translator: {reason}", timings)
    return None


def _best_plan_file(cwd: Path) -> Path | None:
    """`sas_plan`, or for anytime searches the last (best) of `sas_plan.1`, `sas_plan.2`, ..."""
    if (cwd / "sas_plan").is_file():
        return cwd / "sas_plan"
    numbered = [(int(p.suffix[1:]), p) for p in cwd.glob("sas_plan.*") if p.suffix[1:].isdigit()]
    return max(numbered)[1] if numbered else None


def search(cwd: Path, options: tuple[str, ...], timeout: float | None, name: str, *,
           sas_path: Path | None = None, sas_text: str | None = None,
           memory_limit_mb: int | None = None, cpu: float | None = None) -> PlanResult:
    """Run the search binary on a SAS task (file or text) and read its plan file. `cpu`: a CPU budget
    (seconds); the search killed at it (SIGXCPU) is a time limit, as at `timeout`."""
    plan_file = cwd / "sas_plan"
    for old in (plan_file, *cwd.glob("sas_plan.*")):
        old.unlink(missing_ok=True)
    if (timeout is not None and timeout <= 0) or (cpu is not None and cpu <= 0):
        return PlanResult("timeout", (), name, "time limit reached before search", {"search": 0.0}, cpu=0.0)
    cmd = [str(search_binary()), *options, "--internal-plan-file", str(plan_file)]
    run = run_process(cmd, cwd, timeout, stdin_path=sas_path, stdin_text=sas_text, memory_limit_mb=memory_limit_mb,
                      cpu=cpu)
    if run.returncode == -signal.SIGXCPU:
        run = replace(run, returncode=None)  # its CPU budget: a time limit (FD's driver reads it so too)
    timings = {"search": run.seconds}
    best = _best_plan_file(cwd)
    if run.timed_out:
        if best is not None:  # an anytime search (seq-sat-lama-2011, ...) had improved plans: FD's code 2
            return PlanResult("solved", parse_plan_text(best.read_text()), name, EXIT_CODES[2][1], timings, cpu=run.cpu)
        return PlanResult("timeout", (), name, "time limit reached during search", timings, cpu=run.cpu)
    status, meaning = exit_status(run.returncode)
    if status == "solved":
        if best is None:
            return PlanResult("error", (), name, f"exit code {run.returncode} but no plan file: {tail(run.output)}", timings,
                              cpu=run.cpu)
        return PlanResult("solved", parse_plan_text(best.read_text()), name, meaning, timings, cpu=run.cpu)
    message = meaning if status in ("unsolvable", "gave up") else f"{meaning}: {tail(run.output)}"
    return PlanResult(status, (), name, message, timings, cpu=run.cpu)


def solve(domain_text: str, problem_text: str, *, optimal: bool = False, time_limit: float | None = None,
          options: tuple[str, ...] | None = None, translate_options: tuple[str, ...] = (),
          memory_limit_mb: int | None = None, config: SearchConfig | None = None,
          cpu_limit: float | None = None) -> PlanResult:
    """Plan with Fast Downward on PDDL text. `config` (or raw `options`) overrides the search configuration.
    `cpu_limit`: CPU seconds translation and search may use together (the search gets what translation left),
    beside the wall-clock `time_limit`: a loaded machine stretches wall time, not CPU time. The result's `cpu`
    is what they used."""
    deadline = None if time_limit is None else time.monotonic() + time_limit
    name = planner_name(optimal) if options is None else "fd (custom)"
    if config is not None:
        name, options = config.name, config.options
    try:
        opts = search_options(optimal) if options is None else tuple(options)
        with tempfile.TemporaryDirectory(prefix="foon2pddl-fd-") as tmp:
            work = Path(tmp)
            t0 = time.perf_counter()
            (work / "domain.pddl").write_text(domain_text)
            (work / "problem.pddl").write_text(problem_text)
            write_s = time.perf_counter() - t0
            sas = work / "output.sas"
            run = translate(work / "domain.pddl", work / "problem.pddl", sas, work, remaining(deadline),
                            translate_options, memory_limit_mb=memory_limit_mb, cpu=cpu_limit)
            used = run.cpu if run.cpu is not None else run.seconds  # wall time bounds a one-thread run's CPU
            failed = translation_failure(run, name)
            if failed is not None:
                return replace(failed.with_timings(write=write_s), cpu=used)
            result = search(work, opts, remaining(deadline), name, sas_path=sas, memory_limit_mb=memory_limit_mb,
                            cpu=None if cpu_limit is None else cpu_limit - used)
            return replace(result.with_timings(write=write_s, translate=run.seconds), cpu=used + (result.cpu or 0.0))
    except (FastDownwardMissing, OSError) as exc:
        return PlanResult("error", (), name, str(exc))
