"""Command-line interface: `foon2pddl <command>`. One module per command group.

Errors in user input print `path:line: message` on stderr and exit with status 2;
no traceback reaches the user.
"""

from __future__ import annotations

import sys

import click

from .. import __version__
from ..errors import FoonError


class _Group(click.Group):
    """Click group that turns project errors into `path:line: message` and exit status 2."""

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except FoonError as exc:
            click.echo(f"{exc.location()}: error: {exc.message}", err=True)
            if exc.text is not None:
                click.echo(f"    {exc.text!r}", err=True)
            ctx.exit(2)
        except KeyboardInterrupt:
            click.echo("interrupted", err=True)
            ctx.exit(130)
        except BrokenPipeError:
            sys.stderr.close()
            ctx.exit(1)


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, prog_name="foon2pddl")
def main() -> None:
    """FOON (functional object-oriented networks) to PDDL, with native task tree retrieval.

    Every command reads FOON files and directories given as PATHS (merged into one
    universal FOON); with no PATHS it uses the embedded example network and its kitchen.
    """


# Each command module registers its commands on `main` when imported.
from . import (
    check_cmd,
    compile_cmd,
    expand_cmd,
    experiment_cmd,
    generalize_cmd,
    goals_cmd,
    merge_cmd,
    plan_cmd,
    retrieve_cmd,
    similarity_cmd,
    stats_cmd,
)
