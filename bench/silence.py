"""No silent waits: the longest time each documented command goes without printing on stderr.

Runs every command README.md and docs/*.md show (`bench/doc_commands.py`; commands that need
the reader's own files are listed as skipped), plus `EXTRA`, the planner and network variants
the docs name in prose, each from a scratch directory with `tests/` and `docs/` linked in:
first with an empty `FOON2PDDL_CACHE` and `XDG_CACHE_HOME` (a new user's first run), then
again with the cache that run left and its outputs removed (a warm cache moves the slow part:
with the similarity matrix cached, `expand --pairs` opens WordNet in another step). Its
stderr is a pseudo-terminal, as at a user's terminal: a step `slow_step` announces then
counts its seconds on the line. Every write to stderr is timestamped; the silent gaps are
start -> first output, output -> output, last output -> exit; a command's figure is the
longest gap of its two runs. A command still running after `--cap` seconds is interrupted
(SIGINT) and its gaps counted up to then.

    python -m bench.silence [--only TEXT ...] [--limit 2] [--cap 180] [--caches empty warm] [--list]
    python -m bench --only silence

Exit status of `python -m bench.silence`: 0 when no gap exceeds `--limit`, 1 otherwise.
"""

from __future__ import annotations

import argparse
import fcntl
import os
import pty
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import termios
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from .doc_commands import ROOT, DocCommand, documented_commands, missing_inputs
from .harness import Context, run_main

AREA = "silence"
#: A terminal's control sequence (a redraw's `ESC [K`).
_ESCAPE = re.compile(r"\x1b\[[0-9;?]*[A-Za-z]")
LIMIT = 2.0
CAP = 180.0
CACHES = ("empty", "warm")

#: Commands the docs describe in prose (an option named on a page, not a full line): page, command.
EXTRA = (
    ("docs/planning.md", "foon2pddl plan --goal guacamole --planner pyperplan"),
    ("docs/planning.md", "foon2pddl plan --goal guacamole --planner symk"),
    ("docs/planning.md", "foon2pddl plan --goal 'whipped cream' --planner pyperplan --optimal"),
    ("docs/generalization.md", "foon2pddl similarity cilantro banana --similarity paper"),
    ("docs/generalization.md", "foon2pddl expand --similarity paper --pairs"),
    ("docs/generalization.md", "foon2pddl goals --network exp"),
    ("docs/generalization.md", "foon2pddl compile --goal lemonade --network gen -o out/"),
    ("docs/generalization.md", "foon2pddl categories --extend tests/data/foon-subgraphs -o out/index.json"),  # my_recipes/
    ("docs/retrieval.md", "foon2pddl goals --dishes"),
    ("docs/pddl.md", "foon2pddl compile --goal guacamole --encoding relational -o out/"),
    ("README.md", "foon2pddl experiment tests/data/foon-subgraphs --solvers native-greedy,native-complete --jobs 2 "
                  "-o out/exp"),
)


@dataclass(frozen=True)
class Silence:
    """The outputs of one run: when (seconds from the start) and what was printed, and how it ended."""

    command: str
    cache: str  # empty | warm
    events: tuple[tuple[float, str], ...]
    end: float
    exit_status: int | None  # None: interrupted at the cap

    def gaps(self) -> list[tuple[float, str]]:
        """(seconds, where) of every silent stretch: start -> first output, between outputs, last -> exit."""
        times = [0.0, *(t for t, _ in self.events), self.end]
        names = ["start", *(f"after {text[:70]!r}" for _, text in self.events)]
        return [(b - a, where) for a, b, where in zip(times, times[1:], names, strict=False)]

    def longest(self) -> tuple[float, str]:
        return max(self.gaps())


#: What a scratch directory keeps between a command's runs: the inputs and the caches.
_KEPT = ("tests", "docs", "cache", "xdg")


def _scratch(base: Path) -> Path:
    """A working directory where the documented relative paths (tests/data, docs/examples) resolve."""
    for name in ("tests", "docs"):
        (base / name).symlink_to(ROOT / name)
    return base


def _clear_outputs(work: Path) -> None:
    """Remove what a run wrote (out/, trees/, a plot), keeping the inputs and the caches."""
    for entry in work.iterdir():
        if entry.name not in _KEPT:
            shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()


def run_cached(command: str, cap: float = CAP, caches: tuple[str, ...] = CACHES) -> list[Silence]:
    """Run `command` once per entry of `caches`, in order, in one scratch directory: `empty` first
    (its caches are fresh), `warm` with the caches the runs before it left."""
    with tempfile.TemporaryDirectory(prefix="silence-") as tmp:
        work = _scratch(Path(tmp))
        out = []
        for cache in caches:
            _clear_outputs(work)
            if cache == "empty":
                for name in ("cache", "xdg"):
                    shutil.rmtree(work / name, ignore_errors=True)
            out.append(run_one(command, work, cache, cap))
        return out


