"""Constraints on the universal FOON of the shared subgraphs (default kitchen, level 3).

Floor: for 200 seeded (goal, constraints) pairs (`experiment.bans.sample_pairs`),
native `complete` retrieval and Fast Downward (`tree` encoding, constraints applied
by `compile_task`) agree on solvability in every case, and every returned tree (all
four native methods and FD's) validates and contains no banned motion or object and
uses every must-use object. Also: time per pair (native complete with the blocking-set
explanation, FD compile + plan), and the sizes of the minimal blocking sets.
`--quick`: 40 pairs.
"""

from __future__ import annotations

import statistics
import time
from collections import Counter

from foon2pddl.analysis.constraints import removal
from foon2pddl.experiment.bans import sample_pairs
from foon2pddl.io.files import load
from foon2pddl.model.constraints import violations
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.tasktree import validate
from foon2pddl.pddl.constraints import GoalExcluded
from foon2pddl.planners.solve import plan
from foon2pddl.retrieval.constrained import retrieve_constrained

from .harness import Context

AREA = "constraints"
METHODS = ("complete", "greedy", "optimal", "weighted")


def run(ctx: Context) -> None:
    foon, _ = load([ctx.shared / "foon-subgraphs"])
    kitchen = default_kitchen(foon)
    pairs = sample_pairs(foon, kitchen, 40 if ctx.quick else 200, seed=14)
    agree = solvable = bad_trees = method_diff = errors = 0
    native_s, fd_s, sizes = [], [], Counter()
    for node, cons in pairs:
        goal = Goal(spec_of_node(node), (node,), foon.level)
        t0 = time.perf_counter()
        done = retrieve_constrained(foon, kitchen, goal, cons, "complete")
        native_s.append(time.perf_counter() - t0)
        expected = removal(foon, cons).solvable(kitchen.nodes, goal)
        trees = [done.result.tree]
        for method in METHODS[1:]:
            other = retrieve_constrained(foon, kitchen, goal, cons, method).result
            method_diff += (other.tree is not None) != expected
            trees.append(other.tree)
        t0 = time.perf_counter()
        try:
            outcome = plan(foon, kitchen, goal, constraints=cons)
            status, trees = outcome.status, trees + [outcome.tree]
        except GoalExcluded:
            status = "unsolvable"
        fd_s.append(time.perf_counter() - t0)
        errors += status in ("error", "timeout")
        agree += (done.result.tree is not None) == expected == (status == "solved")
        solvable += expected
        bad_trees += sum(t is not None and (not validate(t, kitchen.nodes).ok or bool(violations(t.units, cons)))
                         for t in trees)
        if done.blocking is not None:
            relax = done.blocking.relax
            sizes["not even without constraints" if relax is None else f"{len(relax)} constraint(s)"] += 1
    n = len(pairs)
    note = f"{n} seeded pairs, {solvable} solvable; floor: all agree"
    ctx.report(AREA, "native complete, oracle and FD agree on solvability", agree, f"of {n}", note)
    ctx.report(AREA, "greedy/optimal/weighted disagreeing with the oracle", method_diff, "runs")
    ctx.report(AREA, "trees failing validation or breaking a constraint", bad_trees, "trees", "floor: 0")
    ctx.report(AREA, "planner errors or timeouts", errors, "runs")
    ctx.report(AREA, "native complete + explanation per pair, median", statistics.median(native_s), "s")
    ctx.report(AREA, "FD compile + plan per pair, median", statistics.median(fd_s), "s")
    for size, count in sorted(sizes.items()):
        ctx.report(AREA, f"minimal blocking set: {size}", count, "goals")
