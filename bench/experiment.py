"""Experiment benchmarks on the shared subgraphs: the default protocol's wall time.

Figures (one run each: a run is tens of seconds to minutes; `--quick` runs 2 trials x 20 goals):
- the default protocol (10 trials x 100 goals x REG/EXP/GEN) with native complete alone, greedy and
  complete, and the three native solvers, 2 worker processes (floor: <= 30 s);
- FD on the `tree` encoding (translation reused per trial and network), 2 worker processes, on
  the first trial of the default protocol, and the per-trial figure times 10 as the estimate of
  the default protocol (floor: <= 15 min);
- resuming a finished run (every cell skipped).
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from foon2pddl.experiment import runner
from foon2pddl.experiment.protocol import Protocol

from .harness import Context

AREA = "experiment"
NATIVE = ("native-greedy", "native-complete", "native-optimal")
NETWORKS = ("reg", "exp", "gen")


def _config(paths: tuple[str, ...], protocol: Protocol, solvers: tuple[str, ...], out: Path) -> runner.Config:
    return runner.Config(paths, protocol, NETWORKS, solvers, out, jobs=2)


def _run(paths: tuple[str, ...], protocol: Protocol, solvers: tuple[str, ...], out: Path) -> runner.RunSummary:
    return runner.run(_config(paths, protocol, solvers, out), progress=False)


def run(ctx: Context) -> None:
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
        t0 = time.perf_counter()
        summary = _run(paths, protocol, NATIVE, Path(tmp) / "native")
        ctx.report(AREA, "protocol, 3 native solvers, 2 jobs", time.perf_counter() - t0, "s",
                   f"{summary.ran} cells, floor <= 30 s")
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
