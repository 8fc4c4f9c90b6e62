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
