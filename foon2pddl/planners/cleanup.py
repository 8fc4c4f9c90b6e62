"""Every process and temporary path a run starts is gone when it ends, however it ends.

Marks: a planner run puts a random token in its process's environment (`MARK`).
Children inherit it, including daemons that leave the process group with `setsid`
and would survive `killpg`; `kill_marked` finds them all by reading
`/proc/*/environ` and kills them (Linux; elsewhere it finds nothing and the
process-group kill is all there is).

Scope: `command_scope` wraps a whole CLI command. A private directory under the
user's TMPDIR becomes TMPDIR for the command and every process it starts (planner
work directories, Fast Downward's files, worker processes); a scope token marks
those processes. On exit, whatever the path (return, error, SIGINT, SIGTERM), the
marked processes and the command's own descendants are killed and the directory
removed, so nothing leaks even from a worker killed before its own cleanup ran.
(In a long-lived interpreter, multiprocessing's resource tracker and fork server,
which serve later commands too, are spared: `SPARE_HELPERS`.)
"""

from __future__ import annotations

import os
import shutil
import signal
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager

MARK = "FOON2PDDL_RUN"
SCOPE_MARK = "FOON2PDDL_SCOPE"
_PROC = "/proc"


def new_token() -> str:
    """A fresh random token for `MARK` or `SCOPE_MARK`."""
    return os.urandom(8).hex()  # what secrets.token_hex(8) returns, without importing hashlib and hmac


def _pids() -> list[int]:
    try:
        return [int(e.name) for e in os.scandir(_PROC) if e.name.isdigit()]
    except OSError:
        return []


def marked_pids(name: str, token: str) -> list[int]:
    """Processes (not this one) whose environment holds `name=token`. O(processes on the machine)."""
    needle = f"\0{name}={token}\0".encode()
    me, found = os.getpid(), []
    for pid in _pids():
        if pid == me:
            continue
        try:
            with open(f"{_PROC}/{pid}/environ", "rb") as fh:
                env = fh.read()
        except OSError:  # gone, or another user's
            continue
        if needle in b"\0" + env + b"\0":
            found.append(pid)
    return found


def _stat(pid: int) -> tuple[int, int] | None:
    """(parent pid, start time in clock ticks) of a process, None when it is gone."""
    try:
        with open(f"{_PROC}/{pid}/stat", "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    fields = data[data.rfind(b")") + 2:].split()  # after "pid (comm) "
    return int(fields[1]), int(fields[19])


def _children_file(pid: int) -> list[int] | None:
    """Child processes of `pid` from /proc/PID/task/*/children; None where the kernel lacks that file."""
    try:
        tasks = os.listdir(f"{_PROC}/{pid}/task")
    except OSError:
        return []
    out: list[int] = []
    for tid in tasks:
        try:
            with open(f"{_PROC}/{pid}/task/{tid}/children", "rb") as fh:
                out.extend(int(x) for x in fh.read().split())
        except FileNotFoundError:
            return None
        except OSError:
            continue
    return out


def descendants(root: int, started_after: int = 0) -> list[int]:
    """Processes below `root` in the parent tree, started at or after tick `started_after`.

    O(descendants) reads of /proc where the kernel lists children, else one scan of /proc.
    """
    table: dict[int, list[int]] | None = None
    out, todo = [], [root]
    while todo:
        pid = todo.pop()
        kids = _children_file(pid) if table is None else table.get(pid, [])
        if kids is None:
            table = {}
            for p in _pids():
                info = _stat(p)
                if info is not None:
                    table.setdefault(info[0], []).append(p)
            kids = table.get(pid, [])
        for child in kids:
            info = _stat(child)
            if info is not None and info[1] >= started_after:
                out.append(child)
            todo.append(child)
    return out


