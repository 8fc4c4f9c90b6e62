"""Robot skills under every step: each shared subgraph's dish plan decomposed into skills (`foon2pddl.skills`).

`python -m bench.skills [--shared DIR] [--time-limit S] [--limit N] [--encoding E] [-v]` plans every
subgraph alone (dish goal, default kitchen, the encoding `plan --skills` uses) and
decomposes the plan: per file the macro steps, how many decompose, the skill replay's
verdict; per micro task translate+search wall time and CPU time (the translator runs
in-process, the search binary's CPU is its child time). Reports the share of macro
steps that decompose (floor 90 %), the median micro time per step (floor < 0.1 s),
the median whole-dish skill time (floor < 5 s), motion coverage of the files' units
and of the plans' firings, and every step that did not decompose with its motion and
reason. As a bench area (`run(ctx)`) it reports the same figures.
"""

from __future__ import annotations

import argparse
import collections
import resource
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path

from foon2pddl.errors import FoonError
from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.planners.solve import plan
from foon2pddl.skills import decompose, shipped_domain, shipped_table
from foon2pddl.skills.decompose import StepStatus
from foon2pddl.skills.fd_micro import solve_micro
from foon2pddl.skills.run import skills_encoding
from foon2pddl.skills.source import trace_of
from foon2pddl.skills.table import coverage

from .harness import Context

AREA = "skills"


@dataclass
class Row:
    file: str
    status: str
    unit_motions: list[str]
    steps: int = 0
    decomposed: int = 0
    replay_ok: bool = False
    dish_seconds: float = 0.0
    micro_wall: list[float] = field(default_factory=list)
    micro_cpu: list[float] = field(default_factory=list)
    firings: list[str] = field(default_factory=list)
    misses: list[tuple[str, str, str]] = field(default_factory=list)  # (motion, status, reason)


def _timed(row: Row):
    def solver(domain_text: str, problem_text: str):
        c0, k0, t0 = time.process_time(), resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
        r = solve_micro(domain_text, problem_text)
        k1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        row.micro_wall.append(time.perf_counter() - t0)
        row.micro_cpu.append(time.process_time() - c0 + (k1.ru_utime + k1.ru_stime) - (k0.ru_utime + k0.ru_stime))
        return str(r.status), r.plan, r.message, r.timings.get("translate", 0.0) + r.timings.get("search", 0.0)
    return solver


def check_file(path: Path, time_limit: float, encoding: str | None = None) -> Row | None:
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
    t0 = time.perf_counter()
    skills = decompose(trace, shipped_table(), shipped_domain(), solver=_timed(row))
    row.dish_seconds = time.perf_counter() - t0
    row.steps, row.decomposed, row.replay_ok = len(skills.steps), skills.decomposed, skills.replay.ok
    row.firings = [s.unit.motion.label for s in trace.steps]
    row.misses = [(s.motion, str(s.status), s.reason.splitlines()[0][:160]) for s in skills.steps
                  if s.status is not StepStatus.DECOMPOSED]
    return row


def summary(rows: list[Row]) -> list[tuple[str, float, str]]:
    planned = [r for r in rows if r.steps]
    steps = sum(r.steps for r in planned)
    done = sum(r.decomposed for r in planned)
    wall = [x for r in planned for x in r.micro_wall]
    cpu = [x for r in planned for x in r.micro_cpu]
    table = shipped_table()
    units = coverage([m for r in rows for m in r.unit_motions], table)
    fired = coverage([m for r in planned for m in r.firings], table)
    out = [("files with a dish", len(rows), "files"), ("dish plans", len(planned), "files"),
           ("macro steps", steps, "steps"), ("macro steps decomposed", 100.0 * done / steps if steps else 0.0, "%"),
           ("files at or above 90 % decomposed", sum(r.decomposed >= 0.9 * r.steps for r in planned), "files"),
           ("skill replay valid", sum(r.replay_ok for r in planned), "files"),
           ("micro time per step, median wall", statistics.median(wall) if wall else 0.0, "s"),
           ("micro time per step, median CPU", statistics.median(cpu) if cpu else 0.0, "s"),
           ("whole-dish skill time, median wall", statistics.median(r.dish_seconds for r in planned) if planned
            else 0.0, "s"),
           ("units whose motion maps", 100.0 * units.share, "%"), ("firings whose motion maps", 100.0 * fired.share, "%")]
    return out


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
    ap.add_argument("--encoding", default=None, help="macro encoding (default: the one plan --skills uses)")
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args()
    rows = []
    for f in expand_paths([args.shared / "foon-subgraphs"])[: args.limit]:
        row = check_file(f, args.time_limit, args.encoding)
        if row is None:
            continue
        rows.append(row)
        if args.verbose:
            med = statistics.median(row.micro_wall) if row.micro_wall else 0.0
            cpu = statistics.median(row.micro_cpu) if row.micro_cpu else 0.0
            print(f"{row.file}\t{row.status}\tsteps={row.steps}\tdecomposed={row.decomposed}\t"
                  f"replay={'ok' if row.replay_ok else 'FAIL'}\tdish={row.dish_seconds:.2f}s\t"
                  f"micro median={med:.3f}s wall, {cpu:.3f}s CPU\tmotions={','.join(row.firings)}", flush=True)
            for m in row.misses:
                print("\t" + " | ".join(m), flush=True)
    for name, value, unit in summary(rows):
        print(f"{name}: {value:.4g} {unit}" if isinstance(value, float) else f"{name}: {value} {unit}")
    print("steps that did not decompose:")
    for line in misses(rows):
        print("  " + line)
    cov = coverage([m for r in rows for m in r.unit_motions], shipped_table())
    print("coverage by motion (units): " + ", ".join(f"{m} {n}{'' if m in cov.mapped else ' (unmapped)'}"
                                                   for m, n in cov.counts))


if __name__ == "__main__":
    main()
