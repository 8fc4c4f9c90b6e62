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
