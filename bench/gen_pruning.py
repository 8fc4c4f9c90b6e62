"""Lifted FOON-GEN pruning per goal on the universal FOON: units kept, and that pruning changes no answer.

    python -m bench.gen_pruning [--shared DIR] [--goals N] [--fd] [--time-limit S] [-v]

The universal FOON is every file of `DIR/foon-subgraphs` merged; the kitchen is its default one;
the goals are its dish nodes (the first N with `--goals`). Per goal, the `gen-lifted` task is
encoded with and without relevance pruning (`encode_lifted`, policy `absent`), and beside it the
concrete network's relevant units (`prune.relevant_units`, what `tree` keeps). Goals no unit can
make, lifted or not, are counted apart. With `--fd`, Fast Downward (lama-first) solves both tasks
of every goal and the statuses must agree: pruning is sound only if it never turns a solvable
goal unsolvable. Reports the units kept (min, median, max over the goals the kitchen does not
already hold and some unit can make), the one-off cost of the ground instances shared by every
goal (CPU), and the per-goal encode time (CPU, median).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from foon2pddl.generalize.categories import shipped_index
from foon2pddl.io.files import load
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.levels import project
from foon2pddl.pddl.encode_lifted import encode_lifted
from foon2pddl.pddl.prune import relevant_units
from foon2pddl.pddl.render import render

from .harness import run_main, shared_data


def units(task) -> int:
    return sum(a.unit is not None for a in task.actions)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.gen_pruning", description=__doc__.split("\n\n")[0])
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"))
    ap.add_argument("--goals", type=int, default=0, help="only the first N dish goals (0: all)")
    ap.add_argument("--fd", action="store_true", help="solve pruned and unpruned tasks with FD and compare")
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per goal")
    args = ap.parse_args(argv)
    shared_data(args.shared)
    foon, _ = load([args.shared / "foon-subgraphs"])
    index, kitchen = shipped_index(), default_kitchen(foon)
    level3, held = project(foon, 3), kitchen.project(3).nodes
    dishes = sorted({n for u in foon.units for n in u.outputs if n.dish is not None})
    dishes = dishes[:args.goals] if args.goals else dishes
    t0 = time.process_time()
    whole = encode_lifted(foon, kitchen, Goal(spec_of_node(dishes[0]), (dishes[0],), 3), index, prune=False).task
    kept, tree_kept, seconds, disagree, unmade = [], [], [], [], 0
    first = time.process_time()
    encode_lifted(foon, kitchen, Goal(spec_of_node(dishes[0]), (dishes[0],), 3), index)
    shared = time.process_time() - first
    for d in dishes:
        goal = Goal(spec_of_node(d), (d,), 3)
        c0 = time.process_time()
        pruned = encode_lifted(foon, kitchen, goal, index).task
        seconds.append(time.process_time() - c0)
        n, t = units(pruned), len(relevant_units(level3, held, [d]))
        line = f"{d.describe()[:60]:60} gen-lifted {n:5} of {units(whole)}  tree {t:5}"
        if args.fd:
            from foon2pddl.planners import fd

            full = encode_lifted(foon, kitchen, goal, index, prune=False).task
            answers = [fd.solve(*render(x), time_limit=args.time_limit).status for x in (pruned, full)]
            line += f"  fd {answers[0]} / unpruned {answers[1]}"
            if answers[0] != answers[1] and "timeout" not in answers:
                disagree.append(d.describe())
        if n == 0 and d not in held:
            unmade += 1
        else:
            kept.append(n)
            tree_kept.append(t)
        if args.verbose:
            print(line, file=sys.stderr, flush=True)
    print(f"universal FOON: {len(foon.units)} units, {units(whole)} lifted unit actions unpruned; "
          f"{len(dishes)} dish goals, {unmade} that no unit can make")
    print(f"gen-lifted units kept per goal: min {min(kept)}, median {statistics.median(kept):g}, max {max(kept)} "
          f"(tree's relevant units: min {min(tree_kept)}, median {statistics.median(tree_kept):g}, "
          f"max {max(tree_kept)})")
    print(f"CPU: {shared:.2f} s for the first goal (ground instances shared by every goal), "
          f"median {statistics.median(seconds):.2f} s per goal after it; {time.process_time() - t0:.1f} s in all")
    if args.fd:
        print(f"FD: pruned and unpruned answers differ on {len(disagree)} goals" +
              (": " + "; ".join(disagree) if disagree else ""))


if __name__ == "__main__":
    run_main(main)
