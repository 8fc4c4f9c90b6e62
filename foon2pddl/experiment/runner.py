"""Running an experiment: batches of cells in worker processes, results appended as they finish.

The cells (trial, goal, network, solver) not already in the results file are
grouped into batches, one per (trial, network, solver), so that what a solver
prepares once (a fixpoint, an FD translation) serves every goal of the batch.
Batches run in `jobs` worker processes (`multiprocessing.Pool`, longest kinds
first); each worker sends every finished cell back through a queue and the
main process appends it to the JSONL file at once and advances the progress
bar (tqdm, on stderr). FD runs each search in its own temporary directory
(`pddl.planners.fd`), so concurrent workers never share files. A rerun reads
the file and skips the cells already done: an interrupted run resumes.
"""

from __future__ import annotations

import json
import multiprocessing
import queue as queue_mod
import signal
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from ..errors import FoonInputError
from ..io.atomic import atomic_write
from ..io.files import expand_paths
from ..io.inputs import example_path, load_network
from ..model.kitchen import default_kitchen
from .networks import NETWORKS, NetworkView, build_view
from .protocol import Protocol, Trial, goal_pool, make_trials
from .records import Record, append, done_keys, open_for_append, read_records
from .solvers import DEFAULT_TIME_LIMIT, Outcome, Setting, get_solver

RESULTS = "results.jsonl"
PROTOCOL = "protocol.json"
RUNS = "runs.jsonl"  # one line per invocation that computed cells: cells, jobs, wall seconds
#: Longest reason kept in a record (unreachable goals can list many missing nodes).
REASON_MAX = 300

#: Batches of slower solvers and larger networks are started first (better load balance).
_COST_ORDER = ("fd-state", "fd-tree-opt", "fd-lifted-gen", "fd-tree", "native-optimal", "native-greedy",
               "native-complete")
_NETWORK_ORDER = ("exp", "gen", "reg")


@dataclass(frozen=True)
class Config:
    """Everything that defines a run: inputs, protocol, what to compare, where results go."""

    paths: tuple[str, ...]
    protocol: Protocol
    networks: tuple[str, ...]
    solvers: tuple[str, ...]
    out_dir: Path
    jobs: int = 1
    time_limit: float = DEFAULT_TIME_LIMIT
    goal_limits: tuple[tuple[str, int], ...] = ()  # (solver, n): that solver gets the first n goals of a trial

    @property
    def results_path(self) -> Path:
        return self.out_dir / RESULTS

    def goals_for(self, solver: str, trial: Trial) -> range:
        """1-based indexes of the goals of `trial` that `solver` is asked (goal samples are prefix-stable)."""
        limit = dict(self.goal_limits).get(solver, len(trial.goals))
        return range(1, min(limit, len(trial.goals)) + 1)


@dataclass(frozen=True)
class Batch:
    """The pending goals (1-based indexes into the trial's goals) of one (trial, network, solver)."""

    trial: Trial
    network: str
    solver: str
    goals: tuple[int, ...]


@dataclass(frozen=True)
class RunSummary:
    """What a run did: the trials, the cells it ran and skipped, its wall time, all records of its cells."""

    trials: tuple[Trial, ...]
    ran: int
    skipped: int
    seconds: float
    records: tuple[Record, ...]
    default_kitchen: int = 0  # nodes in the default kitchen trials sample from
    goal_pool: int = 0  # nodes goals are drawn from
    history: tuple[dict, ...] = ()  # the invocations that computed cells in this directory (runs.jsonl)


# -- inputs --------------------------------------------------------------------------------------

def input_files(paths: Sequence[str]) -> list[Path]:
    """The FOON files a run reads (the embedded example when no path is given)."""
    return expand_paths(paths or [example_path()])


def fingerprint(paths: Sequence[str]) -> str:
    """SHA-256 over the names and contents of the input files: results belong to these exact inputs."""
    import hashlib

    h = hashlib.sha256()
    for p in input_files(paths):
        h.update(p.name.encode() + b"\0" + p.read_bytes() + b"\0")
    return h.hexdigest()


# -- worker side ---------------------------------------------------------------------------------

_WORKER: dict = {"networks": {}, "views": {}, "queue": None}


def _view(paths: tuple[str, ...], level: int, name: str) -> NetworkView:
    """The network view, built once per process (inherited from the parent when it forked)."""
    views = _WORKER["views"]
    if paths not in _WORKER["networks"]:
        _WORKER["networks"][paths] = load_network(list(paths))
    key = (paths, level, name)
    if key not in views:
        views[key] = build_view(name, _WORKER["networks"][paths], level)
    return views[key]


