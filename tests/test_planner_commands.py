"""Planner names checked first, --planner-cmd resolved in the caller's directory, and presets that run."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main
from foon2pddl.planners.commands import PRESETS, check_planner, resolve_command


def run(*args: str):
    return CliRunner().invoke(main, list(args))


def test_unknown_planner_fails_first_without_importing_unified_planning():
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-X", "importtime", "-m", "foon2pddl", "plan", "--goal", "guacamole",
                           "--planner", "pyperplna"], capture_output=True, text=True, env=env, check=False)
    assert done.returncode == 2
    assert "unknown planner 'pyperplna'; did you mean 'pyperplan'?" in done.stderr
    assert "phases:" not in done.stderr
    assert "unified_planning" not in done.stderr  # -X importtime lists every module imported


def test_planner_names():
    check_planner("fd")
    check_planner("pyperplan")
    with pytest.raises(ValueError, match="not installed"):
        check_planner("lpg")
    with pytest.raises(ValueError, match="unknown planner 'up_grounder'"):
        check_planner("up_grounder")  # an engine, but not a planner


def test_python_means_this_interpreter_even_without_a_venv(monkeypatch):
    monkeypatch.setenv("PATH", "/nonexistent")
    words = resolve_command("python -m pyperplan {domain} {problem}")
    assert words[0] == sys.executable and words[1:] == ["-m", "pyperplan", "{domain}", "{problem}"]
    with pytest.raises(ValueError, match="not on PATH"):
        resolve_command("no-such-planner {domain} {problem}")


def test_relative_executable_and_arguments_resolve_in_the_callers_directory(tmp_path, monkeypatch):
    script = tmp_path / "tools" / "plan.sh"
    script.parent.mkdir()
    script.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m pyperplan -s gbf -H hff "$@"\n')
    script.chmod(0o755)
    (tmp_path / "wrap.py").write_text("import runpy, sys\nsys.argv = ['pyperplan', *sys.argv[1:]]\n"
                                      "runpy.run_module('pyperplan', run_name='__main__')\n")
    monkeypatch.chdir(tmp_path)
    for cmd in ("tools/plan.sh {domain} {problem}", "python wrap.py -s gbf -H hff {domain} {problem}"):
        r = run("plan", "--goal", "guacamole", "--planner-cmd", cmd)
        assert r.exit_code == 0, (cmd, r.stderr)
        assert "solved (external" in r.stderr
    missing = run("plan", "--goal", "guacamole", "--planner-cmd", "./nope.sh {domain} {problem}")
    assert missing.exit_code == 2 and "no executable './nope.sh'" in missing.stderr
    assert "phases:" not in missing.stderr


@pytest.mark.parametrize("preset", sorted(PRESETS))
def test_every_preset_runs_and_is_documented(preset):
    r = run("plan", "--goal", "guacamole", "--planner-cmd", preset)
    assert r.exit_code == 0, r.stderr
    assert f"solved (external ({preset})): " in r.stderr and "20 units, valid" in r.stderr
    doc = (ROOT / "docs" / "planning.md").read_text()
    assert f"| `{preset}` | `{PRESETS[preset].template}` |" in doc