def _kill(pids: list[int]) -> None:
    for pid in pids:
        try:
            os.kill(pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


def kill_group(pid: int, otherwise: Callable[[], object] = lambda: None) -> None:
    """SIGKILL the process group `pid` leads; `otherwise()` (kill the leader alone, or nothing) when the group is
    gone or not ours to kill: a planner run's, a UP engine's or the translator server's group."""
    try:
        os.killpg(pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        otherwise()


def kill_marked(token: str, name: str = MARK, rounds: int = 5) -> None:
    """SIGKILL every process marked `name=token` (repeated: a dying process may have just forked).

    Done only after two scans in a row, 5 ms apart, find none: a process in the middle of `execve` (a
    daemon's `setsid sleep` starting) can have an unreadable environment for an instant, and one empty
    scan (or two back to back) let it survive on a loaded machine.
    """
    empty = 0
    for _ in range(rounds + 1):
        pids = marked_pids(name, token)
        if not pids:
            empty += 1
            if empty == 2:
                return
            time.sleep(0.005)  # the second scan a moment later: back to back, both fell in one execve
            continue
        empty = 0
        _kill(pids)
        time.sleep(0.01)


def _now_ticks() -> int:
    """This moment in /proc's start-time unit (clock ticks since boot)."""
    try:
        with open(f"{_PROC}/uptime") as fh:
            return int(float(fh.read().split()[0]) * os.sysconf("SC_CLK_TCK"))
    except (OSError, ValueError):
        return 0


#: Whether the interpreter outlives its commands (tests, library use): then the helpers below are
#: spared; the CLI entry point (`foon2pddl.__main__.run`) clears it, its process ends with the command.
SPARE_HELPERS = True


def _interpreter_helpers() -> set[int]:
    """Helper processes this interpreter keeps for its whole life (multiprocessing's resource
    tracker and fork server), when SPARE_HELPERS: started during a command, they serve the next one."""
    import sys

    pids: set[int] = set()
    if not SPARE_HELPERS:
        return pids
    tracker = sys.modules.get("multiprocessing.resource_tracker")
    server = sys.modules.get("multiprocessing.forkserver")
    for pid in (getattr(getattr(tracker, "_resource_tracker", None), "_pid", None),
                getattr(getattr(server, "_forkserver", None), "_forkserver_pid", None)):
        if pid:
            pids.add(pid)
    return pids


#: How long the removal of a command's directory is retried (seconds of the clock): a process killed while it
#: wrote there (a worker between the scans and its SIGKILL, or in uninterruptible I/O on a loaded machine, which
#: finishes its system call before it dies) can leave a file in it after a removal, so it is killed again and the
#: removal repeated, `REMOVAL_PAUSE` apart, until the directory is gone or this much time has passed. A count of
#: tries (20, 0.02 s apart) once lost that race under two test suites at once. Costs nothing when the first
#: removal holds, as it nearly always does.
REMOVAL_SECONDS = 5.0
REMOVAL_PAUSE = 0.02


@contextmanager
def command_scope() -> Iterator[str]:
    """Run a command inside a private TMPDIR and a process mark (see the module doc); yields the TMPDIR.

    The clean-up is registered before the signals held while the directory is made are let through, so a
    SIGINT or SIGTERM that arrived meanwhile (delivered as the block ends) still finds it run."""
    from ..io.interrupts import signals_deferred

    token, started = new_token(), _now_ticks()
    saved = {k: os.environ.get(k) for k in ("TMPDIR", SCOPE_MARK)}
    saved_tempdir = tempfile.tempdir
    with ExitStack() as stack:
        with signals_deferred():
            scope = tempfile.mkdtemp(prefix="foon2pddl-")
            stack.callback(_leave_scope, scope, token, started, saved, saved_tempdir)
            os.environ["TMPDIR"], os.environ[SCOPE_MARK] = scope, token
            tempfile.tempdir = scope
        yield scope


def _leave_scope(scope: str, token: str, started: int, saved: dict[str, str | None], saved_tempdir: str | None) -> None:
    """`command_scope`'s exit: kill what the command started, restore TMPDIR, remove the directory."""
    from ..io.interrupts import signals_deferred

    keep = _interpreter_helpers()

    def kill_started() -> None:
        _kill([p for p in descendants(os.getpid(), started) if p not in keep])
        kill_marked(token, SCOPE_MARK)  # orphans: daemons, children of workers that died first

    with signals_deferred():
        kill_started()
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value
        tempfile.tempdir = saved_tempdir
        deadline = time.monotonic() + REMOVAL_SECONDS
        while True:
            shutil.rmtree(scope, ignore_errors=True)
            if not os.path.lexists(scope) or time.monotonic() >= deadline:
                break
            kill_started()
            time.sleep(REMOVAL_PAUSE)
