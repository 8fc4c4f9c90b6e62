"""The cyclic garbage collector during a run: off while the networks and trials are built, then
everything built frozen (`gc.freeze`), so no later collection walks it again.

The networks are millions of long-lived objects and none of them is garbage: while FOON-EXP is
built, the collector's full passes over them find nothing and cost about a fifth of the build
(0.4 s of 1.6 s on the shared subgraphs), and each full pass later (records arriving, a report
being drawn) walks them again. Frozen before the workers are forked, they also stay out of the
workers' collections (the recipe in the `gc.freeze` documentation). When the run ends the objects
are unfrozen and the collector is as it was, so a long-lived process (a notebook, the tests) keeps
collecting them once they are dropped. The `experiment` command freezes them again, with the network
views its report needs, until the report is written (`cli/experiment_cmd.py`), and draws the report with
full collections held back (`model.bulk.full_gc_paused`): the report's own objects are not walked either.
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterator
from contextlib import contextmanager


@contextmanager
def building() -> Iterator[Callable[[], None]]:
    """Collector off inside; the function it gives (`settle`) freezes what exists and turns the
    collector back on (call it once the networks are built, before any worker is forked)."""
    enabled = gc.isenabled()
    frozen = False

    def settle() -> None:
        nonlocal frozen
        if not frozen:
            gc.freeze()
            frozen = True
        if enabled:
            gc.enable()

    gc.disable()
    try:
        yield settle
    finally:
        if frozen:
            gc.unfreeze()
        if enabled:
            gc.enable()

