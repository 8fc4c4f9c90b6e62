"""`foon2pddl retrieve`: native task tree retrieval for a goal."""

from __future__ import annotations

import click

from ..errors import FoonInputError
from ..io.constraints_file import load_constraints, with_rates
from ..retrieval import FORMATS, METHODS, read_rates, render_tree, retrieve
from ..retrieval.constrained import constraint_notes, explain_line, retrieve_constrained, shaping
from ..retrieval.explain import explain_unreachable
from ..retrieval.greedy import DEFAULT_BUDGET
from ..retrieval.optimal import DEFAULT_NODE_LIMIT
from ..retrieval.result import UNREACHABLE
from . import main
from .options import (
    check_output,
    constraints_options,
    emit,
    goal_file_option,
    goal_option,
    kitchen_option,
    level_option,
    load_view,
    network_option,
    other_networks_hint,
    output_option,
    paths_argument,
    rates_option,
    view_goal,
)


@main.command("retrieve")
@paths_argument
@goal_option
@goal_file_option
@kitchen_option
@level_option
@network_option
@click.option("--method", type=click.Choice(METHODS), default="complete", show_default=True,
              help="greedy: the seed paper's search; complete: a tree whenever one exists; "
                   "optimal: fewest units; weighted: highest success probability (needs --rates).")
@rates_option
@click.option("--format", "fmt", type=click.Choice(FORMATS), default="steps", show_default=True,
              help="How to print the task tree (svg needs Graphviz).")
@click.option("--budget", type=click.IntRange(min=1), default=DEFAULT_BUDGET, show_default=True,
              help="greedy: iterations (objects taken from its queue) before giving up.")
@click.option("--node-limit", "node_limit", type=click.IntRange(min=1), default=DEFAULT_NODE_LIMIT,
              show_default=True, help="optimal/weighted: search nodes expanded before returning the best tree so far.")
@constraints_options
@click.option("--explain", is_flag=True,
              help="With constraints: for an unreachable goal the smallest set of constraints to relax, "
                   "for a solved one the units each constraint made the tree avoid (on stderr).")
@output_option
def retrieve_(paths, goal, goal_file, kitchen, level, network, method, rates, fmt, budget, node_limit,
              constraints_files, without_motions, without, must_use, explain, output) -> None:
    """Find the functional units that make the goal from the kitchen, in executable order.

    Exit status: 0 a tree was found, 1 the goal cannot be made (the reason goes to stderr),
    2 bad input.
    """
    check_output(output)
    cons = load_constraints(constraints_files, without_motions, without, must_use)
    motion_rates = with_rates(read_rates(rates) if rates else None, cons)
    if method == "weighted" and motion_rates is None:
        raise FoonInputError("<options>", 0, "--method weighted needs --rates FILE (motion<TAB>rate) "
                                             "or rates in a --constraints file")
    net, view = load_view(paths, kitchen, level, network)
    foon, kit, target = view.foon, view.kitchen, view_goal(view, goal, goal_file, level)
    if view.note:
        click.echo(view.note, err=True)
    limits = {"budget": budget, "node_limit": node_limit}
    if cons.items:
        done = retrieve_constrained(foon, kit, target, cons, method, rates=motion_rates, **limits)
        for line in constraint_notes(done.removal):
            click.echo(line, err=True)
        result = done.result
        if explain and result.tree is not None:
            for s in shaping(foon, kit, target, done, method, rates=motion_rates, **limits):
                click.echo(explain_line(s), err=True)
    else:
        result = retrieve(foon, kit, target, method, rates=motion_rates, **limits)
        if explain:
            click.echo("explain: no constraints given", err=True)
    if result.tree is None:
        plain = result.reason == UNREACHABLE and not cons.items  # constraints explain themselves
        detail = explain_unreachable(foon, kit.nodes, target) if plain else result.detail
        click.echo(f"cannot make {target.describe()!r} ({method}): {result.reason}: {detail}", err=True)
        if plain and network == "reg":
            other_networks_hint(net, kit, goal, goal_file, level)
        click.get_current_context().exit(1)
    emit(render_tree(result.tree, fmt, kitchen=kit), output)
    note = f"{method}: {len(result.tree)} units"
    if result.probability is not None:
        note += f", success probability {result.probability:.4g}"
    click.echo(note + (f" ({result.detail})" if result.detail else ""), err=True)
