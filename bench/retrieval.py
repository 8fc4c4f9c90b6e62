"""Native retrieval benchmarks on the universal FOON of the shared subgraphs (default kitchen).

Figures (level 3 unless named):
- fixpoint over all nodes (floor <= 50 ms), and the one-off index build;
- per-goal median of `complete` and `greedy` over every produced node (floors
  <= 1 ms; the public reference takes 0.6-4.4 s per goal), and how many recipe
  dishes greedy solves;
- `optimal` and `weighted` (shared motion rates) over 100 seeded reachable goals:
  median, worst case, expansions, and how often they beat `complete`;
- the same medians at level 2;
- anytime `optimal` (default budget) on the experiment protocol's goals on REG, EXP and GEN:
  per-goal median and worst time, search nodes, the share proven optimal and the median gap
  of the rest (the experiment's floor: >= 95 % proven);
- the search-inputs exercise: how many of `goal_nodes.json`'s goals
  `kitchen.json` can make, at levels 3 and 2, by reason (see docs/retrieval.md).
`--quick` uses fewer goals and repeats.
"""

from __future__ import annotations

import json
import random
import statistics
import time
from collections import Counter

from foon2pddl.analysis.index import build_index
from foon2pddl.errors import UsageError
from foon2pddl.io.files import load
from foon2pddl.io.kitchen_files import json_node, read_kitchen
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.levels import project, project_node
from foon2pddl.retrieval import blockers, reachable, read_rates
from foon2pddl.retrieval.complete import complete
from foon2pddl.retrieval.greedy import greedy
from foon2pddl.retrieval.optimal import optimal

from .harness import Context, timeit

AREA = "retrieval"
REFERENCE = "public reference: 0.6-4.4 s per goal"


def _per_goal(fn, goals, repeat: int) -> list[float]:
    """Median time of `fn(goal)` for each goal (each over `repeat` runs)."""
    return [timeit(lambda g=g: fn(g), repeat, warmup=0)[0] for g in goals]


def _exact(node, level: int) -> Goal:
    return Goal(spec_of_node(node), (node,), level)


def speed(ctx: Context, foon, label: str) -> None:
    """Fixpoint, complete and greedy per goal, optimal and weighted on seeded goals."""
    kitchen = default_kitchen(foon).nodes
    t_index, _, _ = timeit(lambda: build_index(foon), ctx.repeat)
    reach = reachable(foon, kitchen)
    t_fix, _, _ = timeit(lambda: reachable(foon, kitchen), max(ctx.repeat, 5))
    made = sum(reach.can_make(n) for n in foon.nodes)
    if label == "level 3":
        ctx.report(AREA, f"index build ({label}, once per network)", t_index * 1e3, "ms")
        ctx.report(AREA, f"fixpoint over all nodes ({label})", t_fix * 1e3, "ms",
                   f"{len(foon.nodes)} nodes, {len(foon.units)} units, {made} makeable; floor <= 50 ms")
    dishes = sorted({n for u in foon.units for n in u.outputs if n.dish is not None})
    solved = sum(greedy(foon, kitchen, _exact(n, foon.level)).tree is not None for n in dishes)
    ctx.report(AREA, f"dish goals with a greedy tree ({label})", solved, f"of {len(dishes)}",
               f"fixpoint: {sum(reach.can_make(n) for n in dishes)} reachable; the public reference's greedy "
               "solved 1 of its first 20 at level 3, 8 of 20 at level 2")
    produced = sorted(foon.producers)
    if ctx.quick:
        produced = random.Random(0).sample(produced, 300)
    goals = [_exact(n, foon.level) for n in produced]
    repeat = 3 if ctx.quick else ctx.repeat
    for name, fn in (("complete", lambda g: complete(foon, kitchen, g)), ("greedy", lambda g: greedy(foon, kitchen, g))):
        times = _per_goal(fn, goals, repeat)
        ctx.report(AREA, f"{name} per goal, median ({label})", statistics.median(times) * 1e3, "ms",
                   f"{len(goals)} goals, max {max(times) * 1e3:.1f} ms; floor <= 1 ms; {REFERENCE}")

    rates = read_rates(ctx.shared / "foon-search-inputs" / "motion.txt")
    makeable = [n for n in sorted(foon.producers) if reach.can_make(n)]
    sample = random.Random(0).sample(makeable, 30 if ctx.quick else 100)
    for weighted in (False, True):
        name = "weighted" if weighted else "optimal"
        times, expansions, better, unproven = [], [], 0, 0
        worst = (0.0, "")
        for node in sample:
            goal = _exact(node, foon.level)
            t0 = time.perf_counter()
            result = optimal(foon, kitchen, goal, weighted=weighted, rates=rates)
            dt = time.perf_counter() - t0
            times.append(dt)
            expansions.append(result.expansions)
            unproven += not result.proven_optimal
            base = complete(foon, kitchen, goal).tree
            better += len(result.tree) < len(base) if not weighted else result.tree.units != base.units
            worst = max(worst, (dt, node.describe()))
        note = (f"{len(sample)} seeded goals; worst {worst[0]:.3f} s ({worst[1][:60]}); median expansions "
                f"{statistics.median(expansions):.0f}, max {max(expansions)}; "
                f"{'fewer units' if not weighted else 'different tree'} than complete on {better}; "
                f"{unproven} not proven optimal")
        ctx.report(AREA, f"{name} per goal, median ({label})", statistics.median(times) * 1e3, "ms", note)
        ctx.report(AREA, f"{name} per goal, worst ({label})", worst[0], "s")


