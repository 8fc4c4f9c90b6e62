"""Batch mode shared by retrieve, compile and plan: which goals, the result table, the files per goal."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import click

from ..errors import UsageError
from ..io.atomic import atomic_write_many
from ..io.batch_report import TABLE_FORMATS, file_names, format_table, summary
from ..io.goal_files import parse_goal_spec
from ..io.goal_lists import GoalEntry, read_goal_list
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree
from ..model.words import count
from .outputs import cannot_write
from .progress import slow_step

#: File name extension per task tree format.
TREE_EXTENSIONS = {"steps": "txt", "recipe": "txt", "foon": "foon", "json": "json", "dot": "dot", "svg": "svg"}


def batch_entries(goal: tuple[str, ...], goals_file: Path | None, goal_file: Path | None,
                  fmt: str | None = None, output: Path | None = None) -> list[GoalEntry] | None:
    """The goals of a batch run, or None for a single-goal run (one `--goal` or `--goal-file`, no
    `--goals`, not a table format): single-goal runs behave exactly as before batches existed.
    A tree format given with `--format` (json, svg, ...) and no `-o DIR` is a usage error: a batch prints
    its table, and the tree format would be ignored. No goal at all, or `--goal` beside `--goal-file`, is a usage
    error naming every way to give one (before anything is loaded)."""
    if goals_file is None and not goal and goal_file is None:
        raise UsageError("no goal given: --goal G (repeat it for a batch), --goals FILE or --goal-file FILE")
    if goals_file is None and len(goal) == 1 and goal_file is not None:
        raise UsageError("--goal and --goal-file: give one of them (--goals FILE for a batch)")
    if goals_file is None and len(goal) <= 1 and fmt not in TABLE_FORMATS:
        return None
    if goal_file is not None:
        raise UsageError("--goal-file names one goal; use --goals FILE for a batch")
    ctx = click.get_current_context(silent=True)
    if (fmt is not None and fmt not in TABLE_FORMATS and output is None and ctx is not None
            and ctx.get_parameter_source("fmt") is not click.core.ParameterSource.DEFAULT):
        raise UsageError(f"--format {fmt}: a batch of goals prints one table (--format text, csv, or jsonl: one "
                         f"JSON object per goal); {fmt} is the format of the tree files it writes with -o DIR")
    entries = []
    for text in goal:
        try:
            entries.append(GoalEntry(parse_goal_spec(text)))
        except ValueError as exc:
            raise UsageError(f"{exc}: {text!r}") from None
    if goals_file is not None:
        from .progress import slow_step

        # a step: `goals ... | retrieve --goals -` waited 2.0 s on its standard input without a line (stop 54)
        with slow_step(f"reading the goals from {'standard input' if str(goals_file) == '-' else goals_file}"):
            entries.extend(read_goal_list(goals_file))
    if not entries:
        raise UsageError("no goal given (--goal G, repeated, or --goals FILE)")
    return entries


def write_files(directory: Path, rows: list[dict], contents: Sequence[str | None], ext: str) -> None:
    """Write each row's content (None: no file) to DIR/<slug of its goal>.<ext>; set each row's `file`.
    DIR is made only when a file is written (`atomic_write_many` makes it): no tree leaves no empty DIR."""
    names = file_names((r["goal"] for r in rows), ext)
    files = {}
    for row, name, text in zip(rows, names, contents, strict=True):
        row["file"] = None
        if text is not None:
            row["file"] = str(directory / name)
            files[directory / name] = text
    try:
        atomic_write_many(files)
    except OSError as exc:
        raise cannot_write(directory, exc) from None


def write_trees(directory: Path, rows: list[dict], trees: Sequence[TaskTree | None], fmt: str,
                kitchen: Kitchen) -> None:
    """Each row's task tree (None: no file) in `fmt`, written by `write_files`, under a step that says so: drawing
    171 trees with Graphviz left `retrieve --goals - --format svg -o DIR` 20.9 s silent (stop 58's pass)."""
    from ..io.tree_formats import render_tree

    made = sum(t is not None for t in trees)
    with slow_step(f"writing {count(made, 'task tree', grouped=True)} to {directory} ({fmt})"):
        texts = [None if t is None else render_tree(t, fmt, kitchen=kitchen) for t in trees]
        write_files(directory, rows, texts, TREE_EXTENSIONS[fmt])


def finish(rows: list[dict], table_fmt: str, note: str, solved: Callable[[dict], bool] | None = None) -> None:
    """Print the table (stdout) and the summary (stderr; at a terminal the text table leaves it out, so it is
    said once); exit 1 unless every goal was solved."""
    click.echo(format_table(rows, table_fmt, total=not (table_fmt == "text" and _stdout_is_terminal())), nl=False)
    click.echo(f"{summary(rows)} ({note})", err=True)
    ok = solved or (lambda r: r["status"] == "solved")
    if not all(ok(r) for r in rows):
        click.get_current_context().exit(1)


def _stdout_is_terminal() -> bool:
    return click.get_text_stream("stdout").isatty()
