"""Progress of a long run: a tqdm bar on a terminal, a periodic line otherwise (logs, CI, nohup).

The bar is redrawn every second (its elapsed time counts while a slow cell runs). In
a log, a first line says how many cells will run; then a line says cells done of
planned, the rate since the start and the estimated time left, every `interval`
seconds and once at the end: `experiment: 1,200/3,000 cells (40.0 %), 85.3 cells/s, ETA 21 s`.
The lines come from a ticker thread, not from finished cells alone: a Dask task is a batch
(fd-tree's 100 goals of a trial and network), whose cells arrive together minutes later (a log
went 57 s without a line, stop 55). With a test's clock (not `time.monotonic`) `update` alone
prints them.

Batches run costliest first (`grid.plan_batches`), so a rate over cells alone predicts
the cheap cells at the rate of the costly ones (`ETA 42 min 47 s` 2 min 23 s into a 2-trial run
with `fd-relational` that took 5 min 01 s). Given `groups`
(the cells planned per solver and network), the estimate weighs each group's cells left
by that group's own work per cell (the cells' times), scaled by the run's wall time per
second of work so far (workers, load, start-up).
"""

from __future__ import annotations

import sys
import threading
import time
from collections import Counter
from collections.abc import Hashable, Mapping
from typing import IO

from ..errors import require

BAR = "bar"
LINES = "lines"
OFF = "off"

#: Seconds between two progress lines when stderr is not a terminal, from Python (`runner.run`'s `every`); the
#: command passes its beat (`cli.progress.BEAT`, 1 s: issue 24's floor, no 2 s without a line).
LINE_INTERVAL = 30.0
#: The estimated time left is shown once this share of the cells is done (and at least `ETA_MIN_CELLS`):
#: the first cells include start-up (workers, networks built per trial), and a rate from them
#: overstates the rest (an `ETA 2 h 01 min` for a run that took 80 s).
ETA_MIN_SHARE = 0.05
ETA_MIN_CELLS = 5
#: The bar without its time-left field, until the estimate means something.
_EARLY_BAR = "{desc}: {percentage:3.0f}%|{bar}| {n_fmt}/{total_fmt} [{elapsed}, estimating time left]"
#: The bar with the time left by groups (`Progress.left`), as its postfix.
_GROUPED_BAR = "{desc}: {percentage:3.0f}%|{bar}| {n_fmt}/{total_fmt} [{elapsed}{postfix}]"


def default_mode(stream: IO[str] | None = None) -> str:
    """A bar on a terminal, lines otherwise."""
    stream = stream or sys.stderr
    return BAR if stream.isatty() else LINES


def duration(seconds: float) -> str:
    """`42 s`, `3 min 05 s`, `2 h 07 min`."""
    s = int(round(seconds))
    if s < 60:
        return f"{s} s"
    if s < 3600:
        return f"{s // 60} min {s % 60:02d} s"
    return f"{s // 3600} h {s % 3600 // 60:02d} min"


