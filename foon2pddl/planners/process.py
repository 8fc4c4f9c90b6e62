"""Running a planner process: own process group, time limit, optional memory limit.

Every planner run gets its own working directory from the caller (planners
write files such as `output.sas` into it), so concurrent runs never share one.
"""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class ProcessRun:
    """How a process ended: exit code (None when killed at the time limit), its output, wall time."""

    returncode: int | None
    output: str
    seconds: float

    @property
    def timed_out(self) -> bool:
        return self.returncode is None


def run_process(
    cmd: Sequence[str],
    cwd: Path,
    timeout: float | None = None,
    *,
    stdin_path: Path | None = None,
    stdin_text: str | None = None,
    env: Mapping[str, str] | None = None,
    memory_limit_mb: int | None = None,
) -> ProcessRun:
    """Run `cmd` (no shell) in `cwd`; kill its whole process group at `timeout` seconds.

    stdout and stderr are merged into `output`. Raises OSError when the command cannot start.
    """
    t0 = time.perf_counter()
    stdin = open(stdin_path, "rb") if stdin_path is not None else (subprocess.PIPE if stdin_text is not None else subprocess.DEVNULL)
    try:
        proc = subprocess.Popen(
            list(cmd), cwd=cwd, stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            env=dict(env) if env is not None else None, start_new_session=True,
        )
    finally:
        if stdin_path is not None:
            stdin.close()
    if memory_limit_mb is not None:
        limit = memory_limit_mb * 1024 * 1024
        try:
            resource.prlimit(proc.pid, resource.RLIMIT_AS, (limit, limit))
        except (OSError, ValueError):
            pass
    data = stdin_text.encode() if stdin_text is not None else None
    try:
        out, _ = proc.communicate(data, timeout=None if timeout is None else max(timeout, 0.001))
        code: int | None = proc.returncode
    except subprocess.TimeoutExpired:
        _kill_group(proc)
        out, _ = proc.communicate()
        code = None
    except BaseException:
        _kill_group(proc)
        proc.wait()
        raise
    return ProcessRun(code, out.decode("utf-8", "replace"), time.perf_counter() - t0)


def _kill_group(proc: subprocess.Popen) -> None:
    """Kill the process group this module started for `proc` (and nothing else)."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        proc.kill()


def remaining(deadline: float | None) -> float | None:
    """Seconds left until a `time.monotonic()` deadline (None = no limit)."""
    return None if deadline is None else deadline - time.monotonic()
