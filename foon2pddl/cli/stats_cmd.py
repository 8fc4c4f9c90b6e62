"""`foon2pddl stats`: the paper's Table 1 and label counts for a network."""

from __future__ import annotations

import json
from pathlib import Path

import click

from ..analysis.stats import format_stats, network_stats
from ..errors import FoonSyntaxError
from ..io.files import STDIN_NAME
from . import main
from .loading import read_network
from .options import output_option, paths_argument
from .outputs import emit


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

    try:
        net = read_network(paths, skip_invalid, say_skipped=False)  # its report lists every warning
    except FoonSyntaxError as exc:  # a file found under a directory: say how to read the others
        if skip_invalid or exc.path in (None, STDIN_NAME) or Path(exc.path) in {Path(p) for p in paths}:
            raise
        raise FoonSyntaxError(exc.path, exc.line, exc.message + "; `--skip-invalid` skips the files that fail to "
                              "parse under a directory (each with a warning)", exc.text) from None
    with slow_step("counting nodes and labels at each level"):
        data = network_stats(net.foon, net.warnings)
    emit(json.dumps(data, indent=2) + "\n" if as_json else format_stats(data), output)
