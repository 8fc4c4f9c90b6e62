"""Object nodes as written, before normalization: label and state lines in file order, with their lines.

The model sorts and deduplicates states (two nodes differing only in state order
are one node), which is right for search but hides how a dataset was written;
the dataset checker needs the written form to report state order and duplicated
states. Cheap: one pass over the lines, no unit structure.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from ..model.foon import normalize_label
from .files import expand_paths
from .parser import read_text


@dataclass(frozen=True)
class RawObject:
    """One `O` line and its `S` lines: normalized label, each state line's text normalized (label, [x], {a,b})."""

    path: str
    line: int
    label: str
    states: tuple[str, ...]


def _state_text(fields: list[str]) -> str:
    return re.sub(r"\s*,\s*", ",", " ".join(normalize_label(f) for f in fields[1:] if f.strip()))


def scan_text(text: str, path: str) -> Iterator[RawObject]:
    """The raw objects of one FOON text (lines that are not O/S are ignored)."""
    label, line, states = None, 0, []
    for lineno, raw in enumerate(text.split("\n"), start=1):
        fields = raw.rstrip("\r").split("\t")
        head = fields[0].strip()
        if head[:1] == "S" and head[1:].isdigit() or head == "S":
            if label is not None:
                states.append(_state_text(fields))
            continue
        if label is not None:
            yield RawObject(path, line, label, tuple(states))
            label = None
        if (head[:1] == "O" and (head[1:].isdigit() or head == "O")) and len(fields) > 1:
            label, line, states = normalize_label(fields[1]), lineno, []
    if label is not None:
        yield RawObject(path, line, label, tuple(states))


def scan_paths(paths: Iterable[str | Path]) -> list[RawObject]:
    """Raw objects of every FOON text file under `paths` (JSON exports have no written order: skipped)."""
    out: list[RawObject] = []
    for p in expand_paths(paths):
        if p.suffix.lower() != ".json":
            out.extend(scan_text(read_text(p), str(p)))
    return out
