"""The committed domains/ and problems/: up to date, parse with two readers, `tree` problems solve with pyperplan."""

from __future__ import annotations

import re

import pddl.parser.domain
import pddl.parser.problem
import pytest
from conftest import ROOT

from foon2pddl.cli import progress
from foon2pddl.cli.examples_cmd import main
from foon2pddl.pddl.compile import GROUND_ENCODINGS, compile_task
from foon2pddl.pddl.examples import GOALS, generate, stale_files
from foon2pddl.pddl.names import sanitize

PAIRS = [(enc, sanitize(goal)) for enc in GROUND_ENCODINGS for goal in GOALS]


def _pair(encoding: str, stem: str):
    return ROOT / "domains" / encoding / f"{stem}.pddl", ROOT / "problems" / encoding / f"{stem}.pddl"


def test_committed_files_are_what_make_pddl_generates(tmp_path):
    files = generate()
    assert len(files) == 2 * len(PAIRS) and len(GOALS) >= 5
    stale = [str(p) for p, text in files.items() if not (ROOT / p).is_file() or (ROOT / p).read_text() != text]
    assert not stale, f"run `make pddl`: out of date: {stale}"
    assert not stale_files(ROOT, files), "run `make pddl`: files no longer generated"
    # Regenerating elsewhere writes the same bytes.
    main([str(tmp_path)])
    for p in files:
        assert (tmp_path / p).read_bytes() == (ROOT / p).read_bytes()


def test_every_committed_file_parses_with_the_pddl_package():
    parse_domain, parse_problem = pddl.parser.domain.DomainParser(), pddl.parser.problem.ProblemParser()
    for encoding, stem in PAIRS:
        domain_path, problem_path = _pair(encoding, stem)
        domain = parse_domain(domain_path.read_text())
        problem = parse_problem(problem_path.read_text())
        assert domain.name == problem.domain_name
        assert domain.actions and problem.goal


@pytest.mark.parametrize("encoding,stem", PAIRS)
def test_every_committed_pair_parses_with_unified_planning(encoding, stem):
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import get_environment

    get_environment().credits_stream = None
    domain_path, problem_path = _pair(encoding, stem)
    problem = PDDLReader().parse_problem(str(domain_path), str(problem_path))
    assert len(problem.actions) == domain_path.read_text().count("(:action ")


@pytest.mark.parametrize("stem", [sanitize(goal) for goal in GOALS])
def test_tree_problems_solve_with_pyperplan(stem):
    from pyperplan.planner import HEURISTICS, SEARCHES, search_plan

    domain_path, problem_path = _pair("tree", stem)
    plan = search_plan(str(domain_path), str(problem_path), SEARCHES["gbf"], HEURISTICS["hff"])
    assert plan, f"pyperplan found no plan for {stem}"
    # Replay: each step's preconditions hold (delete-free) and the goal holds at the end.
    problem = pddl.parser.problem.ProblemParser()(problem_path.read_text())
    facts = {str(a) for a in problem.init}
    for op in plan:
        assert op.preconditions <= facts
        facts |= op.add_effects
    assert all(str(g) in facts for g in getattr(problem.goal, "operands", [problem.goal]))


@pytest.mark.parametrize("goal", GOALS)
def test_instances_problems_solve_with_pyperplan_and_replay_at_the_instance_level(goal):
    from pyperplan.planner import HEURISTICS, SEARCHES, search_plan

    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.pddl.instance_replay import instance_trace
    from foon2pddl.planners.trace_check import check_states

    stem = sanitize(goal)
    domain_path, problem_path = _pair("instances", stem)
    plan = search_plan(str(domain_path), str(problem_path), SEARCHES["gbf"], HEURISTICS["hff"])
    assert plan, f"pyperplan found no plan for {stem}"
    net = load_network([])
    target = load_goal(goal, None, net.at(3))
    task = compile_task(net.at(3), load_kitchen(None, net, 3), target, "instances")
    trace = instance_trace(task, [op.name.strip("()") for op in plan])
    assert check_states(trace, target.candidates).ok


