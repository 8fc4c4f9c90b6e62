"""Per-goal cost of the physical encodings in the experiment, against `fd-tree`.

One trial of the experiment protocol on REG (the universal FOON of the shared subgraphs),
its goals solved one by one as the experiment's workers solve them (`SOLVERS[name].prepare`,
then `solve` per goal). Figures (ms per goal):
- `fd-tree` (translated once per trial, goals swapped in): median, mean, worst, and its setup;
- `fd-instances` as it runs now (goals no task tree reaches answered from the trial's
  fixpoint; the warm translator): median, mean, worst, and the ratio of its median to
  `fd-tree`'s (floor: <= 5x) and its worst goal (floor: < 2 s);
- `fd-instances` as it ran before: every goal compiled and translated by a fresh
  interpreter (`plan` per goal, `FOON2PDDL_WARM_TRANSLATOR=0`), and the ratios new / old;
- on the goals a task tree reaches (those `fd-instances` plans): its median against `fd-tree`'s
  on the same goals, and where the time goes (encode, write, translate, search), before and now;
- the `relational` encode alone, per goal on REG, EXP and GEN (CPU);
- `fd-relational` likewise (median, mean, worst, its median against `fd-tree`'s, and on the goals it
  encodes, where the time goes).
`--quick` uses 20 goals.
"""

from __future__ import annotations

import os
import statistics
import time

from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import Protocol, draw
from foon2pddl.experiment.setting import Setting
from foon2pddl.experiment.solvers import SOLVERS
from foon2pddl.io.inputs import load_network
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.planners import translator
from foon2pddl.planners.solve import plan

from .harness import Context

AREA = "translation"
RATIO_FLOOR = 5.0
WORST_FLOOR = 2.0


def _per_goal(solve, goals) -> tuple[list[float], list[dict]]:
    times, phases = [], []
    for g in goals:
        t0 = time.perf_counter()
        out = solve(g)
        times.append(time.perf_counter() - t0)
        phases.append(dict(out.times) if hasattr(out, "times") else dict(out.timings))
    return times, phases


def _summary(ctx: Context, name: str, times: list[float], note: str = "") -> None:
    ctx.report(AREA, f"{name} median", statistics.median(times) * 1000, "ms/goal", note)
    ctx.report(AREA, f"{name} mean", statistics.fmean(times) * 1000, "ms/goal")
    ctx.report(AREA, f"{name} worst", max(times) * 1000, "ms")


def _against_tree(ctx: Context, name: str, times: list[float], tree_times: list[float], planned: list[int],
                  which: str) -> None:
    """`name`'s median against `fd-tree`'s on the `planned` goals (the goals `which`)."""
    ours = statistics.median(times[k] for k in planned)
    theirs = statistics.median(tree_times[k] for k in planned)
    ctx.report(AREA, f"planned goals: {name} median / fd-tree median", ours / theirs, "x",
               f"{ours * 1000:.3g} ms against {theirs * 1000:.3g} ms on the {len(planned)} goals {which}")


def relational_encode(ctx: Context, net, goals_per_trial: int) -> None:
    """The relational encode alone, per goal of one trial on REG, EXP and GEN (CPU seconds, goals one after another
    over one network object, as a worker encodes them)."""
    for name in ("reg", "exp", "gen"):
        view = build_view(name, net, 3)
        trial = draw(build_view("reg", net, 3).foon, Protocol(trials=1, goals=goals_per_trial)).trials[0]
        kitchen = view.map_kitchen(trial.kitchen)
        times = []
        for g in trial.goals:
            t0 = time.process_time()
            compile_goal(view.foon, kitchen, view.goal_of(g), "relational", view.foon.level)
            times.append(time.process_time() - t0)
        ctx.report(AREA, f"relational encode, {name.upper()}, median", statistics.median(times) * 1000, "ms/goal",
                   f"{len(times)} goals, CPU")
        ctx.report(AREA, f"relational encode, {name.upper()}, worst", max(times) * 1000, "ms")


