"""Running an experiment: what is already done, batches to an engine, records appended.

The cells (point of the sweep, trial, goal, network, solver) not already in the results file are grouped into
batches (`grid.plan_batches`: at most `grid.CHUNK` goals of one point, trial, network and solver, costliest solvers
and largest networks first). Batches run in this process (`jobs` 1) or on Dask (`engine.py`: a LocalCluster of
`jobs` workers, or an existing cluster's `scheduler`); every finished cell is appended to the JSONL file at
once in this process. A rerun reads the file and skips the cells already done: an interrupted run resumes, and
cells that ended in an error or were lost with their worker are redone, as are cells recorded for another goal
or under another time limit (`records.reusable`).

Before any work (no file written, no network built) `check_requirements` refuses a
run whose networks or engine need something missing (WordNet for EXP, Dask for
`jobs` > 1 or a scheduler) or whose scheduler is not one. A write that fails (a
full disk, a read-only directory) is a `FoonInputError`; every record appended
before it stays, so the same command resumes once there is room.
"""

from __future__ import annotations

import json
import shutil
import tempfile
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import FoonInputError, UsageError
from ..io.atomic import atomic_write
from ..io.steps import Step, silent_step
from . import collector
from .config import Config
from .engine import check_scheduler, require_dask, run_dask, run_here
from .grid import cell_keys, cell_labels, cells, plan_batches, trials_at
from .networks import NETWORKS, NetworkView
from .params import Point, check_grid
from .progress import LINE_INTERVAL, OFF, Progress, default_mode
from .protocol import Trial, identity_difference
from .provenance import code_version
from .records import Key, Record, append, open_for_append, read_records, reusable
from .solvers import get_solver
from .worker import Batch, Job, draw_at, fingerprint, has_view, input_files, view

__all__ = ["RunSummary", "run", "views", "input_files", "fingerprint", "read_runs"]

PROTOCOL = "protocol.json"
RUNS = "runs.jsonl"  # a line per invocation that computed cells: cells, jobs, seconds (cells, set-up), code


@dataclass(frozen=True)
class RunSummary:
    """What a run did: the trials, the cells it ran and skipped, its wall time, all records of its cells."""

    trials: tuple[Trial, ...]  # of the first point of the sweep
    ran: int
    skipped: int
    seconds: float
    records: tuple[Record, ...]
    default_kitchen: int = 0  # nodes in the default kitchen trials sample from
    goal_pool: int = 0  # nodes goals are drawn from
    history: tuple[dict, ...] = ()  # the invocations that computed cells in this directory (runs.jsonl)
    warnings: tuple[str, ...] = ()  # damaged result lines skipped
    points: tuple[Point, ...] = ((),)
    lost: int = 0  # cells of this invocation lost with their worker (a rerun redoes them)
    cell_seconds: float = 0.0  # of `seconds`, those running the cells (the progress bar's elapsed time)


# -- protocol.json -------------------------------------------------------------------------------

class OtherResults(FoonInputError):
    """The output directory holds results that cannot be matched to this run's protocol (start afresh or elsewhere)."""


def check_protocol(config: Config, trials: tuple[Trial, ...]) -> float | None:
    """Write protocol.json, or refuse when the directory holds results of another (or an unknown) protocol;
    return the time limit the previous protocol.json recorded (None without results)."""
    path = config.out_dir / PROTOCOL
    identity = config.identity()
    results = config.results_path
    old_limit = None
    if results.is_file() and results.stat().st_size > 0:
        try:
            previous = json.loads(path.read_text(encoding="utf-8"))
            old = previous.get("identity")
            old_limit = previous.get("time_limit")
        except (OSError, ValueError, AttributeError, RecursionError):
            raise OtherResults(str(path), 0, f"{results} holds results but this protocol file is missing or "
                                             "unreadable, so they cannot be matched to a protocol") from None
        if old != identity:
            raise OtherResults(str(path), 0, "this directory holds results of another protocol or input: "
                               + identity_difference(old, identity)
                               + "; the same parameters and inputs resume them")
    data = {
        "identity": identity,
        "trials": config.protocol.trials,
        "goals": config.protocol.goals,
        "networks": list(config.networks),
        "solvers": list(config.solvers),
        "paths": list(config.paths),
        "time_limit": config.time_limit,
        "goal_limits": dict(config.goal_limits),
        "per_trial": [t.summary() for t in trials],
    }
    if config.sweeps:
        data["sweeps"] = {name: list(values) for name, values in config.sweeps}
    atomic_write(path, json.dumps(data, indent=1, sort_keys=True, ensure_ascii=False) + "\n")
    return old_limit if isinstance(old_limit, int | float) and not isinstance(old_limit, bool) else None


