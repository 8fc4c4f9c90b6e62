"""FOON files and directories -> one universal FOON (paths expanded in sorted order)."""

from __future__ import annotations

import re
import sys
from collections.abc import Iterable
from pathlib import Path

from ..errors import FoonInputError, FoonSyntaxError, ParseWarning
from ..model.bulk import full_gc_paused
from ..model.foon import Foon
from ..model.merge import merge
from ..model.words import first_of
from .parser import ParseResult, parse_file, parse_text, read_text

FOON_SUFFIXES = (".txt", ".foon")


#: PATHS entry that reads one network from standard input (FOON text, or the JSON export: text starting with
#: `{`, which no FOON line does), and the name its errors give it.
STDIN = "-"
STDIN_NAME = "<stdin>"
_FOON_LINE = re.compile(r"(?:[OSM]\d*\t|//)")


def expand_paths(paths: Iterable[str | Path]) -> list[Path]:
    """Files named directly, plus FOON files (`*.txt`, `*.foon`) under directories, sorted; `-` (standard
    input) is kept where it stands."""
    out: list[Path] = []
    for raw in paths:
        p = Path(raw)
        if str(raw) == STDIN:
            out.append(p)
        elif p.is_dir():
            found = sorted(f for f in p.rglob("*") if f.is_file() and f.suffix.lower() in FOON_SUFFIXES)
            if not found:
                raise FoonSyntaxError(str(p), 0, "directory holds no FOON files (*.txt, *.foon)")
            out.extend(found)
        elif p.exists():
            out.append(p)
        else:
            raise FoonInputError(str(p), 0, "no such file or directory")
    return sorted(dict.fromkeys(out), key=lambda f: (str(f) != STDIN, f))


def plainly_not_foon(text: str) -> str:
    """What a text is when it is plainly no FOON file ("" when it may be one): a rates file, or
    text without a single `O`, `S`, `M` or `//` line."""
    from .rates import looks_like_rates

    if looks_like_rates(text):
        return "a motion success-rates file (`motion<TAB>rate` lines)"
    if not any(_FOON_LINE.match(line.lstrip("\ufeff")) for line in text.split("\n")):
        return "no FOON text (no `O`, `S`, `M` or `//` line)"
    return ""


def read_network(path: Path) -> ParseResult:
    """One network file: FOON text, or the JSON export (`*.json`, see jsonio); `-`: either on standard input.
    A file that does not parse and is of another kind (a rates file, a list of objects) says so, as it is named
    on standard input too."""
    stdin = sys.stdin.read() if str(path) == STDIN else None
    if stdin is None and path.suffix.lower() == ".json":
        from .jsonio import read_json

        return ParseResult(read_json(path))
    if stdin is not None and stdin.lstrip("\ufeff \t\r\n").startswith("{"):
        from .jsonio import parse_json

        return ParseResult(parse_json(stdin, STDIN_NAME))
    name = STDIN_NAME if stdin is not None else str(path)
    try:
        return parse_file(path) if stdin is None else parse_text(stdin, name)
    except FoonSyntaxError:
        from .kitchen_files import refuse_object_lines
        from .rates import refuse_rates

        text = read_text(path) if stdin is None else stdin  # a file is re-read only on error
        refuse_rates(text, name, "a network")
        refuse_object_lines(text, name)
        raise


def _read_all(paths: Iterable[str | Path], skip_invalid: bool) -> tuple[list[ParseResult], list[ParseWarning]]:
    """Every file's parse; files found under a directory that are plainly not FOON are skipped with a
    warning, and with `skip_invalid` so is any file that fails to parse."""
    named = {Path(p) for p in paths}
    results, skipped = [], []
    for f in expand_paths(paths):
        if f not in named and f.suffix.lower() in FOON_SUFFIXES:
            what = plainly_not_foon(read_text(f))
            if what:
                skipped.append(ParseWarning(str(f), 0, f"skipped: {what}"))
                continue
        try:
            results.append(read_network(f))
        except FoonSyntaxError as exc:
            if not skip_invalid:
                raise
            skipped.append(ParseWarning(exc.path, exc.line, f"skipped (not a valid network): {exc.message}"))
    if not results:
        said = first_of(skipped, 3, lambda w: f"{Path(w.path).name}: {w.message.removeprefix('skipped: ')}")
        raise FoonSyntaxError(str(next(iter(named), "")), 0, "no FOON file to read: every file was skipped"
                              + (f"; {said}" if said else ""))
    return results, skipped


def load(paths: Iterable[str | Path], level: int = 3, skip_invalid: bool = False) -> tuple[Foon, tuple[ParseWarning, ...]]:
    """Parse and merge every FOON file under `paths` (JSON exports named directly too, `-` for
    standard input); return the network and all warnings (skipped files among them, see `_read_all`)."""
    paths = list(paths)
    with full_gc_paused():
        results, skipped = _read_all(paths, skip_invalid)
        warnings = tuple(skipped) + tuple(w for r in results for w in r.warnings)
        return merge((r.foon for r in results), level), warnings
