"""JSON text in, with every failure a located `FoonSyntaxError`, and label text checks.

`load_json` turns what `json.loads` can raise on hostile input into errors naming
the line: invalid JSON, nesting too deep for the decoder (RecursionError), and
integers longer than Python's int-string limit (ValueError). A key given twice in
one object is an error too (`json.loads` keeps the last value silently: a second
`"without_motions": []` would drop a ban); its line is found by `_duplicate_line`,
a linear re-scan run only on that error. `line_of` finds the
line of an item by its path of keys and indexes (a re-parse, only on error;
`decode_tracked` gives every object's and list's offset).
`text_problem` says why a string cannot be a label: a control character or a lone
surrogate (JSON's `"\\ud800"` decodes to one; it can be written to no UTF-8 file).
"""

from __future__ import annotations

import json
import json.scanner
import re
from typing import Any

from ..errors import FoonSyntaxError
from .foon_lines import CONTROL_CHARS, MAX_INT_DIGITS

_SURROGATE = re.compile(r"[\ud800-\udfff]")
_KEY_OR_BRACKET = re.compile(r'"(?:[^"\\]|\\.)*"|[{}\[\]]')
_COLON = re.compile(r"\s*:")
#: JSON strings and numbers, left to right (linear: no nested quantifiers).
_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?')


class _LongInt(ValueError):
    """An integer token longer than MAX_INT_DIGITS."""


class _DuplicateKey(ValueError):
    """A key given twice in one JSON object."""

    def __init__(self, key: str) -> None:
        super().__init__(key)
        self.key = key


def _unique_pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out = dict(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        for key, _ in pairs:
            if key in seen:
                raise _DuplicateKey(key)
            seen.add(key)
    return out


def _bounded_int(token: str) -> int:
    if len(token.lstrip("-").lstrip("0")) > MAX_INT_DIGITS:
        raise _LongInt(token)
    return int(token)


def _long_int_line(text: str) -> int:
    """Line of the first integer token (outside strings) longer than MAX_INT_DIGITS."""
    for m in _TOKEN.finditer(text):
        token = m.group()
        if token[0] != '"' and not any(c in token for c in ".eE") and len(token.lstrip("-0")) > MAX_INT_DIGITS:
            return text.count("\n", 0, m.start()) + 1
    return 1


def _duplicate_line(text: str) -> int:
    """Line of the first key that repeats a key of its own object (1 when none is found).

    One pass over the string tokens and brackets (linear): a stack holds the keys of each open
    object; a string followed by `:` is a key of the innermost object.
    """
    stack: list[set[str] | None] = []  # per open bracket: the object's keys so far, None for a list
    for m in _KEY_OR_BRACKET.finditer(text):
        token = m.group()
        if token in "{[":
            stack.append(set() if token == "{" else None)
        elif token in "}]":
            if stack:
                stack.pop()
        elif stack and stack[-1] is not None and _COLON.match(text, m.end()):
            try:
                key = json.loads(token)
            except ValueError:
                continue
            if key in stack[-1]:
                return text.count("\n", 0, m.start()) + 1
            stack[-1].add(key)
    return 1


def load_json(text: str, path: str) -> Any:
    """`json.loads(text)`; every failure is a FoonSyntaxError naming `path` and the line;
    a key repeated in one object is one (`_DuplicateKey`)."""
    try:
        return json.loads(text, parse_int=_bounded_int, object_pairs_hook=_unique_pairs)
    except _DuplicateKey as exc:
        raise FoonSyntaxError(path, _duplicate_line(text), f"duplicate key {exc.key!r} in one JSON object "
                                                           "(which value was meant?)") from None
    except json.JSONDecodeError as exc:
        raise FoonSyntaxError(path, exc.lineno, f"invalid JSON: {exc.msg} (column {exc.colno})") from None
    except RecursionError:
        raise FoonSyntaxError(path, 1, "invalid JSON: nested too deeply") from None
    except _LongInt as exc:
        digits = len(str(exc).lstrip("-").lstrip("0"))
        raise FoonSyntaxError(path, _long_int_line(text),
                              f"integer with {digits} digits (at most {MAX_INT_DIGITS} are read)") from None


def key_line(text: str, key: str) -> int:
    """1-based line of the first occurrence of `"key"` (1 when not found)."""
    at = text.find(json.dumps(key))
    return text.count("\n", 0, at) + 1 if at >= 0 else 1


def unknown_key(keys, allowed, within: str = "", meant: str | None = None) -> tuple[str, str] | None:
    """The first of `keys` (a JSON object's) not in `allowed`, with the words every reader of a JSON file says it in
    (`unknown key 'state' (expected one of ...)`: a typo must not drop what it holds without a word), else None.
    `within` names the kind of object (`unknown key 'colour' in state`), `meant` the allowed key a typo stands for
    (`: did you mean 'states'?`)."""
    for key in keys:
        if key not in allowed:
            return key, (f"unknown key {key!r}" + (f" in {within}" if within else "")
                         + (f": did you mean {meant!r}?" if meant else "") + f" (expected one of {', '.join(allowed)})")
    return None


def text_problem(value: str, what: str) -> str | None:
    """Why `value` cannot be label text (`what` names it in the message), else None."""
    if CONTROL_CHARS.search(value):
        return f"control character in {what}"
    m = _SURROGATE.search(value)
    if m:
        return f"lone surrogate U+{ord(m.group()):04X} in {what} (not Unicode text)"
    return None


def line_of(text: str, where: tuple[str | int, ...]) -> int:
    """Line of the deepest JSON object or list on the path `where` (re-parses, only on error)."""
    node, starts = decode_tracked(text)
    pos = starts.get(id(node), 0)
    for step in where:
        try:
            node = node[step]
        except (KeyError, IndexError, TypeError):
            break
        pos = starts.get(id(node), pos)
    return text.count("\n", 0, pos) + 1


def item_lines(text: str) -> list[int]:
    """1-based line of each item of the top-level JSON list `text` holds (where the item starts; one
    decode and a binary search per item, for messages about valid files)."""
    from bisect import bisect_left

    data, starts = decode_tracked(text)
    breaks = [m.start() for m in re.finditer("\n", text)]
    return [bisect_left(breaks, starts.get(id(item), 0)) + 1 for item in data] if isinstance(data, list) else []


def decode_tracked(text: str) -> tuple[Any, dict[int, int]]:
    """The decoded value and the start offset of every object and list in it (by id); (None, {})
    when the text does not decode."""
    starts: dict[int, int] = {}
    decoder = json.JSONDecoder(parse_int=_bounded_int)
    parse_object, parse_array = decoder.parse_object, decoder.parse_array

    def tracked_object(s_and_end, *args):
        value, end = parse_object(s_and_end, *args)
        starts[id(value)] = s_and_end[1] - 1
        return value, end

    def tracked_array(s_and_end, *args):
        value, end = parse_array(s_and_end, *args)
        starts[id(value)] = s_and_end[1] - 1
        return value, end

    decoder.parse_object, decoder.parse_array = tracked_object, tracked_array
    decoder.memo = {}
    decoder.scan_once = json.scanner.py_make_scanner(decoder)
    try:
        return decoder.decode(text), starts
    except (ValueError, RecursionError):
        return None, {}
