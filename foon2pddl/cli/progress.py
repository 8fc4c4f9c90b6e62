"""No silent waits: a step that takes longer than `AFTER` seconds says on stderr what it is doing.

`slow_step(what)` wraps a step. A watcher thread waits `AFTER` seconds for it; a
step done by then prints nothing (fast runs keep their output). Otherwise it
prints `what ...` at once; on a terminal the line then counts the seconds and ends
with the step's time, and in a log it is one line. Only the message goes to stderr,
never to stdout, so outputs stay byte-identical however slow the machine is.
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

import click

#: Seconds a step may run silently.
AFTER = 2.0


@contextmanager
def slow_step(what: str, after: float | None = None) -> Iterator[None]:
    """Say `what ...` on stderr if the wrapped step is still running after `after` seconds (default
    `AFTER`; 0: always, at once) (module doc)."""
    after = AFTER if after is None else after
    done = threading.Event()
    tty = sys.stderr.isatty()

    def watch() -> None:
        if after > 0 and done.wait(after):
            return
        start = time.monotonic() - after
        if not tty:
            click.echo(f"{what} ...", err=True)
            return
        click.echo(f"{what} ...", err=True, nl=False)
        while not done.wait(1.0):
            click.echo(f"\r{what} ... {time.monotonic() - start:.0f} s", err=True, nl=False)
        click.echo(f"\r{what}: {time.monotonic() - start:.1f} s", err=True)

    watcher = threading.Thread(target=watch, name="slow-step", daemon=True)
    watcher.start()
    try:
        yield
    finally:
        done.set()
        watcher.join()
