"""Results remembered per network object, for as long as that object lives.

A `Foon` hashes by content (all its units), so caches key it by identity, with a weak
reference that drops the entry when the network is garbage-collected: the network's
indexes and kitchens are built once per `Foon` however many callers ask for them.
"""

from __future__ import annotations

import functools
import weakref
from collections.abc import Callable
from typing import TypeVar

T = TypeVar("T")


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
