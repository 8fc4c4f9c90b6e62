"""FOON files and directories -> one universal FOON (paths expanded in sorted order)."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from ..errors import FoonInputError, FoonSyntaxError, ParseWarning
from ..model.bulk import full_gc_paused
from ..model.foon import Foon
from ..model.merge import merge
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
            raise FoonInputError(str(p), 0, "no such file or directory")
    return sorted(dict.fromkeys(out))


def read_network(path: Path) -> ParseResult:
    """One network file: FOON text, or the JSON export (`*.json`, see jsonio)."""
    if path.suffix.lower() == ".json":
        from .jsonio import read_json

        return ParseResult(read_json(path))
    return parse_file(path)


def load(paths: Iterable[str | Path], level: int = 3) -> tuple[Foon, tuple[ParseWarning, ...]]:
    """Parse and merge every FOON file under `paths` (JSON exports named directly too);
    return the network and all warnings."""
    with full_gc_paused():
        results: list[ParseResult] = [read_network(p) for p in expand_paths(paths)]
        warnings = tuple(w for r in results for w in r.warnings)
        return merge((r.foon for r in results), level), warnings