def _worker_init(q) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the main process's to handle
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # the main process stops workers with SIGTERM
    _WORKER["queue"] = q


def run_batch(batch: Batch, paths: tuple[str, ...], level: int, time_limit: float,
              emit: Callable[[Record], None] | None = None) -> int:
    """Run one batch, passing each cell's record to `emit` (the worker's queue by default) as it finishes.

    Never raises for a solver's failure: a failed preparation or goal becomes an `error` record,
    so every pending cell gets exactly one record.
    """
    emit = emit or _WORKER["queue"].put
    trial = batch.trial
    setup = 0.0
    prepared = None
    failure = ""
    try:
        view = _view(paths, level, batch.network)
        prepared = get_solver(batch.solver).prepare(Setting(view, trial.kitchen, time_limit))
        setup = prepared.setup
    except Exception as exc:  # noqa: BLE001 - recorded, the run goes on
        failure = f"preparation failed: {type(exc).__name__}: {exc}"
    for g in batch.goals:
        node = trial.goals[g - 1]
        if prepared is None:
            outcome = Outcome("error", failure)
        else:
            try:
                outcome = prepared.solve(node)
            except Exception as exc:  # noqa: BLE001 - recorded, the run goes on
                outcome = Outcome("error", f"{type(exc).__name__}: {exc}")
        reason = outcome.reason if len(outcome.reason) <= REASON_MAX else outcome.reason[:REASON_MAX - 3] + "..."
        emit(Record(trial.index, g, batch.network, batch.solver, node.describe(), outcome.status, reason,
                    outcome.times, setup, outcome.units, outcome.plan_length, outcome.validated,
                    outcome.proven_optimal, outcome.foon_valid))
    return len(batch.goals)


# -- main side -----------------------------------------------------------------------------------

def check_protocol(config: Config, trials: tuple[Trial, ...]) -> None:
    """Write protocol.json, or refuse when the directory holds results of another protocol or input."""
    path = config.out_dir / PROTOCOL
    identity = {**config.protocol.identity(), "inputs": fingerprint(config.paths)}
    if path.exists() and config.results_path.exists():
        try:
            old = json.loads(path.read_text(encoding="utf-8")).get("identity")
        except (OSError, ValueError):
            old = None
        if old != identity:
            raise FoonInputError(str(path), 0, "this directory holds results of another protocol or input "
                                               f"({old} != {identity}); use another -o directory or --fresh")
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
    atomic_write(path, json.dumps(data, indent=1, sort_keys=True, ensure_ascii=False) + "\n")


def plan_batches(config: Config, trials: tuple[Trial, ...], done: set) -> list[Batch]:
    """Batches of the cells not yet done, slowest kinds first."""
    batches = []
    for solver in config.solvers:
        spec = get_solver(solver)
        for network in config.networks:
            if not spec.applies_to(network):
                continue
            for trial in trials:
                pending = tuple(g for g in config.goals_for(solver, trial)
                                if (trial.index, g, network, solver) not in done)
                if pending:
                    batches.append(Batch(trial, network, solver, pending))

    def order(b: Batch) -> tuple:
        s = _COST_ORDER.index(b.solver) if b.solver in _COST_ORDER else -1
        n = _NETWORK_ORDER.index(b.network) if b.network in _NETWORK_ORDER else -1
        return (s, n, b.trial.index)

    return sorted(batches, key=order)


def run_cells(config: Config, batches: list[Batch], sink: Callable[[Record], None], progress: bool) -> None:
    """Run `batches`, passing every record to `sink` in the main process as soon as it arrives."""
    from tqdm import tqdm

    total = sum(len(b.goals) for b in batches)
    args = (config.paths, config.protocol.level, config.time_limit)
    stop = _interrupt_on_sigterm()
    tqdm.monitor_interval = 0  # no monitor thread: worker processes are forked while the bar runs
    bar = tqdm(total=total, unit="cell", desc="experiment", file=sys.stderr, disable=not progress or total == 0,
               dynamic_ncols=True, smoothing=0.05)
    try:
        if config.jobs <= 1 or len(batches) <= 1:
            for b in batches:
                run_batch(b, *args, emit=lambda r: (sink(r), bar.update(1)))
            return
        _run_parallel(config, batches, args, total, sink, bar)
    finally:
        bar.close()
        stop()


