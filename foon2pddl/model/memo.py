"""Results remembered per network object, for as long as that object lives.

A `Foon` hashes by content (all its units), so caches key it by identity, with a weak
reference that drops the entry when the network is garbage-collected: the network's
indexes and kitchens are built once per `Foon` however many callers ask for them.
"""

from __future__ import annotations

import functools
import weakref
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeVar

if TYPE_CHECKING:  # pragma: no cover
    from .foon import Foon

T = TypeVar("T")
R = TypeVar("R")


def per_network(fn: Callable[..., T]) -> Callable[..., T]:
    """Decorator: `fn(foon)` computed once per network object (calls with more arguments are not remembered)."""
    cache: dict[int, tuple[weakref.ref, T]] = {}

    @functools.wraps(fn)
    def wrapper(foon, *args, **kwargs):
        if args or kwargs:
            return fn(foon, *args, **kwargs)
        key = id(foon)
        hit = cache.get(key)
        if hit is not None and hit[0]() is foon:
            return hit[1]
        value = fn(foon)
        cache[key] = (weakref.ref(foon, lambda _r, key=key: cache.pop(key, None)), value)
        return value

    wrapper.cache = cache  # type: ignore[attr-defined]
    return wrapper


def per_network_reading(read: Callable[[Foon], R],
                        rewrite: Callable[[Foon, R], Foon]) -> Callable[[Foon], tuple[Foon | None, R]]:
    """`foon -> (rewrite(foon, reading), reading)` with `reading = read(foon)`, once per network object: the
    network read another way where FOON's words say so, and the readings for the task's notes (`pddl.list_placed`,
    `pddl.list_arrivals`, `pddl.list_brought`, `pddl.mutual_lists`). The network is None when the reading is empty
    (falsy): a cached value holding the network it is keyed by would keep that key alive, never dropped."""

    def both(foon: Foon) -> tuple[Foon | None, R]:
        reading = read(foon)
        return (rewrite(foon, reading) if reading else None), reading

    return per_network(both)
