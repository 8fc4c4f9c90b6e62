"""The `relational` encoding against `instances` and `tree` on each subgraph alone (dish goal, default kitchen).

`python -m bench.pddl_relational [--shared DIR] [--universal] [--time-limit S] [--limit N] [--encodings E,E]
[--level L] [-v]` plans every subgraph with `tree`, `instances` and `relational` (`planners.solve.plan`,
Fast Downward lama-first) and reports per encoding: solved, plans whose trace
passes the relational replay (`planners.physical_replay`, zero disagreements;
`instances` traces have no holders, so its figure counts what a holder-blind
plan gets wrong), disagreements by kind, unit steps and objects per task
(median, worst; and those the PDDL problem declares: `pddl.untouched` sets aside
what no action can touch), translate+search seconds (median, worst), and with more than one encoding the unit
steps of each on the dishes all solve (median, total). `-v`: one
line per file and encoding. `--universal`: the merge of all subgraphs (issue 21's universal
floor), its default kitchen, each reachable dish a goal (as `bench.pddl_instances
--universal`); a row's `file` is the goal node. As a bench area (`run(ctx)`) it reports the counts.
`--every K --offset I` / `--sample N --seed S`: only the subgraphs of 0-based sorted index I modulo K, or
N of them drawn with `random.Random(S)` (`pick`): a universal FOON of subgraphs no rule was tuned on (docs/pddl.md,
Unseen universal FOONs).
`--level 2` (or 1): every network, kitchen and goal projected to that level first (`model.levels.project`, as
`plan --level` does).
`--restore`: each task planned with the given encodings' last and again with `plan --restore`
(`planners.solve.plan_restoring`); on the dishes both plan valid and replay-clean, their objects and
`copies` (copies used one after another) before and after.

`planners.copies`: per kitchen node, the objects used less the most in use at once (a bowl of flour and a
bowl of sugar are no copies of each other).
"""

from __future__ import annotations

import argparse
import collections
import random
import statistics
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from foon2pddl.errors import FoonError
from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.foon import Foon
from foon2pddl.model.goal import Goal, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.model.levels import LEVELS, project
from foon2pddl.pddl.restore import is_restoring
from foon2pddl.planners.copies import copies
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan, plan_restoring

from .harness import Context, reachable_dishes, run_main, shared_data

AREA = "pddl_relational"
ENCODINGS = ("tree", "instances", "relational")


@dataclass(frozen=True)
class Row:
    file: str
    encoding: str
    status: str
    steps: int
    objects: int  # the task's objects (the plan's replay holds them all)
    problem: int  # the objects the PDDL problem declares (`pddl.untouched` sets the others aside)
    kinds: tuple[str, ...]  # replay disagreement kinds (one per disagreement)
    seconds: float
    message: str = ""


def check_file(path: Path, time_limit: float, encodings: tuple[str, ...] = ENCODINGS, level: int = 3) -> list[Row]:
    foon, _ = load([path])
    dishes = sorted(n for n in foon.nodes if n.dish is not None)
    if not dishes:
        return []
    kitchen, foon = default_kitchen(foon), project(foon, level)
    try:
        goal = resolve_goal(spec_of_node(dishes[0]), foon)
    except FoonError:
        return []
    return check_goal(path.name, foon, kitchen, goal, time_limit, encodings, level)


def check_goal(name: str, foon: Foon, kitchen: Kitchen, goal: Goal, time_limit: float,
               encodings: tuple[str, ...] = ENCODINGS, level: int = 3) -> list[Row]:
    """One row per encoding: `goal` planned over `foon` (at `level`) from `kitchen`, its trace replayed."""
    rows = []
    for enc in encodings:
        out = plan(foon, kitchen, goal, enc, level, time_limit=time_limit)
        seconds = out.timings.get("translate", 0.0) + out.timings.get("search", 0.0)
        kinds: tuple[str, ...] = ()
        if out.trace is not None:
            kinds = tuple(str(d.kind) for d in replay(out.trace).disagreements)
        steps = len(out.trace.steps) if out.trace is not None else (len(out.tree) if out.tree is not None else 0)
        rows.append(Row(name, enc, str(out.status), steps, len(out.task.instances), len(out.task.objects), kinds,
                        seconds,
                        out.message.splitlines()[0][:200] if out.message else ""))
    return rows


