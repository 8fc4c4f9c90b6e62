"""Physical replay of `instances` (and `relational`) plans: each shared subgraph alone, its dish as the goal.

`python -m bench.physical_replay [--shared DIR] [--encodings E ...] [--universal | --native] [--time-limit S]
[--limit N] [-v]`

Per subgraph (its dish, its default kitchen, level 3, pruned): Fast Downward
(lama-first) on each encoding; every plan becomes a `PhysicalTrace` (the
encoding's replay hook; for `instances`, which models no holders, the holders
are inferred by tracking, `planners.instance_physical`) and is replayed by
`planners.physical_replay`. Reports per encoding: plans, plans with a
disagreement, unit steps after which one holds, plans inconsistent in the
initial state, and per kind the plans and steps it occurs in; for `instances`,
which rule placed the objects. `relational` is measured when it is registered.
`--universal`: the merge of all subgraphs, each reachable dish a goal.

`--native`: FOON's native task tree of each dish (`retrieve`, method `complete`)
scheduled over the default kitchen with one object per kitchen item
(`planners.executable`): how many trees are executable, which labels run short
first, how many need an intermediate again, and how many objects per kitchen node
they would need.
"""

from __future__ import annotations

import argparse
import collections
from dataclasses import dataclass, field
from pathlib import Path

from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import ENCODINGS, compile_goal
from foon2pddl.pddl.registry import PlanDecodeError
from foon2pddl.pddl.render import render
from foon2pddl.planners import fd
from foon2pddl.planners.executable import needed, schedule
from foon2pddl.planners.instance_physical import physical_trace
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.replay_findings import DisagreementKind
from foon2pddl.retrieval.api import retrieve

from .harness import Context, reachable_dishes, run_main, shared_data

AREA = "physical_replay"
WANTED = ("instances", "relational")


@dataclass(frozen=True)
class Row:
    """One subgraph in one encoding: FD status, unit steps, and what the replay found."""

    file: str
    encoding: str
    status: str
    steps: int = 0
    affected: int = 0
    initial_bad: bool = False
    kinds: dict = field(default_factory=dict)  # kind -> steps (distinct, -1 = initial) it is raised at
    evidence: dict = field(default_factory=dict)
    first: str = ""


def check_file(path: Path, encodings: tuple[str, ...], time_limit: float) -> list[Row]:
    foon, _ = load([path])
    dishes = sorted(n for n in foon.nodes if n.dish is not None)
    if not dishes or dishes[0] not in foon.producers:
        return []
    return check_goal(path.name, foon, default_kitchen(foon), dishes[0], encodings, time_limit)


def universal_rows(subgraphs: Path, encodings: tuple[str, ...], time_limit: float,
                   limit: int | None = None) -> list[Row]:
    """The merge of every subgraph, each reachable dish a goal (per-goal pruning)."""
    foon, _ = load([subgraphs])
    kitchen = default_kitchen(foon)
    dishes = reachable_dishes(foon, kitchen.nodes)
    return [r for d in dishes[:limit] for r in check_goal(d.describe(), foon, kitchen, d, encodings, time_limit)]


def check_goal(name: str, foon, kitchen, dish, encodings: tuple[str, ...], time_limit: float) -> list[Row]:
    goal = resolve_goal(spec_of_node(dish), foon)
    rows = []
    for enc in encodings:
        compiled = compile_goal(foon, kitchen, goal, enc)
        res = fd.solve(*render(compiled.task), time_limit=time_limit)
        if not res.solved:
            rows.append(Row(name, enc, res.status))
            continue
        try:
            trace = compiled.replay(compiled.task, res.plan)
        except PlanDecodeError as exc:
            rows.append(Row(name, enc, "undecodable", first=str(exc)))
            continue
        evidence = {}
        if not compiled.holders:
            inferred = physical_trace(compiled.task, trace)
            trace, evidence = inferred.trace, dict(inferred.evidence)
        report = replay(trace)
        kinds: dict[DisagreementKind, set[int]] = collections.defaultdict(set)
        for d in report.disagreements:
            kinds[d.kind].add(d.step)
        rows.append(Row(name, enc, "solved", len(trace.steps), len(report.affected_steps),
                        any(d.step < 0 for d in report.disagreements), dict(kinds), evidence,
                        report.disagreements[0].describe() if report.disagreements else ""))
    return rows


def check_all(subgraphs: Path, encodings: tuple[str, ...], time_limit: float = 60.0,
              limit: int | None = None) -> list[Row]:
    return [r for f in expand_paths([subgraphs])[:limit] for r in check_file(f, encodings, time_limit)]


@dataclass(frozen=True)
class NativeRow:
    """One dish's native tree: units, verdict, the label and step that fail, and the most objects a node needs."""

    file: str
    units: int
    verdict: str
    label: str
    step: int | None
    most: int


