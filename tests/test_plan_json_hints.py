"""`plan --format json` carries the hints the text output prints (issue 24 items 1-2: a hint is true and reaches
every output form). Before, a JSON run did not check which network makes the goal: its document had the `reason`
and no hint, where the text run printed `hint: --network exp and --network gen can make it: ...`."""

from __future__ import annotations

import json

from click.testing import CliRunner

from foon2pddl.cli import main


def _run(*args: str):
    return CliRunner().invoke(main, ["plan", *args])


def test_the_json_document_holds_the_hints_the_text_prints(tmp_path, monkeypatch):
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    text = _run("--goal", "lemonade")
    assert text.exit_code == 1
    said = [line.removeprefix("hint: ") for line in text.stderr.splitlines() if line.startswith("hint: ")]
    assert said and said[0].startswith("--network exp and --network gen can make it")
    given = _run("--goal", "lemonade", "--format", "json")
    assert given.exit_code == 1
    out = json.loads(given.stdout)
    assert out["hints"] == said
    assert out["reason"]  # the reason stays where it was
    assert "hint:" not in given.stderr  # the document says it; stderr does not repeat it


def test_a_solved_plan_has_no_hint():
    result = _run("--goal", "guacamole", "--format", "json")
    assert result.exit_code == 0
    assert json.loads(result.stdout)["hints"] == []
