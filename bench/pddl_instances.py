"""The `instances` encoding against `tree`: each shared subgraph alone, and the universal FOON per goal.

`python -m bench.pddl_instances [--shared DIR] [--universal] [--extra N] [--limit N] [--time-limit S]
                                [--planner lama|fd-opt|symk-opt] [-v]`

Per subgraph (its dish as the goal, its default kitchen, level 3, pruned):
Fast Downward (lama-first) on `tree` and on `instances`; every `instances`
plan is replayed at the instance level (`planners.trace_check.check_states`) and its units,
in plan order, are validated as a FOON task tree from the kitchen. Reports
solved counts, plan lengths (units; repeated firings) and the median and
worst time (translate + search). `--universal`: the merge of all subgraphs,
each subgraph's dish a goal, per-goal relevance pruning. `--extra N` adds N
instances to every starting place (too many instances). `--planner` runs the
`instances` task with an optimal planner instead of lama-first (`fd-opt`: FD
seq-opt-lmcut; `symk-opt`: SymK through unified-planning, `pip install up-symk`).
"""

from __future__ import annotations

import argparse
import statistics
import time
from dataclasses import dataclass
from pathlib import Path

from foon2pddl.analysis.reachability import reachable
from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.foon import Foon, ObjectNode
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.model.tasktree import TaskTree, validate
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.encode_instances import encode_instances
from foon2pddl.pddl.encoding import EncodeOptions
from foon2pddl.pddl.instance_replay import instance_trace
from foon2pddl.pddl.prune import drop_unbindable
from foon2pddl.pddl.render import render
from foon2pddl.planners import fd, up_engine
from foon2pddl.planners.trace_check import check_states

from .harness import Context, reachable_dishes, run_main, shared_data

AREA = "pddl_instances"


@dataclass(frozen=True)
class Row:
    """One goal: tree and instances statuses, plan sizes, instance counts, checks and seconds."""

    name: str
    native: bool
    tree: str
    tree_units: int
    status: str
    steps: int
    distinct_units: int
    instances: int
    valid: bool
    problem: str
    seconds: float  # translate + search of the instances run
    tree_seconds: float


def _seconds(res) -> float:
    return res.timings.get("translate", 0.0) + res.timings.get("search", 0.0)


#: `--planner`: how the instances task is solved (PDDL text, time limit) -> PlanResult.
PLANNERS = {
    "lama": lambda d, p, t: fd.solve(d, p, time_limit=t),
    "fd-opt": lambda d, p, t: fd.solve(d, p, optimal=True, time_limit=t),
    "symk-opt": lambda d, p, t: up_engine.solve((d, p), "symk", optimal=True, time_limit=t),
}


def check_goal(name: str, foon: Foon, kitchen: Kitchen, dish: ObjectNode, time_limit: float, extra: int = 0,
               planner: str = "lama") -> Row:
    goal = resolve_goal(spec_of_node(dish), foon)
    native = reachable(foon, kitchen.nodes, goal.candidates).makes_any(goal.candidates)
    tree_task = compile_task(foon, kitchen, goal, "tree")
    tree = fd.solve(*render(tree_task), time_limit=time_limit)
    tree_units = sum(tree_task.action_for(s.split()[0]).unit is not None for s in tree.plan)
    t0 = time.perf_counter()
    task = encode_instances(foon, kitchen, goal, 3, EncodeOptions(), extra=extra)
    res = PLANNERS[planner](*render(drop_unbindable(task)), time_limit)  # what `plan` gives the planner
    seconds = _seconds(res) or (time.perf_counter() - t0)
    if not res.solved:
        return Row(name, native, tree.status, tree_units, res.status, 0, 0, len(task.instances), False,
                   res.message.splitlines()[0] if res.message else "", seconds, _seconds(tree))
    trace = instance_trace(task, res.plan)
    verdict = check_states(trace, goal.candidates)
    final = {s.node for s in trace.final.values()}
    reached = next((c for c in goal.candidates if c in final), goal.candidates[0])
    steps = trace.steps
    foon_check = validate(TaskTree(tuple(s.unit for s in steps), reached), kitchen.nodes)
    problems = verdict.problems + foon_check.problems
    return Row(name, native, tree.status, tree_units, res.status, len(steps), len({s.unit for s in steps}),
               len(task.instances), not problems, problems[0] if problems else "", seconds, _seconds(tree))


