"""How a message writes a count with its noun (`1 unit`, `2 units`), a cut list and a list in prose (`a, b and c`):
one way for every module.

Messages once wrote `1 units`, `1 objects`, `1 plan steps` or `1 unit(s)`; every count a command prints
goes through `count` (or `plural` when the number is written apart from its noun). A list cut short goes
through `first_of`, so it never reads as the whole.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TypeVar

__all__ = ["count", "first_of", "plural", "prose_list"]

T = TypeVar("T")

#: Endings whose plural adds `es` (`match` -> `matches`).
_ES = ("s", "x", "z", "ch", "sh")


def plural(n: int, noun: str) -> str:
    """`noun` as a count of `n` takes it: singular for exactly one, else its plural (the last word takes the
    ending: `plan step` -> `plan steps`; a consonant's `y` -> `ies`; `s`, `x`, `z`, `ch`, `sh` -> `es`)."""
    if n == 1 or not noun:
        return noun
    if noun.endswith("y") and noun[-2:-1] not in ("", *"aeiou"):
        return noun[:-1] + "ies"
    return noun + ("es" if noun.endswith(_ES) else "s")


def count(n: int, noun: str, *, grouped: bool = False) -> str:
    """`n noun(s)` as a sentence says it: `1 unit`, `0 units`, `1,845 units` with `grouped` (thousands separated)."""
    return f"{n:,} {plural(n, noun)}" if grouped else f"{n} {plural(n, noun)}"


def first_of(items: Sequence[T], limit: int, show: Callable[[T], str] = str, *, sep: str = "; ",
             total: int | None = None) -> str:
    """`items` joined by `sep`, only the first `limit` of them (each as `show` writes it: only those shown are
    written), then `... (N more)` when some are left out. `total`: how many there are in all, when `items` is
    already a cut (a defect keeps its first places and their count).

    >>> first_of(["a", "b", "c"], 2)
    'a; b; ... (1 more)'
    >>> first_of(["a", "b"], 5, sep=", ", total=4)
    'a, b, ... (2 more)'
    """
    shown = items[:limit]
    left = (len(items) if total is None else total) - len(shown)
    return sep.join(map(show, shown)) + (f"{sep}... ({left} more)" if left > 0 else "")


def prose_list(items: Sequence[str]) -> str:
    """`items` as prose lists them: `a`, `a and b`, `a, b and c` (the recipe words and the kitchen additions of
    `retrieve`'s explanation say a list so).

    >>> prose_list(["a", "b", "c"])
    'a, b and c'
    """
    return (", ".join(items[:-1]) + " and " if len(items) > 1 else "") + items[-1]
