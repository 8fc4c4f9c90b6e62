"""The CLI process leaves without the interpreter's teardown (`__main__.leave`), and loses nothing by it:
exit codes, every byte written to a pipe, the atexit handlers."""

from __future__ import annotations

import os
import subprocess
import sys

from click.testing import CliRunner
from conftest import ROOT, SUBGRAPHS

from foon2pddl.cli import main


def _python(code: str, *args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, env=env, timeout=300)


def test_large_output_through_a_pipe_is_complete_and_the_exit_code_kept():
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-m", "foon2pddl", "goals", str(SUBGRAPHS)], capture_output=True,
                          text=True, env=env, timeout=300)
    here = CliRunner().invoke(main, ["goals", str(SUBGRAPHS)])
    assert proc.returncode == here.exit_code == 0
    assert len(proc.stdout) > 100_000 and proc.stdout == here.stdout
    bad = subprocess.run([sys.executable, "-m", "foon2pddl", "goals", "--nope"], capture_output=True, text=True,
                         env=env, timeout=300)
    assert bad.returncode == 2 and "No such option" in bad.stderr


SCRIPT = """
import atexit, sys
from foon2pddl.__main__ import run

class Freed:
    def __del__(self):
        print("freed at teardown", flush=True)

kept = Freed()
atexit.register(lambda: print("atexit ran", flush=True))
print("unflushed output", end="")
sys.argv = ["foon2pddl", *sys.argv[1:]]
run()
"""


def test_atexit_handlers_run_buffered_output_is_flushed_and_the_teardown_is_skipped():
    done = _python(SCRIPT, "--version")
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("unflushed output") and "atexit ran" in done.stdout
    assert "freed at teardown" not in done.stdout  # no object-by-object teardown
    usage = _python(SCRIPT, "goals", "--nope")
    assert usage.returncode == 2 and "atexit ran" in usage.stdout and "No such option" in usage.stderr


def test_non_integer_exit_codes_are_printed_and_exit_1_as_the_interpreter_does():
    code = "import sys\nfrom foon2pddl.__main__ import leave\nprint('before')\nleave(sys.argv[1] or None)"
    text = _python(code, "something failed")
    assert (text.returncode, text.stdout, text.stderr) == (1, "before\n", "something failed\n")
    none = _python(code, "")
    assert (none.returncode, none.stdout) == (0, "before\n")


def test_the_silence_budget_counts_from_the_process_start():
    """A command's first `...` line is due `progress.AFTER` seconds after the user started it. The budget counted
    from the console script's first line, after the interpreter's own start-up (0.3 s at load 16, more above), so
    at load 17-18 the scene commands said nothing for 2.2-2.8 s (stop 50's newcomer pass). Here the process idles
    past the budget before the script runs: its first step speaks at once."""
    code = ("import sys, time; time.sleep(1.6); sys.argv = ['foon2pddl', 'retrieve', '--goal', 'guacamole']; "
            "from foon2pddl.__main__ import run; run()")
    proc = _python(code)
    assert proc.returncode == 0 and proc.stderr.splitlines()[0].endswith(" ..."), proc.stderr
