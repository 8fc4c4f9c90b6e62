#!/usr/bin/env python3
"""`make install`'s pip step: a line per phase on stderr, where `pip -q` said nothing for minutes and
plain pip prints hundreds of lines.

    python3 tools/pip_phases.py --log FILE [--first LINE] PIP_COMMAND...
    python3 tools/pip_phases.py --log FILE [--first LINE] --who "make install" --phase TEXT COMMAND...

Runs the pip command with its output going to FILE, and says on stderr when pip enters each phase
(preparing the project's build, collecting the dependencies, building, installing), with the packages
counted; a phase still running after `TICK` seconds says so again, with the seconds since it began (on a terminal: one line, redrawn). pip's
`ERROR` lines are shown as they come; when pip fails the last `TAIL` lines of its output follow. The exit
status is pip's. `--phase TEXT` runs a command that has no pip phases (`python3 -m venv`) as one phase doing
TEXT, its lines said under `--who`'s name. `--first LINE` is said at once, before the command starts: the step's
own line (`make install: 2/4 ...`), so the first tick comes TICK s after it (an `echo` in the Makefile, then this
interpreter's start under load, then TICK s left 2.08 s without a line at load 6). Standard library only: it runs before the virtual environment holds
anything else.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import threading
import time

#: Seconds a phase may run without a line before it says it is still running: the CLI's beat
#: (`foon2pddl.cli.progress.BEAT`, not importable here), under issue 24's floor of 2 s without a line.
TICK = 1.0
#: Lines of pip's output shown when it fails.
TAIL = 40
#: On a terminal: back to the start of the line and clear it.
REDRAW = "\r\x1b[K"
#: pip's line prefixes that open a phase, and what the phase does.
PHASES = (
    ("Obtaining ", "preparing the project's build"),
    ("Collecting ", "collecting the dependencies (downloading any not cached)"),
    ("Building wheels", "building"),
    ("Installing collected packages", "installing the packages into the environment"),
    ("Successfully installed", "done"),
)


def _packages(n: int) -> str:
    return f"{n} package{'' if n == 1 else 's'}"


class Phases:
    """What pip is doing, said on `out` (a phase per line; on a terminal one redrawn line)."""

    def __init__(self, out, tty: bool, who: str = "pip") -> None:
        self.out, self.tty, self.who = out, tty, who
        self.phase, self.collected, self.start, self.said = "", 0, time.monotonic(), time.monotonic()
        self.lock, self.open = threading.Lock(), False  # open: a redrawn line waits for its end

    def say(self, text: str, redraw: bool = False) -> None:
        with self.lock:
            if self.tty and redraw:
                self.out.write(f"{REDRAW}{self.who}: {text}")
            else:
                self.out.write(f"{REDRAW if self.open else ''}{self.who}: {text}\n")
            self.out.flush()
            self.said, self.open = time.monotonic(), self.tty and redraw

    def end(self) -> None:
        """End a redrawn line."""
        if self.open:
            self.out.write("\n")
            self.open = False

    def line(self, text: str) -> None:
        """One line of pip's output."""
        for prefix, what in PHASES:
            if text.startswith(prefix) and what != self.phase:
                if what == PHASES[-1][1]:
                    what = f"done: {_packages(len(text.split()) - 2)} installed"
                elif prefix == "Installing collected packages":
                    what += f" ({_packages(len(text.split(':', 1)[1].split(',')))})"
                self.phase, self.start = what, time.monotonic()  # a `still` line counts from its phase's start
                self.say(what if prefix == PHASES[-1][0] else what + " ...")
                if prefix == PHASES[-1][0]:
                    self.phase = "finishing"  # pip exits after its last line: not `still done`
        if text.startswith("Collecting "):
            self.collected += 1
            if self.tty:
                self.say(f"{self.phase} ... {self.collected}: {text.split()[1]}", redraw=True)
        if text.startswith("ERROR"):
            self.say(text)

    def tick(self, stop: threading.Event) -> None:
        """Every quarter second until `stop` (a check every second made the 1.5 s TICK 2 s): a phase silent
        for TICK seconds says it is still running."""
        while not stop.wait(0.25):
            if self.phase and time.monotonic() - self.said >= TICK:
                count = f", {self.collected} collected" if self.phase == PHASES[1][1] else ""
                self.say(f"still {self.phase} ({time.monotonic() - self.start:.0f} s{count}) ...", redraw=self.tty)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--log", required=True, help="file receiving pip's whole output")
    parser.add_argument("--who", default="pip", help="the name its lines start with")
    parser.add_argument("--phase", default="", help="what a command without pip's phases does (one phase)")
    parser.add_argument("--first", default="", help="a line said at once, before the command starts")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="the pip command")
    args = parser.parse_args(argv)
    if args.first:
        sys.stderr.write(args.first + "\n")
        sys.stderr.flush()
    phases = Phases(sys.stderr, sys.stderr.isatty(), args.who)
    phases.phase = args.phase or "starting"  # unsaid: only that it still runs (pip's imports, before its first line)
    stop = threading.Event()
    ticker = threading.Thread(target=phases.tick, args=(stop,), daemon=True)
    ticker.start()
    lines: list[str] = []
    with open(args.log, "w", encoding="utf-8") as log:
        proc = subprocess.Popen(args.command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                errors="replace")
        for raw in proc.stdout:
            log.write(raw)
            lines.append(raw.rstrip("\n"))
            phases.line(raw.strip())
        status = proc.wait()
    stop.set()
    ticker.join()
    phases.end()
    if status:
        sys.stderr.write(f"{args.who} failed (exit status {status}); the end of its output ({args.log} has it all):\n")
        sys.stderr.write("".join(f"  {line}\n" for line in lines[-TAIL:]))
    return status


if __name__ == "__main__":
    sys.exit(main())
