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
from ..model.dedupe import network_with_table
from ..model.foon import (
    Foon,
    FunctionalUnit,
    Motion,
    ObjectNode,
    Source,
    State,
    make_node,
    make_source,
    make_unit,
)
from ..model.node_table import NodeTable
from ..model.words import first_of
from .foon_lines import _SKIP, _classify, _parse_motion, _parse_state, plain_state


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
    except FileNotFoundError:
        raise FoonInputError(str(path), 0, "no such file") from None
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


def parse_text(text: str, path: str = "<string>") -> ParseResult:
    """Parse FOON text; `path` is used in errors, warnings and provenance.

    Plain text (`_plain`: every line an `O`, `S`, `M` or `//` line, as exported networks are) is read
    block by block (`_Reader.read_plain`); anything else, and any plain text that turns out to hold an
    error or a block that is not a unit, is read line by line (`_Reader.read`), which gives the same
    network and says where the problem is.
    """
    skip, first = _comment_head(text)
    if _plain(text, skip):
        found = _Reader(path).read_plain(text[skip:], first)
        if found is not None:
            return found
    lines = text.split("\n")
    reader = _Reader(path)
    reader.read(lines)
    return reader.finish(len(lines), text.endswith("\n"))


#: A newline that starts a line of no plain text (`_plain`): one not starting with `O`, `S`, `M` or `//`
#: (a final newline starts no line).
_NOT_PLAIN_LINE = re.compile(r"\n(?:[^OSM/]|/(?!/))")


def _plain(text: str, skip: int = 0) -> bool:
    """Whether every line of `text` from offset `skip` starts with `O`, `S`, `M` or `//` (a final newline
    allowed): no comment, blank or indented line, no carriage return. One regular-expression scan."""
    if not text.startswith(("O", "S", "M", "//"), skip) or "\r" in text:
        return False
    return _NOT_PLAIN_LINE.search(text, skip) is None


def _comment_head(text: str) -> tuple[int, int]:
    """(offset, line number) where `text` goes on after its leading comment lines (a written network's
    header); (0, 1) when one of them is a `# Source:` line, which the line reader keeps."""
    skip = line = 0
    while text.startswith("#", skip):
        end = text.find("\n", skip)
        end = len(text) if end < 0 else end + 1
        if _classify(text[skip:end].rstrip("\n"), None) != _SKIP:
            return 0, 1
        skip, line = end, line + 1
    return skip, line + 1


def _once(texts: list[str], nodes: tuple[ObjectNode, ...]) -> tuple[list[str], tuple[ObjectNode, ...]]:
    """One side of a unit with a node written twice kept once (the first), texts and nodes alike: a line written
    twice is one object (`pairing.unit_roles`). O(n) for n objects; the usual side, no node twice, as given."""
    if len(set(nodes)) == len(nodes):
        return texts, nodes
    first = {n: k for k, n in reversed(tuple(enumerate(nodes)))}
    keep = sorted(first.values())
    return [texts[k] for k in keep], tuple(nodes[k] for k in keep)


class _Made(dict):
    """A dictionary that makes a missing value with `make(key)` and keeps it; a hit is looked up in C, also
    through `map(made.__getitem__, keys)`."""

    __slots__ = ("make",)

    def __init__(self, make) -> None:
        super().__init__()
        self.make = make

    def __missing__(self, key):
        value = self[key] = self.make(key)
        return value