def check_requirements(config: Config, step: Step = silent_step) -> None:
    """Refuse, before any work, a run that needs what is missing: a network kind's dependencies (WordNet for
    EXP), Dask for a cluster, a scheduler that is not one (MissingDependencyError, UsageError, FoonError)."""
    for name in config.networks:
        NETWORKS[name].requires()
    if config.scheduler is not None or config.jobs > 1:
        require_dask()
    if config.scheduler is not None:
        check_scheduler(config.scheduler, step=step)  # a host that never answers: its 10 s, said


# -- running -------------------------------------------------------------------------------------

def build_networks(config: Config, batches: list[Batch]) -> None:
    """Build (and cache in this process) the network views `batches` need: a local run does it before the
    first cell, so local workers, forked, inherit them (each built once). A view that fails to build is not
    cached: its batches try again and record the error."""
    for point, network in dict.fromkeys((b.point, b.network) for b in batches):
        try:
            view(config.paths, config.protocol, point, network)
        except Exception:  # noqa: BLE001 - recorded by the batches that need it
            pass


def run_cells(config: Config, batches: list[Batch], sink: Callable[[Record], None], progress: Progress,
              settle: Callable[[], None] = lambda: None, step: Step = silent_step) -> None:
    """Run `batches` here or on Dask, passing every record to `sink` in this process as it arrives; `settle`
    (`collector.building`) is called before the first cell (a local run has built its networks by then);
    `step` wraps the slow end of a Dask run (`engine.run_dask`)."""
    # Translations are shared through a private directory on this machine (fd-tree and fd-tree-opt translate
    # the same task; local workers see the directory, a remote cluster's may not).
    cache = tempfile.mkdtemp(prefix="foon2pddl-sas-") if config.scheduler is None else None
    job = Job(config.paths, fingerprint(config.paths), config.protocol, config.time_limit, cache)
    try:
        settle()
        if config.scheduler is None and config.jobs <= 1:
            run_here(batches, job, sink, progress)
        else:
            run_dask(batches, job, sink, progress, jobs=config.jobs, scheduler=config.scheduler,
                     no_worker_limit=config.no_worker_limit, step=step)
    finally:
        progress.close()
        if cache is not None:
            shutil.rmtree(cache, ignore_errors=True)


def run(config: Config, progress: bool | str = True, fresh: bool = False, step: Step = silent_step,
        every: float = LINE_INTERVAL) -> RunSummary:
    """Run every cell of `config` not already in its results file (all of them when `fresh`); return all records
    of its cells. `progress`: True (a bar on a terminal, lines otherwise), False, or a mode; `step(what)`: a context
    manager around each slow set-up step (the CLI's `slow_step`); `every`: seconds between log lines (its beat)."""
    with collector.building() as settle:  # no garbage collection while the networks are built
        return _run(config, progress, fresh, settle, step, every)


def _run(config: Config, progress: bool | str, fresh: bool, settle: Callable[[], None], step: Step,
         every: float) -> RunSummary:
    t0 = time.perf_counter()
    for name in config.solvers:
        get_solver(name)
    for name in config.networks:
        if name not in NETWORKS:
            raise UsageError(f"unknown network {name!r} (expected one of {', '.join(NETWORKS)})")
    check_grid(config.sweeps)
    check_requirements(config, step)
    try:
        return _run_checked(config, progress, fresh, settle, t0, step, every)
    except OSError as exc:  # a full disk, a read-only directory: what was appended stays, a rerun resumes
        where = exc.filename or config.out_dir
        raise FoonInputError(str(where), 0, f"cannot write: {exc.strerror or exc}; the cells recorded so far are "
                                            "kept, and running the same command again resumes") from None


