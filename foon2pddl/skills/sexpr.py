"""S-expressions of PDDL text, with the line each list starts on and its span in the text.

PDDL is case-insensitive: symbols are lower-cased; `;` starts a comment to the end of
the line. `parse` returns the top-level lists; an unbalanced parenthesis is a
`SexprError` naming the line. Linear in the text's length.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["SList", "SexprError", "parse", "typed_list"]

_TOKEN = re.compile(r";[^\n]*|\(|\)|[^\s();]+|\s+")


class SexprError(ValueError):
    """Text that is not a balanced s-expression; `line` is 1-based."""

    def __init__(self, line: int, message: str) -> None:
        super().__init__(message)
        self.line = line


@dataclass(frozen=True)
class SList:
    """A parenthesized list: its items (symbols as lower-cased str, or SList), first line, and text span."""

    items: tuple
    line: int
    start: int
    end: int

    @property
    def head(self) -> str | None:
        """The first item when it is a symbol (`and`, `:action`, a predicate name)."""
        return self.items[0] if self.items and isinstance(self.items[0], str) else None

    def __len__(self) -> int:
        return len(self.items)

    def __getitem__(self, k):
        return self.items[k]


def parse(text: str) -> tuple[SList, ...]:
    """The top-level lists of `text` (symbols outside any list are an error)."""
    stack: list[tuple[list, int, int]] = []
    top: list[SList] = []
    line = 1
    for m in _TOKEN.finditer(text):
        tok = m.group()
        if tok == "(":
            stack.append(([], line, m.start()))
        elif tok == ")":
            if not stack:
                raise SexprError(line, "unbalanced ')'")
            items, first, start = stack.pop()
            node = SList(tuple(items), first, start, m.end())
            (stack[-1][0] if stack else top).append(node)
        elif tok[0] == ";" or tok.isspace():
            pass
        elif stack:
            stack[-1][0].append(tok.lower())
        else:
            raise SexprError(line, f"unexpected {tok!r} outside any list")
        line += tok.count("\n")
    if stack:
        raise SexprError(stack[-1][1], "a '(' opened here is never closed")
    return tuple(top)


def typed_list(items) -> list[str]:
    """The symbols of a typed list (`?a ?b - phase ?h - hand`), with `- type` folded: [(name, type)]."""
    out, pending = [], []
    it = iter(items)
    for x in it:
        if x == "-":
            typ = next(it, "object")
            out += [(p, typ if isinstance(typ, str) else "object") for p in pending]
            pending = []
        elif isinstance(x, str):
            pending.append(x)
    out += [(p, "object") for p in pending]
    return out
