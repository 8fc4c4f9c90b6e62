"""`plan --encoding tree` prints what `plan` printed while `tree` was its default encoding.

The files in `tests/data/plan-tree/` are `plan`'s output at 3fbb13a, when `tree` was its default, captured with
`normalised` below (stdout, then stderr without the `phases:` timing line; the JSON without its `timings`).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SHARED, SUBGRAPHS

from foon2pddl.cli import main

GOLDEN = SHARED / "plan-tree"
WHIPPED = str(SUBGRAPHS / "0001-whipped_cream.txt")
APPLE = str(SUBGRAPHS / "0086-apple_turnover.txt")

#: name -> the `plan` arguments whose output (then, with the default encoding) the golden file holds.
CASES = {
    "guacamole-recipe": ["--goal", "guacamole"],
    "guacamole-steps": ["--goal", "guacamole", "--format", "steps"],
    "guacamole-json": ["--goal", "guacamole", "--format", "json"],
    "whipped-foon": ["--goal", "whipped cream", "--format", "foon", WHIPPED],
    "batch-jsonl": ["--goal", "guacamole", "--goal", "lemonade", "--goal", "tomato soup", "--format", "jsonl"],
    "lemonade-unsolvable": ["--goal", "lemonade"],
    "lemonade-gen": ["--goal", "lemonade", "--network", "gen"],
    "guacamole-constraints": ["--goal", "guacamole", "--without-motion", "squeeze"],
}


def run(*args: str):
    result = CliRunner().invoke(main, ["plan", *args])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exception
    return result


def normalised(result) -> str:
    """Exit status, stdout and stderr, without what depends on the machine's speed (phase timings, a batch
    row's seconds)."""
    out = result.stdout
    if out.startswith("{\n"):
        data = json.loads(out)
        data.pop("timings")
        out = json.dumps(data, indent=2) + "\n"
    elif out.startswith("{"):
        rows = [json.loads(line) for line in out.splitlines()]
        out = "".join(json.dumps({k: v for k, v in row.items() if k != "seconds"}) + "\n" for row in rows)
    err = "".join(line for line in result.stderr.splitlines(keepends=True) if not line.startswith("phases: "))
    return f"exit {result.exit_code}\n--- stdout\n{out}--- stderr\n{err}"


@pytest.mark.parametrize("name", sorted(CASES))
def test_encoding_tree_prints_what_the_old_default_printed(name):
    assert normalised(run(*CASES[name], "--encoding", "tree")) == (GOLDEN / f"{name}.txt").read_text()


def capture(directory: Path) -> None:
    """Write the golden files from `plan` as it is now (run once, at the commit the module docstring names)."""
    directory.mkdir(parents=True, exist_ok=True)
    for name, args in CASES.items():
        (directory / f"{name}.txt").write_text(normalised(run(*args)))

