"""Reliability benchmarks (issue 11): linear goal and kitchen parsing, bounded planner output, time limits
that hold against daemon children.

Figures (medians over `ctx.repeat` runs):
- goal text with 100 KB and 1 MB of blanks between a state and its bracket (the former regular
  expression took 45 s at 2 KB, cubic); floor: 1 MB well under a second, ratio 1 MB / 100 KB ~10 (linear);
- a kitchen file whose one line is 1 MB;
- peak memory (max RSS) of a process whose planner prints 300 MB (the former pipe kept it all: 762 MB);
- wall time of a 2 s time limit when the planner leaves a `setsid` daemon (the former code waited 40 s).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.planners.process import run_process

from .harness import Context, timeit

AREA = "reliability"


def _peak_rss_mb(megabytes: int) -> float:
    """Max RSS (MB) of a fresh interpreter that runs a planner printing `megabytes` MB through run_process."""
    code = textwrap.dedent(f"""
        import resource, sys, tempfile
        from pathlib import Path
        from foon2pddl.planners.process import run_process
        printer = "import sys\\nchunk = 'x' * 1048576\\nfor _ in range({megabytes}): sys.stdout.write(chunk)"
        with tempfile.TemporaryDirectory() as tmp:
            run = run_process([sys.executable, "-c", printer], Path(tmp), 600)
        assert run.output_bytes == {megabytes} * 1048576, run.output_bytes
        print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
    """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(out.stdout.strip())


def run(ctx: Context) -> None:
    repeat = max(3, ctx.repeat if not ctx.quick else 3)
    times = {}
    for size in (100_000, 1_000_000):
        goal = "guacamole: a" + " " * size + "[x]y"

        def parse(goal=goal):
            try:
                parse_goal_spec(goal)
            except ValueError:
                pass

        times[size], _, _ = timeit(parse, repeat)
        ctx.report(AREA, f"goal with {size // 1000} KB of blanks before a bracket", times[size], "s",
                   "former regex: 45 s at 2 KB (cubic); floor: 1 MB well under 1 s")
    ctx.report(AREA, "goal parsing ratio 1 MB / 100 KB", times[1_000_000] / times[100_000], "x", "~10 = linear")

    with tempfile.TemporaryDirectory(prefix="foon2pddl-bench-") as tmp:
        kitchen = Path(tmp) / "kitchen.txt"
        kitchen.write_text("bowl: empty\ncream: in" + " " * 1_000_000 + "[bowl]\n")
        t_kitchen, _, _ = timeit(lambda: read_kitchen(kitchen), repeat)
        ctx.report(AREA, "kitchen file with a 1 MB line", t_kitchen, "s")

        megabytes = 50 if ctx.quick else 300
        rss = sorted(_peak_rss_mb(megabytes) for _ in range(1 if ctx.quick else 3))
        ctx.report(AREA, f"peak RSS with a planner printing {megabytes} MB", rss[len(rss) // 2], "MB",
                   "former pipe: 762 MB at 300 MB; output kept in memory: head 64 KB + tail 256 KB")

        walls = []
        for _ in range(1 if ctx.quick else 3):
            t0 = time.perf_counter()
            run_process(["sh", "-c", "setsid sleep 40 & sleep 60"], Path(tmp), 2.0)
            walls.append(time.perf_counter() - t0)
        walls.sort()
        ctx.report(AREA, "2 s time limit, planner with a setsid daemon", walls[len(walls) // 2], "s",
                   "former code: ~40 s (waited for the daemon's pipe); floor: limit + ~1 s")