def restore_rows(paths: list[Path], encoding: str, time_limit: float, verbose: bool) -> str:
    """Objects and copies (`copies`) of each dish's plan without and with restoring units, on the dishes both
    plan valid and replay-clean."""
    pairs = []
    for path in paths:
        foon, _ = load([path])
        dishes = sorted(n for n in foon.nodes if n.dish is not None)
        try:
            goal = resolve_goal(spec_of_node(dishes[0]), foon) if dishes else None
        except FoonError:
            goal = None
        if goal is None:
            continue
        kitchen = default_kitchen(foon)
        outs = [f(foon, kitchen, goal, encoding, time_limit=time_limit) for f in (plan, plan_restoring)]
        if all(str(o.status) == "solved" and o.trace is not None and not replay(o.trace).disagreements for o in outs):
            row = [(len(o.task.instances), copies(o.trace), sum(is_restoring(s.unit) for s in o.trace.steps)) for o in outs]
            pairs.append(row)
            if verbose:
                print(f"{path.name}\tobjects {row[0][0]} -> {row[1][0]}\tcopies {row[0][1]} -> {row[1][1]}\t"
                      f"restoring steps {row[1][2]}", flush=True)
    total = [sum(sum(r[i][1].values()) for r in pairs) for i in (0, 1)]
    by_label = [collections.Counter() for _ in (0, 1)]
    for r in pairs:
        for i in (0, 1):
            by_label[i].update(r[i][1])
    top = ", ".join(f"{lab} {by_label[0][lab]} -> {by_label[1][lab]}" for lab, _ in by_label[0].most_common(6))
    return (f"{encoding} --restore: {len(pairs)} dishes plan valid and replay-clean either way; objects "
            f"{sum(r[0][0] for r in pairs)} -> {sum(r[1][0] for r in pairs)}; copies used one after another "
            f"{total[0]} -> {total[1]} ({top}); restoring steps {sum(r[1][2] for r in pairs)} in "
            f"{sum(r[1][2] > 0 for r in pairs)} plans")


def pick(files: list[Path], every: int = 1, offset: int = 0, sample: int | None = None, seed: int = 0) -> list[Path]:
    """The files of 0-based index `offset` modulo `every` in `files`' order, then `sample` of them drawn with
    `random.Random(seed)` (all when None), in `files`' order: a seeded subset the same on every machine."""
    if every < 1:
        raise ValueError(f"--every {every}: must be 1 or more (every K-th subgraph; 1 takes them all)")
    if not 0 <= offset < every:
        raise ValueError(f"--offset {offset} is not in 0..{every - 1} (--every {every})")
    chosen = files[offset::every]
    if sample is None:
        return chosen
    if not 0 < sample <= len(chosen):
        raise ValueError(f"--sample {sample}: there are {len(chosen)} subgraphs to draw from")
    drawn = set(random.Random(seed).sample(chosen, sample))
    return [f for f in chosen if f in drawn]


def universal_rows(files: list[Path], time_limit: float, limit: int | None = None,
                   encodings: tuple[str, ...] = ENCODINGS, level: int = 3) -> Iterator[Row]:
    """The merged `files` (subgraphs), default kitchen, every dish its kitchen can make a goal (sorted; the first
    `limit`), all at `level`."""
    foon, _ = load(files)
    kitchen = default_kitchen(foon)
    foon = project(foon, level)
    dishes = reachable_dishes(foon, kitchen.project(level).nodes)
    for dish in dishes[:limit]:
        yield from check_goal(dish.describe(), foon, kitchen, resolve_goal(spec_of_node(dish), foon), time_limit,
                              encodings, level)


