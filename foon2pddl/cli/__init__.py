"""Command-line interface: `foon2pddl <command>`. One module per command group.

Errors in an input file print `path:line: error: message` on stderr; errors with no
file (a bad option value, a missing dependency) print in click's style (`Error: ...`,
with the command's usage line for option errors). Both exit with status 2; no
traceback reaches the user. SIGINT exits 130 and SIGTERM 143, after the same
cleanup: every command runs in a `command_scope` (private TMPDIR, processes
marked), so no process or temporary path of the command survives it, and
half-written output files are removed.
"""

from __future__ import annotations

import errno
import importlib
import shlex
import sys

import click

from .. import __version__
from ..errors import FoonError, FoonInputError, UsageError, goes
from ..io.atomic import discard_staged
from ..io.interrupts import interrupt_exit, sigterm_raises
from ..planners.cleanup import command_scope
from . import progress

__all__ = ["COMMANDS", "main", "analyze_cmd", "batch", "batch_pddl", "check_cmd", "compile_cmd", "examples_cmd", "expand_cmd",
           "experiment_cmd", "generalize_cmd", "goal_listing", "goals_cmd", "kitchen_note", "loading", "merge_cmd", "network_hints", "object_options", "options",
           "outputs", "plan_cmd", "progress", "reasons", "retrieve_cmd", "similarity_cmd", "skills_cli", "stats_cmd"]

#: Command name -> the module (in this package) that defines it. The group imports a command's
#: module only when that command runs (or `--help` lists them all), so `foon2pddl --version` and
#: `stats` load none of the planning, generalization or experiment stacks.
COMMANDS = {
    "analyze": "analyze_cmd",
    "categories": "generalize_cmd",
    "check": "check_cmd",
    "compile": "compile_cmd",
    "expand": "expand_cmd",
    "experiment": "experiment_cmd",
    "generalize": "generalize_cmd",
    "goals": "goals_cmd",
    "merge": "merge_cmd",
    "plan": "plan_cmd",
    "retrieve": "retrieve_cmd",
    "similarity": "similarity_cmd",
    "stats": "stats_cmd",
}

#: The option that takes a file of each kind (`errors.INPUTS`), for an error on a file given to another one.
OPTIONS = {"paths": "as a PATHS argument", "kitchen": "with `--kitchen`", "goals": "with `--goals`",
           "constraints": "with `--constraints`", "rates": "with `--rates`", "utensils": "with `--utensils`"}


class _Command(click.Command):
    """Click command that reports the package's `UsageError` as a click usage error (usage line, exit 2)."""

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except UsageError as exc:
            raise click.UsageError(exc.message, ctx) from None


class _Group(click.Group):
    """Click group that turns project errors into `path:line: error: message` (or `Error: message`), exit 2."""

    command_class = _Command

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(set(COMMANDS) | set(self.commands))

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        """The command, importing its module on first use (the module registers it on `main`); the import is a
        step (`plan`'s modules: 0.2 s of CPU, seconds of wall time under load, before any line of the command)."""
        if cmd_name not in self.commands and cmd_name in COMMANDS:
            with progress.slow_step(f"loading foon2pddl {cmd_name}"):
                importlib.import_module(f"{__name__}.{COMMANDS[cmd_name]}")
        return self.commands.get(cmd_name)

    def resolve_command(self, ctx: click.Context, args: list[str]):
        """As click's, but a misspelt command names the closest one and lists them all (as a misspelt option)."""
        name = args[0] if args else ""
        if name and not name.startswith("-") and not ctx.resilient_parsing and self.get_command(ctx, name) is None:
            from ..errors import did_you_mean

            names = self.list_commands(ctx)
            ctx.fail(f"No such command {name!r}{did_you_mean(name, names)} (commands: {', '.join(names)})")
        return super().resolve_command(ctx, args)

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        ctx.meta["argv"] = tuple(args)  # the words as given, for the unquoted-goal hint of an error
        return super().parse_args(ctx, args)

    def invoke(self, ctx: click.Context):
        _escape_unencodable_output()
        progress.begin()
        try:
            with sigterm_raises():
                try:
                    with command_scope():
                        return super().invoke(ctx)
                finally:
                    discard_staged()
        except FoonError as exc:
            where = exc.location()
            message = f"{exc.what}: {goes(exc.belongs, OPTIONS)}" if exc.belongs else exc.message
            click.echo(f"{where}: error: {message}" if where else f"Error: {message}", err=True)
            if exc.text is not None:
                click.echo(f"    {exc.text!r}", err=True)
            hint = _unquoted_goal(exc, ctx.meta.get("argv", ()))
            if hint:
                click.echo(f"hint: a goal of several words is one argument: --goal {hint}", err=True)
            ctx.exit(2)
        except (KeyboardInterrupt, RuntimeError) as exc:
            ended = interrupt_exit(exc)
            if ended is None:
                raise
            click.echo(ended[0], err=True)
            ctx.exit(ended[1])
        except BrokenPipeError:
            sys.stderr.close()
            ctx.exit(1)
        except OSError as exc:
            if exc.errno not in _FULL:
                raise
            output_failed(exc)
            ctx.exit(2)


def _unquoted_goal(exc: FoonError, args) -> str:
    """`'whipped cream'` when a missing PATH is the word after `--goal whipped` (the shell split an unquoted
    goal; a word with `/` or `.` is a path), else ""."""
    missing = exc.path if isinstance(exc, FoonInputError) and not exc.line else None
    if not missing or "/" in missing or "." in missing:
        return ""
    for at in range(len(args) - 2):
        if args[at] == "--goal" and args[at + 2] == missing:
            return shlex.quote(f"{args[at + 1]} {missing}")
    return ""


#: errno values of a write that cannot complete: device full, quota, file too large, I/O error.
_FULL = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO})


def output_failed(exc: OSError) -> None:
    """Say that an output (standard output, or the file the error names) could not be written, and send
    what is still buffered for standard output nowhere (so the exit's flush does not fail again)."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):
        pass
    what = f"{exc.filename}: error: cannot write" if exc.filename else "Error: cannot write the output"
    try:
        click.echo(f"{what}: {exc.strerror or exc}", err=True)
    except OSError:
        pass  # standard error is full too: the exit status says it


def _escape_unencodable_output() -> None:
    """Standard output and error print lone surrogates (undecodable bytes of file names) as escapes."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.reconfigure(errors="backslashreplace")
        except (AttributeError, ValueError):
            pass


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, prog_name="foon2pddl")
def main() -> None:
    """FOON (functional object-oriented networks) to PDDL, with native task tree retrieval.

    Every command reads FOON files and directories given as PATHS (merged into one
    universal FOON); with no PATHS it uses the embedded example network and its kitchen.
    """
