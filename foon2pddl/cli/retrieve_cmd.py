"""`foon2pddl retrieve`: native task tree retrieval for a goal."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import UsageError
from ..generalize.network import NETWORKS, Substitutes
from ..io.batch_report import TABLE_FORMATS
from ..io.tree_formats import DEFAULT_FORMAT, no_tree_json
from ..model.containment import count_inference, inferred_nodes
from ..model.words import count
from ..retrieval import FORMATS, METHODS, render_tree, retrieve
from ..retrieval.constrained import constraint_notes, explain_line, retrieve_constrained, shaping
from ..retrieval.explain import why_unreachable
from ..retrieval.greedy import DEFAULT_BUDGET
from ..retrieval.optimal import DEFAULT_NODE_LIMIT, DEFAULT_TIME_LIMIT
from ..retrieval.result import UNREACHABLE
from ..status import batch_status
from . import main
from .batch import batch_entries, finish, write_trees
from .goal_listing import goals_listing
from .loading import constraint_inputs, load_view, view_goal
from .network_hints import hint_lines, hint_words, networks_hint
from .options import (
    chosen_similarity,
    constraints_options,
    goal_input_options,
    level_option,
    network_option,
    rates_option,
    single_goal,
)
from .outputs import check_output, emit, expansion_notes
from .progress import slow_step
from .reasons import gen_reading_note


class Limit(click.ParamType):
    """A positive cap, or `none` / 0 for no cap (None)."""

    def __init__(self, kind: type, name: str = "N|none") -> None:
        self.kind = kind
        self.name = name

    def convert(self, value, param, ctx):
        if value is None or isinstance(value, self.kind):
            return value or None
        text = str(value).strip().lower()
        if text in ("none", "0", "inf", "unlimited"):
            return None
        try:
            number = self.kind(text)
        except ValueError:
            self.fail(f"{value!r} is not a number or `none`", param, ctx)
        if number < 0:
            self.fail(f"{value!r} is negative", param, ctx)
        return number or None


@main.command("retrieve")
@goal_input_options
@level_option
@network_option
@click.option("--method", type=click.Choice(tuple(METHODS)), default="complete", show_default=True,
              help="; ".join(f"{m.name}: {m.description}" + (" (needs --rates)" if m.needs_rates else "")
                             for m in METHODS.values()) + ".")
@rates_option
@click.option("--format", "fmt", type=click.Choice(FORMATS + TABLE_FORMATS), default=DEFAULT_FORMAT, show_default=True,
              help="How to print the task tree: recipe, steps in a cook's words; steps, each unit's FOON nodes "
                   "(svg needs Graphviz); for a batch, the table (text, csv, jsonl) "
                   "or the format of the tree files in -o DIR.")
@click.option("--budget", type=Limit(float, "SECONDS|none"), default=str(DEFAULT_TIME_LIMIT), show_default=True,
              help="optimal/weighted: seconds per goal before returning the best tree found and its proven "
                   "lower bound (a wall-clock safety cap; `none` or 0: no cap).")
@click.option("--node-limit", "node_limit", type=Limit(int), default=str(DEFAULT_NODE_LIMIT), show_default=True,
              help="optimal/weighted: search nodes expanded per goal before returning the best tree found "
                   "(deterministic: same result on any machine; `none` or 0: no cap). "
                   "Exact search: --node-limit none --budget none.")
@click.option("--iterations", type=click.IntRange(min=1), default=DEFAULT_BUDGET, show_default=True,
              help="greedy: iterations (objects taken from its queue) before giving up.")
@constraints_options
@click.option("--explain", is_flag=True,
              help="With constraints: for an unreachable goal the smallest set of constraints to relax, "
                   "for a solved one the units each constraint made the tree avoid (on stderr).")
@click.option("-o", "--output", "output", type=click.Path(path_type=Path), default=None,
              help="Write the tree to this file (atomically) instead of standard output; for a batch, "
                   "a directory receiving one tree file per solved goal.")
def retrieve_(paths, goal, goals_file, goal_file, kitchen, utensils, containment, level, network, method, rates,
              fmt, budget, node_limit, iterations, constraints_files, without_motions, without, must_use, explain,
              output) -> None:
    """Find the functional units that make the goal from the kitchen, in executable order.

    Several goals (--goal repeated, --goals FILE) run as a batch on one loaded network
    and print one table (text, csv or jsonl: one JSON object per goal).

    Exit status: 0 a tree was found (batch: every goal solved), 1 a goal cannot be made
    (the reason goes to stderr, or into the table), 2 bad input.
    """
    check_output(output, directory=bool(goals_file) or len(goal) > 1 or fmt in TABLE_FORMATS)
    cons, motion_rates, _ = constraint_inputs(constraints_files, without_motions, without, must_use, rates)
    if METHODS[method].needs_rates and motion_rates is None:
        raise UsageError(f"--method {method} needs --rates FILE (motion<TAB>rate) or rates in a --constraints file")
    entries = batch_entries(goal, goals_file, goal_file, fmt, output)
    if entries is not None and cons.items:
        raise UsageError("constraints apply to one goal at a time (not with a batch of goals)")
    net, view = load_view(paths, kitchen, level, network, containment, utensils,
                          cons if cons.items else None)
    limits = {"budget": iterations, "node_limit": node_limit, "time_limit": budget}
    if entries is not None:
        return _batch(view, entries, method, motion_rates, fmt, limits, output, containment)
    foon, kit, target = view.foon, view.kitchen, view_goal(view, single_goal(goal), goal_file, level)
    if view.note:
        click.echo(view.note, err=True)
    done = None
    kind = NETWORKS[network]
    if cons.items:
        if view.index is not None:
            from ..generalize.substitution import category_must_use

            cons, read = category_must_use(cons, view.index, kind.label)
            for line in read:
                click.echo(line, err=True)
        if kind.substitutes is Substitutes.NONE:
            with slow_step(f"retrieving a tree for {target.describe()!r} under the constraints ({method})"):
                done = retrieve_constrained(foon, kit, target, cons, method, rates=motion_rates, **limits)
        else:
            with slow_step(f"retrieving a tree for {target.describe()!r} with substitutes for what is banned"):
                done = _substituted(net, kitchen, network, level, foon, kit, target, cons, method, motion_rates,
                                    limits, view.matrix)
        read_from = view.concrete if kind.substitutes is Substitutes.CATEGORY else None
        for line in constraint_notes(done.removal, read_from, kind.label):
            click.echo(line, err=True)
        result = done.result
        if explain and result.tree is not None:
            for s in shaping(foon, kit, target, done, method, rates=motion_rates, **limits):
                click.echo(explain_line(s), err=True)
    else:
        with slow_step(f"retrieving a tree for {target.describe()!r} ({method})"):
            result = retrieve(foon, kit, target, method, rates=motion_rates, **limits)
        if explain:
            click.echo("explain: no constraints given", err=True)
    if result.tree is None:
        # constraints explain themselves, unless the goal cannot be made even without them
        plain = result.reason == UNREACHABLE and (done is None or (done.blocking and done.blocking.relax is None))
        detail, additions = result.detail, ()
        if plain:  # the smallest kitchen additions: 23 s at load 20-30 for a kitchen of utensils alone (stop 55)
            with slow_step(f"looking for the smallest kitchen additions that make {target.describe()!r}"):
                why = why_unreachable(foon, kit.nodes, target)
            detail, additions = why.text, why.additions
        if plain and done is not None:  # additions make it without the constraints, not under them
            additions = ()
            if not kind.as_read and _made_with_banned(net, view, kitchen, level, target):
                detail = ("the constraints rule out every tree: without them the kitchen makes it (an object "
                          "ban also takes the object out of the kitchen, and no allowed object stands in for it)")
            else:
                detail = "even without the constraints: " + detail
        hinted = plain and kind.as_read and done is None
        if fmt == "json":  # one document: what the text run prints on stderr
            hints = hint_words(hint_lines(net, kit, single_goal(goal), goal_file, level)) if hinted else []
            emit(no_tree_json(target.describe(), method, batch_status(result.reason), f"{result.reason}: {detail}",
                              hints, additions), output)
        else:
            click.echo(f"cannot make {target.describe()!r} ({method}): {result.reason}: {detail}", err=True)
            if hinted:
                networks_hint(net, kit, single_goal(goal), goal_file, level)
        click.get_current_context().exit(1)
    emit(render_tree(result.tree, fmt, kitchen=kit), output)
    if kind.substitutes is Substitutes.SIMILAR and not cons.items:
        expansion_notes(result.tree, view.matrix)
    if view.index is not None and (reading := gen_reading_note(view, single_goal(goal), goal_file, result.tree.goal)):
        click.echo(reading, err=True)
    inferred = inferred_nodes(result.tree.units)
    note = f"{method}: {count(len(result.tree) - count_inference(result.tree.units), 'unit')}"
    if inferred:
        note += f", {len(inferred)} inferred by containment: " + "; ".join(n.describe() for n in inferred)
    if result.bound is not None:
        note += ", proven optimal" if result.proven_optimal else f", not proven optimal (gap {result.gap:.4g})"
    if result.probability is not None:
        note += f", success probability {result.probability:.4g}"
    click.echo(note + (f" ({result.detail})" if result.detail else ""), err=True)


def _batch(view, entries, method, rates, fmt, limits: dict, output, containment) -> None:
    """Every goal of `entries` on the loaded view: one table; trees into the -o directory."""
    from ..model.goal import resolve_goal
    from ..retrieval.batch import solve_goals

    if view.note:
        click.echo(view.note, err=True)
    listing = goals_listing()
    with slow_step(f"retrieving trees for {count(len(entries), 'goal')} ({method})"):
        found = solve_goals(view.foon, view.kitchen.nodes, entries,
                            lambda spec: resolve_goal(view.map_goal(spec), view.foon, listing=listing),
                            method=method, rates=rates, **limits)
    rows = [r.as_dict() for r in found]
    table_fmt = fmt if fmt in TABLE_FORMATS else "text"
    if output is not None:
        tree_fmt = fmt if fmt in FORMATS else DEFAULT_FORMAT
        write_trees(output, rows, [r.tree for r in found], tree_fmt, view.kitchen)
    finish(rows, table_fmt, f"{method}, containment {containment}")


def _made_with_banned(net, view, kitchen_path, level: int, target) -> bool:
    """Whether the view's network makes `target` from the kitchen as given, banned objects included."""
    from ..analysis.reachability import reachable
    from ..io.inputs import load_kitchen

    full = view.map_kitchen(load_kitchen(kitchen_path, net, level))
    reach = reachable(view.foon, full.nodes, target.candidates)
    return reach.makes_any(target.candidates)


def _substituted(net, kitchen_path, network, level, foon, kit, target, cons, method, rates, limits, matrix=None):
    """Retrieval on EXP/GEN under constraints (most similar substitutes first); prints the substitutions made.
    `matrix`: EXP's similarities (`NetworkView.matrix`), read before WordNet is opened for a pair it lacks."""
    from ..generalize.substitution import retrieve_substituted, without_banned
    from ..io.inputs import load_kitchen

    index = None
    if NETWORKS[network].substitutes is Substitutes.CATEGORY:
        from ..generalize.categories import load_index

        index = load_index()
    concrete = without_banned(load_kitchen(kitchen_path, net, level), cons)
    from ..generalize.modes import make_similarity

    mode = chosen_similarity()
    done, subs = retrieve_substituted(network, foon, kit, target, cons, method, index=index,
                                      sim=make_similarity(mode) if matrix is None else
                                      matrix.or_else(lambda: make_similarity(mode)),
                                      concrete_labels={n.label for n in concrete.nodes}, rates=rates, **limits)
    for sub in subs:
        click.echo(f"substitution: {sub.describe()}", err=True)
    return done
