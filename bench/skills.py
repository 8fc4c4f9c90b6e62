"""Robot skills under every step: each shared subgraph's dish plan decomposed into skills (`foon2pddl.skills`).

`python -m bench.skills [--shared DIR] [--time-limit S] [--limit N] [--match TEXT] [--repeat R] [--encoding E] [-v]`
plans every subgraph alone (dish goal, default kitchen, the encoding `plan --skills`
uses, whatever it solves today) and decomposes the plan `R` times, each with a fresh
micro-task memo (as one `plan --skills` run): per file the macro steps, how many
decompose, the skill replay's verdict, the whole-dish skill time (wall and CPU, the
median of the R runs), and per macro step with a micro task its planning time
(micro problem, memo lookup, in-process translate, search binary; CPU includes the
search binary's, the child time). Reports the share of macro steps that decompose
(floor 90 %), the median micro time per step (floor < 0.1 s) over every such step and
over the steps solved afresh (not taken from an equal earlier task), the median
whole-dish skill time (floor < 5 s), the objects a skill moves without holding them (`uncarried`: floor 0), motion coverage of the files' units and of the
plans' firings, every step that did not decompose with its motion and reason, and
the load average (wall times on a shared host mean little without it). As a bench
area (`run(ctx)`) it reports the same figures.
"""

from __future__ import annotations

import argparse
import collections
import os
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path

from foon2pddl.errors import FoonError
from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.planners.process import cpu_seconds
from foon2pddl.planners.solve import plan
from foon2pddl.skills import decompose, shipped_domain, shipped_table
from foon2pddl.skills.decompose import StepStatus, uncarried
from foon2pddl.skills.run import skills_encoding
from foon2pddl.skills.source import trace_of
from foon2pddl.skills.table import coverage

from .harness import Context, run_main, shared_data

AREA = "skills"


@dataclass
class Row:
    file: str
    status: str
    unit_motions: list[str]
    steps: int = 0
    decomposed: int = 0
    replay_ok: bool = False
    dish_seconds: float = 0.0  # median over the repeats, wall
    dish_cpu: float = 0.0  # median over the repeats, CPU (this process and the search binaries)
    micro_wall: list[float] = field(default_factory=list)  # every step with a micro task, every repeat
    micro_cpu: list[float] = field(default_factory=list)
    fresh_wall: list[float] = field(default_factory=list)  # the steps solved afresh (not reused)
    fresh_cpu: list[float] = field(default_factory=list)
    reused: int = 0  # steps (of one run) that took an equal earlier task's plan
    firings: list[str] = field(default_factory=list)
    misses: list[tuple[str, str, str]] = field(default_factory=list)  # (motion, status, reason)
    uncarried: list[str] = field(default_factory=list)  # `step N: object (motion)` moved with no transport skill


def check_file(path: Path, time_limit: float, encoding: str | None = None, repeat: int = 1) -> Row | None:
    foon, _ = load([path])
    dishes = sorted(n for n in foon.nodes if n.dish is not None)
    if not dishes:
        return None
    try:
        goal = resolve_goal(spec_of_node(dishes[0]), foon)
    except FoonError:
        return None
    row = Row(path.name, "", [u.motion.label for u in foon.units])
    out = plan(foon, default_kitchen(foon), goal, encoding or skills_encoding(), time_limit=time_limit)
    row.status = str(out.status)
    trace = trace_of(out) if out.status == "solved" else None
    if trace is None:
        return row
    walls, cpus = [], []
    for _ in range(max(1, repeat)):
        t0, c0 = time.perf_counter(), cpu_seconds()
        skills = decompose(trace, shipped_table(), shipped_domain())
        walls.append(time.perf_counter() - t0)
        cpus.append(cpu_seconds() - c0)
        timed = [s for s in skills.steps if s.problem is not None]
        row.micro_wall += [s.seconds for s in timed]
        row.micro_cpu += [s.cpu for s in timed]
        row.fresh_wall += [s.seconds for s in timed if not s.reused]
        row.fresh_cpu += [s.cpu for s in timed if not s.reused]
    row.dish_seconds, row.dish_cpu = statistics.median(walls), statistics.median(cpus)
    row.steps, row.decomposed, row.replay_ok = len(skills.steps), skills.decomposed, skills.replay.ok
    row.reused = sum(s.reused for s in skills.steps)
    row.firings = [s.unit.motion.label for s in trace.steps]
    row.misses = [(s.motion, str(s.status), s.reason.splitlines()[0][:160]) for s in skills.steps
                  if s.status is not StepStatus.DECOMPOSED]
    row.uncarried = [f"step {k + 1}: {oid} ({skills.steps[k].motion})" for k, oid in uncarried(skills, trace)]
    return row


