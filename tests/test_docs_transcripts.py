"""The command transcripts in docs/generalization.md are what the program prints.

Each `$ foon2pddl ...` line in a fenced block is run; every documented output line
must appear in the command's output: stdout lines in order, stderr lines (notes,
summaries) anywhere. Timing lines (`phases:`) vary and are not documented.
"""

from __future__ import annotations

import re
import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main

DOC = ROOT / "docs" / "generalization.md"


def transcripts(text: str) -> list[tuple[str, list[str]]]:
    """(command, documented output lines) for every `$ foon2pddl` line in fenced blocks."""
    out: list[tuple[str, list[str]]] = []
    for block in re.findall(r"```\n(.*?)```", text, re.S):
        for line in block.splitlines():
            if line.startswith("$ foon2pddl "):
                out.append((line[len("$ foon2pddl "):], []))
            elif out and line and block.lstrip().startswith("$ "):
                out[-1][1].append(line)
    return out


CASES = transcripts(DOC.read_text())


def test_the_document_has_transcripts():
    commands = [c for c, _ in CASES]
    assert "retrieve --goal lemonade --network exp" in commands
    assert "plan --goal lemonade --network gen" in commands


@pytest.mark.parametrize(("command", "expected"), CASES, ids=[c for c, _ in CASES])
def test_transcript_matches_the_program(command, expected):
    result = CliRunner().invoke(main, shlex.split(command))
    out, err = result.stdout.splitlines(), result.stderr.splitlines()
    position = 0
    for line in expected:
        if line in out[position:]:
            position = out.index(line, position) + 1
        elif line not in err:
            pytest.fail(f"documented line not printed (in order): {line!r}\nstdout:\n" + "\n".join(out)
                        + "\nstderr:\n" + "\n".join(err))
