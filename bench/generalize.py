"""Generalization benchmarks on the universal FOON of the shared subgraphs.

Figures:
- similarity matrix over the universal vocabulary (~450 labels, all pairs):
  cold in a fresh process (interpreter, NLTK import, opening WordNet, computing;
  floor <= 10 s), the computation alone with WordNet open, and a disk-cache hit
  (floor <= 0.5 s), in-process and in a fresh process;
- FOON-EXP (threshold 0.89) and FOON-GEN construction time, with their sizes;
- lifted FOON-GEN planning (Fast Downward) per dish goal, default kitchen.
`--quick` uses fewer repeats and goals.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from foon2pddl.generalize.categories import shipped_index
from foon2pddl.generalize.compress import compress
from foon2pddl.generalize.expand import expand, vocabulary
from foon2pddl.generalize.similarity import LabelSimilarity, similarity_matrix
from foon2pddl.io.files import load

from .harness import Context, run_main, timeit

AREA = "generalize"

_CHILD = """
import sys, time
t0 = time.perf_counter()
from foon2pddl.generalize.similarity import similarity_matrix
labels = sys.stdin.read().splitlines()
similarity_matrix(labels, cache={cache})
print(time.perf_counter() - t0)
"""


def _fresh_process(labels: list[str], cache: bool, cache_dir: str) -> float:
    """Seconds a fresh interpreter needs to import the package and build (or load) the matrix."""
    env = {**os.environ, "FOON2PDDL_CACHE": cache_dir}
    out = subprocess.run([sys.executable, "-c", _CHILD.format(cache=cache)], input="\n".join(labels),
                         capture_output=True, text=True, check=True, env=env)
    return float(out.stdout.strip().splitlines()[-1])


def run(ctx: Context) -> None:
    foon, _ = load([ctx.shared / "foon-subgraphs"])
    labels = list(vocabulary(foon))
    repeat = 1 if ctx.quick else 3
    with tempfile.TemporaryDirectory() as tmp:
        cold = [_fresh_process(labels, False, tmp) for _ in range(repeat)]
        ctx.report(AREA, "similarity matrix, cold process", statistics.median(cold), "s",
                   f"{len(labels)} labels, {len(labels) * (len(labels) - 1) // 2} pairs; "
                   "includes NLTK import and opening WordNet; floor <= 10 s")
        t0 = time.perf_counter()
        sim = LabelSimilarity()
        ctx.report(AREA, "opening WordNet (NLTK import + reader)", time.perf_counter() - t0, "s", "once per process")
        compute, _, _ = timeit(lambda: similarity_matrix(labels, cache=False, sim=LabelSimilarity(sim.reader)),
                               repeat, warmup=0)
        ctx.report(AREA, "similarity matrix, computation alone", compute, "s", "WordNet open, no memoized pairs")
        similarity_matrix(labels, sim=sim)  # fills the cache (FOON2PDDL_CACHE is not set in this process)
        hit, _, _ = timeit(lambda: similarity_matrix(labels), max(ctx.repeat, 5))
        ctx.report(AREA, "similarity matrix, disk cache hit", hit, "s", "in process; floor <= 0.5 s")
        _fresh_process(labels, True, tmp)
        fresh_hit = [_fresh_process(labels, True, tmp) for _ in range(repeat)]
        ctx.report(AREA, "similarity matrix, disk cache hit, fresh process", statistics.median(fresh_hit), "s",
                   "includes importing the package (no NLTK import)")

    matrix = similarity_matrix(labels)
    t_exp, _, e = timeit(lambda: expand(foon, matrix), repeat)
    ctx.report(AREA, "FOON-EXP construction (threshold 0.89)", t_exp, "s",
               f"{e.original_units} -> {len(e.foon.units)} units, matrix cached")
    index = shipped_index()
    t_gen, _, c = timeit(lambda: compress(foon, index), max(repeat, 3))
    ctx.report(AREA, "FOON-GEN construction", t_gen, "s", f"{c.original_units} -> {len(c.foon.units)} units")

    from foon2pddl.model.goal import Goal, spec_of_node
    from foon2pddl.model.kitchen import default_kitchen
    from foon2pddl.planners.solve import plan

    kitchen = default_kitchen(foon)
    dishes = sorted({n for u in foon.units for n in u.outputs if n.dish is not None})[: 10 if ctx.quick else 40]
    times, solved, valid = [], 0, 0
    for d in dishes:
        t0 = time.perf_counter()
        out = plan(foon, kitchen, Goal(spec_of_node(d), (d,), 3), "gen-lifted", category_index=index, time_limit=120)
        times.append(time.perf_counter() - t0)
        solved += out.result.solved
        valid += out.status == "solved"
    ctx.report(AREA, "lifted FOON-GEN plan per dish goal (median)", statistics.median(times), "s",
               f"{len(dishes)} dishes, default kitchen: {solved} solved, {valid} map back to valid trees")


if __name__ == "__main__":
    run_main(lambda: run(Context(Path("../shared/data"))))
