"""`foon2pddl plan`: compile a goal, run a planner, print the plan's task tree and the time of each phase."""

from __future__ import annotations

import json
import time
from collections.abc import Sequence
from contextlib import nullcontext
from pathlib import Path

import click

from ..errors import UsageError
from ..generalize.network import NETWORKS, Substitutes
from ..io.batch_report import TABLE_FORMATS
from ..io.tree_formats import DEFAULT_FORMAT, FORMATS, STEP_FORMATS, render_tree
from ..model.words import count, first_of
from ..pddl.compile import PLAN_ENCODING
from ..planners import DEFAULT_PLANNER
from ..planners.commands import PRESETS
from ..planners.registry import UP_ENGINE, UnknownPlanner, lookup
from ..planners.result import plan_cost, sas_plan_text
from ..planners.solve import PHASES, PlanOutcome, plan, plan_restoring
from . import main
from .batch import TREE_EXTENSIONS, batch_entries
from .batch_pddl import plan_batch
from .loading import (
    constraint_inputs,
    load_pddl_view,
    reject_lifted_constraints,
    view_goal,
    warn_unmatched_constraints,
)
from .network_hints import hint_lines, hint_words, networks_hint
from .object_options import category_chains, checked_instances
from .options import (
    check_time_limit,
    constraints_options,
    costs_option,
    encoding_given,
    pddl_task_options,
    prune_option,
    rates_option,
    single_goal,
)
from .outputs import check_output, emit, expansion_notes
from .progress import slow_step
from .reasons import beyond_foon_note, explained, failure_reason
from .skills_cli import EXIT, check_skill_usage, plan_with_skills, skill_encoding, skill_options


def timing_line(timings: dict[str, float]) -> str:
    """`load 0.101 s, encode 0.020 s, ...` in phase order."""
    return ", ".join(f"{p} {timings[p]:.3f} s" for p in PHASES if p in timings)


def outcome_json(outcome: PlanOutcome, timings: dict[str, float], tree_json: str | None,
                 reason: str | None = None, hints: Sequence[str] = (), beyond_foon: str | None = None) -> str:
    """The outcome as one JSON document (status, plan, phases, validation, tree; `reason`: why there is no plan,
    the words the text output's `reason:` line gives; `hints`: those of its `hint:` lines; `beyond_foon`: those of
    its note on a solved plan FOON's own semantics does not make, `cli.reasons.beyond_foon_note`)."""
    d = outcome.decoded

    def check(v):
        return None if v is None else {"ok": v.ok, "problems": list(v.problems)}

    validation = None if d is None else {
        "ok": d.ok, "plan": check(d.plan_check), "foon": check(d.validation), "up": check(d.up_validation),
        "foon_semantics": d.foon_semantics, "notes": list(d.notes),
    }
    data = {
        "status": outcome.status,
        "planner": outcome.result.planner,
        "message": outcome.message or outcome.result.message,
        "reason": reason,
        "hints": list(hints),
        "beyond_foon": beyond_foon,
        "encoding": outcome.task.encoding,
        "level": outcome.task.level,
        "plan": list(outcome.steps),
        "planner_plan": list(outcome.result.plan),
        "timings": {p: round(timings[p], 6) for p in PHASES if p in timings},
        "validation": validation,
        "tree": json.loads(tree_json) if tree_json is not None else None,
    }
    view = outcome.compiled.view
    if d is not None and d.trace_check is not None and view is not None:
        validation[view.key] = check(d.trace_check)
        data[view.key] = view.json(outcome.task, d.trace) if d.trace is not None else None
    return json.dumps(data, indent=2) + "\n"


@main.command("plan")
@pddl_task_options(encoding=PLAN_ENCODING)
@click.option("--planner", default=DEFAULT_PLANNER, show_default=True,
              help="fd (Fast Downward), or a unified-planning engine name such as pyperplan.")
@click.option("--planner-cmd", "planner_cmd", default=None,
              help="External planner command, run without a shell: 'cmd {domain} {problem} {plan}' "
                   "(also {time}); its IPC plan file is read back. Or a preset: "
                   + ", ".join(PRESETS) + " (docs/planning.md).")
@click.option("--optimal", is_flag=True, help="Admissible search (Fast Downward: A* with LM-cut; A* with h^max on "
              "a task with conditional effects (relational), which LM-cut refuses).")
@click.option("--alias", default=None, metavar="NAME",
              help="Fast Downward: a search alias of its driver (lama-first, seq-opt-lmcut, seq-sat-lama-2011, ...).")
@click.option("--search", "search", default=None, metavar="CONFIG",
              help="Fast Downward: a search configuration, as its driver's --search (e.g. 'astar(lmcut())').")
@click.option("--evaluator", "evaluators", multiple=True, metavar="DEF",
              help="Fast Downward: an evaluator for --search (e.g. 'h=ff()'), as its driver's; repeatable.")
@click.option("--plan-file", "plan_file", type=click.Path(path_type=Path), default=None,
              help="Also write the raw plan in Fast Downward's sas_plan format (for VAL and other tools).")
