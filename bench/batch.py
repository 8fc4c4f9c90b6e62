"""Batch goals (`retrieve --goals`): one process for many goals on the universal FOON of the shared subgraphs.

Figures (wall time of the whole command, process start and network loading included;
median over repeats):
- the 25 goals of `goal_nodes.json` from `kitchen.json`, strict and `--containment infer`
  (floor < 3 s each);
- 1,000 goals (produced nodes of the universal FOON, seeded sample, goal-syntax lines) from the
  kitchen `retrieve` chooses when none is named (the base kitchen on this merge; floor < 5 s), with the
  command's CPU time beside it (on a loaded machine the wall time measures the load); and the in-process
  batch alone (`solve_goals`) from the default kitchen, per goal.
"""

from __future__ import annotations

import random
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from foon2pddl.io.files import load
from foon2pddl.io.goal_lists import parse_goal_list
from foon2pddl.model.goal import resolve_goal
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.retrieval.batch import solve_goals

from .harness import Context, timeit

AREA = "batch"


def _cli(*args: str) -> float:
    """Run `retrieve ARGS`; its CPU seconds (user + system)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-m", "foon2pddl", "retrieve", *args], check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def run(ctx: Context) -> None:
    subgraphs = ctx.shared / "foon-subgraphs"
    inputs = ctx.shared / "foon-search-inputs"
    repeat = 1 if ctx.quick else max(3, ctx.repeat)
    for mode in ("strict", "infer"):
        t, _, _ = timeit(lambda mode=mode: _cli(str(subgraphs), "--kitchen", str(inputs / "kitchen.json"), "--goals",
                                                str(inputs / "goal_nodes.json"), "--containment", mode,
                                                "--format", "jsonl"), repeat, warmup=0)
        ctx.report(AREA, f"retrieve --goals goal_nodes.json (25 goals, {mode}), whole command", t, "s",
                   "floor < 3 s")
    foon, _ = load([subgraphs])
    produced = sorted(foon.producers)
    rng = random.Random(13)
    sample = [rng.choice(produced) for _ in range(100 if ctx.quick else 1000)]
    text = "".join(n.describe() + "\n" for n in sample)
    with tempfile.TemporaryDirectory() as tmp:
        goals = Path(tmp) / "goals.txt"
        goals.write_text(text)
        cpu: list[float] = []
        t, _, _ = timeit(lambda: cpu.append(_cli(str(subgraphs), "--goals", str(goals), "--format", "jsonl")),
                         repeat, warmup=0)
    ctx.report(AREA, f"retrieve --goals ({len(sample)} goals, base kitchen), whole command", t, "s",
               "floor < 5 s")
    ctx.report(AREA, f"retrieve --goals ({len(sample)} goals, base kitchen), whole command, CPU",
               statistics.median(cpu), "s", "user + system")
    entries = parse_goal_list(text, "goals.txt")
    kitchen = default_kitchen(foon).nodes
    t, _, rows = timeit(lambda: solve_goals(foon, kitchen, entries, lambda s: resolve_goal(s, foon)), repeat)
    solved = sum(r.status == "solved" for r in rows)
    ctx.report(AREA, "solve_goals per goal (in process, complete)", t / len(entries) * 1e3, "ms",
               f"{solved} of {len(entries)} solved")
