"""Options shared by several commands, so each is spelled and documented once, and what a command asks of its
own options (`--similarity`, whether `--encoding` was given, the one `--goal`).

What the options name is read in `loading` (network, kitchen, goal, constraints) and written through
`outputs`.
"""

from __future__ import annotations

from pathlib import Path

import click

from .object_options import category_types_option, instances_option

paths_argument = click.argument("paths", nargs=-1, type=click.Path(path_type=Path))
level_option = click.option("--level", type=click.IntRange(1, 3), default=3, show_default=True,
                            help="Hierarchy level: 1 object, 2 object+states, 3 object+states+ingredients.")
kitchen_option = click.option("--kitchen", "kitchen", type=click.Path(path_type=Path), default=None,
                              help="Kitchen file (.json, FOON-style O/S lines, or one node per line); `base`: raw ingredients "
                                   "and tools in base states; `default`: the network's default kitchen (what no "
                                   "unit makes and base-state inputs). Default: the example kitchen, `base` on a "
                                   "merge of recipes whose default kitchen holds half-made dishes, else `default` "
                                   "(said on stderr).")
goal_option = click.option("--goal", "goal", multiple=True,
                           help="Goal: 'label', 'label: state, state [obj]' or 'label: contains {a, b}'. "
                                "Repeat for a batch of goals.")
goals_option = click.option("--goals", "goals_file", type=click.Path(path_type=Path, allow_dash=True), default=None,
                            help="Batch of goals: goal_nodes.json-style JSON, `goals --json` output, FOON O/S "
                                 "lines, or one goal a line (also `goals` table rows); '-' reads standard input.")
containment_option = click.option("--containment", type=click.Choice(["strict", "infer"]), default="strict",
                                  show_default=True,
                                  help="infer: a container node `c (contains {x})` is available when its contents "
                                       "`x (in [c])` are (docs/format.md).")
utensils_option = click.option("--utensils", "utensils", type=click.Path(path_type=Path), default=None,
                               help="Utensil labels, one a line: reusable, available in base state (docs/format.md).")
goal_file_option = click.option("--goal-file", "goal_file", type=click.Path(path_type=Path), default=None,
                                help="Goal as one object node in FOON O/S lines.")
output_option = click.option("-o", "--output", "output", type=click.Path(path_type=Path), default=None,
                             help="Write to this file (atomically) instead of standard output.")
prune_option = click.option("--prune/--no-prune", "prune", default=True, show_default=True,
                            help="Compile only the units that can contribute to the goal.")
costs_option = click.option("--costs", type=click.Choice(["unit", "success-rate"]), default=None,
                            help="Action costs: 1 per unit, or from motion success rates (needs --rates).")
rates_option = click.option("--rates", "rates", type=click.Path(path_type=Path), default=None,
                            help="Motion success rates file (motion<TAB>rate).")


def similarity_options(f):
    """`--similarity MODE` and `--overrides FILE` (extra sense overrides and forbidden pairs)."""
    from ..generalize.modes import DEFAULT_MODE, SIMILARITY_MODES

    f = click.option("--overrides", "overrides", type=click.Path(path_type=Path), default=None,
                     help="Extra similarity overrides (JSON: senses, pairs, forbidden; docs/generalization.md), "
                          "added to the mode's shipped table.")(f)
    return click.option("--similarity", "similarity", type=click.Choice(list(SIMILARITY_MODES)),
                        default=DEFAULT_MODE, show_default=True,
                        help="Label similarity: " + "; ".join(f"{m.name}: {m.description}"
                                                               for m in SIMILARITY_MODES.values()) + ".")(f)


def encoding_option(command, default: str | None = None):
    """`--encoding` with the registry's encodings (imported when a command that takes it is defined); `default`:
    the command's own (None: `DEFAULT_ENCODING`)."""
    from ..pddl.compile import DEFAULT_ENCODING, ENCODINGS

    return click.option("--encoding", type=click.Choice(list(ENCODINGS)), default=default or DEFAULT_ENCODING,
                        show_default=True,
                        help="PDDL encoding: " + "; ".join(f"{e.name} ({e.description})" for e in ENCODINGS.values())
                             + " (see docs/pddl.md).")(command)


