"""Each shared subgraph alone, its dish as the goal, its default kitchen: compile in every encoding, run FD.

`python -m bench.pddl_subgraphs [--shared DIR] [--level L] [--no-prune] [--time-limit S] [--limit N] [-v]`
prints, per encoding, how many files compile to PDDL that Fast Downward
accepts, how many it solves, and why the others are not solved (grouped
reasons; `-v` adds one line per file with the specific cause), next to the
native fixpoint's verdict. When the native fixpoint solves a file and another
encoding does not, the `tree` plan's units are replayed in that encoding to
name the first fact that fails. Each FD run has its own temporary directory
(`planners.fd.solve`). As a bench area (`run(ctx)`) it reports the counts.
"""

from __future__ import annotations

import argparse
import collections
import time
from dataclasses import dataclass
from pathlib import Path

from foon2pddl.analysis.reachability import blockers, reachable
from foon2pddl.cli.progress import slow_step
from foon2pddl.errors import FoonError
from foon2pddl.io.files import expand_paths, load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.levels import project, project_node
from foon2pddl.pddl.compile import GROUND_ENCODINGS as ENCODINGS
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import PlanningTask
from foon2pddl.planners import fd

from .harness import Context, run_main, shared_data

AREA = "pddl_subgraphs"


@dataclass(frozen=True)
class Outcome:
    """One file in one encoding: FD status, a reason when not solved, and the native verdict."""

    file: str
    encoding: str
    status: str  # solved | unsolvable | timeout | error | no-goal
    reason: str  # grouping key ("" when solved)
    detail: str  # file-specific explanation
    native: bool | None
    seconds: float


def _reason(status: str, message: str, native: bool) -> str:
    if status == "solved":
        return ""
    if status == "unsolvable":
        kind = ("translator: goal unreachable even ignoring deletes" if message.startswith("translator")
                else "search: unsolvable")
        return f"{kind}, native {'solvable' if native else 'unsolvable'}"
    return f"{status}: {message.splitlines()[0] if message else ''}"


def replay_failure(task: PlanningTask, units: list[int]) -> str:
    """Why the unit sequence `units` (a native plan) fails in `task`: the first missing fact and its cause."""
    by_unit = {a.unit: a for a in task.actions if a.unit is not None}
    state = set(task.init)
    done: list[int] = []
    for u in units:
        a = by_unit[u]
        missing = [x for x in a.pre if x not in state]
        if missing:
            atom = missing[0]
            fact = f"({' '.join((atom.predicate, *atom.args))})"
            culprit = next((v for v in reversed(done) if atom in by_unit[v].delete), None)
            if culprit is not None:
                return (f"deleted fact: {a.name} needs {fact}, deleted by the earlier {by_unit[culprit].name} "
                        f"(one object per label: '{task.labels.get(atom.args[0], atom.args[0])}' is reused "
                        f"or stands for several objects)")
            return f"missing fact: {a.name} needs {fact}, which no earlier unit of the native plan adds"
        state -= set(a.delete)
        state |= set(a.add)
        done.append(u)
    return "goal facts: the native plan runs, but not all goal facts hold at its end"


def check_file(path: Path, level: int = 3, prune: bool = True, time_limit: float = 60.0) -> list[Outcome]:
    """Compile and plan one subgraph in every encoding."""
    foon, _ = load([path])
    dishes = sorted(n for n in foon.nodes if n.dish is not None)
    if not dishes:
        return [Outcome(path.name, e, "no-goal", "no dish", "no O line with a dish field", None, 0.0)
                for e in ENCODINGS]
    try:
        goal = resolve_goal(spec_of_node(dishes[0]), foon)
    except FoonError as exc:
        return [Outcome(path.name, e, "no-goal", "dish is not a goal", exc.message, None, 0.0) for e in ENCODINGS]
    kitchen = default_kitchen(foon)
    reach = reachable(project(foon, level), kitchen.project(level).nodes)
    cands = {project_node(c, level) for c in goal.candidates}
    native = reach.makes_any(cands)
    why = ""
    if not native:
        lacks = blockers(reach, cands, 3)
        why = ("native: the kitchen lacks " + "; ".join(n.describe() for n in lacks) if lacks
               else "native: needed nodes are made only by units that need them (an object returns to a "
                    "state it started in, so the default kitchen misses that start state)")
    out = []
    native_units: list[int] = []
    for enc in ENCODINGS:  # `tree` first: its plan is the native plan the others are checked against
        t0 = time.perf_counter()
        task = compile_task(foon, kitchen, goal, enc, level, prune)
        res = fd.solve(*render(task), time_limit=time_limit)
        seconds = time.perf_counter() - t0
        if enc == "tree" and res.solved:
            steps = [task.action_for(step.split()[0]) for step in res.plan]
            native_units = [a.unit for a in steps if a is not None and a.unit is not None]
        detail = why
        if not res.solved and native and enc not in ("tree", "instances"):  # instances: bench.pddl_instances
            detail = replay_failure(compile_task(foon, kitchen, goal, enc, level, False), native_units)
        out.append(Outcome(path.name, enc, res.status, _reason(res.status, res.message, native), detail, native,
                           seconds))
    return out


