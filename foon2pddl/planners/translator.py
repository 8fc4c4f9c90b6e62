"""Fast Downward's translator kept warm: one server process per interpreter forks a child per task.

A fresh `python -m fast_downward.translate` spends ~100 ms of CPU starting and importing
before it translates (a FOON goal's task takes ~20 ms); `translate_server.py` imports the
translator once and forks a child per task, which runs it exactly as the fresh interpreter
would (same arguments, exit codes, output file, working directory) and so writes the same
SAS file. `run` returns the same `ProcessRun` as `process.run_process`; the time limit kills
the child's process group, as `run_process` does.

The server starts on first use and is replaced when it died (a command scope kills it with
the command's other processes) or when this interpreter is a fork of the one that started
it. One task runs at a time: while the server is busy (another thread), or when it cannot
start, `run` returns None and the caller starts a fresh translator. Set
`FOON2PDDL_WARM_TRANSLATOR=0` to always start a fresh one (benchmarks compare the two).
"""

from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Sequence
from pathlib import Path

from .cleanup import MARK, kill_group, new_token
from .process import OUTPUT_FILE, ProcessRun, bounded_timeout, cpu_limit, read_capped

SWITCH = "FOON2PDDL_WARM_TRANSLATOR"
_SCRIPT = Path(__file__).with_name("translate_server.py")
_LOCK = threading.Lock()


class _Server:
    """A running translate_server.py and the reader of its replies."""

    def __init__(self, bin_dir: Path) -> None:
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(bin_dir), env.get("PYTHONPATH", "")) if p)
        env[MARK] = new_token()
        self.owner = os.getpid()
        self.proc = subprocess.Popen([sys.executable, str(_SCRIPT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, env=env, start_new_session=True)
        self.buffer = b""

    def usable(self) -> bool:
        return self.owner == os.getpid() and self.proc.poll() is None

    def reply(self, deadline: float | None) -> dict | None:
        """The next reply line, or None at the deadline. Raises EOFError when the server is gone."""
        fd = self.proc.stdout.fileno()
        while b"\n" not in self.buffer:
            wait = None if deadline is None else max(0.0, deadline - time.monotonic())
            if not select.select([fd], [], [], wait)[0]:
                return None
            chunk = os.read(fd, 4096)
            if not chunk:
                raise EOFError("translator server ended")
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        return json.loads(line)

    def close(self) -> None:
        kill_group(self.proc.pid)
        for stream in (self.proc.stdin, self.proc.stdout):
            try:
                stream.close()
            except OSError:
                pass
        self.proc.wait()


_server: _Server | None = None


def enabled() -> bool:
    return os.environ.get(SWITCH, "1") != "0"


def run(args: Sequence[str], cwd: Path, timeout: float | None, bin_dir: Path,
        memory_limit_mb: int | None = None, cpu: float | None = None) -> ProcessRun | None:
    """Translate with the warm server (`args` as for `python -m fast_downward.translate`), or None
    when it is switched off, busy or cannot start (then the caller runs a fresh translator). `cpu`: a CPU budget,
    as `process.run_process` takes it; the run's `cpu` is the child's own (the server reaps it)."""
    if not enabled() or not _LOCK.acquire(blocking=False):
        return None
    try:
        return _run_locked(list(args), cwd, timeout, bin_dir, memory_limit_mb, cpu)
    finally:
        _LOCK.release()


def prestart(bin_dir: Path) -> None:
    """Start the server now, when it is on and not running, so that its start-up overlaps the caller's
    work (loading, encoding) instead of delaying the first translation."""
    global _server
    if not enabled() or not _LOCK.acquire(blocking=False):
        return
    try:
        if _server is None or not _server.usable():
            _drop()
            _server = _Server(bin_dir)
    except OSError:
        _server = None
    finally:
        _LOCK.release()


def _run_locked(args: list[str], cwd: Path, timeout: float | None, bin_dir: Path,
                memory_limit_mb: int | None, cpu: float | None) -> ProcessRun | None:
    global _server
    timeout = bounded_timeout(timeout)
    t0 = time.perf_counter()
    try:
        if _server is None or not _server.usable():
            _drop()
            _server = _Server(bin_dir)
        request = {"args": args, "cwd": str(cwd), "memory_mb": memory_limit_mb, "cpu_s": cpu_limit(timeout, cpu)}
        _server.proc.stdin.write((json.dumps(request) + "\n").encode())
        _server.proc.stdin.flush()
        started = _server.reply(None)
    except (OSError, EOFError, ValueError):
        _drop()
        return None
    pid = started["pid"]
    deadline = None if timeout is None else time.monotonic() + timeout
    code: int | None = None
    used: float | None = None
    finished = False
    try:
        done = _server.reply(deadline)
        if done is not None:
            code, used, finished = done["code"], done.get("cpu"), True
    except (OSError, EOFError, ValueError):
        code, finished = -signal.SIGKILL, True  # the server died with its child: report a killed run
        _drop()
    finally:
        if not finished:  # time limit, or an interrupt while waiting: end the child, then the server's wait
            kill_group(pid)
            _settle()
    seconds = time.perf_counter() - t0
    output, size = read_capped(cwd / OUTPUT_FILE)
    return ProcessRun(code, output, seconds, size, used)


def _settle() -> None:
    """After killing a child: read the server's reply for it, so the next request starts clean."""
    try:
        if _server is not None and _server.reply(time.monotonic() + 5.0) is not None:
            return
    except (OSError, EOFError, ValueError):
        pass
    _drop()


def _drop() -> None:
    global _server
    if _server is not None and _server.owner == os.getpid():
        _server.close()
    _server = None
