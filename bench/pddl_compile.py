"""PDDL compile benchmarks: the whole universal FOON (no pruning) to PDDL text, per encoding.

Figures (medians over `ctx.repeat` runs), for the universal FOON of the shared
subgraphs at level 3 with its default kitchen and the first makeable dish as the goal:
- encode + render, no pruning, per encoding (floor for `tree`: <= 0.2 s);
- encode alone and render alone for `tree`, to show where the time goes;
- encode + render with relevance pruning (the per-goal path), per encoding.
"""

from __future__ import annotations

from foon2pddl.analysis.reachability import reachable
from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import GROUND_ENCODINGS as ENCODINGS
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.render import render

from .harness import Context, timeit

AREA = "pddl_compile"
FLOOR_SECONDS = 0.2


def run(ctx: Context) -> None:
    foon, _ = load([ctx.shared / "foon-subgraphs"])
    kitchen = default_kitchen(foon)
    reach = reachable(foon, kitchen.nodes)
    dish = next(n for n in sorted(foon.nodes) if n.dish is not None and reach.can_make(n))
    goal = resolve_goal(spec_of_node(dish), foon)
    repeat = max(3, ctx.repeat)

    for enc in ENCODINGS:
        t, _, (domain, problem) = timeit(
            lambda enc=enc: render(compile_task(foon, kitchen, goal, enc, 3, prune=False)), repeat)
        note = f"{len(foon.units)} units, {len(domain) + len(problem):,} characters"
        if enc == "tree":
            note += f", floor <= {FLOOR_SECONDS} s"
        ctx.report(AREA, f"compile universal FOON, {enc}, no pruning", t, "s", note)

    t_enc, _, task = timeit(lambda: compile_task(foon, kitchen, goal, "tree", 3, prune=False), repeat)
    ctx.report(AREA, "encode only, tree, no pruning", t_enc, "s", f"{len(task.actions)} actions")
    t_ren, _, _ = timeit(lambda: render(task), repeat)
    ctx.report(AREA, "render only, tree, no pruning", t_ren, "s")

    for enc in ENCODINGS:
        t, _, task = timeit(lambda enc=enc: compile_task(foon, kitchen, goal, enc, 3, prune=True), repeat)
        t_r, _, _ = timeit(lambda task=task: render(task), repeat)
        ctx.report(AREA, f"compile with pruning, {enc}", t + t_r, "s",
                   f"goal {goal.describe()}: {len(task.actions)} actions kept")
