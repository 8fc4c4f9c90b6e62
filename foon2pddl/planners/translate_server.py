"""A warm Fast Downward translator: a process that imports the translator once and forks one child per task.

Run as a script (`python translate_server.py`, the wheel's `bin` directory on PYTHONPATH) by
`planners.translator`; of foon2pddl it imports only `fd_speedups`, beside it (four of the translator's
functions rewritten to do less work, the same SAS file). Starting an interpreter and importing
the translator costs ~100 ms of CPU, against ~20 ms for translating a typical FOON goal's
task; a forked child starts in ~2 ms, with the translator's modules loaded and never run, so
every task still gets a pristine translator (its module-level options and counters fresh); the
modules it would import only while running are imported by the server too (`LATE_IMPORTS`).

Protocol, one JSON object a line: a request `{"args": [...], "cwd": DIR, "memory_mb": N|null, "cpu_s": N|null}`
on stdin; the reply `{"pid": P}` as soon as the child runs, then `{"code": C, "cpu": S}` when it ends
(C as `subprocess` reports it: the exit status, or minus the signal that killed it; S the child's CPU seconds). The
child runs in its own session (the caller kills its process group at a time limit), with its
output in `DIR/planner-output.log`, and exits with the codes `python -m fast_downward.translate`
uses (20 out of memory, 21 out of time, 31 input error, 1 on any other exception).
End of stdin ends the server.
"""

from __future__ import annotations

import json
import os
import resource
import signal
import sys
import traceback

OUTPUT_FILE = "planner-output.log"  # the name planners.process uses
#: Modules the translator imports only while it runs: argparse's help formatter (shutil, locale), the input
#: files' encoding, the rule splitting of its Datalog program. Imported by the server, before it forks.
LATE_IMPORTS = ("shutil", "locale", "encodings.latin_1", "fast_downward.translate.split_rules")


def _child(request: dict) -> int:
    """Run the translator on `request` in this (forked) process; its exit code."""
    os.setsid()
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    os.chdir(request["cwd"])
    out = os.open(OUTPUT_FILE, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.dup2(out, 1)
    os.dup2(out, 2)
    sys.stdin = open(0, closefd=False)
    sys.stdout = open(1, "w", closefd=False)
    sys.stderr = open(2, "w", closefd=False)
    if request.get("memory_mb"):
        limit = int(request["memory_mb"]) * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    if request.get("cpu_s"):  # ends the child should its caller die first: the server ends with it, this child not
        limit = int(request["cpu_s"])  # soft; SIGXCPU there is the time limit below, the hard limit a second on
        resource.setrlimit(resource.RLIMIT_CPU, (limit, limit + 1))
    sys.argv = ["translate", *request["args"]]
    from fast_downward.translate import pddl_parser
    from fast_downward.translate.main import main
    from fast_downward.translate.options import set_options

    signal.signal(signal.SIGXCPU, lambda *_: (print("\nTranslator hit the time limit"), os._exit(21)))
    try:
        set_options()
        emergency_memory = b"x" * 10**7  # as the translator's __main__ does
        try:
            main()
        except MemoryError:
            del emergency_memory
            print("\nTranslator ran out of memory, traceback:")
            traceback.print_exc(file=sys.stdout)
            return 20
        except pddl_parser.ParseError as exc:
            print(exc)
            return 31
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    except BaseException:  # noqa: BLE001 - the interpreter would print it and exit 1
        traceback.print_exc()
        return 1
    return 0


def _finish(code: int) -> None:
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        os._exit(code & 0xFF)


def load() -> tuple[str, ...]:
    """Import the translator once, with its rewrites (`fd_speedups`, beside this script: the same SAS
    file, sooner); the rewrites installed."""
    import importlib

    from fast_downward.translate import main, options, pddl_parser  # noqa: F401 - loaded once, run per child
    from fd_speedups import apply

    for name in LATE_IMPORTS:  # what a run would import again in every child (~5 ms of a child's ~20)
        try:
            importlib.import_module(name)
        except ImportError:  # another translator version: its child imports what it needs
            pass
    return apply()


def serve() -> None:
    """Answer requests until stdin ends."""
    load()
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the caller ends us (stdin closed, or killed)
    for line in sys.stdin:
        request = json.loads(line)
        pid = os.fork()
        if pid == 0:
            code = 1
            try:
                code = _child(request)
            finally:
                _finish(code)
        print(json.dumps({"pid": pid}), flush=True)
        _, status, usage = os.wait4(pid, 0)
        print(json.dumps({"code": os.waitstatus_to_exitcode(status), "cpu": usage.ru_utime + usage.ru_stime}),
              flush=True)


if __name__ == "__main__":
    serve()
