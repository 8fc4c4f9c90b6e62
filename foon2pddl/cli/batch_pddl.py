"""Batch mode of `compile` and `plan`: every goal on one loaded network, one table, files per goal."""

from __future__ import annotations

import time
from pathlib import Path

from ..errors import FoonError
from ..io.batch_report import file_names
from ..model.constraints import Constraints
from ..model.containment import count_inference, inferred_nodes
from ..model.goal import resolve_goal
from ..model.words import count
from ..pddl.task import goal_at_start
from ..status import BatchStatus, PlanStatus
from .batch import finish, write_trees
from .goal_listing import goals_listing
from .loading import lifted_goal
from .outputs import cannot_write
from .progress import slow_step
from .reasons import ALREADY_HELD, failure_reason, unreachable_reason


def _resolve(view, entry, encoding: str | None = None):
    """(goal, None) or (None, the reason it names no produced node); the lifted GEN encoding reads categories."""
    try:
        if encoding == "gen-lifted":
            return lifted_goal(view, entry.spec), None
        return resolve_goal(view.map_goal(entry.spec), view.foon, listing=goals_listing()), None
    except FoonError as exc:  # the goal names no node (UsageError)
        return None, exc.message


def _row(entry, goal, status: BatchStatus | PlanStatus, seconds: float, reason: str = "", units=None, inferred=()) -> dict:
    return {"goal": goal.describe() if goal is not None else entry.spec.describe(), "status": status,
            "units": units, "inferred": list(inferred), "seconds": round(seconds, 6), "reason": reason,
            "source": f"{entry.path}:{entry.line}"}


def compile_batch(view, entries, encoding: str, level: int, prune: bool, costs, rates, output_dir: Path,
                  table_fmt: str, shared: bool = False, untype: bool = False, **encoder_options) -> None:
    """DIR/<goal>/domain.pddl and problem.pddl per goal (all written atomically at the end), and the table.

    `shared`: every goal unpruned, DIR/domain.pddl once and DIR/<goal>.pddl per goal (`pddl.shared`);
    `untype`: types written as predicates (`pddl.untyped`)."""
    from ..io.atomic import atomic_write_many
    from ..pddl.compile import compile_task, encoding_named
    from ..pddl.render import render
    from ..pddl.untyped import untyped

    rows, files, compiled = [], {}, []
    stems = [n[: -len(".d")] for n in file_names(["domain", *(e.spec.describe() for e in entries)], "d")][1:]
    lifted = encoding_named(encoding).lifted
    for entry, name in zip(entries, stems, strict=True):
        t0 = time.perf_counter()
        goal, why = _resolve(view, entry, encoding)
        if goal is None:
            rows.append(_row(entry, None, BatchStatus.UNMATCHED, time.perf_counter() - t0, why))
            continue
        # as `plan`'s batch: 171 goals compiled 2.2 s after the batch's last line at load 8 (stop 58's pass)
        with slow_step(f"compiling goal {len(rows) + 1} of {len(entries)}: {goal.describe()!r}"):
            task = None  # (the fixpoint: see `unreachable_reason`; unpruned, a lifted task is checked pruned)
            if (why := unreachable_reason(view.foon, view.kitchen, goal, fixpoint=not lifted)) is None:
                task = compile_task(view.foon, view.kitchen, goal, encoding, level, prune or (shared and lifted),
                                    costs, rates, **encoder_options)
                why = unreachable_reason(view.foon, view.kitchen, goal, task, fixpoint=not lifted)
            if why is None and shared and lifted:
                task = compile_task(view.foon, view.kitchen, goal, encoding, level, False, costs, rates,
                                    **encoder_options)
        if why is not None:
            rows.append(_row(entry, goal, BatchStatus.UNREACHABLE, time.perf_counter() - t0, why))
            continue
        row = _row(entry, goal, BatchStatus.COMPILED, time.perf_counter() - t0,
                   ALREADY_HELD if goal_at_start(task) else "", units=sum(a.unit is not None for a in task.actions))
        task = untyped(task) if untype else task
        if shared:
            compiled.append((goal.describe(), task))
            row["file"] = str(output_dir / f"{name}.pddl")
        else:
            files[output_dir / name / "domain.pddl"], files[output_dir / name / "problem.pddl"] = render(task)
            row["file"] = str(output_dir / name)
        rows.append(row)
    made = count(sum(r["status"] == BatchStatus.COMPILED for r in rows), "goal", grouped=True)
    with slow_step(f"writing the PDDL files of {made} to {output_dir}"):
        if compiled:
            files = _shared_files(compiled, [r["file"] for r in rows if r["status"] == BatchStatus.COMPILED],
                                  output_dir)
        try:
            atomic_write_many(files)
        except OSError as exc:
            raise cannot_write(output_dir, exc) from None
    finish(rows, table_fmt, f"{encoding} encoding" + (", one shared domain" if shared else ""),
           solved=lambda r: r["status"] == BatchStatus.COMPILED)


def _shared_files(compiled, problem_files: list[str], output_dir: Path) -> dict[Path, str]:
    """DIR/domain.pddl and each compiled goal's problem file (`pddl.shared`)."""
    from ..pddl.shared import render_shared, share_domain

    domain, problems = render_shared(share_domain(compiled))
    return {output_dir / "domain.pddl": domain, **{Path(f): text for f, text in zip(problem_files, problems, strict=True)}}


def plan_batch(view, entries, encoding: str, level: int, table_fmt: str, tree_fmt: str, output: Path | None,
               **plan_options) -> None:
    """Plan every goal; one table; with `output`, the task trees of solved goals in that directory."""
    from ..planners.solve import plan

    rows, trees = [], []
    for entry in entries:
        t0 = time.perf_counter()
        goal, why = _resolve(view, entry, encoding)
        if goal is None:
            rows.append(_row(entry, None, BatchStatus.UNMATCHED, time.perf_counter() - t0, why))
            trees.append(None)
            continue
        # the reason is found inside the goal's step: an unsolvable goal's (the kitchen additions' search) left a
        # batch 0.6 s outside every step at load 16, 2.1 s without a line on a terminal (stop 54's pass)
        with slow_step(f"planning goal {len(rows) + 1} of {len(entries)}: {goal.describe()!r}"):
            outcome = plan(view.foon, view.kitchen, goal, encoding, level, **plan_options)
            why, _ = failure_reason(outcome.status, encoding, outcome.task, view.foon, view.kitchen, goal,
                                    Constraints(), plan_options.get("instances", ()), rejected=outcome.rejected,
                                    notes=outcome.decoded.notes if outcome.decoded is not None else ())
        tree = outcome.tree if outcome.status == "solved" else None
        reason = "" if tree is not None else outcome.message or outcome.result.message
        reason += "" if why is None else ": " + why
        units = None if tree is None else len(tree.units) - count_inference(tree.units)
        inferred = () if tree is None else (n.describe() for n in inferred_nodes(tree.units))
        rows.append(_row(entry, goal, outcome.status, time.perf_counter() - t0, reason, units, inferred))
        trees.append(tree)
    if output is not None:
        write_trees(output, rows, trees, tree_fmt, view.kitchen)
    finish(rows, table_fmt, f"{encoding} encoding, planner {plan_options.get('planner')}")
