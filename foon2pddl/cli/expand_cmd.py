"""`foon2pddl expand`: FOON-EXP, units copied onto similar objects (`--pairs`: the substitutions it uses)."""

from __future__ import annotations

import functools

import click

from ..model.words import count
from . import main
from .loading import load_overrides, read_network
from .options import kitchen_option, output_option, paths_argument, similarity_options
from .outputs import emit, emit_network
from .progress import slow_step


@main.command("expand")
@paths_argument
@click.option("--threshold", type=click.FloatRange(0, 1, min_open=True), default=0.89, show_default=True,
              help="Least similarity for a substitution.")
@similarity_options
@click.option("--max-units", "max_units", type=click.IntRange(min=1), default=None,
              help="Fail (exit 2) instead of writing a network with more units than this.")
@kitchen_option
@click.option("--provenance", is_flag=True,
              help="Precede each unit with '# from <file>:<line>' comments; copies say what they were expanded from.")
@click.option("--pairs", "as_pairs", is_flag=True,
              help="Print the substitution pairs the expansion uses (TSV, or JSON with --format json) "
                   "instead of the network.")
@click.option("--format", "fmt", type=click.Choice(["foon", "json"]), default="foon", show_default=True,
              help="FOON text, or the JSON export (always carries provenance).")
@output_option
def expand_(paths, threshold, similarity, overrides, max_units, kitchen, provenance, as_pairs, fmt, output) -> None:
    """Write FOON-EXP of the network: for each unit and each object in it, a copy with a similar object.

    The vocabulary is the network's object labels plus those of --kitchen (the example
    kitchen for the example network; a default kitchen adds no label). Statistics per level go to standard error.
    With --pairs, one row per substitution: label, substitute, similarity, common ancestor, the two
    senses, and the kind (`similar`, or `derived` for a product renamed along, e.g. lemon juice -> lime juice).
    """
    from ..generalize.expand import expand, vocabulary
    from ..generalize.modes import mode_matrix, mode_matrix_is_cached
    from ..generalize.stats import format_levels_table, levels_table
    from ..io.inputs import load_kitchen

    net = read_network(paths)
    kit = load_kitchen(kitchen, net, 3)
    extra = load_overrides(overrides)
    labels = vocabulary(net.foon, kit)
    cold = not mode_matrix_is_cached(labels, similarity, extra)  # seconds to minutes: each step said at once
    matrix = mode_matrix(labels, similarity, extra=extra, step=functools.partial(slow_step, after=0) if cold else slow_step)
    e = expand(net.foon, matrix, threshold=threshold, max_units=max_units, kitchen=kit, similarity=similarity,
               step=slow_step)  # says how far it is
    if as_pairs:
        from ..generalize.pairs import format_pairs, substitution_pairs

        with slow_step(f"listing the {count(len(e.substitutions), 'substitution')} with their WordNet senses"):
            text = format_pairs(substitution_pairs(e, extra), fmt)
        emit(text, output)
        return
    header = (f"{e.title()}: {count(e.original_units, 'unit')} + {e.added_units} expanded, "
              f"{count(len(e.substitutions), 'label substitution')}")
    with slow_step(f"writing FOON-EXP ({count(len(e.foon.units), 'unit', grouped=True)})"):
        emit_network(e.foon, fmt, provenance, header, output)
    table = format_levels_table(levels_table({"REG": net.foon, "EXP": e.foon}, step=slow_step))
    click.echo(table, err=True, nl=False)