class _NotPlain(Exception):
    """Raised inside `_Reader.read_plain`: this text needs the line reader."""


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
            self.units.append(FunctionalUnit(tuple(dict.fromkeys(inputs)), motion, tuple(dict.fromkeys(outputs)),
                                             (Source(self.path, start, url),)))  # a line written twice: one object

    def read_plain(self, text: str, first: int = 1) -> ParseResult | None:
        """The network of plain text (`_plain`; its line 1 is line `first` of the file) read block by block,
        or None when a block is not a well-formed
        unit (no motion or two, no inputs or outputs, a state line first) or a line has an error: the line
        reader then reads the text again and warns or fails where it should.

        A block is cut at its motion line and each side at its `O` lines with `str.split`; each object's
        text (its `O` line and state lines) is looked up whole, in C (`map` over a `_Made` dictionary), so a
        recurring object costs one dictionary look-up; a new one looks its lines up, and a new state line is
        read by one regular expression (`plain_state`) or, in an unusual shape, with the line reader's checks.
        The node numbers of `Foon.table` are assigned on the way (objects in order of first appearance).
        """
        numbers: dict[ObjectNode, int] = {}
        number_of: dict[str, int] = {}  # object text without its leading `O` -> node number
        nodes: dict[tuple, ObjectNode] = {}  # (`O` line fields, states) -> node
        units, ins_ids, outs_ids = self.units, [], []
        path = self.path

        def new_state(raw: str) -> State:
            state = plain_state(raw)
            if state is None:  # an unusual shape: read field by field, with the line reader's checks
                entry = _classify(raw, _not_plain)
                if entry[0] != "S":
                    raise _NotPlain
                state = _parse_state(("S",) + entry[1], _not_plain)
            return state

        def new_head(raw: str) -> tuple:
            head = _classify("O" + raw, _not_plain)
            if head[0] != "O":
                raise _NotPlain
            return head

        state_of, head_of = _Made(new_state).__getitem__, _Made(new_head).__getitem__

        def new_object(chunk: str) -> ObjectNode:
            raws = chunk.split("\n")
            head = head_of(raws[0])
            made = tuple(map(state_of, raws[1:])) if len(raws) > 1 else ()
            node = nodes.get(key := (head, made))  # one node per spelling of the same fields and states
            if node is None:
                node = nodes[key] = make_node(head[1], made, motion_flag=head[2], goal=head[3], dish=head[4])
            number_of[chunk] = numbers.setdefault(node, len(numbers))
            return node

        def new_motion(raw: str) -> Motion:
            entry = _classify("M" + raw, _not_plain)
            if entry[0] != "M":
                raise _NotPlain
            motion = self.motion_cache.get(entry[1])
            if motion is None:
                motion = self.motion_cache[entry[1]] = _parse_motion(entry[1], _not_plain)
            return motion

        node_of, motion_of, number = _Made(new_object).__getitem__, _Made(new_motion).__getitem__, number_of.__getitem__
        # each piece: the rest of a separator line (of a virtual one before line `first`), then its block's lines
        pieces = text.split("\n//")  # as `("\n" + text).split("\n//")` gives them, without copying the text:
        pieces[:1] = ["", pieces[0][2:]] if text.startswith("//") else ["\n" + pieces[0]]
        pieces[-1] = pieces[-1].removesuffix("\n")  # the final newline
        line = first - 1  # the line of the separator that opens the piece
        try:
            for piece in pieces:
                start = line + 1
                line = start + piece.count("\n")
                before, motion_line, after = piece.partition("\nM")
                if not motion_line:
                    if "\n" in piece:  # a block without a motion line
                        raise _NotPlain
                    continue  # an empty block
                ins, outs = before.split("\nO"), after.split("\nO")
                if len(ins) < 2 or len(outs) < 2 or "\n" in ins[0] or "\n" in outs[0] or "\nM" in after:
                    raise _NotPlain  # a block starting with a state line, no inputs or outputs, two motions
                motion = motion_of(outs[0])
                del ins[0], outs[0]
                ins_n, outs_n = tuple(map(node_of, ins)), tuple(map(node_of, outs))
                ins, ins_n = _once(ins, ins_n)
                outs, outs_n = _once(outs, outs_n)
                units.append(make_unit(ins_n, motion, outs_n, (make_source(path, start),)))
                ins_ids.append(tuple(map(number, ins)))
                outs_ids.append(tuple(map(number, outs)))
        except (_NotPlain, FoonSyntaxError):
            return None
        if not units:
            return None
        table = NodeTable(tuple(numbers), tuple(ins_ids), tuple(outs_ids))
        return ParseResult(network_with_table(tuple(units), 3, table))

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
            last = max(lineno - final_newline, 1)
            if self.motion_cache and self.warnings:  # a recipe whose every block was skipped: say why
                said = first_of(self.warnings, 1, lambda w: f"line {w.line}: {w.message}")
                raise FoonSyntaxError(self.path, last, f"no functional units in file: every block was skipped: {said}")
            objects = bool(self.node_cache)  # objects and no motion: a kitchen or goal file (O/S lines)
            raise FoonSyntaxError(self.path, last, "no functional units in file" + (
                ": it lists objects and no motion ('M') line, as a kitchen or a goal file does (docs/format.md), "
                "not a network" if objects else ""), belongs=("kitchen", "goals") if objects else ())
        return ParseResult(Foon(tuple(self.units)), tuple(self.warnings), tuple(dict.fromkeys(self.urls)))


def _not_plain(message: str) -> _NotPlain:
    """The `fail` of `_Reader.read_plain`: an error there sends the text to the line reader."""
    return _NotPlain(message)


