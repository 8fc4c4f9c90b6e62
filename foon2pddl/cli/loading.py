"""What a command reads, from its options: the network and its `--network` view with the kitchen, the goal,
the constraints and the similarity overrides; warnings about what they name go to stderr."""

from __future__ import annotations

import difflib
from pathlib import Path

import click

from ..errors import UsageError
from ..model.words import count
from .goal_listing import goals_listing
from .object_options import check_physical_options
from .options import chosen_similarity, encoding_given


def read_network(paths, skip_invalid: bool = False, say_skipped: bool = True):
    """`io.inputs.load_network(paths)`, said on stderr when it takes a while (a universal FOON); each file it
    skipped under a directory (plainly not FOON; with `skip_invalid`, failing to parse) gets its warning on stderr,
    as docs/format.md says (`say_skipped=False`: the caller prints every warning itself)."""
    from ..io.inputs import load_network
    from .progress import inputs, slow_step

    with slow_step("reading " + inputs(paths)):
        net = load_network(paths, skip_invalid)
    for w in net.warnings if say_skipped else ():
        if w.message.startswith("skipped"):
            click.echo(str(w), err=True)
    return net


def load_view(paths, kitchen: Path | None, level: int, network: str, containment: str = "strict",
              utensils: Path | None = None, constraints=None, strays_network: str | None = None):
    """The loaded network and its `--network` view (network, kitchen and goal mapping at `level`).

    The one place the retrieve, compile and plan commands turn PATHS, --kitchen, --level,
    --network, --utensils and --containment into what they search: utensils extend the
    kitchen, and under `infer` the network gets the containment rule's inference units.
    With `constraints`, EXP and GEN are built from the kitchen without its banned objects
    (so substitutes come from allowed ones). Kitchen items are checked against `strays_network`'s view when
    given (the kind whose lifted encoding plans over this one: a cup is a drinking vessel it can use).
    """
    from dataclasses import replace

    from ..generalize.network import NETWORKS, Substitutes, network_view
    from ..io.inputs import load_kitchen
    from ..io.kitchen_files import read_utensils
    from ..model.containment import with_containment
    from ..model.kitchen import with_utensils
    from .kitchen_note import kitchen_note
    from .progress import slow_step

    net, kind = read_network(paths), NETWORKS[network]
    kit = loaded = load_kitchen(kitchen, net, level)
    if kitchen is None and not net.is_example:
        click.echo(kitchen_note(kit, net.at(level)), err=True)
    if constraints is not None and kind.substitutes is not Substitutes.NONE:
        from ..generalize.substitution import without_banned

        kit = without_banned(kit, constraints)
    building = kind.building or "preparing the {label} network of {units} at level {level}"
    after = 0 if kind.slow_step is not None and kind.slow_step(net, kit) is not None else None  # seconds: at once
    with slow_step(building.format(label=kind.label, units=count(len(net.foon.units), 'unit', grouped=True), level=level),
                   after=after):
        view = network_view(net, network, level, kit, similarity=chosen_similarity())
        # inside the step: FOON-EXP's node table, 0.3-0.5 s at load 14, was outside every step (stop 54's re-check)
        strays = None
        if kitchen is not None:
            seen = view if strays_network in (None, network) else network_view(
                net, strays_network, level, kit, similarity=chosen_similarity())
            strays = seen.kitchen_strays(kit.nodes, net.at(level))
    if strays is not None:
        places = kit.holder_nodes()  # a scene's fridge and counter are places, not items FOON must name
        warn_kitchen(loaded, net.at(level), [n for n in strays if n not in places])
    if utensils is not None:
        view = replace(view, kitchen=with_utensils(view.kitchen, view.foon, read_utensils(utensils)))
    if containment != "strict":
        view = replace(view, foon=with_containment(view.foon, view.kitchen.nodes, containment))
    return net, view


def warn_kitchen(kitchen, foon, strays) -> None:
    """Warn (stderr) about kitchen items that match no node of the network, with close-match hints."""
    from ..model.kitchen import unmatched_items

    messages, total = unmatched_items(strays, foon, lines=kitchen.line_numbers())
    for line, m in messages:
        click.echo(f"{kitchen.source}{f':{line}' if line else ''}: warning: {m}", err=True)
    if total > len(messages):
        click.echo(f"{kitchen.source}: warning: ... and {total - len(messages)} more kitchen items match no node",
                   err=True)


def view_goal(view, goal: str | None, goal_file: Path | None, level: int, encoding: str | None = None):
    """The `--goal`/`--goal-file` goal resolved against a network view; warns when `level` drops part of it.

    Under the lifted GEN encoding a goal may name a category (as `goals --network gen` lists them).
    """
    if (goal is None) == (goal_file is None):
        raise UsageError("give exactly one of --goal and --goal-file")
    from ..io.inputs import load_goal_spec
    from ..model.goal import level_loss

    listing = goals_listing()
    try:  # a goal that does not read or that nothing makes is a bad value of its option (README)
        spec = load_goal_spec(goal, goal_file)
        loss = level_loss(spec, level)
        if loss:
            click.echo(f"warning: {loss}", err=True)
        found = lifted_goal(view, spec) if encoding == "gen-lifted" else view.goal(goal, goal_file, listing)
    except UsageError as exc:
        raise click.BadParameter(str(exc), param_hint="'--goal'" if goal is not None else "'--goal-file'") from None
    if found.preferred:
        click.echo("note: " + found.choice_note(asked=spec.label, network=view.name), err=True)
    return found


