"""Slow steps told from below: a layer that runs something long takes a `Step` and wraps each long part in it.

The command passes `cli.progress.slow_step`, which says on stderr what a step does when it runs long;
the Python API and `--no-progress` pass `silent_step`. Lower layers never print themselves.
"""

from __future__ import annotations

from contextlib import AbstractContextManager, nullcontext
from typing import Protocol


class Step(Protocol):
    """A context manager factory around a slow step, given what the step does (`cli.progress.slow_step`)
    and, for the shares of one long computation run one after another, the name of that series (one
    redrawn line on a terminal)."""

    def __call__(self, what: str, *, series: str | None = None) -> AbstractContextManager[None]: ...


def silent_step(what: str, *, series: str | None = None) -> AbstractContextManager[None]:
    """No message (`--no-progress`, the Python API)."""
    return nullcontext()
