"""Network-sized builds hold back the cyclic garbage collector's full collections.

Loading a network and building its indexes allocate millions of long-lived objects and
no reference cycles. A full collection walks every tracked object; CPython starts one
whenever the objects that survived since the last one exceed a quarter of the heap, so
during a build that keeps growing the heap, full collections rescan the whole network
again and again (the index of a 30k-unit network took twice as long with them; the first
retrieval on 100k units, four times). Disabling the collector instead leaves one huge
young generation to scan afterwards, which is slow too. So builds keep young collections
and hold back full ones; the next full collection after the build walks the heap once,
which keeps every build linear in the network's size.
"""

from __future__ import annotations

import functools
import gc
from collections import deque
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TypeVar

F = TypeVar("F", bound=Callable)

_NEVER = 1 << 30

#: Run an iterator to its end, keeping nothing: `drain(map(f, xs))` is a loop calling `f` in C.
drain = functools.partial(deque, maxlen=0)


#: Set by a process that keeps what it builds until it exits (the CLI's entry point, `foon2pddl.__main__`):
#: builds then run with the collector off and move what exists at their end to the permanent generation
#: (`gc.freeze`), so that no collection ever scans the network again, young ones included (on a 1M-unit
#: network they took ~10 % of loading and indexing). Garbage cycles made during a build are then never
#: collected; builds make none, and the process ends with the command.
KEEP_BUILDS = False


@contextmanager
def full_gc_paused() -> Iterator[None]:
    """Hold back full collections inside the block (young ones keep running); nests; thresholds restored after.
    Under `KEEP_BUILDS`: no collection inside the block, what exists after it frozen."""
    if KEEP_BUILDS:
        if not gc.isenabled():  # nested, or the collector is off anyway
            yield
            return
        gc.disable()
        try:
            yield
        finally:
            gc.freeze()
            gc.enable()
        return
    thresholds = gc.get_threshold()
    gc.set_threshold(thresholds[0], thresholds[1], _NEVER)
    try:
        yield
    finally:
        gc.set_threshold(*thresholds)


def bulk(fn: F) -> F:
    """Decorator: run `fn` under `full_gc_paused` (for functions that build network-sized structures)."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with full_gc_paused():
            return fn(*args, **kwargs)

    return wrapper  # type: ignore[return-value]