def lifted_goal(view, spec):
    """A goal of the lifted GEN encoding: a concrete node of the network, else a category's nodes."""
    from ..errors import FoonError
    from ..generalize.categories import load_index
    from ..generalize.compress import category_goal
    from ..generalize.network import NETWORKS

    try:
        return view.resolve(spec, goals_listing())
    except FoonError as exc:
        index = load_index()
        found = category_goal(spec, view.foon, index)
        if found is None:  # the categories made here close to it (`beverage` -> `beverages`), as labels get theirs
            made = sorted({c for label in view.foon.produced_by_label if (c := index.choose(label)) is not None})
            close = difflib.get_close_matches(spec.label, made, n=5, cutoff=0.6)
            lifted = next(k.name for k in NETWORKS.values() if k.encoding == "gen-lifted")  # the kind that plans it
            raise UsageError(f"{exc.message}; `{goals_listing(lifted)}` lists the categories it also takes, "
                             "when they are made on this network"
                             + (f" (close categories: {', '.join(close)})" if close else "")) from None
        return found


def load_pddl_view(paths, kitchen: Path | None, level: int, network: str, encoding: str, costs: str | None,
                   containment: str = "strict", utensils: Path | None = None, *, restore: bool = False,
                   instances: tuple[str, ...] = (), category_types: bool = False):
    """`load_view` for the PDDL commands (compile, plan), with the encoding they use.

    A network kind with its own encoding (`gen`: the lifted one) compiles that encoding over the concrete
    network unless `--encoding tree` is given (FOON's tree over the kind's own nodes, as the experiment's
    `fd-tree` plans it); an encoding without action costs rejects --costs, and one without
    physical objects the options over them (`check_physical_options`), before anything is read.
    """
    from ..generalize.network import NETWORKS
    from ..pddl.compile import ENCODINGS

    own, lifted = NETWORKS[network].encoding, None
    if own is not None and not (encoding_given() and encoding == "tree"):
        if encoding_given() and encoding != own:
            raise UsageError(f"--network {network} compiles the {own} encoding, or FOON's tree over its nodes with "
                             "--encoding tree; drop --encoding")
        if costs is not None and not ENCODINGS[own].costs:
            raise UsageError(f"--network {network} does not support --costs")
        encoding, lifted, network = own, network, next(iter(NETWORKS))
    if costs is not None and not ENCODINGS[encoding].costs:
        raise UsageError(f"--encoding {encoding} does not support --costs")
    check_physical_options(encoding, restore, instances, category_types)
    net, view = load_view(paths, kitchen, level, network, containment, utensils, strays_network=lifted)
    return net, view, encoding


def constraint_inputs(files, without_motions, without, must_use, rates: Path | None, costs: str | None = None,
                      without_skills=(), skill_table: Path | None = None):
    """(constraints, motion rates, cost mode) from the options: rates from --rates and the constraints
    files together; a constraints file with rates turns on `success-rate` costs unless --costs says otherwise.
    Skills the robot lacks (`without_skills` of a file, `--without-skill`) ban the motions the motion table
    (shipped, or `skill_table`) maps to them."""
    from ..io.constraints_file import load_constraints, with_rates
    from ..io.rates import read_rates

    cons = load_constraints(files, without_motions, without, must_use, without_skills)
    if cons.without_skills:
        from ..model.constraints import combine
        from ..skills.profile import Robot, robot_constraints
        from ..skills.table import read_table, shipped_table

        table = read_table(skill_table) if skill_table is not None else shipped_table()
        cons = combine(cons, robot_constraints(table, Robot.of(without=cons.without_skills)))
    motion_rates = with_rates(read_rates(rates) if rates else None, cons)
    if costs is None and cons.rates:
        costs = "success-rate"
    return cons, motion_rates, costs


def warn_unmatched_constraints(foon, cons) -> None:
    """Warn (stderr) about each constraint that matches nothing in `foon`, in `retrieve`'s words
    (docs/constraints.md): a typo (`--without-motion scop`) must not plan as if no constraint were given."""
    if not cons.items:
        return
    from ..analysis.constraints import removal
    from ..retrieval.constrained import constraint_notes

    for line in constraint_notes(removal(foon, cons)):
        if not line.startswith("constraints: "):  # what each removes: retrieve's summary, not a warning
            click.echo(line, err=True)


def reject_lifted_constraints(network: str, cons) -> None:
    """A network with its own encoding (GEN's lifted one) takes no constraints in the PDDL commands, in that
    encoding or in `--encoding tree` over its nodes (native `retrieve --network gen` does)."""
    from ..generalize.network import NETWORKS

    if NETWORKS[network].encoding is not None and cons.items:
        others = " or ".join(k.name for k in NETWORKS.values() if k.encoding is None)
        raise UsageError(f"constraints are not supported by --network {network} here ({NETWORKS[network].label}'s "
                         f"lifted encoding, or --encoding tree over its nodes); use --network {others}, or "
                         f"`retrieve --network {network}`")


def load_overrides(path: Path | None):
    """The user's overrides file (`--overrides`), parsed (located errors), or None."""
    if path is None:
        return None
    from ..generalize.senses import parse_overrides
    from ..io.parser import read_text

    return parse_overrides(read_text(path), str(path))