def run(ctx: Context) -> None:
    goals_per_trial = 20 if ctx.quick else 100
    net = load_network([ctx.shared / "foon-subgraphs"])
    relational_encode(ctx, net, goals_per_trial)
    view = build_view("reg", net, 3)
    trial = draw(view.foon, Protocol(trials=1, goals=goals_per_trial)).trials[0]
    setting = Setting(view, trial.kitchen, 60.0)

    tree = SOLVERS["fd-tree"].prepare(setting)
    tree_times, _ = _per_goal(tree.solve, trial.goals)
    ctx.report(AREA, "fd-tree setup", tree.setup * 1000, "ms/trial", "one translation of the unpruned task")
    _summary(ctx, "fd-tree", tree_times, f"{len(trial.goals)} goals, REG, one trial")

    inst = SOLVERS["fd-instances"].prepare(setting)
    new_times, new_phases = _per_goal(inst.solve, trial.goals)
    ctx.report(AREA, "fd-instances setup", inst.setup * 1000, "ms/trial", "the trial's reachability fixpoint")
    _summary(ctx, "fd-instances", new_times, "screened by the fixpoint, warm translator")
    ratio = statistics.median(new_times) / statistics.median(tree_times)
    ctx.report(AREA, "fd-instances median / fd-tree median", ratio, "x",
               f"floor <= {RATIO_FLOOR:g}" + ("" if ratio <= RATIO_FLOOR else ": ABOVE"))
    worst = max(new_times)
    ctx.report(AREA, "fd-instances worst goal", worst, "s",
               f"floor < {WORST_FLOOR:g} s" + ("" if worst < WORST_FLOOR else ": ABOVE"))

    rel = SOLVERS["fd-relational"].prepare(setting)
    rel_times, rel_phases = _per_goal(rel.solve, trial.goals)
    _summary(ctx, "fd-relational", rel_times, "screened by the fixpoint, warm translator")
    ctx.report(AREA, "fd-relational median / fd-tree median", statistics.median(rel_times) / statistics.median(tree_times),
               "x", "issue 25: not slower per goal than fd-tree's median")
    planned = [k for k, p in enumerate(rel_phases) if "encode" in p]
    if planned:
        _against_tree(ctx, "fd-relational", rel_times, tree_times, planned, "it encodes")
        for phase in ("encode", "translate", "search"):
            ctx.report(AREA, f"planned goals: fd-relational {phase} median",
                       statistics.median(rel_phases[k].get(phase, 0.0) for k in planned) * 1000, "ms")

    os.environ[translator.SWITCH] = "0"
    try:
        kitchen = view.map_kitchen(trial.kitchen)
        old_times, old_phases = _per_goal(
            lambda g: plan(view.foon, kitchen, view.goal_of(g), "instances", view.foon.level, time_limit=60.0),
            trial.goals)
    finally:
        os.environ.pop(translator.SWITCH, None)
    _summary(ctx, "fd-instances before (fresh translator, every goal planned)", old_times)
    ctx.report(AREA, "fd-instances median: before / now", statistics.median(old_times) / statistics.median(new_times),
               "x")
    ctx.report(AREA, "fd-instances mean: before / now", statistics.fmean(old_times) / statistics.fmean(new_times), "x")
    planned = [k for k, p in enumerate(new_phases) if "translate" in p]
    if planned:
        _against_tree(ctx, "fd-instances", new_times, tree_times, planned, "a task tree reaches")
        for phase in ("encode", "write", "translate", "search"):
            now = statistics.median(new_phases[k].get(phase, 0.0) for k in planned) * 1000
            before = statistics.median(old_phases[k].get(phase, 0.0) for k in planned) * 1000
            ctx.report(AREA, f"planned goals: {phase} median", now, "ms", f"before {before:.3g} ms; {len(planned)} goals")