def _committed_encodings():
    return sorted(p.name for p in (ROOT / "domains").iterdir() if p.is_dir())


def test_docs_state_the_committed_file_count():
    count = sum(1 for top in ("domains", "problems") for _ in (ROOT / top).glob("*/*.pddl"))
    text = " ".join((ROOT / "docs" / "pddl.md").read_text().split())
    assert f"all {count} files parse" in text


def test_domains_readme_lists_every_committed_encoding():
    text = (ROOT / "domains" / "README.md").read_text()
    assert [e for e in _committed_encodings() if f"`{e}`" not in text] == []


def test_planning_usage_line_lists_every_encoding():
    from foon2pddl.pddl.compile import ENCODINGS

    usage = next(line for line in (ROOT / "docs" / "planning.md").read_text().splitlines()
                 if line.startswith("foon2pddl plan --goal G"))
    assert f"--encoding {'|'.join(ENCODINGS)}]" in usage


def test_make_pddl_says_on_stderr_what_it_compiles(tmp_path, capsys):
    """`make pddl` ran 10.8 s (load 10) with nothing on stderr: it says which goal it compiles, one line each
    (stdout keeps its one summary line)."""
    main([str(tmp_path)])
    out = capsys.readouterr()
    said = [line for line in out.err.splitlines() if not re.search(r" \.\.\. \d+ s$", line)]  # beats: a slow goal
    assert said == ["loading the PDDL encodings ..."] + [
        f"compiling '{goal}' ({i} of {len(GOALS)}) in {len(GROUND_ENCODINGS)} encodings ..." for i, goal in enumerate(GOALS, 1)]
    assert out.out.splitlines() == [f"wrote {2 * len(PAIRS)} files under {tmp_path / 'domains'} and "
                                    f"{tmp_path / 'problems'}"]


def test_make_pddl_speaks_before_loading_the_encodings():
    """Stop 51's pass (nc51b): `make pddl` said nothing for 3.1-4.0 s at load 20 (3.8 s at stop 52's): its first line
    came once `foon2pddl.pddl.examples` had imported the encodings and jinja2 (0.5 s of CPU, seconds of wall time
    under load). Importing the module loads neither, so `main` says what it does before they load."""
    import subprocess
    import sys

    code = ("import sys, foon2pddl.cli.examples_cmd; "
            "print(sorted(m for m in ('foon2pddl.pddl.compile', 'foon2pddl.io.inputs', 'jinja2') if m in sys.modules))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.strip() == "[]", r.stdout


def test_make_pddl_beats_through_a_pipe_while_a_goal_compiles(tmp_path, capsys, monkeypatch):
    """Stop 55's pass (nc55b): `make pddl` said each step once and never again, so at load 30 it went 5.3 s after
    `loading the PDDL encodings ...` and 2.2-2.7 s per dish without a line. Each step now adds its seconds every
    `progress.BEAT` s while it runs, as every said step of the CLI does through a pipe."""
    import time

    import foon2pddl.pddl.compile as compile_module

    real, calls = compile_module.compile_task, []

    def slow_first(*args, **kwargs):
        calls.append(1)
        if len(calls) == 1:
            time.sleep(0.5)  # the first goal's first encoding: several beats long
        return real(*args, **kwargs)

    monkeypatch.setattr(progress, "BEAT", 0.05)
    monkeypatch.setattr(compile_module, "compile_task", slow_first)
    main([str(tmp_path)])
    beats = [line for line in capsys.readouterr().err.splitlines()
             if re.fullmatch(rf"compiling '{GOALS[0]}' \(1 of {len(GOALS)}\) in \d+ encodings \.\.\. \d+ s", line)]
    assert len(beats) >= 2, beats
