"""Planning benchmarks on the universal FOON of the shared subgraphs (level 3, `tree` encoding).

Figures:
- per-goal compile (with pruning) + Fast Downward plan + decode + validate over a
  seeded sample of 50 goal nodes: median and 90th percentile, median per phase
  (floor: median <= 0.5 s);
- translation reuse (`GoalReplanner`): one translation of the whole network,
  then the per-goal time, against a fresh run per goal on the same goals;
- equivalence: for the default kitchen and 5 seeded random kitchens (70 % of the default one,
  `experiment.protocol.sample_kitchen`), a seeded
  sample of >= 200 goal nodes: FD (fresh runs) plans iff native complete
  retrieval finds a tree, every plan validates, and the reuse path agrees.
`--quick` samples fewer goals and kitchens.
"""

from __future__ import annotations

import random
import statistics
import time

from foon2pddl.experiment.protocol import sample_kitchen
from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.planners.goal_replanner import GoalReplanner
from foon2pddl.planners.solve import PHASES, plan
from foon2pddl.retrieval.complete import complete

from .harness import Context

AREA = "planning"
FLOOR_SECONDS = 0.5


def sample_goals(foon, n: int, seed: int):
    """Goals for `n` seeded random produced nodes (each node asked for exactly)."""
    nodes = random.Random(seed).sample(sorted(foon.producers), n)
    return [resolve_goal(spec_of_node(x), foon) for x in nodes]


def _timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def per_goal(ctx: Context, foon, kitchen, goals) -> None:
    """Fresh compile + plan per goal, and the reuse path on the same goals."""
    fresh = [_timed(lambda g=g: plan(foon, kitchen, g)) for g in goals]
    times = [t for t, _ in fresh]
    solved = [t for t, o in fresh if o.status == "solved"]
    note = f"{len(goals)} goals ({len(solved)} solvable), floor <= {FLOOR_SECONDS} s"
    ctx.report(AREA, "compile + FD plan per goal, pruned, median", statistics.median(times), "s", note)
    ctx.report(AREA, "compile + FD plan per goal, pruned, p90", statistics.quantiles(times, n=10)[-1], "s")
    if solved:
        ctx.report(AREA, "compile + FD plan per solvable goal, median", statistics.median(solved), "s")
    for phase in PHASES[1:]:
        values = [o.timings.get(phase, 0.0) for _, o in fresh]
        ctx.report(AREA, f"  phase {phase}, median", statistics.median(values), "s")

    build_s, replanner = _timed(lambda: GoalReplanner(foon, kitchen))
    ctx.report(AREA, "reuse: translate whole network once", build_s, "s",
               f"{len(replanner.task.actions)} actions; translator {replanner.translated.translate_seconds:.3f} s")
    reused = [_timed(lambda g=g: replanner.plan(g)) for g in goals]
    r_times = [t for t, _ in reused]
    ctx.report(AREA, "reuse: per goal, median", statistics.median(r_times), "s",
               f"fresh median {statistics.median(times):.3f} s")
    r_solved = [t for (t, o) in reused if o.status == "solved"]
    if r_solved:
        ctx.report(AREA, "reuse: per solvable goal, median", statistics.median(r_solved), "s")
    gain = sum(times) - sum(r_times)
    ctx.report(AREA, "reuse: break-even goals", build_s / max(gain / len(goals), 1e-9), "goals",
               "goals after which translating once pays off")
    mismatched = sum(a.status != b.status for (_, a), (_, b) in zip(fresh, reused, strict=True))
    ctx.report(AREA, "reuse: status differs from fresh", mismatched, "goals")


def equivalence(ctx: Context, foon, goals, kitchens) -> None:
    """FD plans iff complete retrieval finds a tree; every plan validates; reuse agrees."""
    agree = both = neither = invalid = reuse_diff = errors = 0
    plan_units = tree_units = 0
    t0 = time.perf_counter()
    for kitchen in kitchens:
        replanner = GoalReplanner(foon, kitchen)
        for goal in goals:
            native = complete(foon, kitchen.nodes, goal)
            out = plan(foon, kitchen, goal)
            reused = replanner.plan(goal)
            found = out.status == "solved"
            errors += out.status in ("error", "timeout")
            agree += found == native.found
            both += found and native.found
            neither += not found and not native.found
            for o in (out, reused):
                invalid += o.tree is not None and not o.validation.ok
            reuse_diff += reused.status != out.status
            if found and native.found:
                plan_units += len(out.tree)
                tree_units += len(native.tree)
    runs = len(goals) * len(kitchens)
    note = f"{len(goals)} goals x {len(kitchens)} kitchens (default + {len(kitchens) - 1} random)"
    ctx.report(AREA, "equivalence: FD plans iff complete finds a tree", agree, f"of {runs}", note)
    ctx.report(AREA, "equivalence: both solve", both, "runs")
    ctx.report(AREA, "equivalence: neither solves", neither, "runs")
    ctx.report(AREA, "equivalence: plans that fail validation", invalid, "plans", "fresh and reuse paths")
    ctx.report(AREA, "equivalence: reuse status differs", reuse_diff, "runs")
    ctx.report(AREA, "equivalence: planner errors or timeouts", errors, "runs")
    if both:
        ctx.report(AREA, "equivalence: FD plan units / complete tree units", plan_units / tree_units, "ratio")
    ctx.report(AREA, "equivalence: wall time", time.perf_counter() - t0, "s")


def run(ctx: Context) -> None:
    foon, _ = load([ctx.shared / "foon-subgraphs"])
    kitchen = default_kitchen(foon)
    per_goal(ctx, foon, kitchen, sample_goals(foon, 15 if ctx.quick else 50, seed=1))
    n_goals, n_random = (40, 1) if ctx.quick else (200, 5)
    kitchens = [kitchen] + [sample_kitchen(kitchen, 0.7, seed) for seed in range(1, n_random + 1)]
    equivalence(ctx, foon, sample_goals(foon, n_goals, seed=2), kitchens)
