"""Planner compatibility: which planners read and solve which encoding's PDDL (the table in docs/planning.md).

    python -m bench.planner_compat [--planners fd up:pyperplan ...] [--encodings tree ...] [--goals G ...]
                                   [--time-limit 60] [--cmd NAME=TEMPLATE ...] [--untyped]

For every encoding and goal (default: the dishes of `domains/`, on the embedded example network and
kitchen; `lemonade` too for `gen-lifted`, whose lifted actions stand a lime in for the recipe's lemon),
the domain and problem `compile` writes are given to each planner:

- `fd`: Fast Downward (lama-first) from the up-fast-downward wheel, on the PDDL text;
- `up:<engine>`: a unified-planning engine (pyperplan, tamer, aries, enhsp, symk, ...) on what UP's
  PDDL reader reads from the text, in a child process killed at the time limit;
- `--cmd NAME=TEMPLATE`: any planner command (`{domain} {problem} {plan}`, as `plan --planner-cmd`),
  e.g. `--cmd lpg='lpg-td -o {domain} -f {problem} -n 1 -out {plan}'`.

"parses" counts the tasks the planner read without an error (for UP engines: UP's reader and the
engine's support check; for commands and FD: no error status), "solves" those with a plan that
unified-planning's validator accepts on the PDDL as UP reads it. Notes give the first message of each
kind of failure. Planners that are not installed are listed as such; the table says which ran.
"""

from __future__ import annotations

import argparse
import datetime
import sys
from collections import Counter
from dataclasses import dataclass, field

from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
from foon2pddl.pddl.compile import ENCODINGS, compile_task
from foon2pddl.pddl.examples import GOALS, LEVEL
from foon2pddl.pddl.render import render
from foon2pddl.pddl.untyped import untyped
from foon2pddl.planners import external, fd, up_engine
from foon2pddl.planners.result import PlanResult

from .harness import run_main

#: The planners tried by default (the UP engines whose PyPI packages the `interop` extra names).
DEFAULT_PLANNERS = ("fd", "up:pyperplan", "up:tamer", "up:aries", "up:enhsp", "up:symk")

#: Extra goals per encoding (the lifted encoding's own story).
EXTRA_GOALS = {"gen-lifted": ("lemonade",)}


@dataclass
class Cell:
    """One planner on one encoding: tasks tried, read, solved (validated), and notes by kind."""

    tried: int = 0
    parsed: int = 0
    solved: int = 0
    notes: Counter = field(default_factory=Counter)

    def text(self) -> tuple[str, str, str]:
        notes = "; ".join(f"{n} ({k})" if k > 1 else n for n, k in self.notes.most_common(3))
        return f"{self.parsed}/{self.tried}", f"{self.solved}/{self.tried}", notes


def tasks(encodings, goals, flat: bool = False) -> list[tuple[str, str, str, str]]:
    """(encoding, goal, domain text, problem text) of every task, as `compile` writes them (`flat`: `--untyped`)."""
    net = load_network([])
    foon, kitchen = net.at(LEVEL), load_kitchen(None, net, LEVEL)
    out = []
    for enc in encodings:
        for goal in (*goals, *EXTRA_GOALS.get(enc, ())):
            task = compile_task(foon, kitchen, load_goal(goal, None, foon), enc, LEVEL)
            out.append((enc, goal, *render(untyped(task) if flat else task)))
    return out


def validated(domain: str, problem: str, steps: tuple[str, ...]) -> str | None:
    """None when UP's validator accepts the plan on the PDDL as UP reads it, else why not."""
    from unified_planning.plans import ActionInstance, SequentialPlan
    from unified_planning.shortcuts import PlanValidator

    from foon2pddl.pddl.up_problem import quiet_environment

    quiet_environment()
    try:
        up, _ = up_engine._read_pddl((domain, problem))
        actions = {a.name.lower(): a for a in up.actions}
        objects = {o.name.lower(): o for o in up.all_objects}
        plan = SequentialPlan([ActionInstance(actions[s.split()[0]], [objects[x] for x in s.split()[1:]])
                               for s in steps])
        with PlanValidator(name="sequential_plan_validator") as v:
            res = v.validate(up, plan)
    except Exception as exc:  # a plan naming unknown actions or objects, a reader error
        return f"plan not checkable: {type(exc).__name__}"
    return None if res.status.name == "VALID" else f"invalid plan ({res.reason})"


