"""`foon2pddl merge`: write the universal FOON of many files (FOON text or JSON)."""

from __future__ import annotations

import click

from ..io.jsonio import write_json
from ..io.writer import write_foon
from ..model.words import count
from . import main
from .loading import read_network
from .options import level_option, output_option, paths_argument
from .outputs import emit


@main.command("merge")
@paths_argument
@level_option
@click.option("--ids", "with_ids", is_flag=True,
              help="FOON text: write the id-ful variant (O<id>/S<id>/M<id>, ids numbered by first appearance).")
@click.option("--provenance", is_flag=True,
              help="Precede each unit with '# from <file>:<line>' comments naming every place it was read.")
@click.option("--format", "fmt", type=click.Choice(["foon", "json"]), default="foon", show_default=True,
              help="FOON text, or the JSON export (docs/json-schema.md; always carries provenance).")
@output_option
def merge(paths, level, with_ids, provenance, fmt, output) -> None:
    """Merge the FOON files and directories PATHS into one universal FOON.

    Files are read in sorted path order; units that are equal at the chosen level
    (same motion, same set of input nodes and of output nodes) are kept once, with
    their provenance joined. Writes the id-less FOON text by default. Skipped
    blocks are reported on standard error as warnings.
    """
    net = read_network(paths, say_skipped=False)
    for w in net.warnings:
        click.echo(str(w), err=True)
    foon = net.at(level)
    if fmt == "json":
        text = write_json(foon)
    else:
        header = f"universal FOON: level {foon.level}, {count(len(foon.units), 'unit')}, {count(len(foon.nodes), 'object node')}"
        text = write_foon(foon, with_ids=with_ids, provenance=provenance, header=header)
    emit(text, output)
