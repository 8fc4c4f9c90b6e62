"""Foundation benchmarks: load + merge of the shared subgraphs, level projections, linear growth.

Figures (medians over `ctx.repeat` runs):
- load+merge of the 100 shared subgraphs (floor: <= 0.3 s; the public reference
  loader takes ~112 s CPU for 111 files);
- parse alone and merge alone, to show where the time goes;
- projection of the universal FOON to levels 2 and 1;
- growth: 10 relabelled copies of the subgraphs (object labels suffixed per copy,
  so nothing deduplicates across copies) against one copy (floor: ratio <= 12).
"""

from __future__ import annotations

import re
import statistics
import tempfile
import time
from pathlib import Path

from foon2pddl.io.files import expand_paths, load
from foon2pddl.io.parser import parse_file
from foon2pddl.model.levels import project
from foon2pddl.model.merge import merge

from .harness import Context, timeit

AREA = "foundation"
REFERENCE_SECONDS = 112.0  # public foon_api loader, 111 files, CPU time (see shared notes)
_OBJECT_LINE = re.compile(r"^(O\d*\t)([^\t\r\n]*)", re.MULTILINE)


def relabelled_copies(src: Path, dest: Path, copies: int) -> list[Path]:
    """Write `copies` copies of every FOON file under `src`, object labels suffixed with ` copy<k>`."""
    files = expand_paths([src])
    dirs = []
    for k in range(copies):
        d = dest / f"copy{k:02d}"
        d.mkdir(parents=True)
        for f in files:
            text = f.read_text(encoding="utf-8-sig")
            (d / f.name).write_text(_OBJECT_LINE.sub(lambda m, k=k: f"{m[1]}{m[2]} copy{k}", text), encoding="utf-8")
        dirs.append(d)
    return dirs


def cpu_median(fn, repeat: int) -> float:
    """Median process CPU time of `fn` (less disturbed than wall time when other jobs share the cores)."""
    fn()
    times = []
    for _ in range(repeat):
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return statistics.median(times)


def run(ctx: Context) -> None:
    subgraphs = ctx.shared / "foon-subgraphs"
    files = expand_paths([subgraphs])
    repeat = max(3, ctx.repeat if not ctx.quick else 3)

    t_load, _, (foon, _warnings) = timeit(lambda: load([subgraphs]), repeat)
    ctx.report(AREA, "load+merge 100 subgraphs", t_load, "s",
               f"{len(files)} files, {len(foon.units)} units, floor <= 0.3 s; "
               f"{REFERENCE_SECONDS / t_load:.0f}x faster than the reference's ~{REFERENCE_SECONDS:.0f} s")
    t_parse, _, results = timeit(lambda: [parse_file(f) for f in files], repeat)
    ctx.report(AREA, "parse 100 subgraphs", t_parse, "s")
    t_merge, _, _ = timeit(lambda: merge(r.foon for r in results), repeat)
    ctx.report(AREA, "merge (dedupe) parsed subgraphs", t_merge, "s")

    for level in (2, 1):
        t_proj, _, projected = timeit(lambda level=level: project(foon, level), repeat)
        ctx.report(AREA, f"project universal FOON to level {level}", t_proj, "s",
                   f"{len(projected.nodes)} object nodes, {len(projected.units)} units")

    copies = 10
    with tempfile.TemporaryDirectory(prefix="foon2pddl-bench-") as tmp:
        dirs = relabelled_copies(subgraphs, Path(tmp), copies)
        t_one, _, (one, _) = timeit(lambda: load(dirs[:1]), repeat)
        t_all, _, (many, _) = timeit(lambda: load(dirs), repeat)
        cpu_one = cpu_median(lambda: load(dirs[:1]), repeat)
        cpu_all = cpu_median(lambda: load(dirs), repeat)
    if len(many.units) != copies * len(one.units):
        raise AssertionError(f"relabelled copies deduplicated: {len(many.units)} != {copies} x {len(one.units)}")
    ctx.report(AREA, "load+merge 1 relabelled copy", t_one, "s", f"{len(one.units)} units")
    ctx.report(AREA, f"load+merge {copies} relabelled copies", t_all, "s", f"{len(many.units)} units")
    ctx.report(AREA, f"growth ratio {copies} copies / 1 copy", t_all / t_one, "x", "wall time; floor <= 12 (linear)")
    ctx.report(AREA, f"growth ratio {copies} copies / 1 copy (CPU)", cpu_all / cpu_one, "x",
               f"process CPU time {cpu_one:.3f} s -> {cpu_all:.3f} s; floor <= 12")