def check_all(subgraphs: Path, level: int = 3, prune: bool = True, time_limit: float = 60.0,
              limit: int | None = None) -> list[Outcome]:
    """`check_file` for every FOON file under `subgraphs` (the first `limit` ones)."""
    files = expand_paths([subgraphs])[:limit]
    out: list[Outcome] = []
    for i, f in enumerate(files, 1):  # a step each: a long run says which file it is at
        with slow_step(f"{f.name} ({i} of {len(files)}): {len(ENCODINGS)} encodings, Fast Downward"):
            out += check_file(f, level, prune, time_limit)
    return out


def summary(outcomes: list[Outcome]) -> str:
    """Per encoding: accepted by FD, solved, agreement with native, and grouped reasons for the rest."""
    lines = []
    files = len({o.file for o in outcomes})
    for enc in ENCODINGS:
        mine = [o for o in outcomes if o.encoding == enc]
        if not mine:
            continue
        counts = collections.Counter(o.status for o in mine)
        accepted = sum(o.status in ("solved", "unsolvable", "timeout") for o in mine)
        agree = sum((o.status == "solved") == o.native for o in mine if o.native is not None)
        lines.append(f"{enc}: {counts['solved']}/{files} solved, {accepted}/{files} accepted by FD, "
                     f"agrees with native on {agree}; status {', '.join(f'{k} {n}' for k, n in sorted(counts.items()))}; "
                     f"median {sorted(o.seconds for o in mine)[len(mine) // 2]:.2f} s per file (compile + FD)")
        reasons = collections.Counter(
            o.reason + (f" [{o.detail.split(':')[0]}]" if o.native and o.detail else "")
            for o in mine if o.status != "solved")
        for reason, n in reasons.most_common():
            lines.append(f"  {n:3d}  {reason}")
    return "\n".join(lines)


def run(ctx: Context) -> None:
    outcomes = check_all(ctx.shared / "foon-subgraphs", limit=10 if ctx.quick else None)
    files = len({o.file for o in outcomes})
    for enc in ENCODINGS:
        mine = [o for o in outcomes if o.encoding == enc]
        ctx.report(AREA, f"{enc}: subgraph dishes solved by FD", sum(o.status == "solved" for o in mine), "files",
                   f"of {files}; accepted by FD: {sum(o.status in ('solved', 'unsolvable', 'timeout') for o in mine)}")
    print(summary(outcomes))


def main() -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.pddl_subgraphs", description=__doc__)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"), help="shared data directory")
    ap.add_argument("--level", type=int, default=3, choices=(1, 2, 3))
    ap.add_argument("--no-prune", action="store_true", help="compile every unit")
    ap.add_argument("--time-limit", type=float, default=60.0, help="seconds per FD run")
    ap.add_argument("--limit", type=int, default=None, help="only the first N files")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per file and encoding")
    args = ap.parse_args()
    shared_data(args.shared)
    outcomes = check_all(args.shared / "foon-subgraphs", args.level, not args.no_prune, args.time_limit, args.limit)
    if args.verbose:
        for o in outcomes:
            print(f"{o.file}\t{o.encoding}\t{o.status}\t{o.reason}\t{o.detail}")
    print(summary(outcomes))


if __name__ == "__main__":
    run_main(main)
