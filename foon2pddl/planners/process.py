"""Running a planner process: own process group, time limit, optional memory limit, bounded output.

Every planner run gets its own working directory from the caller (planners
write files such as `output.sas` into it), so concurrent runs never share one.
The process writes its stdout and stderr to a file there (`OUTPUT_FILE`), not
to a pipe: memory stays bounded whatever it prints (`ProcessRun.output` keeps
the head and the tail), and a daemon child that inherited the output cannot
make us wait for it. When the run ends (exit, time limit or interrupt) its
process group and every process carrying its mark (`cleanup.MARK`, inherited
even across `setsid`) are killed; should the caller die before it can, a CPU
limit (`CPU_LIMIT_FACTOR`) still ends a run that has a time limit. The CPU and memory limits are
set before the planner's `exec`, by a `/bin/sh` that sets them and execs it (`limited`): the child
carries them from its first instruction, whenever the caller dies. (`preexec_fn` would do the same
in Python, but is unsafe in a threaded process such as a Dask worker; `prlimit` after `Popen` left
a window in which a caller killed with SIGKILL left its planner unlimited.)
"""

from __future__ import annotations

import errno
import math
import os
import resource
import subprocess
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from ..io.interrupts import signals_deferred
from .cleanup import MARK, kill_group, kill_marked, new_token

#: Output file of a run, in its working directory.
OUTPUT_FILE = "planner-output.log"
#: Bytes of output kept in memory: the first HEAD_BYTES and the last TAIL_BYTES.
HEAD_BYTES = 64 * 1024
TAIL_BYTES = 256 * 1024
#: Longer time limits (seconds, ~11 days) mean no limit: waits take them as C ints of milliseconds.
MAX_TIMEOUT = 1e6
#: A run with a time limit of t seconds may use at most CPU_LIMIT_FACTOR * t seconds of CPU (RLIMIT_CPU):
#: never reached by a run the time limit ends (the planners use one core), it ends a planner whose caller
#: was killed before it could kill the run (a pool worker sent SIGKILL left Fast Downward searching for
#: 90 minutes past its 30 s limit).
CPU_LIMIT_FACTOR = 2


def cpu_seconds() -> float:
    """CPU time (user + system) of this process and of the child processes it has waited for (planner runs)."""
    return time.process_time() + _children_cpu()


@dataclass(frozen=True)
class ProcessRun:
    """How a process ended: exit code (None when killed at the time limit), its output
    (head and tail when long), wall time, and the output's full size in bytes."""

    returncode: int | None
    output: str
    seconds: float
    output_bytes: int = 0
    #: CPU seconds (user + system) the run used, when measured (None: not known).
    cpu: float | None = None

    @property
    def timed_out(self) -> bool:
        return self.returncode is None


def cpu_limit(timeout: float | None, cpu: float | None = None) -> int | None:
    """The RLIMIT_CPU (seconds) of a run with a (bounded) time limit: CPU_LIMIT_FACTOR times it, plus a second;
    with a CPU budget `cpu` (seconds), that budget rounded up (at least 1 s) when lower. A run past it gets
    SIGXCPU (Fast Downward's components then report their time limit)."""
    backstop = None if timeout is None else math.ceil(CPU_LIMIT_FACTOR * timeout) + 1
    if cpu is None:
        return backstop
    budget = max(math.ceil(cpu), 1)
    return budget if backstop is None else min(budget, backstop)


def bounded_timeout(seconds: float | None) -> float | None:
    """A time limit every wait accepts: None (no limit) for None, infinity or more than MAX_TIMEOUT;
    at least a millisecond. Raises ValueError for NaN."""
    if seconds is None:
        return None
    if math.isnan(seconds):
        raise ValueError("time limit is not a number")
    return None if seconds > MAX_TIMEOUT else max(seconds, 0.001)


def read_capped(path: Path, head: int = HEAD_BYTES, tail: int = TAIL_BYTES) -> tuple[str, int]:
    """(text, size) of an output file: the whole text, or its head and tail around an omission note."""
    try:
        size = path.stat().st_size
        with open(path, "rb") as fh:
            if size <= head + tail:
                data = fh.read()
            else:
                first = fh.read(head)
                fh.seek(size - tail)
                data = first + f"\n[... {size - head - tail} bytes of output omitted ...]\n".encode() + fh.read()
    except OSError:
        return "", 0
    return data.decode("utf-8", "replace"), size


