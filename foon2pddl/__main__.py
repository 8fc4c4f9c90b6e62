"""`python -m foon2pddl` and the `foon2pddl` console script."""

from __future__ import annotations

import sys


def run() -> None:
    """Exit 130/143 on SIGINT/SIGTERM even while the CLI's modules load, then run the CLI."""
    import time

    started = time.monotonic() - process_age()  # no command may stay silent long, counted from here (cli.progress)
    early = _Loading(started)
    from .io.interrupts import exit_on_signals

    exit_on_signals()
    from .cli import main, progress
    from .model import bulk
    from .planners import cleanup

    progress.process_started(early.stop())

    cleanup.SPARE_HELPERS = False  # this process ends with the command: nothing it started may stay
    bulk.KEEP_BUILDS = True  # ... and keeps its network until then: no collection rescans it
    try:
        main()
    except SystemExit as exc:
        leave(exc.code)
    leave(0)


#: Seconds of silence from the process's start after which the console script says it is loading (the CLI's
#: `progress.AFTER`, which cannot be imported before the CLI loads; a test checks they agree).
LOADING_AFTER = 1.0


class _Loading:
    """Says `loading foon2pddl ...` on stderr if the package's own modules are still loading `LOADING_AFTER`
    seconds after the process started. Before `foon2pddl.cli` (click, the command group) has loaded, no step of
    `cli.progress` exists to speak: at load 23 the interpreter and that import took 2.05 s of wall time for 0.09 s
    of CPU, silent. A thread of the standard library alone, started first thing."""

    def __init__(self, started: float) -> None:
        import threading
        import time

        self._started, self._said = started, None
        self._lock, self._done = threading.Lock(), threading.Event()
        wait = max(0.0, started + LOADING_AFTER - time.monotonic())
        threading.Thread(target=self._watch, args=(wait,), name="loading", daemon=True).start()

    def _watch(self, wait: float) -> None:
        import time

        if self._done.wait(wait):
            return
        with self._lock:
            if self._done.is_set():
                return
            sys.stderr.write("loading foon2pddl ...\n")
            sys.stderr.flush()
            self._said = time.monotonic()

    def stop(self) -> float:
        """Stop watching; since when the command has been silent: the line's time if it was said, else the start."""
        with self._lock:
            self._done.set()
            return self._started if self._said is None else self._said


def process_age() -> float:
    """Seconds since this process started: the interpreter's own start-up (0.3 s on a 2-core host at load 16,
    more under heavier load) comes before any line of ours, and the user waits through it too. Linux: the start
    time in `/proc/self/stat` (clock ticks since boot) against CLOCK_BOOTTIME; 0.0 where that cannot be read."""
    import os
    import time

    try:
        with open("/proc/self/stat", "rb") as stat:
            ticks = int(stat.read().rsplit(b")", 1)[1].split()[19])  # field 22, starttime; the name may hold spaces
        return max(0.0, time.clock_gettime(time.CLOCK_BOOTTIME) - ticks / os.sysconf("SC_CLK_TCK"))
    except (OSError, ValueError, IndexError, AttributeError):
        return 0.0


def leave(code: object) -> None:
    """End the process as the interpreter would, without its teardown.

    The interpreter's shutdown frees every object one at a time: after an experiment (FOON-EXP
    has ~18,000 units, each network view is cached) that alone took ~1 s. A CLI process has nothing
    left to free, so this does what the shutdown does that matters (joins non-daemon threads, runs
    the atexit handlers: Dask's, multiprocessing's, logging's; flushes stdout and stderr) and leaves
    with `os._exit`. Anything unusual (no `threading._shutdown`, a stream that cannot be flushed)
    falls back to the ordinary exit, which reports it as always.
    """
    import atexit
    import os
    import threading

    shutdown = getattr(threading, "_shutdown", None)
    if shutdown is None:
        raise SystemExit(code)
    shutdown()
    atexit._run_exitfuncs()
    if code is not None and not isinstance(code, int):
        print(code, file=sys.stderr)  # what the interpreter does with a non-integer exit code
        code = 1
    try:
        for stream in (sys.stdout, sys.stderr):
            if stream is not None and not stream.closed:
                stream.flush()
    except OSError as exc:
        from .cli import output_failed  # standard output's device is full: an error, not a traceback

        output_failed(exc)
        os._exit(2)
    except ValueError:
        raise SystemExit(code) from None
    os._exit((code or 0) & 0xFF)


if __name__ == "__main__":
    run()
