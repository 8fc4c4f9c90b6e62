"""`make install` says what it does (issue 24): `pip install -q` was silent for minutes (4 min 20 s wall, load 6-9,
stop 49's pass), and plain pip prints hundreds of lines. `tools/pip_phases.py` runs pip with its output in a log
file and says each phase on one line; the Makefile runs it, with a line per step of its own."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "pip_phases.py"


@pytest.fixture
def pip_phases(monkeypatch):
    """tools/pip_phases.py as a module (a script, outside the package), for the tests that run its `main`."""
    monkeypatch.syspath_prepend(str(SCRIPT.parent))
    import pip_phases

    return pip_phases


#: What pip prints for an editable install, shortened.
PIP_OUTPUT = """Obtaining file:///work/foon2pddl
  Installing build dependencies: started
WARNING: Location 'file:///opt/x/' is ignored: it is neither a file nor a directory.
Collecting click>=8
  Downloading click-8.1.7-py3-none-any.whl (97 kB)
Collecting jinja2>=3
Requirement already satisfied: markupsafe in ./.venv/lib/python3.11/site-packages
Building wheels for collected packages: foon2pddl
  Building editable for foon2pddl (pyproject.toml): started
Successfully built foon2pddl
Installing collected packages: click, jinja2, foon2pddl
Successfully installed click-8.1.7 foon2pddl-0.1 jinja2-3.1.4
"""


def fake_pip(tmp_path: Path, output: str, status: int = 0) -> list[str]:
    """A command that prints `output` as pip would and exits with `status`."""
    script = tmp_path / "pip_output.txt"
    script.write_text(output)
    return [sys.executable, "-c", f"import sys; sys.stdout.write(open({str(script)!r}).read()); sys.exit({status})"]


def run_phases(tmp_path: Path, command: list[str]) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(SCRIPT), "--log", str(tmp_path / "pip.log"), *command],
                          capture_output=True, text=True, timeout=60)


def test_each_phase_of_pip_is_one_line_and_the_log_keeps_everything(tmp_path):
    done = run_phases(tmp_path, fake_pip(tmp_path, PIP_OUTPUT))
    assert done.returncode == 0, done.stderr
    ticks = re.compile(r"pip: still \w.* \(\d+ s(, \d+ collected)?\) \.\.\.")  # a slow machine's, every TICK s
    assert [s for s in done.stderr.splitlines() if not ticks.fullmatch(s)] == [
        "pip: preparing the project's build ...",
        "pip: collecting the dependencies (downloading any not cached) ...",
        "pip: building ...",
        "pip: installing the packages into the environment (3 packages) ...",
        "pip: done: 3 packages installed",
    ]
    assert done.stdout == ""
    assert (tmp_path / "pip.log").read_text() == PIP_OUTPUT


def test_a_failing_pip_shows_its_errors_and_its_exit_status(tmp_path):
    failed = run_phases(tmp_path, fake_pip(tmp_path, "Collecting nosuch\nERROR: No matching distribution found "
                                                     "for nosuch\n", status=1))
    assert failed.returncode == 1
    said = [s for s in failed.stderr.splitlines() if not s.startswith("pip: still ")]  # a slow machine's ticks
    assert said[:2] == ["pip: collecting the dependencies (downloading any not cached) ...",
                        "pip: ERROR: No matching distribution found for nosuch"]
    assert said[2] == f"pip failed (exit status 1); the end of its output ({tmp_path / 'pip.log'} has it all):"
    assert said[3:] == ["  Collecting nosuch", "  ERROR: No matching distribution found for nosuch"]


def test_a_long_phase_says_it_is_still_running(tmp_path, monkeypatch, capsys, pip_phases):
    monkeypatch.setattr(pip_phases, "TICK", 0.0)
    slow = [sys.executable, "-c", "import time; print('Collecting click', flush=True); time.sleep(2.5)"]
    assert pip_phases.main(["--log", str(tmp_path / "pip.log"), *slow]) == 0
    said = capsys.readouterr().err.splitlines()
    assert said[0] == "pip: collecting the dependencies (downloading any not cached) ..."
    assert said[1].startswith("pip: still collecting the dependencies") and said[1].endswith(", 1 collected) ..."), said


def test_make_install_says_each_step_and_runs_pip_through_the_phases():
    recipe = re.search(r"^\$\(STAMP\):.*?\n((?:\t.*\n)+)", (ROOT / "Makefile").read_text(), re.M).group(1)
    steps = recipe.splitlines()
    said = [s for s in steps if s.startswith("\t@echo ") or "--first " in s]  # make's own line, or the script's
    assert len(said) >= 5, recipe  # system packages, the environment, the packages, bytecode, done
    pips = [s for s in steps if "pip install" in s]
    assert pips and all("pip_phases.py" in s and " -q " not in s for s in pips), pips


def test_a_phase_counts_its_seconds_from_its_own_start(tmp_path, monkeypatch, capsys, pip_phases):
    """Stop 55's pass: `pip: still installing the packages into the environment (58 packages) (60 s) ...` came
    right after the phase began: its seconds counted from pip's start. Here the build phase takes 4 s, then
    collecting runs 2.5 s: collecting's `still` lines count from 0, not from 4."""
    monkeypatch.setattr(pip_phases, "TICK", 0.0)
    slow = [sys.executable, "-c", "import time; print('Obtaining file:///x', flush=True); time.sleep(4); "
                                  "print('Collecting click', flush=True); time.sleep(2.5)"]
    assert pip_phases.main(["--log", str(tmp_path / "pip.log"), *slow]) == 0
    said = capsys.readouterr().err.splitlines()
    building = [int(re.search(r"\((\d+) s\) \.\.\.$", s).group(1)) for s in said if s.startswith("pip: still prep")]
    collecting = [int(re.search(r"\((\d+) s, 1 collected\)", s).group(1)) for s in said
                  if s.startswith("pip: still collecting")]
    assert building and collecting, said
    assert max(building) >= 3 and collecting[0] <= 2 and collecting == sorted(collecting), said


