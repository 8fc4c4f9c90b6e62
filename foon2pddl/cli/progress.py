"""No silent waits: no command goes `AFTER` seconds without a line on stderr saying what it does.

`slow_step(what)` wraps a step. A watcher thread waits until the command has been
silent for `AFTER` seconds: counted from the command's start (the process's, when
run as `foon2pddl`), or from the end of the last step that said what it did (through
a pipe, which has no closing line, from that step's last line: its call may go on for up
to `BEAT` seconds after it), so that several short steps in a row cannot add up to a long silence. A step done by
then prints nothing (fast runs keep their output). Otherwise it prints `what ...`
at once; on a terminal the line then counts the seconds and ends with the step's
time; in a log, which has no line that counts, it adds a line with its seconds every `BEAT` seconds
(a step said once, then silent for its whole length, left a log 16 s without a line: stop 54's pass).
Only the message goes to stderr, never to stdout, so outputs stay byte-identical however slow the machine is. A line printed
by other means (a note) is not seen here: after one, a step may speak up early.

A series of steps (`series=NAME`: the shares of one long computation, run one after another with
nothing printed between them) is one line on a terminal: once a step of the series has spoken, the
next ones speak at once and redraw that line (cursor up, clear), its seconds counting from the
series's first line, so the terminal keeps the last share's line and the series's time, not a line
per share. In a log each step is a line of its own, as above.

Work outside every step is silent: a slow stretch gets its own step (`python -m
bench.silence` measures every documented command). Lower layers that have slow
steps take a `step` callable (this one, passed down by the command) rather than
printing themselves.
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import click

#: Seconds a command may stay silent before the step it is in says what it is: a second under the 2 s floor, for
#: a wake-up that waits for the interpreter lock while a long call in C holds it (0.88 s late once at load 8.7;
#: at 1.5 s that left a gap of 2.38 s).
AFTER = 1.0
#: Through a pipe, seconds between the lines a said step adds while it runs (its seconds so far): as `AFTER`, the
#: same margin (at 2.0 s, gaps of 2.1-2.2 s at load 16-19; at 1.5 s, one of 2.38 s at load 8.7).
BEAT = 1.0
#: On a terminal: back to the start of the line and clear it (a shorter text leaves nothing behind).
_REDRAW = "\r\x1b[K"
#: On a terminal: up to the line a finished step left, and clear it (the next step of its series redraws it).
_REDRAW_ABOVE = "\x1b[A" + _REDRAW

#: Since when (time.monotonic) the running command has said nothing a step knows of; None: a step is
#: saying what it does now, or no command runs (a step then counts from its own start).
_quiet_since: float | None = None
#: When this process started the command-line interface (set by the console script), for its first command.
_process_start: float | None = None
#: On a terminal: (series, when its first line was drawn) of the finished step whose line is the last a
#: step printed; None when another step spoke since (its series's next step then starts a new line).
_series_line: tuple[str, float] | None = None


def process_started(at: float) -> None:
    """Record the process's start (the console script's first line), so the first command counts from it."""
    global _process_start
    _process_start = at


def begin() -> None:
    """A command starts: its silence counts from now (from the process's start for the first one)."""
    global _quiet_since, _process_start, _series_line
    _quiet_since = time.monotonic() if _process_start is None else _process_start
    _process_start = None
    _series_line = None


@contextmanager
def slow_step(what: str | Callable[[], str], after: float | None = None, *,
              series: str | None = None) -> Iterator[threading.Event]:
    """Say `what ...` on stderr if the wrapped step is still running once the command has been silent
    for `AFTER` seconds, or (when given) after `after` seconds of the step (0: always, at once)
    (module doc). `what` may be a callable, read when the line is printed: a step whose plan changes
    midway (a fallback its own note announced) says what it does then, not what it set out to do.
    `series`: the name of the series of steps this one belongs to (one redrawn line on a terminal).
    Yields an event set once the line is said (a caller may close a said step with what it found)."""
    text = what if callable(what) else lambda: what
    global _quiet_since
    start = time.monotonic()
    tty = sys.stderr.isatty()
    above = _series_line if tty and series is not None and _series_line and _series_line[0] == series else None
    if above is not None:
        after = 0.0  # the series's line is on screen: keep it current
    elif after is None:
        since = start if _quiet_since is None else _quiet_since
        after = max(0.0, since + AFTER - start)
    done, said = threading.Event(), threading.Event()
    first = start if above is None else above[1]  # a series's line counts from its first step's start
    last_line: list[float] = []  # through a pipe, when a said step said its last line (no closing line follows)

    def watch() -> None:
        global _quiet_since, _series_line
        if after > 0 and done.wait(after):
            return
        said.set()
        _quiet_since = None
        _series_line = None
        if not tty:
            click.echo(f"{text()} ...", err=True)
            last_line.append(time.monotonic())
            while not done.wait(BEAT):
                click.echo(f"{text()} ... {time.monotonic() - first:.0f} s", err=True)
                last_line.append(time.monotonic())
            return
        click.echo(f"{_REDRAW_ABOVE if above else ''}{text()} ...", err=True, nl=False)
        while not done.wait(1.0):
            click.echo(f"{_REDRAW}{text()} ... {time.monotonic() - first:.0f} s", err=True, nl=False)
        click.echo(f"{_REDRAW}{text()}: {time.monotonic() - first:.1f} s", err=True)
        if series is not None:
            _series_line = (series, first)

    watcher = threading.Thread(target=watch, name="slow-step", daemon=True)
    watcher.start()
    try:
        yield said
    finally:
        done.set()
        watcher.join()
        if said.is_set():  # its line no longer says what the command does: silent since its last line
            _quiet_since = last_line[-1] if last_line else time.monotonic()  # a terminal's closing line: its end


def inputs(paths) -> str:
    """What a step reads, for its message: up to three PATHS, or the embedded example."""
    if not paths:
        return "the embedded example"
    return ", ".join(str(p) for p in paths[:3]) + (" ..." if len(paths) > 3 else "")