def run_one(command: str, work: Path, cache: str = "empty", cap: float = CAP) -> Silence:
    """Run `command` (shell text) in `work` with stderr on a pseudo-terminal; timestamp every write to it."""
    env = dict(os.environ, FOON2PDDL_CACHE=str(work / "cache"), XDG_CACHE_HOME=str(work / "xdg"),
               PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}")
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))  # a terminal's size: tqdm needs one
    events: list[tuple[float, str]] = []
    start = time.monotonic()
    proc = subprocess.Popen(["bash", "-c", command], cwd=work, env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=slave, start_new_session=True)
    os.close(slave)

    def read() -> None:
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:  # EIO: every writer closed
                return
            if not chunk:
                return
            text = _ESCAPE.sub("", chunk.decode(errors="replace")).replace("\r", "\n")
            shown = [line.strip() for line in text.split("\n") if line.strip()]
            if shown:
                events.append((time.monotonic() - start, shown[-1]))

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        status: int | None = proc.wait(timeout=cap)
    except subprocess.TimeoutExpired:
        status = None
        os.killpg(proc.pid, signal.SIGINT)
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    end = time.monotonic() - start
    reader.join(timeout=5)
    os.close(master)
    kept = tuple((t, text) for t, text in events if t <= end)
    return Silence(command, cache, kept, min(end, cap) if status is None else end, status)


def commands() -> tuple[list[DocCommand], list[tuple[DocCommand, list[str]]]]:
    """(commands to run, (skipped command, the reader's files it needs))."""
    shown = documented_commands() + [DocCommand(page, 0, text, "prose") for page, text in EXTRA]
    runnable, skipped = [], []
    for c in shown:
        missing = missing_inputs(c.text)
        (skipped.append((c, missing)) if missing else runnable.append(c))
    return runnable, skipped


def measure(only: list[str] | None = None, cap: float = CAP, caches: tuple[str, ...] = CACHES,
            echo=print) -> list[tuple[DocCommand, Silence]]:
    """Run every runnable command (those containing one of `only`, when given) with each cache state;
    echo one line each; return each command's run with the longest gap."""
    runnable, skipped = commands()
    for c, missing in skipped:
        echo(f"skipped {c.where}: {c.text} (needs the reader's {', '.join(missing)})")
    out = []
    for c in runnable:
        if only and not any(o in c.text for o in only):
            continue
        runs = run_cached(c.text, cap, caches)
        worst = max(runs, key=lambda r: r.longest()[0])
        gap, where = worst.longest()
        each = ", ".join(f"{r.cache} {r.longest()[0]:.1f} s of {r.end:.1f} s "
                         + (f"exit {r.exit_status}" if r.exit_status is not None else f"cut at {cap:.0f} s")
                         for r in runs)
        echo(f"{gap:6.1f} s  {c.text}  [{worst.cache} cache, {where}; {each}; {c.where}]")
        out.append((c, worst))
    return out


def run(ctx: Context) -> None:
    """`python -m bench` area: the longest silent gap of each documented command."""
    for c, s in measure(cap=60.0 if ctx.quick else CAP, echo=lambda _line: None):
        gap, where = s.longest()
        ctx.report(AREA, c.text.removeprefix("foon2pddl "), gap, "s", f"{s.cache} cache, {where}; {c.where}")


def main() -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.silence", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="*", help="run only the commands containing one of these texts")
    ap.add_argument("--limit", type=float, default=LIMIT, help="longest allowed silent gap, seconds")
    ap.add_argument("--cap", type=float, default=CAP, help="interrupt a command after this many seconds")
    ap.add_argument("--caches", nargs="+", choices=CACHES, default=list(CACHES),
                    help="cache states to run each command with, in order (warm: what the runs before left)")
    ap.add_argument("--list", action="store_true", help="list the commands, run none")
    args = ap.parse_args()
    if args.list:
        runnable, skipped = commands()
        for c in runnable:
            print(f"{c.where}\t{c.text}")
        for c, missing in skipped:
            print(f"{c.where}\tskipped (needs {', '.join(missing)})\t{c.text}")
        return 0
    print(f"load: {os.getloadavg()[0]:.2f} (1 min)", flush=True)
    results = measure(args.only, args.cap, tuple(args.caches), echo=lambda line: print(line, flush=True))
    over = [(c, s) for c, s in results if s.longest()[0] > args.limit]
    print(f"{len(results)} commands, {len(over)} silent for more than {args.limit:g} s; "
          f"load: {os.getloadavg()[0]:.2f} (1 min)")
    return 1 if over else 0


if __name__ == "__main__":
    run_main(main)