@click.option("--time-limit", "time_limit", type=click.FloatRange(min=0, min_open=True), default=300.0,
              show_default=True, callback=lambda ctx, param, value: check_time_limit(value),
              help="Seconds for the planner (translation and search); 'inf' (or over 1e6) for no limit.")
@prune_option
@costs_option
@rates_option
@constraints_options
@click.option("--restore", is_flag=True,
              help="Physical encodings: add generic restoring units (wash, empty, switch off; an assumption beyond "
                   "FOON, see docs/pddl.md) and plan with the fewer objects they allow.")
@click.option("--up-validate", is_flag=True,
              help="Also check the plan with unified-planning's validator (tasks up to 300 actions).")
@click.option("--format", "fmt", type=click.Choice(FORMATS + TABLE_FORMATS), default=DEFAULT_FORMAT, show_default=True,
              help="How to print the task tree (recipe: steps in a cook's words; steps: each unit's FOON "
                   "nodes); for a batch, the table (text, csv, jsonl) or the tree files' format; with --skills, "
                   "the skill plan: steps (the default there), recipe or json.")
@click.option("-o", "--output", "output", type=click.Path(path_type=Path), default=None,
              help="Write the task tree to this file (atomically) instead of standard output; for a batch, "
                   "a directory receiving one tree file per solved goal; with --skills, a directory receiving "
                   "the skill domain, one PDDL problem per step and the skill plan.")
