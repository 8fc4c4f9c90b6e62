"""One line of FOON text: what kind of line it is and what its fields say (shared by the network reader,
`parser`, and the readers of kitchen and goal files, `parse_objects`).

Each function checks only what the line itself shows and reports a problem through `fail(message)`,
which returns the exception to raise: a `FoonSyntaxError` naming the file and line, or, inside the
block reader, an exception that hands the text to the line reader.
"""

from __future__ import annotations

import re

from ..errors import FoonSyntaxError
from ..model.foon import Motion, ObjectNode, State, make_node, make_state, normalize_label

#: the head of a FOON line: `O`, `S` or `M` and an optional id.
LINE_ID = re.compile(r"[OSM]\d*")
#: A FOON line head followed by spaces where the format has a tab (`O bowl 0`, `S2 contains {egg}`).
_SPACED = re.compile(r"[OSM]\d* +\S")
CONTROL_CHARS = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
_INT = re.compile(r"\d+")
#: Longest integer read (Python's default int-string limit): longer ones are errors, never ValueError.
MAX_INT_DIGITS = 4300
#: A motion line where a list of objects (a kitchen, a goal) is read: the file is a network (PATHS).
NETWORK_NOT_OBJECTS = "a motion line ('M'): this file is a FOON network of functional units, not a list of objects"


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
    fields = list(map(str.strip, stripped.split("\t")))
    head = fields[0]
    kind = head[:1]
    if kind not in "OSM" or not LINE_ID.fullmatch(head):
        if _SPACED.match(head):  # `O bowl 0`: a FOON line typed with spaces, not the format's tabs
            raise fail(f"'{kind}' line with its fields separated by spaces: FOON separates them with tabs "
                       f"(expected '{kind}<id><TAB><label>')")
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
    return [item for item in map(str.strip, body.split(",")) if item]


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


#: A state line of the usual shapes (`S<id>`, a label, then at most a `[related]` and an `{ingredient, ...}`
#: field, in that order, with no control character, stray space, bracket or brace): label, related, ingredients.
_PLAIN_STATE = re.compile(r"S\d*\t([^\t\[\]{}\x00-\x1f\x7f]+)(?:\t\[([^\t\[\]{},\x00-\x1f\x7f]*)\])?"
                          r"(?:\t\{([^\t\[\]{}\x00-\x1f\x7f]*)\})?")


def plain_state(raw: str) -> State | None:
    """The state of a state line of the usual shapes (`_PLAIN_STATE`), or None for any other line (which
    `_classify` and `_parse_state` then read, or reject with their messages). One regular expression instead of
    their field-by-field checks; the same state they make (`make_state` normalizes and sorts)."""
    match = _PLAIN_STATE.fullmatch(raw)
    if match is None:
        return None
    label, related, body = match.groups()
    if not label.strip() or (related is not None and not related.strip()):
        return None  # no label, or `[ ]`: the field-by-field reader says what it is
    return make_state(label, related or "", body.split(",") if body else ())


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
        if head[:1] == "M" and LINE_ID.fullmatch(head):
            raise FoonSyntaxError(path, lineno, NETWORK_NOT_OBJECTS, line, ("paths",))
        if head[:1] not in "OS" or not LINE_ID.fullmatch(head):
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