def run_planner(planner: str, commands: dict[str, str], domain: str, problem: str, limit: float) -> PlanResult:
    if planner == "fd":
        return fd.solve(domain, problem, time_limit=limit)
    if planner.startswith("up:"):
        return up_engine.solve((domain, problem), planner[3:], time_limit=limit)
    return external.solve(commands[planner], domain, problem, time_limit=limit)


def short(message: str) -> str:
    """A failure message cut to its first clause (notes stay one line)."""
    text = " ".join(message.split())
    return (text[:90] + "...") if len(text) > 93 else text


def measure(planners, commands, encodings, goals, limit: float, log=sys.stderr, flat: bool = False
            ) -> dict[tuple[str, str], Cell]:
    cells = {(p, e): Cell() for p in planners for e in encodings}
    for enc, goal, domain, problem in tasks(encodings, goals, flat):
        for p in planners:
            cell = cells[(p, enc)]
            cell.tried += 1
            res = run_planner(p, commands, domain, problem, limit)
            unsupported = res.status == "error" and ("does not support" in res.message or "Error" in res.message)
            if not unsupported:
                cell.parsed += 1
            why = validated(domain, problem, res.plan) if res.solved else short(f"{res.status}: {res.message}")
            if why is None:
                cell.solved += 1
            else:
                cell.notes[why] += 1
            print(f"{p:14} {enc:12} {goal:14} {res.status:10} {'' if why is None else why}", file=log, flush=True)
    return cells


def table(cells, planners, encodings, limit: float, mark: str = "") -> str:
    """The markdown table: one row per planner and encoding (`mark` after the encoding's name)."""
    lines = ["| planner | encoding | parses | solves | notes |", "|---|---|---|---|---|"]
    for p in planners:
        for e in encodings:
            parsed, solved, notes = cells[(p, e)].text()
            lines.append(f"| {p} | {e}{mark} | {parsed} | {solved} | {notes} |")
    day = datetime.datetime.now(datetime.UTC).date().isoformat()
    return "\n".join(lines) + f"\n\n({day}, {limit:g} s per task; planners available: {', '.join(planners)})\n"


def available(planners) -> tuple[list[str], list[str]]:
    """(the planners that can run here, those that cannot)."""
    engines = set(up_engine.engine_names())
    ok = [p for p in planners if not p.startswith("up:") or p[3:] in engines]
    return ok, [p for p in planners if p not in ok]


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.planner_compat", description=__doc__.split("\n\n")[0])
    ap.add_argument("--planners", nargs="*", default=list(DEFAULT_PLANNERS))
    ap.add_argument("--encodings", nargs="*", default=list(ENCODINGS), choices=list(ENCODINGS))
    ap.add_argument("--goals", nargs="*", default=list(GOALS))
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--untyped", action="store_true", help="compile --untyped: types as static predicates")
    ap.add_argument("--cmd", action="append", default=[], metavar="NAME=TEMPLATE",
                    help="a planner command (as plan --planner-cmd), tried as planner NAME")
    args = ap.parse_args(argv)
    commands = dict(c.split("=", 1) for c in args.cmd)
    planners, missing = available(args.planners)
    planners += list(commands)
    if missing:
        print(f"not installed here: {', '.join(missing)}", file=sys.stderr)
    cells = measure(planners, commands, args.encodings, args.goals, args.time_limit, flat=args.untyped)
    print(table(cells, planners, args.encodings, args.time_limit, " (--untyped)" if args.untyped else ""))


if __name__ == "__main__":
    run_main(main)
