"""Planner names checked first, --planner-cmd resolved in the caller's directory, and presets that run."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main
from foon2pddl.errors import UsageError
from foon2pddl.planners.commands import PRESETS, resolve_command
from foon2pddl.planners.registry import PLANNERS, Planner, PlanRequest, lookup, register


def run(*args: str):
    return CliRunner().invoke(main, list(args))


def test_unknown_planner_fails_before_loading_anything():
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-m", "foon2pddl", "plan", "--goal", "guacamole",
                           "--planner", "pyperplna"], capture_output=True, text=True, env=env, check=False)
    assert done.returncode == 2
    assert "unknown planner 'pyperplna'; did you mean 'pyperplan'?" in done.stderr
    assert "phases:" not in done.stderr and "Traceback" not in done.stderr


def test_built_in_planner_names_are_checked_without_unified_planning():
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    code = "from foon2pddl.planners.registry import lookup; import sys; lookup('fd').check('fd'); " \
           "print('unified_planning' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    assert done.stdout.strip() == "False"


def check(name: str) -> None:
    lookup(name).check(name)


def test_planner_names():
    check("fd")
    check("pyperplan")
    with pytest.raises(UsageError, match="not installed"):
        check("lpg")
    with pytest.raises(UsageError, match="unknown planner 'up_grounder'"):
        check("up_grounder")  # an engine, but not a planner
    assert lookup("fd") is PLANNERS["fd"] and lookup("fd", "some command") is PLANNERS["command"]
    assert PLANNERS["fd"].configurable and not lookup("pyperplan").configurable


def test_an_engine_added_to_unified_planning_is_a_planner():
    """UP's own extension point (`factory.add_engine`) is enough: no list of ours to edit."""
    from unified_planning.shortcuts import get_environment

    from foon2pddl.pddl.up_problem import quiet_environment

    name = "pyperplan-again-for-test"
    factory = quiet_environment().factory
    assert factory is get_environment().factory
    with pytest.raises(UsageError, match="unknown planner"):
        check(name)
    factory.add_engine(name, "up_pyperplan.engine", "EngineImpl")
    check(name)
    r = run("plan", "--goal", "guacamole", "--encoding", "tree", "--planner", name)  # pyperplan: no conditional effects
    assert r.exit_code == 0, r.stderr
    assert f"solved (up:{name})" in r.stderr


def test_a_registered_planner_runs_through_run_planner():
    from foon2pddl.planners import run_planner
    from foon2pddl.planners.result import PlanResult

    seen = []

    def solve(request: PlanRequest) -> PlanResult:
        seen.append((request.name, request.optimal))
        return PlanResult("unsolvable", (), request.name, "proved nothing, said no")

    register(Planner("say-no", "a planner that never finds a plan", solve, lambda name: None))
    try:
        result = run_planner(None, "", "", planner="say-no", optimal=True)
        r = run("plan", "--goal", "guacamole", "--planner", "say-no")
    finally:
        del PLANNERS["say-no"]
    assert result.status == "unsolvable" and seen[0] == ("say-no", True)
    assert r.exit_code == 1 and "unsolvable (say-no): proved nothing, said no" in r.stderr


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
        r = run("plan", "--goal", "guacamole", "--encoding", "tree", "--planner-cmd", cmd)  # pyperplan: STRIPS only
        assert r.exit_code == 0, (cmd, r.stderr)
        assert "solved (external" in r.stderr
    missing = run("plan", "--goal", "guacamole", "--planner-cmd", "./nope.sh {domain} {problem}")
    assert missing.exit_code == 2 and "no executable './nope.sh'" in missing.stderr
    assert "Invalid value for '--planner-cmd': " in missing.stderr  # quoted as click quotes '--goal'
    assert "phases:" not in missing.stderr


@pytest.mark.parametrize("preset", sorted(PRESETS))
def test_every_preset_runs_and_is_documented(preset):
    r = run("plan", "--goal", "guacamole", "--encoding", "tree", "--planner-cmd", preset)  # every preset reads STRIPS
    assert r.exit_code == 0, r.stderr
    assert f"solved (external ({preset})): " in r.stderr and "20 units, valid" in r.stderr
    doc = (ROOT / "docs" / "planning.md").read_text()
    assert f"| `{preset}` | `{PRESETS[preset].template}` |" in doc


def test_a_planner_that_dies_in_python_says_its_exception_not_a_cut_traceback():
    """Stop 56's newcomer pass: pyperplan refusing the relational encoding's `forall` printed the last 8 lines of
    its stderr, a traceback cut mid-stack (`node.effect.accept(self)`, three `File "..."` frames); the planner's
    message is its exception line, and the reason line follows (docs/planning.md)."""
    r = run("plan", "--goal", "whipped cream", "--planner-cmd", "pyperplan")
    assert r.exit_code == 2
    error = next(line for line in r.stderr.splitlines() if line.startswith("error (external (pyperplan))"))
    assert error.endswith("SemanticError: 'Error: unknown predicate forall used in effect of action'"), error
    assert 'File "' not in r.stderr and "node.effect.accept" not in r.stderr, r.stderr
    assert "reason: the relational encoding's actions have conditional effects" in r.stderr


def test_tail_of_a_traceback_is_its_exception():
    from foon2pddl.planners.result import tail

    text = "\n".join(["search ...", "Traceback (most recent call last):", '  File "a.py", line 3, in <module>',
                      "    main()", '  File "b.py", line 9, in main', "    raise ValueError(", "ValueError: bad",
                      "  more of the message"])
    assert tail(text) == "ValueError: bad\n  more of the message"
    assert tail("line 1\nline 2") == "line 1\nline 2"  # no traceback: the last lines as they are