@skill_options
def plan_(paths, goal, goals_file, goal_file, kitchen, utensils, containment, encoding, instances, category_types,
          level, network, planner,
          planner_cmd, optimal, alias, search, evaluators, plan_file, time_limit, prune, costs, rates,
          constraints_files, without_motions, without, must_use, restore, up_validate, fmt, output, skills,
          skill_domain, skill_table, without_skills, hands) -> None:
    """Plan for a goal and print the task tree; the time of each phase goes to stderr (or into --format json).

    Exit status: 0 solved, 1 unsolvable, search gave up or time limit (reason on stderr), 2 bad input or planner error.
    """
    check_skill_usage(skills, skill_domain, paths, fmt)
    entries = batch_entries(goal, goals_file, goal_file, fmt, output)
    if skills and entries is not None:
        raise UsageError("--skills plans one goal at a time (not a batch)")
    check_output(output, directory=entries is not None or skills)
    check_output(plan_file)
    config = _search_config(planner, planner_cmd, optimal, alias, search, evaluators)
    entry = lookup(planner, planner_cmd)
    engine = entry is UP_ENGINE  # its check imports unified-planning: seconds, so it says so at once
    what = f"looking up planner {planner_cmd or planner!r}" + (" among unified-planning's engines" if engine else "")
    try:  # before anything is loaded or timed
        with slow_step(what, after=0 if engine else None):
            entry.check(planner if planner_cmd is None else planner_cmd)
    except UnknownPlanner as exc:
        raise click.BadParameter(f"{exc} (or --planner-cmd with a command or a preset: {', '.join(PRESETS)})",
                                 param_hint="'--planner'") from None
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="'--planner-cmd'" if planner_cmd else "'--planner'") from None
    t0 = time.perf_counter()
    cons, motion_rates, costs = constraint_inputs(constraints_files, without_motions, without, must_use, rates,
                                                  costs, without_skills=without_skills, skill_table=skill_table)
    reject_lifted_constraints(network, cons)
    if costs == "success-rate" and motion_rates is None:
        raise UsageError("--costs success-rate needs --rates FILE (motion<TAB>rate)")
    if restore and (entries is not None or skills):
        raise UsageError("--restore plans one goal at a time, without --skills")
    if entries is not None:
        if cons.items:
            raise UsageError("constraints plan one goal at a time (not a batch)")
        _, view, encoding = load_pddl_view(paths, kitchen, level, network, encoding, costs, containment, utensils,
                                           instances=instances, category_types=category_types)
        return plan_batch(view, entries, encoding, level, fmt if fmt in TABLE_FORMATS else "text",
                          fmt if fmt in TREE_EXTENSIONS else DEFAULT_FORMAT, output, planner=planner,
                          planner_cmd=planner_cmd, optimal=optimal, time_limit=time_limit, prune=prune, costs=costs,
                          rates=motion_rates, up_validate=up_validate, search=config,
                          instances=checked_instances(instances, encoding, view.foon),
                          categories=category_chains(view.foon) if category_types else ())
    if skills:
        default_encoding = not encoding_given()
        encoding = skill_encoding(encoding, not default_encoding)
        if click.get_current_context().get_parameter_source("fmt") is click.core.ParameterSource.DEFAULT:
            fmt = "steps"  # a skill plan's own default: each FOON unit with its skill calls (docs/skills.md)
    net, view, encoding = load_pddl_view(paths, kitchen, level, network, encoding, costs, containment, utensils,
                                         restore=restore, instances=instances, category_types=category_types)
    foon, kit, target = view.foon, view.kitchen, view_goal(view, single_goal(goal), goal_file, level, encoding)
    warn_unmatched_constraints(foon, cons)
    counts = checked_instances(instances, encoding, foon)
    load_s = time.perf_counter() - t0
    if skills:
        return plan_with_skills(foon, kit, target, None if default_encoding else encoding, cons,
                                skill_domain=skill_domain, table_path=skill_table,
                                without_skills=without_skills, hands=hands, fmt=fmt, output=output,
                                timings={"load": load_s}, level=level, planner=planner, planner_cmd=planner_cmd,
                                optimal=optimal, time_limit=time_limit, prune=prune, costs=costs,
                                rates=motion_rates, up_validate=up_validate, search=config, instances=counts,
                                categories=category_chains(foon) if category_types else ())
    then = ", then validating the plan with unified-planning" if up_validate else ""  # 8-13 s at load 14-17
    with slow_step(f"planning {target.describe()!r} ({planner_cmd or planner}, {encoding} encoding, "
                   f"planner time limit {time_limit:g} s{then})"):
        outcome = (plan_restoring if restore else plan)(
                       foon, kit, target, encoding, level, planner=planner, planner_cmd=planner_cmd,
                       optimal=optimal, time_limit=time_limit, prune=prune, costs=costs, rates=motion_rates,
                       up_validate=up_validate, constraints=cons, search=config, instances=counts,
                       categories=category_chains(foon) if category_types else ())
    timings = {"load": load_s, **outcome.timings}
    status = outcome.status
    data: str | None = None
    if outcome.tree is not None and status == "solved":
        data = render_tree(outcome.tree, fmt, kitchen=kit)
        steps_view = outcome.compiled.view
        if fmt in STEP_FORMATS and steps_view is not None and outcome.trace is not None and outcome.trace.steps:
            data += steps_view.text(outcome.task, outcome.trace)
    beyond = beyond_foon_note(foon, kit, target, encoding) if status == "solved" else None
    if fmt != "json":  # the outcome first, then the search for why there is no plan (its step and reason)
        summary = f"{status} ({outcome.result.planner})"
        if status == "solved":
            summary += f": {count(len(outcome.steps), 'plan step')}, {count(len(outcome.tree), 'unit')}, valid"
            if not outcome.validation.ok:  # state encoding: its semantics are not FOON's
                summary += (f" under the {encoding} encoding; as a FOON task tree it is not executable: "
                            + first_of(outcome.validation.problems, 2))
        else:
            summary += f": {outcome.message or outcome.result.message}"
        click.echo(summary, err=True)
        for note in outcome.decoded.notes if outcome.decoded is not None else ():
            click.echo("note: " + note, err=True)
        if beyond is not None:
            click.echo("note: " + beyond, err=True)
        if status == "solved" and NETWORKS[network].substitutes is Substitutes.SIMILAR and not cons.items:
            expansion_notes(outcome.tree, view.matrix)
    # the kitchen additions' search, a step only without a plan (a solved plan's step would say a false thing)
    searching = (nullcontext() if status == "solved"
                 else slow_step(f"finding why there is no plan for {target.describe()!r}"))
    with searching:
        reason, makes = failure_reason(status, encoding, outcome.task, foon, kit, target, cons, counts,
                                       net.foon if NETWORKS[network].as_read else None, rejected=outcome.rejected,
                                       notes=outcome.decoded.notes if outcome.decoded is not None else ())
    hinted = explained(status, encoding) and NETWORKS[network].as_read and not cons.items and not makes
    if fmt == "json":
        hints = hint_words(hint_lines(net, kit, single_goal(goal), goal_file, level)) if hinted else []
        data = outcome_json(outcome, timings, data, reason, hints, beyond)
    else:
        if reason is not None:
            click.echo("reason: " + reason, err=True)
        if hinted:
            networks_hint(net, kit, single_goal(goal), goal_file, level)
        click.echo("phases: " + timing_line(timings), err=True)
    if data is not None:
        emit(data, output)
    if plan_file is not None and status == "solved":  # only a plan that decoded and validated (atomically)
        emit(sas_plan_text(outcome.steps, plan_cost(outcome.task, outcome.steps)), plan_file)
    if EXIT[status]:
        click.get_current_context().exit(EXIT[status])


def _search_config(planner, planner_cmd, optimal, alias, search, evaluators):
    """Fast Downward's configuration from the driver-style options (None: the default); usage errors first."""
    if alias is None and search is None and not evaluators:
        return None
    if not lookup(planner, planner_cmd).configurable:
        raise click.BadParameter("--alias, --search and --evaluator are Fast Downward options (--planner fd)",
                                 param_hint="'--planner-cmd'" if planner_cmd else "'--planner'")
    from ..planners.fd import search_config

    try:
        return search_config(alias, search, evaluators, optimal)
    except ValueError as exc:
        given = "--alias" if alias else "--search" if search is not None else "--evaluator"  # the option misused
        raise click.BadParameter(str(exc), param_hint=f"'{given}'") from None
