"""Retrieval on the universal FOON of the shared subgraphs (level 3, default kitchen) and its CLI."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.io.kitchen_files import read_kitchen, write_kitchen
from foon2pddl.io.parser import parse_text
from foon2pddl.io.writer import write_node
from foon2pddl.model.goal import Goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.model.levels import project
from foon2pddl.model.tasktree import TaskTree, validate
from foon2pddl.retrieval import reachable, retrieve
from foon2pddl.retrieval.result import UNREACHABLE


@pytest.fixture(scope="module")
def setting(universal):
    foon = universal[0]
    kitchen = default_kitchen(foon).nodes
    return foon, kitchen, reachable(foon, kitchen)


def exact_goal(node, level=3):
    return Goal(spec_of_node(node), (node,), level)


def test_every_reachable_goal_gets_a_valid_complete_tree(setting):
    foon, kitchen, reach = setting
    produced = sorted(foon.producers)
    made = 0
    for node in produced:
        result = retrieve(foon, kitchen, exact_goal(node), "complete")
        if reach.can_make(node):
            made += 1
            assert result.tree is not None and result.tree.goal == node
            check = validate(result.tree, kitchen)
            assert check.ok, (node.describe(), check.problems)
        else:
            assert result.tree is None and result.reason == UNREACHABLE and result.detail
    assert 0 < made < len(produced)  # the data has both kinds


def test_greedy_terminates_and_its_trees_validate(setting):
    foon, kitchen, reach = setting
    for node in sorted(foon.producers):
        result = retrieve(foon, kitchen, exact_goal(node), "greedy")
        # greedy gives up only when nothing more can be made, so it finds a tree whenever one exists
        assert (result.tree is not None) == reach.can_make(node), node.describe()
        if result.tree is not None:
            assert validate(result.tree, kitchen).ok, node.describe()


def test_optimal_on_dishes_is_valid_and_no_larger(setting):
    foon, kitchen, reach = setting
    dishes = sorted({n for u in foon.units for n in u.outputs if n.dish is not None and reach.can_make(n)})
    assert dishes
    for node in dishes[:15]:
        goal = exact_goal(node)
        best = retrieve(foon, kitchen, goal, "optimal")
        assert validate(best.tree, kitchen).ok
        assert len(best.tree) <= min(len(retrieve(foon, kitchen, goal, m).tree) for m in ("complete", "greedy"))


def test_unreachable_goal_exits_1_with_the_reason(setting, tmp_path):
    foon, _, reach = setting
    node = next(n for n in sorted(foon.producers) if not reach.can_make(n))
    goal_file = tmp_path / "goal.txt"
    goal_file.write_text(write_node(node))
    for method in ("complete", "greedy", "optimal"):
        run = CliRunner().invoke(main, ["retrieve", str(SUBGRAPHS), "--goal-file", str(goal_file),
                                        "--method", method])
        assert run.exit_code == 1, run.output
        assert "unreachable" in run.stderr and node.label in run.stderr
        assert run.stdout == ""


@pytest.mark.parametrize("level", [3, 2])
def test_foon_output_reparses_and_runs_from_the_kitchen_file(setting, tmp_path, level):
    foon, kitchen, reach = setting
    at_level = project(foon, level)
    kitchen_file = tmp_path / "kitchen.txt"  # FOON-style O/S lines
    kitchen_file.write_text(write_kitchen(default_kitchen(at_level)))
    given = read_kitchen(kitchen_file).project(level).nodes
    level_reach = reachable(at_level, given)
    dishes = sorted({n for u in at_level.units for n in u.outputs if n.dish is not None and level_reach.can_make(n)})
    for method, node in zip(("complete", "greedy", "optimal"), dishes[:3], strict=False):
        goal_file = tmp_path / "goal.txt"
        goal_file.write_text(write_node(node))
        run = CliRunner().invoke(main, ["retrieve", str(SUBGRAPHS), "--level", str(level), "--kitchen",
                                        str(kitchen_file), "--goal-file", str(goal_file), "--method", method,
                                        "--format", "foon"])
        assert run.exit_code == 0, run.stderr
        units = parse_text(run.stdout, "<tree>").foon.units
        assert units and node in units[-1].outputs
        check = validate(TaskTree(units, node, level), given)
        assert check.ok, check.problems
