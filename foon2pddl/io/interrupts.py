"""Interrupts: SIGTERM handled like SIGINT, and short sections that no interrupt may split.

Python turns SIGINT into KeyboardInterrupt, so `finally` blocks and context
managers remove temporary files and kill planner processes. SIGTERM's default
action kills the process outright and skips all of that; `sigterm_raises` makes
it raise `Terminated` (a KeyboardInterrupt) instead, so both take the same
cleanup paths. `signals_deferred` holds SIGINT and SIGTERM back (signal mask)
across a few statements such as "create a temporary file, register it for
removal", which an interrupt landing between the two would otherwise leak.

A process forked while these handlers are installed (Dask's local workers,
engine processes) gets the default actions back at once (`_forked_child`): the
handlers serve the command's own cleanup, and `pkill -f`, which also signals
forked children (same command line), must end them quietly, not print a
`Terminated` traceback from each.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager

_HELD = {signal.SIGINT, signal.SIGTERM}
#: Seconds after which an interrupt raised where it could not propagate is sent again (`_redeliver`).
REDELIVERY_DELAY = 0.05


class Terminated(KeyboardInterrupt):
    """SIGTERM received (raised where KeyboardInterrupt would be, so the same cleanup runs)."""


def _raise_terminated(signum: int, frame: object) -> None:
    raise Terminated()


def carried_interrupt(exc: BaseException) -> KeyboardInterrupt | None:
    """The interrupt `exc` is, or carries as its cause: Python 3.11 wraps an exception raised in `__set_name__`
    in a RuntimeError ("Error calling __set_name__"), so a signal landing while a class with dataclass `field()`
    defaults is created (a module the command imports lazily) arrives as one. None for any other exception."""
    while isinstance(exc, RuntimeError) and exc.__cause__ is not None:
        exc = exc.__cause__
    return exc if isinstance(exc, KeyboardInterrupt) else None


def interrupt_exit(exc: BaseException) -> tuple[str, int] | None:
    """The line to print and the exit status when `exc` is (or carries) an interrupt: `interrupted`, 130 for
    SIGINT, `terminated`, 143 for SIGTERM (the shell's 128 + signal number); None for any other exception.
    The CLI and `python -m bench` end on an interrupt this one way."""
    interrupt = carried_interrupt(exc)
    if interrupt is None:
        return None
    return ("terminated", 143) if isinstance(interrupt, Terminated) else ("interrupted", 130)


def _main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


def _redeliver(unraisable) -> None:
    """`sys.unraisablehook` from the program's start: an interrupt raised inside a weak-reference callback or a
    finalizer (the garbage collector, or importlib's module locks, ran one just as the signal came) cannot
    propagate; Python would print it and lose it. It is sent again from another thread a moment later, so its
    handler runs once the callback has returned (should it land in another callback, this repeats), and the
    command ends as for any interrupt."""
    exc = unraisable.exc_value
    if isinstance(exc, _SignalExit):
        signum = exc.signum
    elif isinstance(exc, KeyboardInterrupt):
        signum = signal.SIGTERM if isinstance(exc, Terminated) else signal.SIGINT
    else:
        sys.__unraisablehook__(unraisable)
        return
    again = threading.Timer(REDELIVERY_DELAY, os.kill, (os.getpid(), signum))
    again.daemon = True
    again.start()


@contextmanager
def sigterm_raises() -> Iterator[None]:
    """While inside, SIGINT raises KeyboardInterrupt and SIGTERM `Terminated` in the main thread
    (the previous handlers are restored on the way out); one raised where it cannot propagate is sent again
    (`_redeliver`)."""
    if not _main_thread():
        yield
        return
    previous = {signal.SIGINT: signal.signal(signal.SIGINT, signal.default_int_handler),
                signal.SIGTERM: signal.signal(signal.SIGTERM, _raise_terminated)}
    hook, sys.unraisablehook = sys.unraisablehook, _redeliver
    try:
        yield
    finally:
        sys.unraisablehook = hook
        for signum, handler in previous.items():
            signal.signal(signum, handler)


class _SignalExit(SystemExit):
    """The exit (status 128 + signal number) of a signal that came before a command's handling began."""

    def __init__(self, signum: int) -> None:
        super().__init__(128 + signum)
        self.signum = signum


def _exit_quietly(signum: int, frame: object) -> None:
    raise _SignalExit(signum)


def exit_on_signals() -> None:
    """Until a command installs its own handling: SIGINT and SIGTERM exit 130 and 143, without a
    traceback (for the program's start, while modules load, and its end)."""
    for signum in _HELD:
        signal.signal(signum, _exit_quietly)
    sys.unraisablehook = _redeliver


def _forked_child() -> None:
    """In a child forked while the command's handlers are installed: SIGINT and SIGTERM back to their
    default actions (the parent, which holds the handlers' cleanup, ends its children itself)."""
    if signal.getsignal(signal.SIGTERM) in (_raise_terminated, _exit_quietly):
        for signum in _HELD:
            signal.signal(signum, signal.SIG_DFL)


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forked_child)


@contextmanager
def signals_deferred() -> Iterator[None]:
    """Deliver SIGINT and SIGTERM only after the block (main thread; elsewhere nothing to defer)."""
    if not _main_thread():
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)
