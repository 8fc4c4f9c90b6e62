"""Writer for canonical FOON text (id-less by default, id-ful on request).

`parse_text(write_foon(f)).foon == f` for every network whose labels the
format can carry (no tabs, newlines, brackets or commas inside labels).
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, State

#: What `escape_text` escapes: the backslash, C0/C1 controls (every line break `str.splitlines` knows
#: among them), U+2028/U+2029 and lone surrogates (undecodable bytes of file names).
_UNSAFE = re.compile(r"[\\\x00-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]")
_NAMED = {"\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape_char(m: re.Match[str]) -> str:
    ch = m.group()
    return _NAMED.get(ch) or (f"\\x{ord(ch):02x}" if ord(ch) < 0x100 else f"\\u{ord(ch):04x}")


def escape_text(text: str) -> str:
    """`text` (a file name in a comment) on one line, as valid UTF-8: Python-style escapes for
    backslashes, control characters, line and paragraph separators and lone surrogates."""
    return _UNSAFE.sub(_escape_char, text)


class _Ids:
    """First-appearance ids for object, state and motion labels (id-ful variant)."""

    def __init__(self) -> None:
        self.maps: dict[str, dict[str, int]] = {"O": {}, "S": {}, "M": {}}

    def __call__(self, kind: str, label: str) -> str:
        table = self.maps[kind]
        return kind + str(table.setdefault(label, len(table)))


def _no_ids(kind: str, label: str) -> str:
    return kind


def write_state(state: State, ids=_no_ids) -> str:
    """One `S` line."""
    fields = [ids("S", state.label), state.label]
    if state.related:
        fields.append(f"[{state.related}]")
    if state.ingredients:
        fields.append("{" + ",".join(state.ingredients) + "}")
    return "\t".join(fields) + "\n"


def write_node(node: ObjectNode, ids=_no_ids) -> str:
    """An `O` line and its `S` lines."""
    fields = [ids("O", node.label), node.label, str(node.motion_flag)]
    if node.dish is not None:
        fields.append(str(node.dish))
    if node.goal:
        fields.append("!")
    return "\t".join(fields) + "\n" + "".join(write_state(s, ids) for s in node.states)


def write_motion(motion: Motion, ids=_no_ids) -> str:
    """One `M` line (times kept when known)."""
    label = motion.label + ("*" if motion.composite else "")
    fields = [ids("M", motion.label), label]
    if motion.start is not None:
        fields += [motion.start, motion.end or motion.start]
    return "\t".join(fields) + "\n"


def write_unit(unit: FunctionalUnit, ids=_no_ids, provenance: bool = False) -> str:
    """A unit followed by its `//` separator."""
    head = ""
    if provenance:
        head = "".join(f"# from {escape_text(s.path)}:{s.line}"
                       + (f" (expanded from {escape_text(s.expanded_from)})" if s.expanded_from else "") + "\n"
                       for s in unit.sources)
    return (
        head
        + "".join(write_node(n, ids) for n in unit.inputs)
        + write_motion(unit.motion, ids)
        + "".join(write_node(n, ids) for n in unit.outputs)
        + "//\n"
    )


def write_units(units: Iterable[FunctionalUnit], *, with_ids: bool = False, provenance: bool = False,
                header: str = "") -> str:
    """FOON text for a sequence of units (a network or a task tree)."""
    ids = _Ids() if with_ids else _no_ids
    head = "".join(f"# {escape_text(line)}\n" for line in header.split("\n"))
    return head + "//\n" + "".join(write_unit(u, ids, provenance) for u in units)


def write_foon(foon: Foon, *, with_ids: bool = False, provenance: bool = False, header: str = "") -> str:
    """Canonical FOON text of a network."""
    return write_units(foon.units, with_ids=with_ids, provenance=provenance, header=header)
