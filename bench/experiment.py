"""Experiment benchmarks on the shared subgraphs: the default protocol's wall time.

Figures (one run each: a run is tens of seconds to minutes; `--quick` runs 2 trials x 20 goals):
- the default protocol (10 trials x 100 goals x REG/EXP/GEN) with native complete alone, greedy and
  complete, and the three native solvers, 2 worker processes, and the CPU time of this (the main)
  process during the last: start-up, the Dask scheduler and client, appending records;
- the same as the `experiment` command in a fresh process (network construction, Dask start-up, report
  and exit included), median of up to 3 runs (floor: <= 30 s);
- FD on the `tree` encoding (translation reused per trial and network), 2 worker processes, on
  the first trial of the default protocol, and the per-trial figure times 10 as the estimate of
  the default protocol (floor: <= 15 min);
- resuming a finished run (every cell skipped);
- Dask scaling: the same grid (native solvers and fd-tree on REG and GEN) with a LocalCluster of 1 and
  of 2 workers, started and warmed up outside the timings (speed-up = 1 worker / 2 workers), and
  Dask's per-cell overhead: the 1-worker wall time minus the same cells in this process, per cell
  (medians over `repeat` runs).
"""

from __future__ import annotations

import resource
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from foon2pddl.experiment import grid, runner
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.protocol import Protocol

from .harness import Context

AREA = "experiment"
NATIVE = ("native-greedy", "native-complete", "native-optimal")
NETWORKS = ("reg", "exp", "gen")


def _config(paths: tuple[str, ...], protocol: Protocol, solvers: tuple[str, ...], out: Path) -> Config:
    return Config(paths, protocol, NETWORKS, solvers, out, jobs=2)


def _run(paths: tuple[str, ...], protocol: Protocol, solvers: tuple[str, ...], out: Path) -> runner.RunSummary:
    return runner.run(_config(paths, protocol, solvers, out), progress=False)


def run(ctx: Context) -> None:
    run_scaling(ctx)
    paths = (str(ctx.shared / "foon-subgraphs"),)
    protocol = Protocol(trials=2, goals=20) if ctx.quick else Protocol()
    cells = protocol.trials * protocol.goals * len(NETWORKS)
    with tempfile.TemporaryDirectory(prefix="foon2pddl-bench-exp-") as tmp:
        # build the views (EXP: similarity matrix, expansion) outside the timings
        runner.views(_config(paths, protocol, NATIVE, Path(tmp)))
        t0 = time.perf_counter()
        _run(paths, protocol, ("native-complete",), Path(tmp) / "complete")
        ctx.report(AREA, "protocol, native complete, 2 jobs", time.perf_counter() - t0, "s", f"{cells} cells")
        t0 = time.perf_counter()
        _run(paths, protocol, ("native-greedy", "native-complete"), Path(tmp) / "greedy")
        ctx.report(AREA, "protocol, native greedy + complete, 2 jobs", time.perf_counter() - t0, "s",
                   f"{2 * cells} cells")
        t0, cpu0 = time.perf_counter(), _own_cpu()
        summary = _run(paths, protocol, NATIVE, Path(tmp) / "native")
        ctx.report(AREA, "protocol, 3 native solvers, 2 jobs", time.perf_counter() - t0, "s",
                   f"{summary.ran} cells, networks built before")
        ctx.report(AREA, "protocol, 3 native solvers, 2 jobs: main process CPU", _own_cpu() - cpu0, "s",
                   "scheduler, client, records; the workers are other processes")
        walls = [_cli_run(paths, protocol, Path(tmp) / f"cli{i}") for i in range(max(1, min(ctx.repeat, 3)))]
        ctx.report(AREA, "`experiment` command, 3 native solvers, 2 jobs, fresh process", statistics.median(walls),
                   "s", "networks, Dask start-up, report and exit included; floor <= 30 s")
        t0 = time.perf_counter()
        again = _run(paths, protocol, NATIVE, Path(tmp) / "native")
        ctx.report(AREA, "resume a finished run", time.perf_counter() - t0, "s", f"{again.skipped} cells skipped")
        one = Protocol(trials=1, goals=protocol.goals, kitchen_fraction=protocol.kitchen_fraction)
        t0 = time.perf_counter()
        summary = _run(paths, one, ("fd-tree",), Path(tmp) / "fd")
        seconds = time.perf_counter() - t0
        ctx.report(AREA, "one trial, fd-tree, 2 jobs", seconds, "s", f"{summary.ran} cells")
        ctx.report(AREA, "protocol, fd-tree, 2 jobs (estimate: trials x one trial)", seconds * protocol.trials, "s",
                   "floor <= 900 s")


def _own_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _cli_run(paths: tuple[str, ...], protocol: Protocol, out: Path) -> float:
    """Wall time of the `experiment` command with the three native solvers in a fresh process."""
    args = [sys.executable, "-m", "foon2pddl", "experiment", *paths, "--trials", str(protocol.trials), "--goals",
            str(protocol.goals), "--solvers", ",".join(NATIVE), "--jobs", "2", "--no-progress", "-o", str(out)]
    t0 = time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def _timed_runs(config: Config, repeat: int) -> float:
    """Median wall time of `repeat` fresh runs of `config` (each into its own directory)."""
    times = []
    for i in range(repeat):
        c = replace(config, out_dir=config.out_dir / f"r{i}")
        t0 = time.perf_counter()
        runner.run(c, progress=False)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def run_scaling(ctx: Context) -> None:
    """Speed-up from 1 to 2 local Dask workers, and Dask's overhead per cell against one process.

    The speed-up grid mixes native solvers and fd-tree on REG and GEN; the overhead grid is
    native-complete on REG alone (cells of ~0.1 ms), so its difference to one process is Dask's.
    """
    import distributed

    paths = (str(ctx.shared / "foon-subgraphs"),)
    repeat = max(1, min(ctx.repeat, 3))
    with tempfile.TemporaryDirectory(prefix="foon2pddl-bench-dask-") as tmp:
        grids = {
            "mixed": Config(paths, Protocol(trials=2, goals=10 if ctx.quick else 40), ("reg", "gen"),
                            (*NATIVE, "fd-tree"), Path(tmp) / "mixed"),
            "cheap": Config(paths, Protocol(trials=4, goals=100), ("reg",), ("native-complete",),
                            Path(tmp) / "cheap"),
        }
        here, walls = {}, {}
        for name, config in grids.items():
            runner.views(config)
            here[name] = _timed_runs(config, repeat)
            ctx.report(AREA, f"{name} grid in one process", here[name], "s", f"{len(grid.cell_keys(config))} cells")
        for workers in (1, 2):
            with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                          dashboard_address=":0") as cluster:
                for name, config in grids.items():
                    config = replace(config, out_dir=config.out_dir / f"dask{workers}",
                                     scheduler=cluster.scheduler_address)
                    runner.run(replace(config, out_dir=config.out_dir / "warm"), progress=False)  # build views
                    walls[(name, workers)] = _timed_runs(config, repeat)
                    ctx.report(AREA, f"{name} grid on a LocalCluster of {workers} worker(s), warm",
                               walls[(name, workers)], "s")
        ctx.report(AREA, "Dask speed-up, 2 workers against 1 (mixed grid)", walls[("mixed", 1)] / walls[("mixed", 2)],
                   "x", "2 cores")
        cells = len(grid.cell_keys(grids["cheap"]))
        ctx.report(AREA, "Dask overhead per cell (cheap grid, 1 worker against one process)",
                   (walls[("cheap", 1)] - here["cheap"]) / cells * 1000, "ms",
                   f"{cells} cells in batches of {grid.CHUNK}")