def summary(rows: list[Row], encodings: tuple[str, ...] = ENCODINGS) -> str:
    lines = []
    for enc in encodings:
        mine = [r for r in rows if r.encoding == enc]
        solved = [r for r in mine if r.status == "solved"]
        line = f"{enc}: {len(solved)}/{len(mine)} solved"
        if enc != "tree":
            traced = [r for r in mine if r.steps and r.status in ("solved", "error")]
            clean = [r for r in traced if not r.kinds]
            kinds = collections.Counter(k for r in traced for k in r.kinds)
            bad_plans = collections.Counter(k for r in traced for k in set(r.kinds))
            line += (f"; plans with zero replay disagreements {len(clean)}/{len(traced)} "
                     f"({sum(r.status == 'solved' for r in clean)} of them solved: valid and replay-clean); "
                     f"disagreements {sum(kinds.values())} ("
                     + ", ".join(f"{k} {v} in {bad_plans[k]} plans" for k, v in kinds.most_common()) + ")")
            objs, problem = [r.objects for r in traced], [r.problem for r in traced]
            if objs:
                line += (f"; objects median {statistics.median(objs):.0f}, worst {max(objs)} (in the problem: median "
                         f"{statistics.median(problem):.0f}, worst {max(problem)})")
        if solved:
            secs = [r.seconds for r in solved]
            line += (f"; unit steps median {statistics.median(r.steps for r in solved):.0f}; "
                     f"translate+search median {statistics.median(secs):.2f} s, worst {max(secs):.2f} s")
        lines.append(line)
    if len(encodings) > 1:
        lines.append(common_steps(rows, encodings))
    return "\n".join(lines)


def common_steps(rows: list[Row], encodings: tuple[str, ...]) -> str:
    """Plan length (unit steps) per encoding on the dishes every one of `encodings` solves: each encoding's
    median and total over the same dishes, so lengths compare plan for plan (issue 21's "plan length against
    `instances` and `tree`")."""
    solved = {(r.file, r.encoding): r.steps for r in rows if r.status == "solved"}
    files = sorted({r.file for r in rows if all((r.file, e) in solved for e in encodings)})
    if not files:
        return "on the dishes every encoding solves (0): no plan length to compare"
    parts = [f"{e} median {statistics.median(solved[f, e] for f in files):.0f}, "
             f"total {sum(solved[f, e] for f in files):,}" for e in encodings]
    return f"unit steps on the {len(files)} dishes every encoding solves: " + "; ".join(parts)


def run(ctx: Context) -> None:
    rows = [r for f in expand_paths([ctx.shared / "foon-subgraphs"])[: 10 if ctx.quick else None]
            for r in check_file(f, 60.0)]
    for enc in ENCODINGS:
        mine = [r for r in rows if r.encoding == enc]
        ctx.report(AREA, f"{enc} solved", sum(r.status == "solved" for r in mine), "files")
        if enc != "tree":
            ctx.report(AREA, f"{enc} plans without replay disagreements",
                       sum(1 for r in mine if r.steps and not r.kinds), "plans")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--shared", type=Path, default=Path(__file__).resolve().parent.parent / "tests" / "data")
    ap.add_argument("--universal", action="store_true", help="the merged subgraphs, every reachable dish a goal")
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--limit", type=int, default=None)
    ap.add_argument("--encodings", default=",".join(ENCODINGS), help="comma-separated, of " + ", ".join(ENCODINGS))
    ap.add_argument("--level", type=int, choices=LEVELS, default=3, help="project network, kitchen and goal first")
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--restore", action="store_true", help="without and with restoring units: objects and copies")
    ap.add_argument("--every", type=int, default=1, help="only the subgraphs of sorted index OFFSET modulo EVERY")
    ap.add_argument("--offset", type=int, default=0)
    ap.add_argument("--sample", type=int, default=None, help="then N of those subgraphs, drawn with --seed")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    shared_data(args.shared)
    encodings = tuple(e for e in args.encodings.split(",") if e)
    try:
        files = pick(expand_paths([args.shared / "foon-subgraphs"]), args.every, args.offset, args.sample, args.seed)
    except ValueError as e:
        ap.error(str(e))
    if args.restore:
        print(restore_rows(files[: args.limit], encodings[-1], args.time_limit, args.verbose))
        return
    found = (universal_rows(files, args.time_limit, args.limit, encodings, args.level) if args.universal
             else (r for f in files[: args.limit] for r in check_file(f, args.time_limit, encodings, args.level)))
    rows = []
    for r in found:
        rows.append(r)
        if args.verbose:
            kinds = collections.Counter(r.kinds)
            print(f"{r.file}\t{r.encoding}\t{r.status}\tsteps={r.steps}\tobjects={r.objects}\tproblem={r.problem}\t"
                  f"{r.seconds:.2f}s\t{dict(kinds)}\t{r.message}", flush=True)
    print(summary(rows, encodings))


if __name__ == "__main__":
    run_main(main)