def run_process(
    cmd: Sequence[str],
    cwd: Path,
    timeout: float | None = None,
    *,
    stdin_path: Path | None = None,
    stdin_text: str | None = None,
    env: Mapping[str, str] | None = None,
    memory_limit_mb: int | None = None,
    cpu: float | None = None,
) -> ProcessRun:
    """Run `cmd` (no shell) in `cwd`; at `timeout` seconds (None: no limit) kill it and everything it started.

    `cpu`: a CPU budget (seconds, rounded up), the run's RLIMIT_CPU (`cpu_limit`): it bounds the work, where
    `timeout` bounds the wall time a loaded machine stretches. `ProcessRun.cpu` is the CPU the run's reaped
    processes used (this process's children's, before and after: a thread running others at once adds theirs).
    stdout and stderr are merged into `cwd/OUTPUT_FILE`; `output` holds at most
    HEAD_BYTES + TAIL_BYTES of it. Raises OSError when the command cannot start.
    """
    timeout = bounded_timeout(timeout)
    token = new_token()
    run_env = dict(os.environ if env is None else env)
    run_env[MARK] = token
    if stdin_text is not None:
        stdin_path = cwd / "planner-input.txt"
        stdin_path.write_text(stdin_text)
    log = cwd / OUTPUT_FILE
    t0, cpu0 = time.perf_counter(), _children_cpu()
    proc: subprocess.Popen | None = None
    code: int | None = None
    try:
        # Not under signals_deferred (the child would inherit the blocked mask): an interrupt before
        # `proc` is bound is covered by the mark, which the child carries from its first instruction.
        # the CPU limit is a backstop should this process die uncleaned (SIGKILL): see CPU_LIMIT_FACTOR
        argv = limited(cmd, cwd, run_env, cpu_limit(timeout, cpu), memory_limit_mb)
        with open(log, "wb") as out, open(stdin_path or os.devnull, "rb") as stdin:
            proc = subprocess.Popen(argv, cwd=cwd, stdin=stdin, stdout=out, stderr=subprocess.STDOUT,
                                    env=run_env, start_new_session=True)
        try:
            code = proc.wait(timeout)
        except subprocess.TimeoutExpired:
            code = None
    finally:
        with signals_deferred():
            _end(proc, token)
    seconds = time.perf_counter() - t0
    output, size = read_capped(log)
    return ProcessRun(code, output, seconds, size, _children_cpu() - cpu0)


def _children_cpu() -> float:
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return kids.ru_utime + kids.ru_stime


#: Sets the limits given as $1 (CPU seconds) and $2 (address space, KiB; "-" for none), then execs the rest.
#: A limit above the inherited hard limit cannot be set: the inherited (lower) one stays, as with prlimit. The CPU
#: limit's hard limit is a second past the soft one, as Fast Downward's driver sets it: at the soft limit the
#: planner gets SIGXCPU and reports its time limit (at an equal hard limit Linux sends SIGKILL instead).
_LIMIT_SCRIPT = ('[ "$1" = - ] || { ulimit -S -t "$1" && ulimit -H -t "$(($1 + 1))"; } 2>/dev/null; '
                 '[ "$2" = - ] || ulimit -v "$2" 2>/dev/null; shift 2; exec "$@"')


def limited(cmd: Sequence[str], cwd: Path, env: Mapping[str, str], cpu_limit: int | None,
            memory_limit_mb: int | None) -> list[str]:
    """`cmd` run with RLIMIT_CPU = `cpu_limit` (soft; hard a second later) and RLIMIT_AS = `memory_limit_mb` from its
    first instruction: `/bin/sh -c _LIMIT_SCRIPT` execs it (same pid, argv and environment). `cmd` itself
    when there is no limit to set.

    The program is looked up first, as `Popen` would (on `env`'s PATH, relative to `cwd`), so a missing
    or non-executable one still raises FileNotFoundError / PermissionError rather than the shell's 127.
    """
    if cpu_limit is None and memory_limit_mb is None:
        return list(cmd)
    _check_program(cmd[0], cwd, env)
    memory = "-" if memory_limit_mb is None else str(memory_limit_mb * 1024)
    return ["/bin/sh", "-c", _LIMIT_SCRIPT, "sh", "-" if cpu_limit is None else str(cpu_limit), memory,
            *cmd]


def _check_program(program: str, cwd: Path, env: Mapping[str, str]) -> None:
    """Raise the OSError `Popen` would for a program it cannot execute (ENOENT, EACCES)."""
    dirs = [""] if "/" in program else os.get_exec_path(env)
    candidates = [Path(cwd, d, program) for d in dirs]
    if any(c.is_file() and os.access(c, os.X_OK) for c in candidates):
        return
    if any(c.exists() for c in candidates):
        raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), program)
    raise FileNotFoundError(errno.ENOENT, os.strerror(errno.ENOENT), program)


def _end(proc: subprocess.Popen | None, token: str) -> None:
    """Kill the run's process group (while its leader is unreaped, so the group id is still ours),
    then every process carrying the run's mark, and reap the leader."""
    if proc is not None and proc.returncode is None:
        kill_group(proc.pid, proc.kill)
    kill_marked(token)
    if proc is not None:
        proc.wait()


def remaining(deadline: float | None) -> float | None:
    """Seconds left until a `time.monotonic()` deadline (None = no limit)."""
    return None if deadline is None else deadline - time.monotonic()
