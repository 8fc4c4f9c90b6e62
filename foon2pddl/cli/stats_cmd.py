"""`foon2pddl stats`: the paper's Table 1 and label counts for a network."""

from __future__ import annotations

import json

import click

from ..analysis.stats import format_stats, network_stats
from . import main
from .options import emit, output_option, paths_argument, read_network


@main.command("stats")
@paths_argument
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@click.option("--skip-invalid", "skip_invalid", is_flag=True,
              help="Skip (with a warning) files that fail to parse instead of stopping at the first.")
@output_option
def stats(paths, as_json, skip_invalid, output) -> None:
    """Object and motion nodes at each hierarchy level, label counts, units per file, warnings.

    PATHS are FOON files or directories (`-`: FOON text on standard input); files under a
    directory that are plainly not FOON (a rates file, text without FOON lines) are skipped
    with a warning.
    """
    from .progress import slow_step

    net = read_network(paths, skip_invalid)
    with slow_step("counting nodes and labels at each level"):
        data = network_stats(net.foon, net.warnings)
    emit(json.dumps(data, indent=2) + "\n" if as_json else format_stats(data), output)
