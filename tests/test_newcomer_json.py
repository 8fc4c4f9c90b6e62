"""A newcomer's re-pass (issue 24): what `--format json` and batch formats give when a goal cannot be made.

Found in a fresh clone: `plan --goal lemonade --format json` dropped the reason the text output gives (the
kitchen additions), `plan --skills --format json` printed nothing at all for a goal with no plan, and a batch
with `--format json` and no `-o DIR` printed the text table instead.
"""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main


def run(*args: str):
    return CliRunner().invoke(main, [str(a) for a in args])


def test_plan_json_of_an_unreachable_goal_gives_the_reason():
    r = run("plan", "--goal", "lemonade", "--format", "json")
    assert r.exit_code == 1, r.output
    data = json.loads(r.stdout)
    assert data["status"] == "unsolvable"
    assert "smallest kitchen additions that make it: add `lemon (whole)`" in data["reason"]
    solved = json.loads(run("plan", "--goal", "guacamole", "--format", "json").stdout)
    assert solved["status"] == "solved" and solved["reason"] is None


def test_skill_plan_json_of_an_unreachable_goal_is_one_json_document_with_the_reason():
    r = run("plan", "--goal", "lemonade", "--skills", "--format", "json")
    assert r.exit_code == 1, r.output
    data = json.loads(r.stdout)
    assert data["status"] == "unsolvable" and data["ok"] is False and data["skills"] == []
    assert "add `lemon (whole)`" in data["reason"]


@pytest.mark.parametrize("command", ["plan", "retrieve"])
@pytest.mark.parametrize("fmt", ["json", "svg"])
def test_a_batch_with_a_tree_format_and_no_directory_is_a_usage_error(command, fmt):
    r = run(command, "--goal", "guacamole", "--goal", "whipped cream", "--format", fmt)
    assert r.exit_code == 2, r.output
    assert f"--format {fmt}" in r.output and "jsonl" in r.output and "-o DIR" in r.output
    assert "Traceback" not in r.output


def test_a_dish_the_merge_cannot_make_from_its_kitchen_names_the_recipe_file_that_makes_it_alone():
    # the shared subgraphs, merged: the french toast of 0037 starts from `maple syrup (in [bowl])`, which another
    # recipe makes (so no kitchen of the merge holds it) by units that never fire; the file alone makes the dish
    from conftest import SUBGRAPHS

    for command in ("retrieve", "plan"):
        r = run(command, SUBGRAPHS, "--goal", "french toast")
        assert r.exit_code == 1, r.output
        hint = next(line for line in r.stderr.splitlines() if "alone makes it" in line)
        suggested = hint.split("`foon2pddl ", 1)[1].split("`", 1)[0]
        assert suggested.startswith(f"{command} ") and "0037-make_quick_french_toast.txt" in suggested
        import shlex

        again = run(*shlex.split(suggested))
        assert again.exit_code == 0, again.output
    assert not any("alone makes it" in line for line in run("retrieve", "--goal", "lemonade").stderr.splitlines())


def test_retrieve_json_of_a_goal_it_cannot_make_is_a_document_with_the_reason_hints_and_additions(tmp_path,
                                                                                                   monkeypatch):
    """Issue 24's leftover (stop 60): `retrieve --format json` printed no JSON for a goal it cannot make; the text
    output gives the reason and the hint. The document holds them: `status`, `reason` (the words after the text's
    `cannot make ...:`), `hints` (its `hint:` lines' words) and `additions` (each way to add to the kitchen)."""
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    text = run("retrieve", "--goal", "lemonade")
    assert text.exit_code == 1
    said = [line.removeprefix("hint: ") for line in text.stderr.splitlines() if line.startswith("hint: ")]
    assert said and said[0].startswith("--network exp and --network gen can make it")
    r = run("retrieve", "--goal", "lemonade", "--format", "json")
    assert r.exit_code == 1, r.output
    data = json.loads(r.stdout)
    assert data["status"] == "unreachable" and data["method"] == "complete"
    assert data["goal"] == "lemonade"
    cannot = next(line for line in text.stderr.splitlines() if line.startswith("cannot make"))
    assert cannot.endswith(": " + data["reason"]) and "add `lemon (whole)`" in data["reason"]
    assert data["hints"] == said
    (lemon,), = data["additions"]  # one way, one node, in the node schema of the tree's steps
    assert lemon["label"] == "lemon" and lemon["states"] == [{"label": "whole"}]
    assert "hint:" not in r.stderr and "cannot make" not in r.stderr  # the document says them
    out = tmp_path / "tree.json"  # -o FILE gets the document too
    assert run("retrieve", "--goal", "lemonade", "--format", "json", "-o", out).exit_code == 1
    assert json.loads(out.read_text()) == data


def test_retrieve_json_under_a_constraint_that_rules_out_every_tree_has_no_additions():
    r = run("retrieve", "--goal", "guacamole", "--without-motion", "cut", "--format", "json")
    assert r.exit_code == 1, r.output
    data = json.loads(r.stdout)
    assert data["status"] == "unreachable" and data["reason"] and data["additions"] == [] and data["hints"] == []
