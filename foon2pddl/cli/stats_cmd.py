"""`foon2pddl stats`: the paper's Table 1 and label counts for a network."""

from __future__ import annotations

import json

import click

from ..analysis.stats import format_stats, network_stats
from ..io.inputs import load_network
from . import main
from .options import emit, output_option, paths_argument


@main.command("stats")
@paths_argument
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@output_option
def stats(paths, as_json, output) -> None:
    """Object and motion nodes at each hierarchy level, label counts, units per file, warnings."""
    net = load_network(paths)
    data = network_stats(net.foon, net.warnings)
    emit(json.dumps(data, indent=2) + "\n" if as_json else format_stats(data), output)