class Progress:
    """Counts finished cells and shows them in `mode` (BAR, LINES or OFF) on `stream`; `groups`: the cells
    planned per group (solver and network), whose work per cell weighs the estimate of the time left."""

    def __init__(self, total: int, mode: str = OFF, stream: IO[str] | None = None,
                 interval: float = LINE_INTERVAL, clock=time.monotonic,
                 groups: Mapping[Hashable, int] | None = None) -> None:
        self.total = total
        self.done = 0
        self.closed = False
        self.groups = {g: n for g, n in (groups or {}).items() if n > 0}
        self.done_in: Counter = Counter()  # group -> cells done
        self.work_in: Counter = Counter()  # group -> seconds of work of its cells done
        self.mode = mode if total else OFF
        self.stream = stream or sys.stderr
        self.interval = interval
        self.clock = clock
        self.start = clock()
        self.last = self.start
        self.bar = None
        self._lock = threading.RLock()  # the ticker's lines and `update`'s counts
        self._stop = threading.Event()
        self._ticker: threading.Thread | None = None
        if self.mode == BAR:
            tqdm = require("tqdm", "experiment", "the experiment's progress bar").tqdm
            tqdm.monitor_interval = 0  # no monitor thread
            self.bar = tqdm(total=total, unit="cell", desc="experiment", file=self.stream, dynamic_ncols=True,
                            smoothing=0.05, bar_format=_EARLY_BAR)
            self._ticker = threading.Thread(target=self._tick, name="experiment-bar", daemon=True)
            self._ticker.start()
        elif self.mode == LINES:
            print(f"experiment: {total:,} cells to run; a progress line every {interval:g} s", file=self.stream,
                  flush=True)
            if clock is time.monotonic:
                self._ticker = threading.Thread(target=self._tick_lines, name="experiment-lines", daemon=True)
                self._ticker.start()

    def _tick(self) -> None:
        """Redraw the bar every second until it closes."""
        while not self._stop.wait(1.0):
            self.bar.refresh()

    def _tick_lines(self) -> None:
        """In a log, the progress line once `interval` seconds passed since the last, until it closes."""
        while not self._stop.wait(max(0.01, self.interval - (self.clock() - self.last))):
            self._line_if_due()

    def _line_if_due(self) -> None:
        """Print the progress line when `interval` seconds passed since the last one."""
        with self._lock:
            if self.clock() - self.last >= self.interval:
                self.last = self.clock()
                print(self.line(), file=self.stream, flush=True)

    @property
    def eta_meaningful(self) -> bool:
        """Whether enough cells are done for the rate to predict the rest: with groups, a cell of every group
        (and `ETA_MIN_CELLS`); without, `ETA_MIN_SHARE` of them."""
        if self.groups:
            return self.done >= ETA_MIN_CELLS and all(g in self.done_in for g in self.groups)
        return self.done >= max(ETA_MIN_CELLS, ETA_MIN_SHARE * self.total)

    def left(self) -> float | None:
        """Estimated seconds left (None until `eta_meaningful`): with groups whose cells took time, each
        group's cells left times its work per cell, times the wall time per second of work so far;
        otherwise the cells left at the rate so far."""
        if not self.eta_meaningful:
            return None
        elapsed = max(self.clock() - self.start, 1e-9)
        work = sum(self.work_in.values())
        if self.groups and work > 0:
            rest = sum(max(0, n - self.done_in[g]) * self.work_in[g] / self.done_in[g] for g, n in self.groups.items())
            return rest * elapsed / work
        return (self.total - self.done) * elapsed / self.done if self.done else None

    def line(self) -> str:
        """The progress line for the cells done so far."""
        elapsed = max(self.clock() - self.start, 1e-9)
        rate = self.done / elapsed
        pct = 100.0 * self.done / self.total if self.total else 100.0
        left = self.left()
        if self.done >= self.total:
            eta = "0 s"
        elif left is not None:
            eta = duration(left)
        elif self.groups:
            eta = "after a first cell of every solver and network"
        else:
            eta = f"after {max(ETA_MIN_CELLS, int(ETA_MIN_SHARE * self.total + 0.999)):,} cells"
        return (f"experiment: {self.done:,}/{self.total:,} cells ({pct:.1f} %), {rate:,.1f} cells/s, "
                f"elapsed {duration(elapsed)}, ETA {eta}")

    def update(self, n: int = 1, group: Hashable | None = None, seconds: float = 0.0) -> None:
        """`n` cells done, of `group` when given, with `seconds` of work between them."""
        with self._lock:  # a line the ticker prints meanwhile sees the counts before or after, never half
            self.done += n
            if group is not None:
                self.done_in[group] += n
                self.work_in[group] += seconds
        if self.bar is not None:
            if self.bar.bar_format == _EARLY_BAR and self.eta_meaningful:
                self.bar.bar_format = _GROUPED_BAR if self.groups else None  # None: tqdm's own time left
            if self.groups and self.eta_meaningful:
                left = self.left()
                self.bar.set_postfix_str("" if left is None else f"ETA {duration(left)}", refresh=False)
            self.bar.update(n)
        elif self.mode == LINES:
            self._line_if_due()

    def note(self, text: str) -> None:
        """A message that does not break the bar (the dashboard link, a lost task)."""
        if self.bar is not None:
            self.bar.write(text, file=self.stream)
        elif self.mode != OFF:
            with self._lock:  # not inside a line the ticker prints
                print(text, file=self.stream, flush=True)

    def close(self) -> None:
        """End the bar (or print the last line); once: the Dask run ends it before stopping its workers."""
        if self.closed:
            return
        self.closed = True
        self._stop.set()
        if self._ticker is not None:
            self._ticker.join()
        if self.bar is not None:
            self.bar.close()
        elif self.mode == LINES:
            print(self.line(), file=self.stream, flush=True)
