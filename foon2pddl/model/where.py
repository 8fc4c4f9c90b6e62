"""How messages and generated files name where a unit was read (`FILE:LINE`): one way for every module.

Messages (notes, reasons, reports) name a file shipped with the package, the embedded example, by its path in
the package (`foon2pddl/data/example/07-guacamole.foon:28`, wherever it is installed) and any other file as the
user gave it; generated files (PDDL comments) by the file name alone, so they do not depend on a checkout place.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from functools import lru_cache
from pathlib import Path

from .foon import FunctionalUnit, Source

__all__ = ["TRANSFER_SOURCE", "beyond_foon", "short_path", "shown_path", "source_where", "unit_where"]

#: The source path of an assumed transfer unit (`pddl.transfer`): its url is the `FILE:LINE` of the unit it serves.
TRANSFER_SOURCE = "assumed-transfer"


@lru_cache(maxsize=4096)
def short_path(path: str) -> str:
    """A source path as written in comments: the file name (output must not depend on checkout place)."""
    return path.replace("\\", "/").rstrip("/").rsplit("/", 1)[-1] or path


#: The package's directory: a file shipped with it (the embedded example) is named by its path in the package.
_PACKAGE = Path(__file__).resolve().parent.parent


@lru_cache(maxsize=4096)
def shown_path(path: str) -> str:
    """A source path as notes and reports show it: a file shipped with the package by its path in the package
    (`foon2pddl/data/example/02-whipped_cream.foon`, wherever it is installed), any other as the user gave it."""
    if not os.path.isabs(path):
        return path
    file = Path(path).resolve()
    return (Path(_PACKAGE.name) / file.relative_to(_PACKAGE)).as_posix() if file.is_relative_to(_PACKAGE) else path


def unit_where(unit: FunctionalUnit, path: Callable[[str], str] = shown_path) -> str:
    """`FILE:LINE` of the unit's first source, `?` when unknown; `path` names the file: `shown_path` in
    messages, `short_path` (the file name) in generated files."""
    src = unit.source
    return f"{path(src.path)}:{src.line}" if src is not None else "?"


def source_where(src: Source, path: Callable[[str], str] = shown_path) -> str:
    """`FILE:LINE` of one source, then ` (expanded from X)` for a FOON-EXP copy, which shares its original's line
    (PDDL comments and count reasons: one file:line must not read as two units); `path` as `unit_where`'s."""
    return f"{path(src.path)}:{src.line}" + (f" (expanded from {src.expanded_from})" if src.expanded_from else "")


def beyond_foon(unit: FunctionalUnit) -> str:
    """The `FILE:LINE` of the FOON unit an assumed transfer unit (`pddl.transfer`) pours an ingredient over for;
    empty for any other unit (the words a plan's step and its JSON add: the step is beyond FOON)."""
    src = unit.source
    return src.url or "?" if src is not None and src.path == TRANSFER_SOURCE else ""
