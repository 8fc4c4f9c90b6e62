"""`plan --skills`: the plan's macro steps, each with the robot skills that carry it out (docs/skills.md)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import click

from ..errors import UsageError
from ..model.words import count
from ..pddl.compile import ENCODINGS
from ..pddl.constraints import GoalExcluded
from ..status import PlanStatus
from .outputs import emit
from .progress import slow_step
from .reasons import why_unsolvable

__all__ = ["EXIT", "SKILL_FORMATS", "check_skill_usage", "plan_with_skills", "skill_encoding", "skill_options"]

#: `plan`'s exit status per outcome status, with or without --skills (docs/planning.md): no plan is 1, a failure 2.
EXIT = {PlanStatus.SOLVED: 0, PlanStatus.UNSOLVABLE: 1, PlanStatus.GAVE_UP: 1, PlanStatus.TIMEOUT: 1,
        PlanStatus.ERROR: 2}

#: The `--format`s of a skill plan: the steps with their skills, a cook's sentences, the executive's JSON.
SKILL_FORMATS = ("steps", "recipe", "json")


def skill_options(command):
    """`--skills`, `--skill-domain FILE`, `--skill-table FILE`, `--without-skill SKILL`, `--hands N`."""
    options = [
        click.option("--skills", "skills", is_flag=True, default=False,
                     help="Decompose every step into robot skills (pick, place, pour, stir, cut ...) with the "
                          "shipped skill domain, or the one of --skill-domain (docs/skills.md)."),
        click.option("--skill-domain", "skill_domain", type=click.Path(path_type=Path), default=None,
                     metavar="FILE", help="A PDDL skill domain instead of the shipped one (with --skills)."),
        click.option("--skill-table", "skill_table", type=click.Path(path_type=Path), default=None,
                     help="Motion-to-skill table (JSON, docs/skills.md) instead of the shipped one."),
        click.option("--without-skill", "without_skills", multiple=True, metavar="SKILL",
                     help="A skill the robot lacks: the motions that map to it are banned (as --without-motion). "
                          "Repeatable."),
        click.option("--hands", "hands", type=click.IntRange(1, 4), default=1, show_default=True,
                     help="How many hands the robot has (with --skills)."),
    ]
    for option in reversed(options):
        command = option(command)
    return command


def skill_encoding(encoding: str, explicit: bool) -> str:
    """The encoding `--skills` plans with: the default one when none was asked for, else the one asked for,
    which must have physical objects (UsageError otherwise)."""
    from ..skills.run import skills_encoding

    if not explicit:
        return skills_encoding()
    if not ENCODINGS[encoding].physical:
        raise UsageError(f"--skills needs an encoding over physical objects (e.g. {skills_encoding()}), "
                         f"not {encoding}")
    return encoding


def check_skill_usage(skills: bool, skill_domain: Path | None, paths, fmt: str) -> None:
    """UsageError, before anything is loaded, for skill options that would be ignored or misread: a skill
    domain among the network's PATHS (`--skills FILE`: `--skills` takes no value), `--skill-domain` or
    `--hands` without `--skills`, and a `--format` the skill plan has no form in."""
    ctx = click.get_current_context()
    given = {name for name in ("skill_domain", "hands")
             if ctx.get_parameter_source(name) is not click.core.ParameterSource.DEFAULT}
    if not skills:
        if given:
            flag = "--skill-domain" if "skill_domain" in given else "--hands"
            raise UsageError(f"{flag} is used with --skills (add --skills to decompose the plan into robot skills)")
        return
    domains = [str(p) for p in paths if str(p).lower().endswith(".pddl")]
    if domains:
        raise UsageError(f"{domains[0]}: a skill domain is given with --skill-domain FILE (--skills takes no "
                         "value; the PATHS are FOON files)")
    if fmt not in SKILL_FORMATS:
        raise UsageError(f"--skills prints the skill plan as {', '.join(SKILL_FORMATS[:-1])} or "
                         f"{SKILL_FORMATS[-1]}, not --format {fmt}")


def _inputs(skill_domain: Path | None, table_path: Path | None):
    from ..skills.domain import read_domain, shipped_domain
    from ..skills.table import read_table, shipped_table

    domain = read_domain(skill_domain) if skill_domain is not None else shipped_domain()
    table = read_table(table_path) if table_path is not None else shipped_table()
    table.check(domain)
    return domain, table


def _check_skill_names(domain, names) -> None:
    """UsageError for a lacked skill the skill domain does not have (a typo would give a robot that can do
    everything), with the closest names."""
    import difflib

    known = sorted(domain.by_name)
    for name in names:
        if name not in domain.by_name:
            close = difflib.get_close_matches(name, known, n=3)
            raise UsageError(f"--without-skill {name!r}: the skill domain has no such skill"
                             + (f" (did you mean {', '.join(close)}?)" if close else ""))


def plan_with_skills(foon, kitchen, goal, encoding: str | None, cons, *, skill_domain: Path | None,
                     table_path: Path | None, without_skills: tuple[str, ...], hands: int, fmt: str,
                     output: Path | None, timings: dict, **options) -> None:
    """Plan, decompose, print (or write `-o DIR`); exits as `plan` does when there is no plan (`EXIT`: 1, or 2 when
    the planner failed), 2 when the skill replay fails. `encoding` None: the default one, which falls back to
    `instances` when it finds no plan (`skills.run`), saying so on stderr."""
    from ..io.atomic import atomic_write_many
    from ..skills.decompose import StepStatus
    from ..skills.recipe import skill_plan_recipe
    from ..skills.report import micro_files, skill_plan_json, skill_plan_text
    from ..skills.run import FALLBACK_ENCODING, FIRST_SHARE, plan_skills, robot_profile, skills_encoding

    domain, table = _inputs(skill_domain, table_path)
    _check_skill_names(domain, (*without_skills, *(cons.without_skills if cons is not None else ())))
    robot = robot_profile(cons, hands, without_skills)
    ctx = click.get_current_context()
    first = encoding or skills_encoding()
    then = ""
    if encoding is None and first != FALLBACK_ENCODING:
        limit = options.get("time_limit")
        within = f" in {limit * FIRST_SHARE:g} s" if limit is not None and math.isfinite(limit) else ""
        then = f", then {FALLBACK_ENCODING} if it finds no plan{within}"

    step = [f"planning {goal.describe()!r} ({first} encoding{then}) and each step's robot skills"]

    def falling_back(outcome) -> None:
        click.echo(f"note: the {first} encoding found no plan ({outcome.status}: "
                   f"{outcome.result.message}); planning with the {FALLBACK_ENCODING} encoding (holders read from "
                   f"FOON's words, not planned; --encoding {first} gives it the whole time limit)", err=True)
        step[0] = f"planning {goal.describe()!r} ({FALLBACK_ENCODING} encoding) and each step's robot skills"

    try:
        with slow_step(lambda: step[0]):
            done = plan_skills(foon, kitchen, goal, encoding=encoding, domain=domain, table=table, robot=robot,
                               constraints=cons, on_fallback=falling_back, **options)
    except GoalExcluded as exc:
        click.echo(f"unsolvable (robot and constraints): {exc}", err=True)
        _failed_json(fmt, output, PlanStatus.UNSOLVABLE, first, "robot and constraints", str(exc))
        ctx.exit(1)
    outcome, plan = done.outcome, done.skills
    encoding = outcome.task.encoding
    if done.first is not None:
        timings[f"{first} (no plan)"] = sum(done.first.timings.values())
    if plan is None:
        message = outcome.message or outcome.result.message
        click.echo(f"{outcome.status} ({outcome.result.planner}): {message}", err=True)
        reason = None
        if outcome.status in (PlanStatus.UNSOLVABLE, PlanStatus.GAVE_UP):
            from ..model.constraints import combine
            from ..skills.profile import robot_constraints

            reason, _ = why_unsolvable(foon, kitchen, goal, combine(cons, robot_constraints(table, robot)), encoding)
            click.echo("reason: " + reason, err=True)
        _failed_json(fmt, output, outcome.status, encoding, message, reason)
        ctx.exit(EXIT[outcome.status])
    if fmt == "json":
        text = json.dumps({"status": outcome.status, "encoding": outcome.task.encoding,
                           "plan": list(outcome.result.plan), **skill_plan_json(plan)}, indent=2) + "\n"
    elif fmt == "recipe":
        text = skill_plan_recipe(plan, done.trace, robot.hands)
    else:
        text = skill_plan_text(plan, robot)
    click.echo(f"solved ({outcome.result.planner}): {count(len(plan.steps), 'macro step')} under the {encoding} encoding, "
               f"{plan.decomposed} decomposed into {count(len(plan.calls), 'skill')}; skill replay "
               + ("valid" if plan.replay.ok else "INVALID"), err=True)
    for s in plan.steps:
        if s.reason:
            kept = (" failed to decompose, kept as an abstract step (the replay goes on from FOON's state after it)"
                    if s.status == StepStatus.FAILED else f" is {s.status}")
            click.echo(f"note: step {s.index + 1} ({s.motion}, {s.source}){kept}: {s.reason}", err=True)
    for problem in plan.replay.problems:
        click.echo(f"error: {problem}", err=True)
    micro_s = sum(s.seconds for s in plan.steps)
    click.echo("phases: " + ", ".join(f"{p} {v:.3f} s" for p, v in {**timings, **outcome.timings}.items())
               + f", skills {micro_s:.3f} s", err=True)
    if output is not None:
        files = {output / name: body for name, body in micro_files(plan, robot).items()}
        files[output / ("skills.json" if fmt == "json" else "skills.txt")] = text
        atomic_write_many(files)
    else:
        emit(text, None)
    if not plan.replay.ok:
        ctx.exit(2)


def _failed_json(fmt: str, output: Path | None, status: str, encoding: str, message: str, reason: str | None) -> None:
    """With --format json (and no -o DIR, which gets all its files or none), the one JSON document of a run with
    no macro plan: the keys of a skill plan's, empty, with the planner's message and the reason."""
    if fmt == "json" and output is None:
        emit(json.dumps({"status": status, "encoding": encoding, "message": message, "reason": reason, "plan": [],
                         "ok": False, "replay": None, "macro_steps": 0, "decomposed": 0, "steps": [], "skills": []},
                        indent=2) + "\n", None)
