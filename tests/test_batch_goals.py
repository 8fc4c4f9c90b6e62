"""Batch goals: goal-list formats, one table for many goals, tree files per goal, exit codes."""

from __future__ import annotations

import csv
import io
import json

import pytest
from click.testing import CliRunner
from conftest import SEARCH_INPUTS, SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.batch_report import file_names, slug
from foon2pddl.io.goal_lists import parse_described, parse_goal_list
from foon2pddl.model.foon import make_state


def run(*args: str, input: str | None = None):
    return CliRunner().invoke(main, list(args), input=input)


def test_goal_nodes_json_keeps_states_container_ingredients_and_lines():
    text = '[\n {"label": "Salad", "states": ["mixed"],\n  "ingredients": ["b", "a"], "container": "bowl"},\n' \
           ' {"label": "tea", "states": [], "ingredients": [], "container": null}\n]\n'
    a, b = parse_goal_list(text, "g.json")
    assert a.spec.label == "salad" and a.line == 2 and b.line == 4
    assert set(a.spec.states) == {make_state("mixed"), make_state("in", "bowl"), make_state("contains", "", ["a", "b"])}
    assert b.spec.states == ()


def test_foon_text_with_several_nodes():
    text = "O1\tonion\t1\nS1\tchopped\n//\nO2\tbowl\t0\nS2\tcontains\t{onion}\n"
    entries = parse_goal_list(text, "g.txt")
    assert [(e.spec.label, e.line) for e in entries] == [("onion", 1), ("bowl", 4)]
    assert entries[1].spec.states == (make_state("contains", "", ["onion"]),)


def test_plain_lines_goal_syntax_described_nodes_and_goals_table_rows():
    text = "reachable: 2 of 9 goal candidates can be made from x (round = ...)\nmade round  dish goal\n" \
           "# goals\nonion: chopped\nbowl (contains {a, b}, in [sink])\nyes      3  *    tea (hot)\n" \
           "no               9 lives: x\n"
    specs = [e.spec.describe() for e in parse_goal_list(text, "g.txt")]
    assert specs == ["onion: chopped", "bowl: contains {a, b}, in [sink]", "tea: hot", "9 lives: x"]


@pytest.mark.parametrize("text, line", [("[1, 2]", 1), ('[\n{"label": ""}]', 2), ("onion: [x\n", 1), ("", 0)])
def test_bad_goal_lists_name_file_and_line(text, line):
    with pytest.raises(FoonSyntaxError) as exc:
        parse_goal_list(text, "g")
    assert exc.value.path == "g" and exc.value.line == line


def test_parse_described_round_trips_describe(example):
    for node in list(example.foon.nodes)[:200]:
        assert parse_described(node.describe()).describe() == (node.label if not node.states else
                                                              f"{node.label}: " + ", ".join(s.describe() for s in node.states))


def test_file_names_are_safe_and_collision_free():
    names = file_names(["Tomato Soup: pureed", "tomato soup pureed", "../../etc/passwd", "", "x-2", "x", "x"], "txt")
    assert len(set(names)) == len(names)
    assert all("/" not in n and not n.startswith(".") for n in names)
    assert names[0] == "tomato-soup-pureed.txt" and names[1] == "tomato-soup-pureed-2.txt"
    assert slug("é!!") == "goal"


def test_repeated_goal_gives_one_table_and_exit_1_when_one_fails(tmp_path):
    r = run("retrieve", "--goal", "guacamole", "--goal", "lemonade", "--format", "jsonl", "-o", str(tmp_path / "t"))
    assert r.exit_code == 1, r.output
    rows = [json.loads(line) for line in r.stdout.splitlines()]
    assert [row["status"] for row in rows] == ["solved", "unreachable"]
    for row in rows:
        assert {"goal", "status", "units", "seconds", "reason"} <= set(row)
    assert rows[0]["units"] > 0 and rows[1]["units"] is None and "lemon" in rows[1]["reason"]
    files = sorted(p.name for p in (tmp_path / "t").iterdir())
    assert files == ["guacamole.txt"]
    single = run("retrieve", "--goal", "guacamole")
    assert (tmp_path / "t" / "guacamole.txt").read_text() == single.stdout