def native_rows(subgraphs: Path, limit: int | None = None) -> list[NativeRow]:
    rows = []
    for path in expand_paths([subgraphs])[:limit]:
        foon, _ = load([path])
        dishes = sorted(n for n in foon.nodes if n.dish is not None)
        if not dishes or dishes[0] not in foon.producers:
            continue
        kitchen = default_kitchen(foon)
        found = retrieve(foon, kitchen, resolve_goal(spec_of_node(dishes[0]), foon))
        if found.tree is None:
            continue
        got = schedule(found.tree, kitchen.nodes)
        most = max((k for _, k in needed(found.tree, kitchen.nodes).drawn), default=0)
        rows.append(NativeRow(path.name, len(found.tree), str(got.verdict), got.label, got.step, most))
    return rows


def native_summary(rows: list[NativeRow]) -> str:
    verdicts = collections.Counter(r.verdict for r in rows)
    short = collections.Counter(r.label for r in rows if r.verdict == "short")
    return "\n".join([
        f"native trees: {len(rows)}; " + ", ".join(f"{k} {v}" for k, v in sorted(verdicts.items())),
        "  runs short first: " + ", ".join(f"{k} {v}" for k, v in short.most_common(8)),
        f"  trees needing 2+ objects in one kitchen node: {sum(r.most >= 2 for r in rows)}; "
        f"most in one node: {max((r.most for r in rows), default=0)}",
    ])


def summary(rows: list[Row]) -> str:
    lines = []
    for enc in dict.fromkeys(r.encoding for r in rows):
        mine = [r for r in rows if r.encoding == enc]
        plans = [r for r in mine if r.status == "solved"]
        bad = [r for r in plans if r.kinds]
        steps = sum(r.steps for r in plans)
        lines.append(f"{enc}: {len(mine)} goals, {len(plans)} plans, {sum(r.steps for r in plans)} unit steps; "
                     f"{len(bad)} plans with a disagreement, {sum(r.affected for r in plans)} of {steps} steps "
                     f"after which one holds, {sum(r.initial_bad for r in plans)} plans inconsistent initially")
        for kind in DisagreementKind:
            having = [r for r in plans if kind in r.kinds]
            if having:
                lines.append(f"  {kind}: {len(having)} plans, "
                             f"{sum(len(r.kinds[kind] - {-1}) for r in having)} steps")
        evidence = collections.Counter()
        for r in plans:
            evidence.update(r.evidence)
        if evidence:
            total = sum(evidence.values())
            lines.append("  holders placed by: " + ", ".join(f"{k} {v} ({100 * v / total:.0f} %)"
                                                             for k, v in sorted(evidence.items())))
    return "\n".join(lines)


def run(ctx: Context) -> None:
    encodings = tuple(e for e in WANTED if e in ENCODINGS)
    rows = check_all(ctx.shared / "foon-subgraphs", encodings, limit=10 if ctx.quick else None)
    for enc in encodings:
        plans = [r for r in rows if r.encoding == enc and r.status == "solved"]
        ctx.report(AREA, f"{enc}: plans with a physical disagreement", sum(bool(r.kinds) for r in plans), "plans",
                   f"of {len(plans)}; steps after which one holds: {sum(r.affected for r in plans)} of "
                   f"{sum(r.steps for r in plans)}")
    print(summary(rows))
    native = native_rows(ctx.shared / "foon-subgraphs", limit=10 if ctx.quick else None)
    ctx.report(AREA, "native trees executable with one object per kitchen item",
               sum(r.verdict == "executable" for r in native), "trees", f"of {len(native)}")
    print(native_summary(native))


def main() -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.physical_replay", description=__doc__)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"), help="shared data directory")
    ap.add_argument("--encodings", nargs="*", default=None, help=f"default: those of {', '.join(WANTED)} registered")
    ap.add_argument("--time-limit", type=float, default=60.0, help="seconds per FD run")
    ap.add_argument("--limit", type=int, default=None, help="only the first N files")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per file and encoding")
    ap.add_argument("--native", action="store_true", help="schedule native trees instead (module doc)")
    ap.add_argument("--universal", action="store_true", help="the merged network, each reachable dish a goal")
    args = ap.parse_args()
    shared_data(args.shared)
    if args.native:
        native = native_rows(args.shared / "foon-subgraphs", args.limit)
        if args.verbose:
            for r in native:
                print(f"{r.file}\t{r.units}\t{r.verdict}\t{r.label}\t{r.step}\t{r.most}")
        print(native_summary(native))
        return
    encodings = tuple(args.encodings or (e for e in WANTED if e in ENCODINGS))
    if args.universal:
        rows = universal_rows(args.shared / "foon-subgraphs", encodings, args.time_limit, args.limit)
    else:
        rows = check_all(args.shared / "foon-subgraphs", encodings, args.time_limit, args.limit)
    if args.verbose:
        for r in rows:
            print(f"{r.file}\t{r.encoding}\t{r.status}\t{r.affected}/{r.steps}\t"
                  f"{','.join(sorted(r.kinds))}\t{r.first}")
    print(summary(rows))


if __name__ == "__main__":
    run_main(main)