def protocol_goals(ctx: Context) -> None:
    """Anytime optimal (default budget) on the protocol's goals, per network view."""
    from foon2pddl.experiment.networks import NETWORKS, build_view
    from foon2pddl.experiment.protocol import Protocol, make_trials
    from foon2pddl.io.inputs import load_network

    net = load_network([ctx.shared / "foon-subgraphs"])
    protocol = Protocol(trials=2, goals=20) if ctx.quick else Protocol()
    views = {name: build_view(name, net, protocol.level) for name in NETWORKS}
    trials = make_trials(views["reg"].foon, protocol)
    for name, view in views.items():
        times, expansions, gaps, solved = [], [], [], 0
        for trial in trials:
            nodes = view.map_kitchen(trial.kitchen).project(view.foon.level).nodes
            reach = reachable(view.foon, nodes)
            for node in trial.goals:
                try:
                    goal = view.goal_of(node)
                except UsageError:  # no node of this view matches the goal
                    continue
                t0 = time.perf_counter()
                result = optimal(view.foon, nodes, goal, reach=reach)
                times.append(time.perf_counter() - t0)
                if result.tree is not None:
                    solved += 1
                    expansions.append(result.expansions)
                    if not result.proven_optimal:
                        gaps.append(result.gap)
        proven = solved - len(gaps)
        note = (f"{len(times)} goals, {solved} solved, worst {max(times):.3f} s, median search nodes "
                f"{statistics.median(expansions or [0]):.0f}; proven optimal {proven} of {solved} "
                f"({100 * proven / max(solved, 1):.1f} %, floor >= 95 %); median gap of the rest "
                f"{statistics.median(gaps) if gaps else 0:g} units")
        ctx.report(AREA, f"anytime optimal per goal, median (protocol, {name.upper()})",
                   statistics.median(times) * 1e3, "ms", note)
        ctx.report(AREA, f"anytime optimal, proven share (protocol, {name.upper()})",
                   100 * proven / max(solved, 1), "%")


def search_inputs(ctx: Context, universal) -> None:
    """How many of the search inputs' 25 goals the search inputs' kitchen can make, and why not."""
    inputs = ctx.shared / "foon-search-inputs"
    items = json.loads((inputs / "goal_nodes.json").read_text(encoding="utf-8"))
    kitchen = read_kitchen(inputs / "kitchen.json")
    for level in (3, 2):
        foon = project(universal, level)
        nodes = kitchen.project(level).nodes
        reach = reachable(foon, nodes)
        in_foon = sum(n in reach.index.node_id for n in nodes)
        labels = {n.label for n in foon.nodes}
        produced_labels = {n.label for n in foon.producers}
        why: Counter[str] = Counter()
        for i, item in enumerate(items):
            node = project_node(json_node(item, str(inputs / "goal_nodes.json"), i), level)
            if reach.can_make(node) and node in foon.producers:
                why["reachable"] += 1
            elif node in foon.producers:
                lacking = "; ".join(b.describe() for b in blockers(reach, [node], 3))
                why[f"node exists, kitchen lacks: {lacking}"] += 1
            elif node.label in produced_labels:
                why["label produced, but no node in those states/container/ingredients"] += 1
            elif node.label in labels:
                why["label only occurs as an input"] += 1
            else:
                why["label not in the 100 subgraphs"] += 1
        note = f"{in_foon} of {len(nodes)} kitchen nodes occur in the FOON; " + "; ".join(
            f"{k}: {v}" for k, v in sorted(why.items()))
        ctx.report(AREA, f"search-inputs goals reachable (level {level})", why["reachable"], f"of {len(items)}",
                   note)


def run(ctx: Context) -> None:
    universal, _ = load([ctx.shared / "foon-subgraphs"])
    speed(ctx, universal, "level 3")
    speed(ctx, project(universal, 2), "level 2")
    protocol_goals(ctx)
    search_inputs(ctx, universal)