def network_option(command):
    """`--network` with the registry's network kinds (imported when a command that takes it is defined)."""
    from ..generalize.modes import DEFAULT_MODE, SIMILARITY_MODES
    from ..generalize.network import NETWORKS

    def remember(ctx, _param, value):
        ctx.meta["foon2pddl.similarity"] = value  # read by load_view and the substitution notes
        return value

    command = click.option("--similarity", type=click.Choice(list(SIMILARITY_MODES)), default=DEFAULT_MODE,
                           show_default=True, expose_value=False, callback=remember, is_eager=True,
                           help="The similarity FOON-EXP and --without substitutes use (cook; paper: the seed "
                                "paper's rule). See docs/generalization.md.")(command)
    return click.option("--network", type=click.Choice(list(NETWORKS)), default=next(iter(NETWORKS)),
                        show_default=True,
                        help="; ".join(f"{k.name}: {k.description}" for k in NETWORKS.values())
                             + ". See docs/generalization.md.")(command)


def chosen_similarity() -> str:
    """The command's `--similarity` (the default mode outside a command or without the option)."""
    from ..generalize.modes import DEFAULT_MODE

    ctx = click.get_current_context(silent=True)
    return ctx.meta.get("foon2pddl.similarity", DEFAULT_MODE) if ctx is not None else DEFAULT_MODE


def constraints_options(command):
    """`--constraints FILE` (repeatable) and the one-off `--without-motion`, `--without`, `--must-use`."""
    options = [
        click.option("--constraints", "constraints_files", multiple=True, type=click.Path(path_type=Path),
                     help="Constraints file (JSON, docs/constraints.md); repeat to combine profiles."),
        click.option("--without-motion", "without_motions", multiple=True, metavar="MOTION",
                     help="A motion the robot cannot perform (also bans motions containing it: pour -> "
                          "scoop and pour). Repeatable."),
        click.option("--without", "without", multiple=True, metavar="OBJECT",
                     help="An object or ingredient that must not appear anywhere in the tree (labels, "
                          "ingredient lists, everything made from it). Repeatable."),
        click.option("--must-use", "must_use", multiple=True, metavar="OBJECT",
                     help="An object some unit of the tree must use. Repeatable."),
    ]
    for option in reversed(options):
        command = option(command)
    return command


def check_time_limit(value: float | None) -> float | None:
    """A `--time-limit` value: NaN is a usage error (exit 2); infinity means no limit."""
    if value is not None and value != value:
        raise click.BadParameter("not a number (give seconds, or 'inf' for no limit)")
    return value


def single_goal(goal: tuple[str, ...]) -> str | None:
    """The one `--goal` of a single-goal run (None when not given)."""
    return goal[0] if goal else None


def _apply(command, options):
    for option in reversed(options):
        command = option(command)
    return command


def goal_input_options(command):
    """The inputs every goal-over-a-network command shares, in --help order: PATHS, goals, kitchen, containment."""
    return _apply(command, (paths_argument, goal_option, goals_option, goal_file_option, kitchen_option,
                            utensils_option, containment_option))


def pddl_task_options(command=None, *, encoding: str | None = None):
    """What compile and plan share: `goal_input_options`, then encoding (`encoding`: the command's default),
    instances, level and network. `@pddl_task_options` or `@pddl_task_options(encoding=NAME)`."""
    if command is None:
        return lambda c: pddl_task_options(c, encoding=encoding)
    return goal_input_options(_apply(command, (lambda c: encoding_option(c, encoding), instances_option,
                                               category_types_option, level_option, network_option)))


def encoding_given() -> bool:
    """Whether the running command's `--encoding` was given (False outside a command, or at its default)."""
    ctx = click.get_current_context(silent=True)
    return ctx is not None and ctx.get_parameter_source("encoding") not in (None, click.core.ParameterSource.DEFAULT)
