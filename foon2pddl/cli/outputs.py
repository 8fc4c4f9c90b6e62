"""Where a command's output goes: standard output or a file written atomically (checked writable before any
long work), and the notes a tree's substitutions add on stderr."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import FoonInputError
from ..io.atomic import atomic_write
from .options import chosen_similarity


def cannot_write(path: Path | str, exc: OSError) -> FoonInputError:
    """The error of an output `path` that cannot be written (exit 2), in the words every command says it in."""
    return FoonInputError(str(path), 0, f"cannot write: {exc.strerror or exc}")


def emit(text: str, output: Path | None) -> None:
    """Print `text`, or write it atomically to `output`."""
    if output is None:
        click.echo(text, nl=False)
    else:
        try:
            atomic_write(output, text)
        except OSError as exc:
            raise cannot_write(output, exc) from None


def check_output(output: Path | None, directory: bool = False) -> None:
    """Fail now (exit 2) when `output` cannot be written, before any long work runs."""
    if output is None:
        return
    from ..io.atomic import check_writable

    try:
        check_writable(output, directory)
    except OSError as exc:
        raise cannot_write(output, exc) from None


def emit_network(foon, fmt: str, provenance: bool, header: str, output: Path | None) -> None:
    """Write a derived network (FOON text with `header`, or the JSON export) and echo the header on stderr."""
    from ..io.jsonio import write_json
    from ..io.writer import write_foon

    emit(write_json(foon) if fmt == "json" else write_foon(foon, provenance=provenance, header=header), output)
    click.echo(header, err=True)


def expansion_notes(tree, matrix) -> None:
    """Say (stderr) which FOON-EXP substitutions a tree relies on, with their similarity from `matrix`, the one
    the EXP view substituted by (`NetworkView.matrix`: no second matrix, no WordNet opened for a new goal). A
    product renamed along (`lemon juice -> lime juice`) that neither the network nor the kitchen holds is not
    in that matrix: its pair is scored by the mode itself (`SimilarityMatrix.or_else`)."""
    from ..generalize.modes import make_similarity
    from ..generalize.substitution import expansion_substitutions
    from .progress import slow_step

    def opened():  # WordNet opens only here, for a pair the matrix lacks
        with slow_step("scoring the tree's FOON-EXP substitutions in WordNet"):
            return make_similarity(chosen_similarity())

    subs = expansion_substitutions(tree, matrix.or_else(opened))
    for line in [sub.describe() for sub in subs] or ["none (the tree uses only units as read)"]:
        click.echo(f"substitution: {line}", err=True)
