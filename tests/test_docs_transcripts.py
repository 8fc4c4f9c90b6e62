"""The command transcripts in docs/generalization.md and the README are what the program prints.

Each `$ foon2pddl ...` line in a fenced block is run; every documented output line
must appear in the command's output: stdout lines in order, stderr lines (notes,
summaries) anywhere. Timing lines (`phases: ...`) vary from run to run and are skipped, and
so is an elision line (`...`). Only transcripts on the embedded example (no PATHS) run here.
"""

from __future__ import annotations

import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main

DOCS = (ROOT / "docs" / "generalization.md", ROOT / "README.md")


def transcripts(text: str) -> list[tuple[str, list[str]]]:
    """(command, documented output lines) for every `$ foon2pddl` line in fenced blocks."""
    out: list[tuple[str, list[str]]] = []
    fenced, transcript = False, False
    for line in text.splitlines():
        if line.startswith("```"):
            fenced, transcript = not fenced, False
        elif fenced and line.startswith("$ foon2pddl "):
            command = line[len("$ foon2pddl "):]
            transcript = "../" not in command  # the embedded example and the shipped test corpus
            if transcript:
                out.append((command, []))
        elif fenced and transcript and line:
            out[-1][1].append(line)
    return out


CASES = [case for doc in DOCS for case in transcripts(doc.read_text())]


def test_the_document_has_transcripts():
    commands = [c for c, _ in CASES]
    assert "retrieve --goal lemonade --network exp" in commands
    assert commands.count("plan --goal lemonade --network gen") == 2  # the README shows it too


@pytest.mark.parametrize(("command", "expected"), CASES, ids=[f"{i}: {c}" for i, (c, _) in enumerate(CASES)])
def test_transcript_matches_the_program(command, expected):
    result = CliRunner().invoke(main, shlex.split(command))
    out, err = result.stdout.splitlines(), result.stderr.splitlines()
    position = 0
    for line in expected:
        if line.startswith("phases: ") or line == "...":
            continue
        if line in out[position:]:
            position = out.index(line, position) + 1
        elif line not in err:
            pytest.fail(f"documented line not printed (in order): {line!r}\nstdout:\n" + "\n".join(out)
                        + "\nstderr:\n" + "\n".join(err))
