"""`foon2pddl retrieve` and `foon2pddl goals` on the embedded example: exit codes, outputs, bad input."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from conftest import SEARCH_INPUTS

from foon2pddl.cli import main
from foon2pddl.io import tree_formats as formats
from foon2pddl.io.inputs import load_kitchen
from foon2pddl.io.parser import parse_text
from foon2pddl.io.writer import write_node
from foon2pddl.model.tasktree import TaskTree, validate
from foon2pddl.retrieval import render_tree, retrieve

RATES = str(SEARCH_INPUTS / "motion.txt")


def run(*args: str):
    return CliRunner().invoke(main, list(args))


@pytest.fixture(scope="module")
def dishes(example):
    """The dish node of every example recipe."""
    return sorted({n for u in example.foon.units for n in u.outputs if n.dish is not None})


@pytest.fixture(scope="module")
def goals_json():
    result = run("goals", "--json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_goals_lists_every_produced_node_with_reachability(example, goals_json):
    rows = goals_json["goals"]
    assert [r["goal"] for r in rows] == [n.describe() for n in sorted(example.foon.producers)]
    assert goals_json["reachable"] == sum(r["reachable"] for r in rows)
    assert all((r["round"] is None) == (not r["reachable"]) for r in rows)


def test_every_dish_but_the_unreachable_lemonade_can_be_made(goals_json, dishes):
    marked = [r for r in goals_json["goals"] if r["dish"]]
    assert [r["goal"] for r in marked] == [d.describe() for d in dishes]
    assert [r["node"]["label"] for r in marked if not r["reachable"]] == ["lemonade"]


def test_goals_text_matches_json(goals_json):
    text = run("goals").stdout.splitlines()
    assert len(text) == len(goals_json["goals"]) + 2  # legend, column header, one row per goal
    assert text[0].startswith(f"reachable: {goals_json['reachable']} of {goals_json['total']} ")


@pytest.mark.parametrize("method", ["complete", "greedy", "optimal", "weighted"])
def test_every_reachable_dish_is_retrieved_and_valid(example, dishes, tmp_path, method):
    kitchen = load_kitchen(None, example, 3).nodes
    for dish in dishes:
        if dish.label == "lemonade":
            continue
        goal_file = tmp_path / "goal.foon"
        goal_file.write_text(write_node(dish))
        result = run("retrieve", "--goal-file", str(goal_file), "--method", method, "--rates", RATES,
                     "--format", "foon")
        assert result.exit_code == 0, result.stderr
        units = parse_text(result.stdout, "<tree>").foon.units
        assert validate(TaskTree(units, dish), kitchen).ok
        if method == "weighted":
            assert "success probability" in result.stderr


def test_lemonade_cannot_be_made_and_says_why():
    for method in ("complete", "greedy", "optimal"):
        result = run("retrieve", "--goal", "lemonade", "--method", method)
        assert result.exit_code == 1
        assert result.stdout == ""
        assert "lemonade" in result.stderr and "unreachable" in result.stderr
    assert "lemon (whole)" in run("retrieve", "--goal", "lemonade").stderr


#: Set cover: the goal needs a, b and c; `add` makes one of them, `mix` two. Complete takes the three
#: `add` units (4 with serve), the optimum is two `mix` units (3), and LM-cut proves only 2 at the root.
SET_COVER = "".join(f"//\nO\tk\t0\nM\tadd\nO\t{x}\t0\n" for x in "abc") + "".join(
    f"//\nO\tk\t0\nM\tmix\nO\t{x}\t0\nO\t{y}\t0\n" for x, y in ("ab", "bc", "ac")) + \
    "//\nO\ta\t0\nO\tb\t0\nO\tc\t0\nM\tserve\nO\tgoal\t0\n//\n"


def test_node_limit_returns_the_best_tree_so_far_marked_unproven(tmp_path):
    path = tmp_path / "cover.foon"
    path.write_text(SET_COVER)
    limited = run("retrieve", str(path), "--goal", "goal", "--method", "optimal", "--node-limit", "1")
    full = run("retrieve", str(path), "--goal", "goal", "--method", "optimal", "--node-limit", "none",
               "--budget", "none")
    assert limited.exit_code == full.exit_code == 0
    assert "not proven optimal (gap 1)" in limited.stderr and "cost 3, lower bound 2" in limited.stderr
    assert "3 units, proven optimal" in full.stderr and "not proven" not in full.stderr
    assert limited.stdout == full.stdout  # the local search found the optimum, only the proof is missing


@pytest.mark.parametrize("flag,value", [("--budget", "-1"), ("--budget", "soon"), ("--node-limit", "1.5")])
def test_bad_search_limits_are_usage_errors(flag, value):
    result = run("retrieve", "--goal", "greek salad", "--method", "optimal", flag, value)
    assert result.exit_code == 2 and flag in result.output


def test_formats_are_deterministic_and_written_atomically(tmp_path):
    for fmt in ("steps", "foon", "json", "dot", "svg"):
        first = run("retrieve", "--goal", "greek salad", "--format", fmt)
        second = run("retrieve", "--goal", "greek salad", "--format", fmt)
        assert first.exit_code == 0 and first.stdout == second.stdout and first.stdout
        out = tmp_path / f"tree.{fmt}"
        written = run("retrieve", "--goal", "greek salad", "--format", fmt, "-o", str(out))
        assert written.exit_code == 0 and written.stdout == ""
        assert out.read_text() == first.stdout


def test_json_and_steps_describe_the_same_tree(example):
    kitchen = load_kitchen(None, example, 3)
    from foon2pddl.io.inputs import load_goal

    tree = retrieve(example.foon, kitchen, load_goal("greek salad", None, example.foon), "complete").tree
    data = json.loads(render_tree(tree, "json", kitchen))
    steps = render_tree(tree, "steps", kitchen).splitlines()
    numbered = [s for s in steps if s[:1].isdigit()]
    assert len(numbered) == len(data["steps"]) == len(tree.units) == data["units"]
    assert [s.split(". ", 1)[1] for s in numbered] == [d["text"] for d in data["steps"]]
    assert [d["motion"] for d in data["steps"]] == [u.motion.label for u in tree.units]
    # the first unit can only use kitchen items, and everything taken from the kitchen is in it
    used = [n["label"] for n in data["from_kitchen"]]
    assert all(n.label in used for n in tree.units[0].inputs)
    assert set(used) <= {n.label for n in kitchen.nodes}


def test_svg_without_graphviz_is_a_clear_error(monkeypatch):
    monkeypatch.setattr(formats.shutil, "which", lambda name: None)
    result = run("retrieve", "--goal", "greek salad", "--format", "svg")
    assert result.exit_code == 2
    assert "Graphviz" in result.stderr and "Traceback" not in result.output


@pytest.mark.parametrize(("args", "needle"), [
    (["--goal", "no such dish"], "unknown object label"),
    (["--goal", "greek salad", "--method", "weighted"], "needs --rates"),
    (["--goal", "greek salad", "--kitchen", "/nonexistent/kitchen.txt"], "kitchen.txt"),
    (["--goal", "greek salad", "--goal-file", "x"], "--goal and --goal-file: give one of them"),
])
def test_bad_input_exits_2(args, needle):
    result = run("retrieve", *args)
    assert result.exit_code == 2
    assert needle in result.stderr and "Traceback" not in result.output


def test_bad_rates_file_names_file_and_line(tmp_path):
    rates = tmp_path / "rates.txt"
    rates.write_text("chop\t0.5\npour\tlots\n")
    result = run("retrieve", "--goal", "greek salad", "--method", "weighted", "--rates", str(rates))
    assert result.exit_code == 2
    assert f"{rates}:2:" in result.stderr and "not a number" in result.stderr


def test_unwritable_output_is_an_error_not_a_traceback(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    result = run("retrieve", "--goal", "greek salad", "-o", str(blocker / "tree.txt"))
    assert result.exit_code == 2 and "cannot write" in result.stderr


def test_render_rejects_unknown_format(example):
    tree = TaskTree((), example.foon.nodes[0])
    with pytest.raises(ValueError):
        render_tree(tree, "pdf")
