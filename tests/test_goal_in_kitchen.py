"""A goal already in the kitchen: every encoding gives a task whose goal holds at the start, an empty plan,
and says so (a regression of 20601e8 left `plan --network gen --goal knife` unsolvable)."""

from __future__ import annotations

import pddl.parser.problem
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, assume, given, settings
from test_pddl_encodings import cases

from foon2pddl.cli import main
from foon2pddl.model.levels import project_node
from foon2pddl.pddl.compile import ENCODINGS, compile_goal
from foon2pddl.pddl.task import PlanningTask

PARSE_PROBLEM = pddl.parser.problem.ProblemParser()

#: (extra CLI arguments, what they run): every registered encoding, and the GEN network (its own lifted encoding).
RUNS = [("--encoding", e) for e in ENCODINGS] + [("--network", "gen")]


def _goal_holds_at_start(task: PlanningTask) -> bool:
    return set(task.goal) <= set(task.init)


@pytest.mark.parametrize("args", RUNS, ids=lambda a: " ".join(a))
def test_plan_of_a_goal_in_the_kitchen_is_empty_and_says_so(args):
    result = CliRunner().invoke(main, ["plan", "--goal", "knife", *args])
    assert result.exit_code == 0, result.output
    assert "solved (" in result.stderr and ": 0 plan steps, 0 units, valid" in result.stderr
    assert "nothing to do: the goal is already available" in result.stdout
    assert "step by step" not in result.stdout  # no empty step list after it


@pytest.mark.parametrize("args", RUNS, ids=lambda a: " ".join(a))
def test_compile_of_a_goal_in_the_kitchen_writes_a_task_whose_goal_holds_in_init(args, tmp_path):
    result = CliRunner().invoke(main, ["compile", "--goal", "knife", *args, "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "the goal already holds in the kitchen: the plan is empty" in result.output
    problem = PARSE_PROBLEM((tmp_path / "problem.pddl").read_text())
    goal = getattr(problem.goal, "operands", (problem.goal,))
    assert goal and set(goal) <= set(problem.init)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(cases())
def test_every_encoding_puts_a_goal_candidate_held_by_the_kitchen_in_init(case):
    foon, kitchen, goal, level = case
    have = kitchen.project(level).nodes
    assume(any(project_node(c, level) in have for c in goal.candidates))
    for encoding in ENCODINGS:
        task = compile_goal(foon, kitchen, goal, encoding, level).task
        assert _goal_holds_at_start(task), encoding


@pytest.mark.parametrize("encoding", ["tree", "gen-lifted", "instances"])
def test_a_batch_says_which_goal_already_holds_and_a_shared_domain_reads_its_problem(encoding, tmp_path):
    import json

    from unified_planning.io import PDDLReader

    shared = () if encoding == "instances" else ("--shared-domain",)  # instances: counts depend on the goal
    result = CliRunner().invoke(main, ["compile", "--goal", "knife", "--goal", "whipped cream", "--encoding", encoding,
                                       *shared, "--format", "jsonl", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    rows = {r["goal"]: r for r in map(json.loads, result.stdout.splitlines())}
    assert rows["knife"]["reason"] == "the goal already holds in the kitchen: the plan is empty"
    assert rows["whipped cream"]["reason"] == ""
    domain = tmp_path / ("domain.pddl" if shared else "knife/domain.pddl")
    problem = PDDLReader().parse_problem(str(domain), str(tmp_path / ("knife.pddl" if shared else "knife/problem.pddl")))
    values = problem.initial_values
    assert problem.goals and all(values.get(g) is not None and values[g].is_true() for g in problem.goals)


def test_a_shared_domain_renames_the_reached_goal_a_kitchen_holds_in_its_problem(tmp_path):
    from unified_planning.io import PDDLReader

    from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
    from foon2pddl.model.goal import Goal, GoalSpec
    from foon2pddl.model.kitchen import Kitchen
    from foon2pddl.pddl.shared import render_shared, share_domain

    whole, chopped = make_node("onion", [make_state("whole")]), make_node("onion", [make_state("chopped")])
    knife, bowl = make_node("knife"), make_node("bowl", [make_state("contains", "", ["onion"])])
    foon = Foon((FunctionalUnit((whole, knife), Motion("chop"), (chopped, knife)),
                 FunctionalUnit((chopped,), Motion("pour"), (bowl,))), 3)
    kitchen = Kitchen(frozenset({whole, knife}), 3)
    held = Goal(GoalSpec("onion"), (chopped, whole), 3)  # two candidates: a goal action each, one in the kitchen
    made = Goal(GoalSpec("bowl"), (bowl,), 3)
    tasks = [(g.describe(), compile_goal(foon, kitchen, g, "tree", prune=False).task) for g in (held, made)]
    assert [len(t.goal) for _, t in tasks] == [1, 1] and _goal_holds_at_start(tasks[0][1])
    domain, problems = render_shared(share_domain(tasks))
    (tmp_path / "domain.pddl").write_text(domain)
    for i, text in enumerate(problems):
        (tmp_path / f"{i}.pddl").write_text(text)
    first = PDDLReader().parse_problem(str(tmp_path / "domain.pddl"), str(tmp_path / "0.pddl"))
    assert all(first.initial_values[g].is_true() for g in first.goals)
    second = PDDLReader().parse_problem(str(tmp_path / "domain.pddl"), str(tmp_path / "1.pddl"))
    assert not any(second.initial_values[g].is_true() for g in second.goals)
