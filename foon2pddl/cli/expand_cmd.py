"""`foon2pddl expand`: FOON-EXP, units copied onto similar objects."""

from __future__ import annotations

import click

from ..io.inputs import load_network
from . import main
from .options import emit_network, kitchen_option, output_option, paths_argument


@main.command("expand")
@paths_argument
@click.option("--threshold", type=click.FloatRange(0, 1, min_open=True), default=0.89, show_default=True,
              help="Least Wu-Palmer similarity for a substitution.")
@click.option("--max-units", "max_units", type=click.IntRange(min=1), default=None,
              help="Fail (exit 2) instead of writing a network with more units than this.")
@kitchen_option
@click.option("--provenance", is_flag=True,
              help="Precede each unit with '# from <file>:<line>' comments; copies say what they were expanded from.")
@click.option("--format", "fmt", type=click.Choice(["foon", "json"]), default="foon", show_default=True,
              help="FOON text, or the JSON export (always carries provenance).")
@output_option
def expand_(paths, threshold, max_units, kitchen, provenance, fmt, output) -> None:
    """Write FOON-EXP of the network: for each unit and each object in it, a copy with a similar object.

    The vocabulary is the network's object labels plus those of --kitchen (the example
    kitchen for the example network; a default kitchen adds no label). Statistics per level go to standard error.
    """
    from ..generalize.expand import expand
    from ..generalize.stats import format_levels_table, levels_table
    from ..io.inputs import load_kitchen

    net = load_network(paths)
    e = expand(net.foon, threshold=threshold, max_units=max_units, kitchen=load_kitchen(kitchen, net, 3))
    header = (f"FOON-EXP (threshold {threshold}): {e.original_units} units + {e.added_units} expanded, "
              f"{len(e.substitutions)} label substitutions")
    emit_network(e.foon, fmt, provenance, header, output)
    click.echo(format_levels_table(levels_table({"REG": net.foon, "EXP": e.foon})), err=True, nl=False)