def subgraph_rows(shared: Path, time_limit: float, limit: int | None, extra: int = 0, planner: str = "lama"
                  ) -> list[Row]:
    rows = []
    for path in expand_paths([shared / "foon-subgraphs"])[:limit]:
        foon, _ = load([path])
        dishes = sorted(n for n in foon.nodes if n.dish is not None)
        if dishes and dishes[0] in foon.producers:
            rows.append(check_goal(path.name, foon, default_kitchen(foon), dishes[0], time_limit, extra, planner))
    return rows


def universal_rows(shared: Path, time_limit: float, limit: int | None, extra: int = 0, planner: str = "lama"
                   ) -> list[Row]:
    foon, _ = load([shared / "foon-subgraphs"])
    kitchen = default_kitchen(foon)
    dishes = reachable_dishes(foon, kitchen.nodes)
    return [check_goal(d.describe(), foon, kitchen, d, time_limit, extra, planner) for d in dishes[:limit]]


def summary(rows: list[Row]) -> str:
    solved = [r for r in rows if r.status == "solved"]
    tree_solved = [r for r in rows if r.tree == "solved"]
    both = [r for r in solved if r.tree == "solved"]
    times = sorted(r.seconds for r in solved) or [0.0]
    worst = max(solved, key=lambda r: r.seconds) if solved else None
    lines = [
        f"goals {len(rows)}: tree solves {len(tree_solved)}, instances solves {len(solved)} "
        f"({len(both)} of tree's), {sum(r.valid for r in solved)} plans validate (instance level + FOON tree)",
        f"instances translate+search: median {statistics.median(times):.3f} s, worst {times[-1]:.3f} s"
        + (f" ({worst.name})" if worst else ""),
    ]
    if both:
        lines.append(
            f"plan length on goals both solve: tree {sum(r.tree_units for r in both)} unit steps, instances "
            f"{sum(r.steps for r in both)} unit steps ({sum(r.distinct_units for r in both)} distinct units; "
            f"{sum(r.steps > r.distinct_units for r in both)} plans fire a unit more than once); "
            f"median instances per task {statistics.median(r.instances for r in both):.0f}")
    for r in rows:
        if r.tree == "solved" and (r.status != "solved" or not r.valid):
            lines.append(f"  not solved or invalid: {r.name}: {r.status} {r.problem}")
    return "\n".join(lines)


def run(ctx: Context) -> None:
    rows = subgraph_rows(ctx.shared, 60.0, 10 if ctx.quick else None)
    ctx.report(AREA, "instances: subgraph dishes solved by FD", sum(r.status == "solved" for r in rows), "files",
               f"of {len(rows)}; tree solves {sum(r.tree == 'solved' for r in rows)}")
    print(summary(rows))


def main() -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.pddl_instances", description=__doc__)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"), help="shared data directory")
    ap.add_argument("--universal", action="store_true", help="the merged network, every reachable dish a goal")
    ap.add_argument("--extra", type=int, default=0, help="instances added to every starting place")
    ap.add_argument("--time-limit", type=float, default=60.0, help="seconds per FD run")
    ap.add_argument("--limit", type=int, default=None, help="only the first N files or goals")
    ap.add_argument("--planner", choices=sorted(PLANNERS), default="lama", help="planner for the instances task")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per goal")
    args = ap.parse_args()
    shared_data(args.shared)
    rows = (universal_rows if args.universal else subgraph_rows)(args.shared, args.time_limit, args.limit, args.extra,
                                                                 args.planner)
    if args.verbose:
        for r in rows:
            print(f"{r.name}\ttree={r.tree}/{r.tree_units}\tinstances={r.status}/{r.steps}/{r.distinct_units}"
                  f"\tobjects={r.instances}\tvalid={r.valid}\t{r.seconds:.3f}s\t{r.problem}")
    print(summary(rows))


if __name__ == "__main__":
    run_main(main)