def _median(xs) -> float:
    xs = list(xs)
    return statistics.median(xs) if xs else 0.0


def load_text() -> str:
    return "load average " + ", ".join(f"{x:.2f}" for x in os.getloadavg())


def summary(rows: list[Row]) -> list[tuple[str, float, str]]:
    planned = [r for r in rows if r.steps]
    steps = sum(r.steps for r in planned)
    done = sum(r.decomposed for r in planned)
    table = shipped_table()
    units = coverage([m for r in rows for m in r.unit_motions], table)
    fired = coverage([m for r in planned for m in r.firings], table)
    return [("files with a dish", len(rows), "files"), ("dish plans", len(planned), "files"),
            ("macro steps", steps, "steps"), ("macro steps decomposed", 100.0 * done / steps if steps else 0.0, "%"),
            ("files at or above 90 % decomposed", sum(r.decomposed >= 0.9 * r.steps for r in planned), "files"),
            ("skill replay valid", sum(r.replay_ok for r in planned), "files"),
            ("objects moved by a skill that does not hold them", sum(len(r.uncarried) for r in planned), "objects"),
            ("steps reusing an equal earlier micro task", sum(r.reused for r in planned), "steps"),
            ("micro time per step, median wall", _median(x for r in planned for x in r.micro_wall), "s"),
            ("micro time per step, median CPU", _median(x for r in planned for x in r.micro_cpu), "s"),
            ("micro time per step solved afresh, median wall", _median(x for r in planned for x in r.fresh_wall), "s"),
            ("micro time per step solved afresh, median CPU", _median(x for r in planned for x in r.fresh_cpu), "s"),
            ("whole-dish skill time, median wall", _median(r.dish_seconds for r in planned), "s"),
            ("whole-dish skill time, median CPU", _median(r.dish_cpu for r in planned), "s"),
            ("units whose motion maps", 100.0 * units.share, "%"), ("firings whose motion maps", 100.0 * fired.share, "%")]


def misses(rows: list[Row]) -> list[str]:
    found = collections.Counter((m, s, why) for r in rows for m, s, why in r.misses)
    return [f"{n} x {m} ({s}): {why}" for (m, s, why), n in found.most_common()]


def run(ctx: Context) -> None:
    rows = [r for f in expand_paths([ctx.shared / "foon-subgraphs"])[: 10 if ctx.quick else None]
            if (r := check_file(f, 60.0)) is not None]
    for name, value, unit in summary(rows):
        ctx.report(AREA, name, value, unit)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--shared", type=Path, default=Path(__file__).resolve().parent.parent / "tests" / "data")
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--limit", type=int, default=None)
    ap.add_argument("--match", action="append", default=[], help="only files whose name contains TEXT (repeatable)")
    ap.add_argument("--repeat", type=int, default=1, help="decompose each dish plan R times (medians)")
    ap.add_argument("--encoding", default=None, help="macro encoding (default: the one plan --skills uses)")
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args()
    shared_data(args.shared)
    print(f"start: {load_text()}", flush=True)
    rows = []
    files = [f for f in expand_paths([args.shared / "foon-subgraphs"])
             if not args.match or any(m in f.name for m in args.match)][: args.limit]
    for f in files:
        row = check_file(f, args.time_limit, args.encoding, args.repeat)
        if row is None:
            continue
        rows.append(row)
        if args.verbose:
            print(f"{row.file}\t{row.status}\tsteps={row.steps}\tdecomposed={row.decomposed}\t"
                  f"replay={'ok' if row.replay_ok else 'FAIL'}\treused={row.reused}\t"
                  f"dish={row.dish_seconds:.2f}s wall, {row.dish_cpu:.2f}s CPU\t"
                  f"micro median={_median(row.micro_wall):.3f}s wall, {_median(row.micro_cpu):.3f}s CPU\t"
                  f"motions={','.join(row.firings)}", flush=True)
            for m in row.misses:
                print("\t" + " | ".join(m), flush=True)
            for m in row.uncarried:
                print("\tmoved with no transport skill: " + m, flush=True)
    print(f"end: {load_text()}")
    for name, value, unit in summary(rows):
        print(f"{name}: {value:.4g} {unit}" if isinstance(value, float) else f"{name}: {value} {unit}")
    print("steps that did not decompose:")
    for line in misses(rows):
        print("  " + line)
    cov = coverage([m for r in rows for m in r.unit_motions], shipped_table())
    print("coverage by motion (units): " + ", ".join(f"{m} {n}{'' if m in cov.mapped else ' (unmapped)'}"
                                                   for m, n in cov.counts))


if __name__ == "__main__":
    run_main(main)
