"""Universal FOON: merge many files into one network with duplicate units removed.

Files are read in sorted path order so the result never depends on the file
system; duplicates are found with hashed keys in one pass (linear time).
"""

from __future__ import annotations

import gc
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from .errors import FoonSyntaxError, ParseWarning
from .model import Foon, FunctionalUnit
from .parser import ParseResult, parse_file

FOON_SUFFIXES = (".txt", ".foon")


def expand_paths(paths: Iterable[str | Path]) -> list[Path]:
    """Files named directly, plus FOON files (`*.txt`, `*.foon`) under directories, sorted."""
    out: list[Path] = []
    for raw in paths:
        p = Path(raw)
        if p.is_dir():
            found = sorted(f for f in p.rglob("*") if f.is_file() and f.suffix.lower() in FOON_SUFFIXES)
            if not found:
                raise FoonSyntaxError(str(p), 0, "directory holds no FOON files (*.txt, *.foon)")
            out.extend(found)
        elif p.exists():
            out.append(p)
        else:
            raise FoonSyntaxError(str(p), 0, "no such file or directory")
    return sorted(dict.fromkeys(out))


def dedupe_units(units: Iterable[FunctionalUnit]) -> tuple[FunctionalUnit, ...]:
    """Keep the first of each group of units with the same key; join their sources."""
    kept: dict[tuple, FunctionalUnit] = {}
    for u in units:
        first = kept.get(u.key)
        if first is None:
            kept[u.key] = u
        else:
            kept[u.key] = FunctionalUnit(first.inputs, first.motion, first.outputs, first.sources + u.sources)
    return tuple(kept.values())


def merge(foons: Iterable[Foon], level: int = 3) -> Foon:
    """Merge networks (projected to `level`) into one, removing duplicate units.

    A network already at a lower level (e.g. a level-1 JSON export) lowers the
    result's level, so that all nodes are compared at one level.
    """
    from .levels import project

    foons = list(foons)
    level = min([level, *(f.level for f in foons)])
    return Foon(dedupe_units(u for f in foons for u in project(f, level).units), level)


def read_network(path: Path) -> ParseResult:
    """One network file: FOON text, or the JSON export (`*.json`, see jsonio)."""
    if path.suffix.lower() == ".json":
        from .jsonio import read_json

        return ParseResult(read_json(path))
    return parse_file(path)


@contextmanager
def full_gc_paused() -> Iterator[None]:
    """Hold back the cyclic garbage collector's full collections while building a network.

    Loading allocates many long-lived objects and no reference cycles. Full
    collections would re-scan the growing heap again and again (10 relabelled
    copies of the subgraphs took ~19x the time of one copy); disabling the
    collector instead leaves one huge young generation to scan afterwards, which
    is slow too. Young collections keep running; the thresholds are restored after.
    """
    thresholds = gc.get_threshold()
    gc.set_threshold(thresholds[0], thresholds[1], 1 << 30)
    try:
        yield
    finally:
        gc.set_threshold(*thresholds)


def load(paths: Iterable[str | Path], level: int = 3) -> tuple[Foon, tuple[ParseWarning, ...]]:
    """Parse and merge every FOON file under `paths` (JSON exports named directly too);
    return the network and all warnings."""
    with full_gc_paused():
        results: list[ParseResult] = [read_network(p) for p in expand_paths(paths)]
        warnings = tuple(w for r in results for w in r.warnings)
        return merge((r.foon for r in results), level), warnings