def test_a_phase_says_it_still_runs_within_the_clis_beat(pip_phases):
    """Issue 24's floor (no 2 s without a line on stderr), which the CLI meets through a pipe with a line every
    `cli.progress.BEAT` s: `make install` said a pip phase was still running only every 30 s (a fresh clone at
    40ca45c, load 8: 30.3 s twice while installing the 58 packages, 11.2 s while collecting)."""
    assert pip_phases.TICK < 2.0  # the floor (conftest sets the CLI's BEAT to an hour for every test)


def test_a_command_without_pip_phases_is_one_phase_that_says_it_still_runs(tmp_path, monkeypatch, capsys, pip_phases):
    """`python3 -m venv .venv` (make install's step 2) went 13.5 s without a line at load 8 (the same clone): run
    through the script as one named phase, it says it is still running, under make install's name."""
    monkeypatch.setattr(pip_phases, "TICK", 0.0)
    quiet = [sys.executable, "-c", "import time; time.sleep(2.5)"]
    assert pip_phases.main(["--log", str(tmp_path / "venv.log"), "--who", "make install", "--phase",
                            "creating a virtual environment in .venv", *quiet]) == 0
    said = capsys.readouterr().err.splitlines()
    assert said and all(re.fullmatch(r"make install: still creating a virtual environment in \.venv \(\d+ s\) \.\.\.",
                                     s) for s in said), said


@pytest.mark.parametrize("runs", ["-m venv", "-m compileall"])
def test_make_install_creates_the_environment_and_the_bytecode_through_the_phases(runs):
    """The bytecode's compiling went 1.97 s without a line at load 10 (a fresh clone at fed2021): it ticks too."""
    recipe = re.search(r"^\$\(STAMP\):.*?\n((?:\t.*\n)+)", (ROOT / "Makefile").read_text(), re.M).group(1)
    lines = [s for s in recipe.splitlines() if runs in s]
    assert lines and all("pip_phases.py" in s and "--phase" in s for s in lines), lines


