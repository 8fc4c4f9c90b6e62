"""Scaling benchmarks: whole commands on synthetic FOONs of 10k .. 1M units (bench/synthetic.py).

Each size is one FOON text file; each command runs in a fresh interpreter, so its figures
are those a user sees (load, index, kitchen, goal, the work), with the child's own CPU time
and peak RSS from `wait4`. Figures:
- `retrieve --goal` (one recipe's dish) and `compile --goal` (its PDDL, pruned) per size:
  wall, CPU, peak RSS;
- the time exponent of each command: the least-squares slope of log CPU time against log
  units over all sizes (floor: <= 1.1; CPU, not wall, because other jobs share the cores);
- the largest size against its floors: answers the goal in under 60 s wall and 4 GB peak RSS.
`--quick` stops at 100k units.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .harness import Context
from .synthetic import goal_of, write_synthetic

AREA = "scaling"
SIZES = (10_000, 30_000, 100_000, 300_000, 1_000_000)
QUICK_SIZES = (10_000, 30_000, 100_000)
EXPONENT_FLOOR = 1.1
SECONDS_FLOOR = 60.0
RSS_FLOOR_GB = 4.0


def _env() -> dict[str, str]:
    return dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parent.parent))


def measure(argv: list[str]) -> tuple[float, float, float]:
    """Wall seconds, CPU seconds (user + system) and peak RSS (GB) of one child process; it must succeed."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(argv, env=_env(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read().decode(errors="replace") if proc.stderr else ""
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(argv[:6])} ... exited {proc.returncode}: {err[-500:]}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / (1 << 20)


def exponent(sizes: list[int], times: list[float]) -> float:
    """Least-squares slope of log(time) against log(size)."""
    xs = [math.log(s) for s in sizes]
    ys = [math.log(t) for t in times]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys, strict=True)) / sum((x - mx) ** 2 for x in xs)


def run(ctx: Context) -> None:
    sizes = list(QUICK_SIZES if ctx.quick else SIZES)
    py = [sys.executable, "-m", "foon2pddl"]
    goal = goal_of(5)
    commands = {
        "retrieve": lambda path, out: [*py, "retrieve", str(path), "--goal", goal],
        "compile": lambda path, out: [*py, "compile", str(path), "--goal", goal, "-o", str(out)],
    }
    cpu: dict[str, list[float]] = {name: [] for name in commands}
    last: dict[str, tuple[float, float, float]] = {}
    with tempfile.TemporaryDirectory(prefix="foon2pddl-scaling-") as tmp:
        for size in sizes:
            path = Path(tmp) / f"synthetic-{size}.foon"
            write_synthetic(path, size)
            mb = path.stat().st_size / 1e6
            for name, argv in commands.items():
                wall, seconds, rss = measure(argv(path, Path(tmp) / f"out-{name}-{size}"))
                cpu[name].append(seconds)
                last[name] = (wall, seconds, rss)
                ctx.report(AREA, f"{name} {size} units", seconds, "s CPU",
                           f"wall {wall:.3g} s, peak RSS {rss:.3g} GB, file {mb:.0f} MB")
            path.unlink()
    for name in commands:
        k = exponent(sizes, cpu[name])
        ctx.report(AREA, f"{name} time exponent {sizes[0]}..{sizes[-1]} units", k, "",
                   f"least squares on log CPU; floor <= {EXPONENT_FLOOR}" + ("" if k <= EXPONENT_FLOOR else ": ABOVE"))
    wall, seconds, rss = last["retrieve"]
    ctx.report(AREA, f"retrieve one goal on {sizes[-1]} units: wall", wall, "s",
               f"floor < {SECONDS_FLOOR:.0f} s" + ("" if wall < SECONDS_FLOOR else ": ABOVE"))
    ctx.report(AREA, f"retrieve one goal on {sizes[-1]} units: peak RSS", rss, "GB",
               f"floor < {RSS_FLOOR_GB:.0f} GB" + ("" if rss < RSS_FLOOR_GB else ": ABOVE"))