def test_a_batch_that_writes_no_tree_leaves_no_directory(tmp_path):
    """-o DIR is made only when a tree is written: a batch with no tree leaves no empty DIR (no half output)."""
    r = run("retrieve", "--goal", "lemonade", "--goal", "unicorn stew", "-o", str(tmp_path / "trees"))
    assert r.exit_code == 1 and "unmatched" in r.stdout and "unreachable" in r.stdout
    assert not (tmp_path / "trees").exists()


def test_all_solved_exits_0_and_csv_has_a_row_per_goal():
    r = run("retrieve", "--goal", "guacamole", "--goal", "guacamole", "--format", "csv")
    assert r.exit_code == 0, r.output
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    assert [row["status"] for row in rows] == ["solved", "solved"]


def test_goals_reachable_output_piped_back(tmp_path):
    listed = run("goals", "--reachable")
    assert listed.exit_code == 0
    r = run("retrieve", "--goals", "-", "--format", "jsonl", input=listed.stdout)
    assert r.exit_code == 0, r.output
    rows = [json.loads(line) for line in r.stdout.splitlines()]
    assert len(rows) == len(listed.stdout.splitlines()) - 2 and all(row["status"] == "solved" for row in rows)


def test_unknown_goal_in_batch_is_a_row_not_an_error():
    r = run("retrieve", "--goal", "guacamole", "--goal", "unicorn stew", "--format", "jsonl")
    assert r.exit_code == 1
    assert json.loads(r.stdout.splitlines()[1])["status"] == "unmatched"


def test_bad_goal_list_exits_2_with_location(tmp_path):
    bad = tmp_path / "g.json"
    bad.write_text('[\n{"label": 3}\n]\n')
    r = run("retrieve", "--goals", str(bad))
    assert r.exit_code == 2 and f"{bad}:2: error:" in r.stderr


def test_single_goal_output_unchanged_by_batch_support():
    r = run("retrieve", "--goal", "guacamole", "--method", "optimal")
    assert r.exit_code == 0 and r.stdout.startswith("task tree for guacamole")
    assert r.stderr.strip().startswith("optimal: 20 units")


def test_search_inputs_batch_every_tree_validates():
    for containment in ("strict", "infer"):
        r = run("retrieve", str(SUBGRAPHS), "--kitchen", str(SEARCH_INPUTS / "kitchen.json"),
                "--goals", str(SEARCH_INPUTS / "goal_nodes.json"), "--containment", containment,
                "--level", "2", "--format", "jsonl")
        rows = [json.loads(line) for line in r.stdout.splitlines()]
        assert len(rows) == 25 and r.exit_code == 1
        assert not [row for row in rows if row["status"] == "invalid"]
        assert sum(row["status"] == "solved" for row in rows) >= 1


def test_compile_batch_writes_one_directory_per_goal(tmp_path):
    r = run("compile", "--goal", "guacamole", "--goal", "unicorn stew", "--format", "jsonl", "-o", str(tmp_path))
    assert r.exit_code == 1, r.output
    rows = [json.loads(line) for line in r.stdout.splitlines()]
    assert [row["status"] for row in rows] == ["compiled", "unmatched"]
    single = tmp_path / "single"
    assert run("compile", "--goal", "guacamole", "-o", str(single)).exit_code == 0
    for name in ("domain.pddl", "problem.pddl"):
        assert (tmp_path / "guacamole" / name).read_text() == (single / name).read_text()


def test_plan_batch_table_and_trees(tmp_path):
    r = run("plan", "--goal", "guacamole", "--goal", "lemonade", "--format", "jsonl", "-o", str(tmp_path / "t"))
    assert r.exit_code == 1, r.output
    rows = [json.loads(line) for line in r.stdout.splitlines()]
    assert [row["status"] for row in rows] == ["solved", "unsolvable"]
    assert rows[0]["units"] > 0 and (tmp_path / "t" / "guacamole.txt").read_text().startswith("task tree for")
