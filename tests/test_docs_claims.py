"""What the docs say in prose about a transcript, and the files their commands read, hold for a new user's clone.

The transcripts themselves are checked line by line (test_docs_transcripts.py); these are the claims
around them that a reader acts on: the step a paragraph points to, and whether a command shown can be
run from a fresh clone as written (only the reader's own files may be missing).
"""

from __future__ import annotations

import re
import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from bench.doc_commands import PAGES, documented_commands, missing_inputs
from foon2pddl.cli import main

#: A paragraph's pointer into the transcript under it: "... poured into the avocado's bowl at step 10".
_AT_STEP = re.compile(r"(pour\w*)[^.:]*? at step (\d+)", re.S)


def _pointed_steps() -> list[tuple[str, str, str, int]]:
    """(page, command, verb, step) for every "<verb> ... at step N" in the prose just above a transcript."""
    out = []
    for page in PAGES:
        text = page.read_text()
        for block in re.finditer(r"^```\n\$ foon2pddl (.*)$", text, re.M):
            before = text[:block.start()].rstrip().rsplit("\n\n", 1)[-1]  # the paragraph above the block
            for m in _AT_STEP.finditer(before):
                out.append((page.name, block.group(1), m.group(1), int(m.group(2))))
    return out


POINTED = _pointed_steps()


def test_the_guacamole_pours_are_pointed_to():
    assert {(page, command) for page, command, _, _ in POINTED} >= {
        ("README.md", "plan --goal guacamole --skills --format recipe"),
        ("skills.md", "plan --goal guacamole --skills")}


@pytest.mark.parametrize(("page", "command", "verb", "step"), POINTED, ids=[f"{p}: {c}" for p, c, _, _ in POINTED])
def test_the_step_a_paragraph_points_to_is_that_step(page, command, verb, step, monkeypatch):
    monkeypatch.chdir(ROOT)
    result = CliRunner().invoke(main, shlex.split(command))
    assert result.exit_code == 0, result.stderr
    line = next((x for x in result.stdout.splitlines() if x.startswith(f"{step}. ")), "")
    assert line.split()[1:2] == [verb.removesuffix("ed")], f"{page} says step {step} is a {verb}; it is: {line!r}"


#: Files the docs name as the reader's own (their recipes, their robot, their planner), not shipped.
READERS_OWN = {"my_recipes/", "index.json", "my-robot.pddl", "my-motions.json", "./my-downward/fast-downward.py"}


def test_every_documented_command_runs_from_a_clone_as_written():
    """A command shown with a file a clone lacks sends a new user looking for it: name the shipped copy."""
    missing = {(c.where, path) for c in documented_commands() for path in missing_inputs(c.text)
               if path not in READERS_OWN}
    assert not missing


def test_skills_md_says_how_long_the_relational_try_takes_by_default():
    """skills.md said the merged subgraphs' black bean "solves under `instances` in ~2 s"; a new user running it
    waited 80 s, since the relational try takes its whole share of the default time limit first."""
    from foon2pddl.cli.plan_cmd import plan_ as plan_command
    from foon2pddl.skills.run import FIRST_SHARE

    default = next(p.default for p in plan_command.params if p.name == "time_limit")
    text = " ".join((ROOT / "docs" / "skills.md").read_text().split())
    assert f"after {default * FIRST_SHARE:g} s, a quarter of the default {default:g} s limit" in text