def test_pip_after_done_is_finishing_not_still_done(tmp_path, monkeypatch, capsys, pip_phases):
    """With the 1.5 s tick, pip's exit after `Successfully installed` said `pip: still done: 58 packages installed
    (2 s) ...` (the same clone): what runs then is pip finishing. The fake pip starts slowly, as a loaded machine's
    does: since 3b3a53b its start ticks `still starting` before the first line (rv56: this test then failed on
    `said[0]` whenever the child took over 0.25 s to print)."""
    monkeypatch.setattr(pip_phases, "TICK", 0.0)
    slow = [sys.executable, "-c", "import time; time.sleep(0.6); print('Successfully installed click-8.1.7', "
                                  "flush=True); time.sleep(2.5)"]
    assert pip_phases.main(["--log", str(tmp_path / "pip.log"), *slow]) == 0
    said = capsys.readouterr().err.splitlines()
    done = said.index("pip: done: 1 package installed")
    assert all(re.fullmatch(r"pip: still starting \(\d+ s\) \.\.\.", s) for s in said[:done]), said
    assert len(said) > done + 1, said
    assert all(re.fullmatch(r"pip: still finishing \(\d+ s\) \.\.\.", s) for s in said[done + 1:]), said


def test_pip_starting_says_it_still_starts(tmp_path, monkeypatch, capsys, pip_phases):
    """pip's start before its first line (its imports) went 1.6-1.8 s without a line at load 7 (a fresh clone at
    16e1306), over 2 s under more load: it is a phase too, `starting`, said only if it lasts."""
    monkeypatch.setattr(pip_phases, "TICK", 0.0)
    slow = [sys.executable, "-c", "import time; time.sleep(2.5); print('Collecting click', flush=True)"]
    assert pip_phases.main(["--log", str(tmp_path / "pip.log"), *slow]) == 0
    said = capsys.readouterr().err.splitlines()
    first = said.index("pip: collecting the dependencies (downloading any not cached) ...")
    assert first > 0 and all(re.fullmatch(r"pip: still starting \(\d+ s\) \.\.\.", s) for s in said[:first]), said


def test_the_pip_upgrade_and_the_install_are_one_run_of_the_phases():
    """Two runs of pip_phases left 2.2 s without a line between the upgrade's `done` and the install's first phase
    (a fresh clone at 3b3a53b, load 8): the upgrade's exit, then a new process whose first tick comes TICK s after
    its start. One run (both pips in one shell command) ticks across the seam."""
    recipe = re.search(r"^\$\(STAMP\):.*?\n((?:\t.*\n)+)", (ROOT / "Makefile").read_text(), re.M).group(1)
    runs = [s for s in recipe.splitlines() if "pip_phases.py" in s and "pip install" in s]
    assert len(runs) == 1 and "--upgrade pip" in runs[0] and "-e '.[test,gen,experiment]'" in runs[0], runs


def test_each_step_of_make_install_is_said_by_the_process_that_runs_it():
    """Issue 24's last pass: `make install`'s first tick came 2.08 s after the step's line at load 6: make echoed
    the step, then the script started (an interpreter under load) and ticked only TICK s after its own start.
    The script says the step's line itself, at once, so its first tick comes TICK s after that line."""
    recipe = re.search(r"^\$\(STAMP\):.*?\n((?:\t.*\n)+)", (ROOT / "Makefile").read_text(), re.M).group(1)
    lines = [s.strip() for s in recipe.splitlines() if not s.strip().startswith("@#")]
    runs = [k for k, s in enumerate(lines) if "pip_phases.py" in s]
    assert len(runs) == 3 and all("--first" in lines[k] for k in runs), lines
    assert not any(lines[k - 1].startswith("@echo") for k in runs), lines


def test_the_first_line_comes_before_the_command_runs(tmp_path, monkeypatch, capsys, pip_phases):
    monkeypatch.setattr(pip_phases, "TICK", 3600.0)
    mark = tmp_path / "ran"
    quiet = [sys.executable, "-c", f"open({str(mark)!r}, 'w').close()"]
    assert pip_phases.main(["--log", str(tmp_path / "venv.log"), "--first", "make install: 2/4 a virtual "
                            "environment ...", "--who", "make install", "--phase", "creating it", *quiet]) == 0
    assert capsys.readouterr().err.splitlines() == ["make install: 2/4 a virtual environment ..."]
    assert mark.exists()
