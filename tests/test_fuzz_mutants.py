"""Bounded, seeded mutation fuzzing of the shared subgraphs through `stats`, `retrieve` and `compile`.

Each mutant is one of the 100 subgraph files with a few random edits of the kinds
issue 11's campaign used: lines deleted, duplicated, swapped or truncated, fields
replaced by huge integers or hostile text (control characters, U+2028, brackets,
tabs, `//`), invalid UTF-8 bytes. Every mutant runs in-process through the CLI
(one command each, in turn): the outcome must be exit 0, 1 or 2, never an
exception, and every error must name `path:line` with a line inside the file.
`make test` runs MUTANTS (500) mutants; `make fuzz` runs 10,000
(FOON2PDDL_MUTANTS=10000).
"""

from __future__ import annotations

import os
import random
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main

MUTANTS = int(os.environ.get("FOON2PDDL_MUTANTS", "500"))
SEED = int(os.environ.get("FOON2PDDL_FUZZ_SEED", "11"))
ERROR = re.compile(r"^(?P<path>.+?):(?P<line>\d+): error: ", re.M)

HOSTILE = ["9" * 5000, "\x00", "\x1b[31m", "\u2028", "\u2029", "\x85", "[", "]", "{", "}", "{a,[b]}", "\t", "//",
           "#", "!", "*", "M", "O", "S", "(", ")", ";", "-1", "0" * 4400 + "1", "é", "\ufeff", " " * 300,
           "<Assumed>", "S\tx\t[y]\t{z}", "O\tq\t1\t2\t3"]


def mutate(text: str, rng: random.Random) -> bytes:
    """A few random edits of a FOON file's text (as bytes: some edits break the UTF-8)."""
    lines = text.split("\n")
    for _ in range(rng.randint(1, 4)):
        i = rng.randrange(len(lines))
        op = rng.randrange(9)
        if op == 0:
            del lines[i]
        elif op == 1:
            lines.insert(i, lines[i])
        elif op == 2:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif op == 3:
            lines[i] = lines[i][: rng.randrange(len(lines[i]) + 1)]
        elif op in (4, 5):
            fields = lines[i].split("\t")
            fields[rng.randrange(len(fields))] = rng.choice(HOSTILE)
            lines[i] = "\t".join(fields)
        elif op == 6:
            pos = rng.randrange(len(lines[i]) + 1)
            lines[i] = lines[i][:pos] + rng.choice(HOSTILE) + lines[i][pos:]
        elif op == 7:
            lines.insert(i, rng.choice(HOSTILE))
        else:
            lines = lines[: i + 1]
        if not lines:
            lines = [""]
    data = "\n".join(lines).encode("utf-8", "surrogatepass")
    if rng.random() < 0.05:
        pos = rng.randrange(len(data) + 1)
        data = data[:pos] + rng.choice([b"\xff", b"\xc3", b"\xed\xa0\x80"]) + data[pos:]
    return data


def _goal_of(text: str) -> str:
    """A label the file's last unit makes (the goal asked of its mutant)."""
    outputs = re.findall(r"^O\d*\t([^\t\n]+)", text, re.M)
    return outputs[-1].strip() if outputs else "x"


def check_mutant(path: Path, data: bytes, command: str, goal: str, out_dir: Path) -> None:
    path.write_bytes(data)
    args = {"stats": ["stats", str(path)],
            "retrieve": ["retrieve", "--goal", goal, str(path)],
            "compile": ["compile", "--goal", goal, "-o", str(out_dir), str(path)]}[command]
    result = CliRunner().invoke(main, args)
    where = f"{command} on mutant {data[:300]!r}"
    assert result.exception is None or isinstance(result.exception, SystemExit), (where, repr(result.exception))
    assert result.exit_code in (0, 1, 2), (where, result.exit_code, result.output)
    if result.exit_code == 2:
        m = ERROR.search(result.stderr)
        # a file error names path:line; an error in the goal text (no file) is click-style `Error: ...`
        assert m or re.search(r"^Error: \S", result.stderr, re.M), (where, result.stderr)
        if m and m.group("path") == str(path):
            assert 0 <= int(m.group("line")) <= data.count(b"\n") + 1, (where, result.stderr)
    leftovers = [p.name for p in out_dir.iterdir() if p.name.startswith(".")] if out_dir.exists() else []
    assert leftovers == [], where


@pytest.mark.parametrize("part", range(4))
def test_mutants_never_crash_and_errors_name_path_and_line(tmp_path, part):
    files = sorted(SUBGRAPHS.glob("*.txt"))
    texts = {f: f.read_text(encoding="utf-8") for f in files}
    rng = random.Random(SEED * 100 + part)
    commands = ("stats", "retrieve", "compile")
    for n in range(part, MUTANTS, 4):
        source = rng.choice(files)
        data = mutate(texts[source], rng)
        check_mutant(tmp_path / "mutant.txt", data, commands[n % 3], _goal_of(texts[source]), tmp_path / "out")