def _interrupt_on_sigterm() -> Callable[[], None]:
    """Make SIGTERM interrupt the run like Ctrl-C (workers stopped, records kept); returns the undo."""
    import threading

    if threading.current_thread() is not threading.main_thread():
        return lambda: None

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGTERM, interrupt)
    return lambda: signal.signal(signal.SIGTERM, previous)


def _run_parallel(config: Config, batches: list[Batch], args: tuple, total: int,
                  sink: Callable[[Record], None], bar) -> None:
    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    if ctx.get_start_method() == "fork":  # build the views once; the workers inherit them
        for network in sorted({b.network for b in batches}):
            _view(config.paths, config.protocol.level, network)
    q = ctx.Queue()
    pool = ctx.Pool(config.jobs, initializer=_worker_init, initargs=(q,))
    try:
        pending = [pool.apply_async(run_batch, (b, *args)) for b in batches]
        received = 0
        idle_since = None
        while received < total:
            record = _next(q)
            if record is not None:
                sink(record)
                received += 1
                bar.update(1)
                continue
            for job in pending:
                if job.ready() and not job.successful():
                    job.get()  # re-raises the worker's exception
            if all(job.ready() for job in pending):
                idle_since = idle_since or time.monotonic()
                if time.monotonic() - idle_since > 10:
                    raise RuntimeError(f"workers finished but {total - received} results never arrived")
        pool.close()
    except BaseException:
        pool.terminate()  # an interrupt or a failure: stop the workers now; written records stay
        raise
    finally:
        pool.join()


def _next(q, timeout: float = 0.2) -> Record | None:
    """The next record from the workers' queue, or None after `timeout` seconds."""
    try:
        return q.get(timeout=timeout)
    except queue_mod.Empty:
        return None


def run(config: Config, progress: bool = True, fresh: bool = False) -> RunSummary:
    """Run every cell of `config` not already in its results file (all of them when `fresh`);
    return all records of its cells."""
    t0 = time.perf_counter()
    for name in config.solvers:
        get_solver(name)
    for name in config.networks:
        if name not in NETWORKS:
            raise ValueError(f"unknown network {name!r} (expected one of {', '.join(NETWORKS)})")
    reg = _view(config.paths, config.protocol.level, "reg").foon
    trials = make_trials(reg, config.protocol)
    config.out_dir.mkdir(parents=True, exist_ok=True)
    if fresh:
        config.results_path.unlink(missing_ok=True)
        (config.out_dir / RUNS).unlink(missing_ok=True)
    check_protocol(config, trials)
    existing = read_records(config.results_path)
    done = done_keys(existing)
    batches = plan_batches(config, trials, done)
    ran = sum(len(b.goals) for b in batches)
    if batches:
        t_run = time.perf_counter()
        try:
            with open_for_append(config.results_path) as fh:
                run_cells(config, batches, lambda r: append(fh, r), progress)
        finally:
            log = {"cells": ran, "jobs": config.jobs, "seconds": round(time.perf_counter() - t_run, 3),
                   "solvers": sorted({b.solver for b in batches})}
            with open(config.out_dir / RUNS, "a", encoding="utf-8") as fh:
                fh.write(json.dumps(log, sort_keys=True) + "\n")
    records = read_records(config.results_path)
    keys = cell_keys(config, trials)
    mine = tuple(records[k] for k in sorted(keys) if k in records)
    full = default_kitchen(reg)
    return RunSummary(trials, ran, len(keys) - ran, time.perf_counter() - t0, mine, len(full),
                      len(goal_pool(reg, full)), read_runs(config.out_dir / RUNS))


def read_runs(path: Path) -> tuple[dict, ...]:
    """The invocations logged in runs.jsonl (a damaged line is skipped: the log is informative only)."""
    if not path.exists():
        return ()
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            out.append(json.loads(line))
        except ValueError:
            continue
    return tuple(out)


def views(config: Config) -> list[NetworkView]:
    """The run's network views (built once per process)."""
    return [_view(config.paths, config.protocol.level, n) for n in config.networks]


def cell_keys(config: Config, trials: tuple[Trial, ...]) -> set:
    """Every cell key of the run (solvers only on the networks they apply to)."""
    keys = set()
    for solver in config.solvers:
        spec = get_solver(solver)
        for network in config.networks:
            if spec.applies_to(network):
                keys.update((t.index, g, network, solver) for t in trials for g in config.goals_for(solver, t))
    return keys
