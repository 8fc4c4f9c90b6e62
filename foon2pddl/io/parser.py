"""Reader for the FOON text format (id-ful public dataset and id-less universal variant).

Accepts every quirk of the public data (see docs/format.md); rejects anything
else with a `FoonSyntaxError` naming path, line, the offending text and what
was expected. Blocks that are not units (no motion, no outputs, no inputs)
are skipped with a `ParseWarning`, never half-added.
"""

from __future__ import annotations

import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from ..errors import FoonInputError, FoonSyntaxError, ParseWarning
from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, Source, State, make_node, make_state, normalize_label

_ID = re.compile(r"[OSM]\d*")
CONTROL_CHARS = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
_INT = re.compile(r"\d+")
#: Longest integer read (Python's default int-string limit): longer ones are errors, never ValueError.
MAX_INT_DIGITS = 4300


@dataclass(frozen=True)
class ParseResult:
    """A parsed file: its network, the warnings raised and its `# Source:` URLs."""

    foon: Foon
    warnings: tuple[ParseWarning, ...] = ()
    urls: tuple[str, ...] = ()


def read_bytes(path: Path) -> bytes:
    """A regular file's bytes. FIFOs, devices and sockets are refused without blocking
    (opened non-blocking, checked with fstat), so a FIFO never hangs a command."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as exc:
        raise FoonInputError(str(path), 0, f"cannot read file: {exc.strerror or exc}") from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise FoonInputError(str(path), 0, "cannot read file: Is a directory")
        if not stat.S_ISREG(info.st_mode):
            raise FoonInputError(str(path), 0, "not a regular file (FIFOs and devices are not read)")
        os.set_blocking(fd, True)
        with os.fdopen(fd, "rb", closefd=False) as fh:
            return fh.read()
    except OSError as exc:
        raise FoonInputError(str(path), 0, f"cannot read file: {exc.strerror or exc}") from None
    finally:
        os.close(fd)


def read_text(path: Path) -> str:
    """Read a regular file as UTF-8 (BOM tolerated); a decoding error names the line."""
    data = read_bytes(path)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise FoonSyntaxError(str(path), line, f"not UTF-8 text (byte 0x{data[exc.start]:02x})") from None


def parse_file(path: str | Path) -> ParseResult:
    """Parse one FOON file."""
    p = Path(path)
    return parse_text(read_text(p), str(p))


class _PendingObject:
    __slots__ = ("label", "flag", "goal", "dish", "states", "keys")

    def __init__(self, label: str, flag: int, goal: bool, dish: int | None) -> None:
        self.label = label
        self.flag = flag
        self.goal = goal
        self.dish = dish
        self.states: list[State] = []
        self.keys: list[tuple[str, ...]] = []  # raw state fields, for the node cache

    def cache_key(self) -> tuple:
        return (self.label, self.flag, self.goal, self.dish, tuple(self.keys))

    def build(self) -> ObjectNode:
        return make_node(self.label, self.states, motion_flag=self.flag, goal=self.goal, dish=self.dish)


def parse_text(text: str, path: str = "<string>") -> ParseResult:
    """Parse FOON text; `path` is used in errors, warnings and provenance."""
    lines = text.split("\n")
    reader = _Reader(path)
    reader.read(lines)
    return reader.finish(len(lines), text.endswith("\n"))


class _Reader:
    """The state of one `parse_text` run: what was read so far, and caches.

    Lines recur verbatim (a unit's outputs are the next unit's inputs): each distinct
    line is classified once, each state, motion and object built once and shared (an
    object is looked up by its `O` line's fields and its states' raw fields, so a
    recurring object costs one dictionary look-up per line); what depends on the
    surrounding block is checked per occurrence. `read` is one loop over the lines
    with the open block in local variables: O(lines) dictionary look-ups.
    """

    def __init__(self, path: str) -> None:
        self.path = path
        self.units: list[FunctionalUnit] = []
        self.warnings: list[ParseWarning] = []
        self.urls: list[str] = []
        self.state_cache: dict[tuple[str, ...], State] = {}
        self.node_cache: dict[tuple, ObjectNode] = {}
        self.raw_nodes: dict[tuple[str, ...], ObjectNode] = {}
        self.line_cache: dict[str, tuple] = {}
        self.motion_cache: dict[tuple[str, ...], Motion] = {}
        #: The open block, once `read` has returned (`finish` closes it).
        self.open: tuple = (1, [], None, [], [])

    def fail(self, lineno: int, message: str, line: str) -> FoonSyntaxError:
        return FoonSyntaxError(self.path, lineno, message, line)

    def at(self, lineno: int, raw: str):
        """`fail` for one line: message -> error naming that line."""
        return lambda message: self.fail(lineno, message, raw.rstrip("\r"))

    def node(self, raws: tuple[str, ...]) -> ObjectNode:
        """The object its raw `O` and `S` lines make (all classified and their states parsed), built once
        per distinct spelling and shared by every spelling with the same fields."""
        node = self.raw_nodes.get(raws)
        if node is None:
            head = self.line_cache[raws[0]]
            keys = tuple(self.line_cache[raw][1] for raw in raws[1:])
            key = (head, keys)
            node = self.node_cache.get(key)
            if node is None:
                states = [self.state_cache[k] for k in keys]
                node = self.node_cache[key] = make_node(head[1], states, motion_flag=head[2], goal=head[3],
                                                        dish=head[4])
            self.raw_nodes[raws] = node
        return node

    def unit(self, start: int, inputs: list[ObjectNode], motion: Motion | None, outputs: list[ObjectNode]) -> None:
        """Add the block read from line `start` as a unit, or warn why it is skipped (nothing for an empty one)."""
        if motion is None and not inputs and not outputs:
            return
        problem = None
        if motion is None:
            problem = "block has no motion line ('M'); skipped"
        elif not outputs:
            problem = "unit has no output objects after its motion line; skipped"
        elif not inputs:
            problem = "unit has no input objects before its motion line; skipped"
        if problem:
            self.warnings.append(ParseWarning(self.path, start, problem))
        else:
            url = self.urls[-1] if self.urls else None
            self.units.append(FunctionalUnit(tuple(inputs), motion, tuple(outputs), (Source(self.path, start, url),)))

    def read(self, lines: list[str]) -> None:
        """Read `lines` (line 1 first); the last block stays open in `self.open`.

        A line enters the line cache once it passed every check that does not depend on its block
        (a state line: once its state is parsed), so a cached line needs only its block's checks.
        """
        line_cache, state_cache, raw_nodes, node = self.line_cache, self.state_cache, self.raw_nodes, self.node
        start, inputs, motion, outputs = 1, [], None, []
        raws: list[str] = []  # the open object's raw `O` line and state lines ([] when none is open)
        for lineno, raw in enumerate(lines, start=1):
            entry = line_cache.get(raw)
            if entry is None:
                entry = _classify(raw, self.at(lineno, raw))
                if entry[0] == "S" and raws:
                    key = entry[1]
                    if key not in state_cache:
                        state_cache[key] = _parse_state(("S",) + key, self.at(lineno, raw))
                    line_cache[raw] = entry
                elif entry[0] != "S":
                    line_cache[raw] = entry
            kind = entry[0]
            if kind == "S":
                if not raws:
                    raise self.fail(lineno, "state line ('S') before any object line ('O') of its unit",
                                    raw.rstrip("\r"))
                raws.append(raw)
            elif kind == "O":
                if raws:
                    made = raw_nodes.get(key := tuple(raws)) or node(key)
                    (inputs if motion is None else outputs).append(made)
                elif motion is None and not inputs and not outputs:
                    start = lineno
                raws = [raw]
            elif kind == "//":
                if raws:
                    made = raw_nodes.get(key := tuple(raws)) or node(key)
                    (inputs if motion is None else outputs).append(made)
                    raws = []
                self.unit(start, inputs, motion, outputs)
                start, inputs, motion, outputs = lineno + 1, [], None, []
            elif kind == "M":
                if motion is not None:
                    raise self.fail(lineno, "second motion line ('M') in one unit (missing '//'?)", raw.rstrip("\r"))
                if raws:
                    inputs.append(raw_nodes.get(key := tuple(raws)) or node(key))
                    raws = []
                elif not inputs and not outputs:
                    start = lineno
                key = entry[1]
                motion = self.motion_cache.get(key)
                if motion is None:
                    motion = self.motion_cache[key] = _parse_motion(key, self.at(lineno, raw))
            elif kind == "url":
                self.urls.append(entry[1])
        self.open = (start, inputs, motion, outputs, raws)

    def finish(self, lineno: int, final_newline: bool) -> ParseResult:
        """Close the last block; the result (FoonSyntaxError at the last line when no unit was read)."""
        start, inputs, motion, outputs, raws = self.open
        if raws:
            (inputs if motion is None else outputs).append(self.node(tuple(raws)))
        self.unit(start, inputs, motion, outputs)
        if not self.units:  # reported at the last line of the file (1 when empty)
            raise FoonSyntaxError(self.path, max(lineno - final_newline, 1), "no functional units in file")
        return ParseResult(Foon(tuple(self.units)), tuple(self.warnings), tuple(dict.fromkeys(self.urls)))


_SKIP = ("#",)
_SEPARATOR = ("//",)


def _classify(raw: str, fail) -> tuple:
    """What one raw line is, independent of its block: `("#",)`, `("url", url)`, `("//",)`,
    `("O", label, flag, goal, dish)`, `("S", fields after the head)` or `("M", all fields)`."""
    line = raw.rstrip("\r")
    stripped = line.strip()
    if not stripped:
        return _SKIP
    if stripped.startswith("#"):
        comment = stripped[1:].lstrip()
        if comment.lower().startswith("source:"):
            url = comment[len("source:"):].strip()
            if url:
                return ("url", url)
        return _SKIP
    if stripped.startswith("//"):
        return _SEPARATOR
    if CONTROL_CHARS.search(line):
        raise fail("control character in line (garbage bytes?)")
    fields = [f.strip() for f in stripped.split("\t")]
    head = fields[0]
    kind = head[:1]
    if kind not in "OSM" or not _ID.fullmatch(head):
        raise fail("expected an 'O', 'S' or 'M' line, '//' or a '#' comment")
    if len(fields) < 2 or not fields[1]:
        raise fail(f"'{kind}' line has no label (expected '{kind}<id><TAB><label>')")
    if kind == "O":
        obj = _parse_object(fields, fail)
        return ("O", obj.label, obj.flag, obj.goal, obj.dish)
    if kind == "S":
        return ("S", tuple(fields[1:]))
    return ("M", tuple(fields))


def _parse_object(fields: list[str] | tuple[str, ...], fail) -> _PendingObject:
    """`O<id> label [flag] [dish|!]`: flag 0/1 (`00` seen), dish an integer, `!` a goal mark."""
    label = fields[1]
    if CONTROL_CHARS.search(label):
        raise fail("control character in object label")
    flag, goal, dish = 0, False, None
    rest = [f for f in fields[2:] if f]
    for i, value in enumerate(rest):
        if value == "!":
            goal = True
        elif value.endswith("!") and _INT.fullmatch(value[:-1]):
            goal = True
            value = value[:-1]
            if i == 0:
                flag = _int(value, fail)
            else:
                dish = _int(value, fail)
        elif _INT.fullmatch(value):
            if i == 0:
                flag = _int(value, fail)
            elif dish is None:
                dish = _int(value, fail)
            else:
                raise fail(f"unexpected extra field {value!r} on object line")
        else:
            what = "motion identifier 0/1" if i == 0 else "dish marker (integer) or '!'"
            raise fail(f"expected {what}, found {value!r}")
    return _PendingObject(label, flag, goal, dish)


def _int(digits: str, fail) -> int:
    """A field of digits as an int; more than MAX_INT_DIGITS significant digits is an error."""
    significant = digits.lstrip("0") or "0"
    if len(significant) > MAX_INT_DIGITS:
        raise fail(f"integer field with {len(significant)} digits (at most {MAX_INT_DIGITS} are read)")
    return int(significant)


def _split_list(body: str) -> list[str]:
    return [item.strip() for item in body.split(",") if item.strip()]


def _parse_state(fields: list[str] | tuple[str, ...], fail) -> State:
    """`S<id> label [ [related] | {ingredients} ]...`; `[a,b]` lists are read as ingredients."""
    label = fields[1]
    related = ""
    ingredients: list[str] = []
    for extra in fields[2:]:
        if not extra:
            continue
        if extra.startswith("[") and extra.endswith("]"):
            items = _split_list(extra[1:-1])
            if len(items) == 1:
                if related:
                    raise fail("state has two related objects")
                related = items[0]
            else:
                ingredients.extend(items)
        elif extra.startswith("{") and extra.endswith("}"):
            ingredients.extend(_split_list(extra[1:-1]))
        else:
            raise fail(f"expected '[related object]' or '{{ingredient, ...}}' after the state label, found {extra!r}")
    return make_state(label, related, ingredients)


def _parse_motion(fields: list[str] | tuple[str, ...], fail) -> Motion:
    """`M<id> label [start end]` or `<start,end>` / `<Assumed>`; `label*` marks a composite unit."""
    label = fields[1]
    composite = label.endswith("*")
    label = label.rstrip("*").strip()
    if not label:
        raise fail("motion line has no label before '*'")
    times = [f for f in fields[2:] if f]
    start = end = None
    if len(times) == 1 and times[0].startswith("<") and times[0].endswith(">"):
        parts = re.split(r"[,\-]", times[0][1:-1], maxsplit=1)
        start = parts[0].strip() or None
        end = parts[1].strip() if len(parts) > 1 else start
    elif times:
        start = times[0]
        end = times[1] if len(times) > 1 else start
    return Motion(normalize_label(label), start, end, composite)


def parse_objects(text: str, path: str = "<string>") -> list[tuple[ObjectNode, int]]:
    """Object nodes written as O/S lines (kitchen and goal files), with their line numbers.

    Objects end at the next `O` line or at `//`; motion lines are an error here.
    """
    nodes: list[tuple[ObjectNode, int]] = []
    obj: _PendingObject | None = None
    start = 0

    def close() -> None:
        nonlocal obj
        if obj is not None:
            nodes.append((obj.build(), start))
            obj = None

    for lineno, raw in enumerate(text.split("\n"), start=1):
        line = raw.rstrip("\r")
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if stripped.startswith("//"):
            close()
            continue
        if CONTROL_CHARS.search(line):
            raise FoonSyntaxError(path, lineno, "control character in line (garbage bytes?)", line)
        fields = [f.strip() for f in stripped.split("\t")]
        head = fields[0]
        if head[:1] not in "OS" or not _ID.fullmatch(head):
            raise FoonSyntaxError(path, lineno, "expected an 'O' or 'S' line, '//' or a '#' comment", line)
        if len(fields) < 2 or not fields[1]:
            raise FoonSyntaxError(path, lineno, f"'{head[0]}' line has no label", line)

        def fail(message: str, lineno: int = lineno, line: str = line) -> FoonSyntaxError:
            return FoonSyntaxError(path, lineno, message, line)

        if head[0] == "O":
            close()
            obj, start = _parse_object(fields, fail), lineno
        else:
            if obj is None:
                raise fail("state line ('S') before any object line ('O')")
            obj.states.append(_parse_state(fields, fail))
    close()
    return nodes