def _run_checked(config: Config, progress: bool | str, fresh: bool, settle: Callable[[], None],
                 t0: float, step: Step, every: float) -> RunSummary:
    with step("drawing the trials (kitchens and goals) and reading the cells already run"):
        first = config.points[0]
        trials = trials_at(config, first)
        config.out_dir.mkdir(parents=True, exist_ok=True)
        if config.results_path.exists() and not config.results_path.is_file():
            raise FoonInputError(str(config.results_path), 0, "not a results file (a directory or a special file); "
                                                              "remove it or use another -o directory")
        if fresh:
            config.results_path.unlink(missing_ok=True)
            (config.out_dir / RUNS).unlink(missing_ok=True)
        old_limit = check_protocol(config, trials)
        warnings: list[str] = []
        grid = cells(config)
        done = reusable(read_records(config.results_path, warnings), cell_labels(config, grid), config.time_limit,
                        old_limit)
        batches = plan_batches(config, done, grid)
    planned = sum(len(b.goals) for b in batches)
    written = [0, 0]  # cells written, of which lost
    running = 0.0  # seconds running the cells (the rest: reading, drawing, building the networks)
    if batches:
        if config.scheduler is None:
            kinds = ", ".join(NETWORKS[n].label for n in config.networks if n in {b.network for b in batches})
            with step(f"building the networks ({kinds}) before the first of {planned:,} cells"):
                build_networks(config, batches)
        mode = (default_mode() if progress else OFF) if isinstance(progress, bool) else progress
        groups: Counter = Counter()  # cells per (solver, network): `Progress.left` weighs them
        for b in batches:
            groups[b.solver, b.network] += len(b.goals)
        bar = Progress(planned, mode, interval=every, groups=groups)
        for w in warnings:
            bar.note(w)
        t_run = time.perf_counter()

        def sink(record: Record) -> None:
            append(fh, record)
            written[0] += 1
            written[1] += record.status == "lost"

        try:
            with open_for_append(config.results_path) as fh:
                run_cells(config, batches, sink, bar, settle, step)
        finally:
            running = time.perf_counter() - t_run
            log = {"cells": written[0], "planned": planned, "jobs": config.jobs, **code_version(),
                   "seconds": round(running, 3), "setup_seconds": round(t_run - t0, 3), "solvers": sorted({b.solver for b in batches})}
            if config.scheduler:
                log["scheduler"] = config.scheduler
            try:
                with open(config.out_dir / RUNS, "a", encoding="utf-8") as fh:
                    fh.write(json.dumps(log, sort_keys=True) + "\n")
            except OSError:
                pass  # the log is informative only; a failed append of results is what is reported
    # every cell's record parsed again (6,000 of the README's quick run: 1.5 s at load 12, after the bar's last line)
    with step(f"reading the results back ({config.results_path})"):
        records = read_records(config.results_path)
        keys = cell_keys(config, grid)
        mine = tuple(records[k] for k in sorted(keys, key=_sortable) if k in records)
        drawn = draw_at(config.paths, config.protocol, first)
    return RunSummary(trials, written[0], len(keys) - planned, time.perf_counter() - t0, mine, len(drawn.kitchen),
                      len(drawn.pool), read_runs(config.out_dir / RUNS), tuple(warnings), config.points,
                      written[1], running)


def _sortable(key: Key) -> tuple:
    return (*key[:4], repr(key[4]))


def read_runs(path: Path) -> tuple[dict, ...]:
    """The invocations logged in runs.jsonl (a damaged line is skipped: the log is informative only)."""
    if not path.is_file():
        return ()
    out = []
    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        try:
            entry = json.loads(line)
        except (ValueError, RecursionError):
            continue
        if isinstance(entry, dict):
            out.append(entry)
    return tuple(out)


def views(config: Config, point: Point | None = None) -> list[NetworkView]:
    """The run's network views at `point` (the first of the sweep by default), built once per process."""
    point = config.points[0] if point is None else point
    return [view(config.paths, config.protocol, point, n) for n in config.networks]


def unbuilt(config: Config) -> list[str]:
    """The networks `views` would build now (none when this process ran cells on them)."""
    return [n for n in config.networks if not has_view(config.paths, config.protocol, config.points[0], n)]
