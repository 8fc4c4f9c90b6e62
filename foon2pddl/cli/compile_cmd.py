"""`foon2pddl compile`: write domain.pddl and problem.pddl for a goal."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import UsageError
from ..generalize.network import DEFAULT_NETWORK
from ..io.atomic import atomic_write_many
from ..io.batch_report import TABLE_FORMATS
from ..io.rates import read_rates
from ..pddl.compile import compile_task, encoding_named
from ..pddl.constraints import GoalExcluded
from ..pddl.render import render
from ..pddl.restore import with_restore
from ..pddl.task import PlanningTask, goal_at_start
from ..pddl.untyped import untyped
from . import main
from .batch import batch_entries
from .batch_pddl import compile_batch
from .loading import constraint_inputs, load_pddl_view, reject_lifted_constraints, view_goal, warn_unmatched_constraints
from .object_options import category_chains, checked_instances
from .options import constraints_options, costs_option, pddl_task_options, prune_option, rates_option, single_goal
from .outputs import cannot_write, check_output
from .progress import slow_step
from .reasons import ALREADY_HELD


def build_task(paths, goal: str | None, goal_file: Path | None, kitchen: Path | None, encoding: str, level: int,
               prune: bool, costs: str | None, rates: Path | None, network: str = DEFAULT_NETWORK,
               containment: str = "strict", utensils: Path | None = None, instances: tuple[str, ...] = (),
               category_types: bool = False, constraints=((), (), (), ()), restore: bool = False) -> PlanningTask:
    """Load network, kitchen, goal, rates and constraints (files, without-motion, without, must-use labels)
    as the CLI options say, and compile (FoonError on bad input; GoalExcluded when nothing is left); with
    `restore`, the network gains restoring units and the counts they allow (`pddl.restore.with_restore`)."""
    cons, motion_rates, costs = constraint_inputs(*constraints, rates, costs)
    reject_lifted_constraints(network, cons)
    if costs == "success-rate" and motion_rates is None:
        raise UsageError("--costs success-rate needs --rates FILE (motion<TAB>rate)")
    _, view, encoding = load_pddl_view(paths, kitchen, level, network, encoding, costs, containment, utensils,
                                       restore=restore, instances=instances, category_types=category_types)
    target = view_goal(view, single_goal(goal) if isinstance(goal, tuple) else goal, goal_file, level, encoding)
    warn_unmatched_constraints(view.foon, cons)
    from .reasons import unreachable_reason

    fixpoint = not encoding_named(encoding).lifted  # (see `unreachable_reason`)
    if fixpoint:  # an unreachable goal's kitchen additions: a search (stop 55: 23 s for `retrieve`'s)
        with slow_step(f"checking that the kitchen can make {target.describe()!r}"):
            why = unreachable_reason(view.foon, view.kitchen, target)
        if why is not None:
            raise GoalExcluded(f"{target.describe()!r} is unreachable: {why}")
    foon, kit = view.foon, view.kitchen
    if restore:
        foon, kit = with_restore(foon, kit, target, level)
    with slow_step(f"compiling {target.describe()!r} ({encoding} encoding)"):
        task = compile_task(foon, kit, target, encoding, level, prune, costs, motion_rates, cons,
                            **encoder_options(encoding, instances, category_types, view.foon))
    if (why := unreachable_reason(view.foon, view.kitchen, target, task, fixpoint=fixpoint)) is not None:
        raise GoalExcluded(f"{target.describe()!r} is unreachable: {why}")
    return task


def encoder_options(encoding: str, instances: tuple[str, ...], category_types: bool, foon) -> dict:
    """Keyword options of encodings over physical objects (none for the others)."""
    counts = checked_instances(instances, encoding, foon)
    if not encoding_named(encoding).physical:
        return {}
    return {"instances": counts, "categories": category_chains(foon) if category_types else ()}


@main.command("compile")
@pddl_task_options
@prune_option
@costs_option
@rates_option
@constraints_options
@click.option("-o", "--output-dir", "output_dir", type=click.Path(path_type=Path, file_okay=False),
              default=Path("."), show_default=True,
              help="Directory for domain.pddl and problem.pddl (a batch: one subdirectory per goal).")
@click.option("--format", "fmt", type=click.Choice(TABLE_FORMATS), default="text", show_default=True,
              help="Batch result table: text, csv or jsonl (one JSON object per goal).")
@click.option("--shared-domain", "shared", is_flag=True, default=False,
              help="One domain for every goal (DIR/domain.pddl, all units: no relevance pruning) and one problem "
                   "per goal (DIR/<goal>.pddl), the goal in its :goal.")
@click.option("--untyped", "untype", is_flag=True, default=False,
              help="No :typing: each type a static predicate type_<T> (for planners without subtypes, Tamer).")
@click.option("--restore", is_flag=True,
              help="Physical encodings: add generic restoring units (wash, empty, switch off; an assumption beyond "
                   "FOON, see docs/pddl.md) and the fewer objects they allow.")
def compile_(paths, goal, goals_file, goal_file, kitchen, utensils, containment, encoding, instances, category_types,
             level, network, prune, costs, rates, constraints_files, without_motions, without, must_use, output_dir,
             fmt, shared, untype, restore) -> None:
    """Compile a goal over the network into PDDL: DIR/domain.pddl and DIR/problem.pddl (written atomically).

    Several goals (--goal repeated, --goals FILE) compile into one subdirectory each, with one table;
    with --shared-domain, into one domain and one problem per goal (a benchmark set).

    Exit status: 0 written, 1 nothing makes the goal from the kitchen or the constraints leave no way to it
    (nothing written; the reason `retrieve` gives), or some goal of a batch names no produced node or is
    unreachable, 2 bad input.
    """
    check_output(output_dir, directory=True)
    entries = batch_entries(goal, goals_file, goal_file, "text" if shared else None)
    if entries is not None:
        if constraints_files or without_motions or without or must_use or restore:
            raise UsageError("constraints and --restore compile one goal at a time (not a batch)")
        if costs == "success-rate" and rates is None:
            raise UsageError("--costs success-rate needs --rates FILE (motion<TAB>rate)")
        _, view, encoding = load_pddl_view(paths, kitchen, level, network, encoding, costs, containment, utensils,
                                           instances=instances, category_types=category_types)
        return compile_batch(view, entries, encoding, level, prune and not shared, costs,
                             read_rates(rates) if rates else None, output_dir, fmt, shared=shared, untype=untype,
                             **encoder_options(encoding, instances, category_types, view.foon))
    try:
        task = build_task(paths, goal, goal_file, kitchen, encoding, level, prune, costs, rates, network, containment,
                          utensils, instances, category_types, (constraints_files, without_motions, without, must_use),
                          restore)
    except GoalExcluded as exc:
        click.echo(f"cannot compile: {exc}", err=True)
        click.get_current_context().exit(1)
    task = untyped(task) if untype else task
    domain, problem = render(task)
    files = {output_dir / "domain.pddl": domain, output_dir / "problem.pddl": problem}
    try:
        atomic_write_many(files)
    except OSError as exc:
        raise cannot_write(output_dir, exc) from None
    units = sum(a.unit is not None for a in task.actions)
    click.echo(f"wrote {output_dir / 'domain.pddl'} and {output_dir / 'problem.pddl'} "
               f"({task.encoding} encoding, level {task.level}: {units} unit actions, "
               f"{len(task.predicates)} predicates)")
    if goal_at_start(task):
        click.echo(f"note: {ALREADY_HELD}")
