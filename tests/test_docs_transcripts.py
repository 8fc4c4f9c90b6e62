"""The command transcripts in the README and every docs/*.md are what the program prints.

Each `$ foon2pddl ...` line in a fenced block is run (from a scratch directory with the repository's
`tests/` and `docs/` linked in, so `tests/data/...` PATHS resolve and no output may depend on running from
the checkout); every documented output line must appear in the command's output: stdout lines in
order, stderr lines (notes, summaries) anywhere; stdout the transcript leaves out is marked by an elision line (`...`) where it is left out.
Timing lines (`phases: ...`) vary from run to run and are skipped, and so is an
elision line (`...`); inside a line, `...` stands for any text (a documented line
may shorten a long one).
"""

from __future__ import annotations

import re
import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from bench.doc_commands import PAGES as DOCS
from bench.doc_commands import blocks, documented_commands, is_synopsis, joined, missing_inputs, prose, transcripts
from foon2pddl.cli import main

CASES = [case for doc in DOCS for case in transcripts(doc.read_text())]


def test_the_document_has_transcripts():
    commands = [c for c, _ in CASES]
    assert "retrieve --goal lemonade --network exp" in commands
    assert commands.count("plan --goal lemonade --network gen") == 2  # the README shows it too


def test_every_form_of_a_documented_command_is_read():
    """What `python -m bench.silence` runs: transcripts, command lines of fenced blocks (continuations
    joined), inline commands of prose; synopses and a bare command name are no command."""
    shown = {c.text: c for c in documented_commands()}
    assert shown["foon2pddl plan --goal lemonade --network gen"].form == "transcript"
    excerpt = shown["foon2pddl compile --goal lemonade --network gen -o out/"]  # a `; $` block of file excerpts
    assert excerpt.page == "README.md" and excerpt.form == "transcript"
    sweep = next(c for c in shown if c.startswith("foon2pddl experiment --trials 2 --goals 10"))
    assert sweep.endswith("--sweep level=2,3 -o out/sweep")  # the `\\` continuation joined
    assert shown["foon2pddl expand --pairs"].form == "inline"
    assert "foon2pddl plan" not in shown and not any(c.startswith("foon2pddl compile --goal G") for c in shown)


def test_every_reader_of_fenced_blocks_reads_them_one_way():
    """Stop 58's re-read F8: `_shown` and `_goal_texts` each read a page's fenced blocks their own way (a toggle, a
    regex), each joining `\\` continuations and stripping prompts itself, and tests/ had four more. One reading:
    `blocks` (the info string, the first line's number, the lines; an unclosed block runs to the end), `joined`
    (continuations), `prose` (what is outside the blocks, at its own offsets)."""
    page = ("Run `foon2pddl plan --goal x`.\n\n```python\nprint(1)\n```\ntext\n```\n$ foon2pddl retrieve --goal a\n"
            "out line\nfoon2pddl plan --goal b \\\n  --time-limit 5\n```\n```\nfoon2pddl goals\n")
    python, shell, unclosed = blocks(page)
    assert (python.lang, python.start, python.lines) == ("python", 4, ("print(1)",))
    assert (shell.lang, shell.start, shell.lines[0]) == ("", 8, "$ foon2pddl retrieve --goal a")
    assert (unclosed.start, unclosed.lines) == (14, ("foon2pddl goals",))
    assert list(joined(shell))[-1] == (10, 11, "foon2pddl plan --goal b --time-limit 5")
    outside = prose(page)
    assert len(outside) == len(page) and outside.splitlines()[5] == "text" and "print" not in outside
    assert transcripts(page) == [("retrieve --goal a", ["out line", "foon2pddl plan --goal b \\", "  --time-limit 5"])]


@pytest.mark.parametrize(("command", "synopsis"), [
    ("foon2pddl retrieve --goal G [--method greedy|complete]", True),
    ("foon2pddl similarity A B [...]", True),
    ("foon2pddl retrieve --goals FILE|- --format csv", True),
    ("foon2pddl experiment /shared/x --scheduler tcp://HEAD:8786", True),
    ("foon2pddl experiment --sweep NAME=V1,V2", True),
    ('foon2pddl plan --goal "tomato soup: pureed, garnished {basil}, in [bowl]"', False),
    ('foon2pddl plan --goal guacamole --search "lazy_greedy([h], preferred=[h])"', False),
    ("foon2pddl retrieve --goal lemonade  # exit 1: FOON-EXP, G", False),
])
def test_a_synopsis_is_told_from_a_command(command, synopsis):
    assert is_synopsis(command) is synopsis


def test_a_command_naming_the_readers_own_files_is_told(tmp_path):
    (tmp_path / "have.json").write_text("{}")
    assert missing_inputs("foon2pddl generalize my_recipes/ --categories index.json -o out.txt", tmp_path) == [
        "my_recipes/", "index.json"]
    assert missing_inputs("foon2pddl retrieve --kitchen have.json -o new/dir/x.txt --plot p.png", tmp_path) == []
    assert missing_inputs("foon2pddl plan --planner-cmd './my/planner {domain} {problem}'", tmp_path) == ["./my/planner"]


def matches(documented: str, printed: str) -> bool:
    """Whether a printed line is the documented one, `...` inside it standing for any text."""
    if "..." not in documented:
        return documented == printed
    return re.fullmatch(".*".join(re.escape(part) for part in documented.split("...")), printed) is not None


def test_matches_reads_an_elision_as_any_text():
    assert matches("start: a_1: a; ...; k_1: k", "start: a_1: a; b_1: b; k_1: k")
    assert not matches("start: a_1: a; ...; k_1: k", "start: a_1: a; b_1: b")
    assert matches("plain", "plain") and not matches("plain", "plain.")


@pytest.mark.parametrize(("command", "expected"), CASES, ids=[f"{i}: {c}" for i, (c, _) in enumerate(CASES)])
def test_transcript_matches_the_program(command, expected, monkeypatch, tmp_path):
    # From a directory of the reader's own, as after `pip install` (`tests/` and `docs/` linked so the paths
    # the pages give resolve): what the program prints must not depend on running from the checkout.
    for name in ("tests", "docs"):
        (tmp_path / name).symlink_to(ROOT / name)
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, shlex.split(command))
    out, err = result.stdout.splitlines(), result.stderr.splitlines()
    position, elided, left_out = 0, False, []
    for line in expected:
        if line.startswith("phases: "):
            continue
        if line == "...":
            elided = True
            continue
        at = next((i for i in range(position, len(out)) if matches(line, out[i])), None)
        if at is not None:
            if at > position and not elided:
                left_out.append(f"stdout lines {position + 1}-{at} before {line!r}")
            position, elided = at + 1, False
        elif not any(matches(line, e) for e in err):
            pytest.fail(f"documented line not printed (in order): {line!r}\nstdout:\n" + "\n".join(out)
                        + "\nstderr:\n" + "\n".join(err))
    if position < len(out) and not elided:
        left_out.append(f"stdout lines {position + 1}-{len(out)} at the end")
    assert not left_out, f"the transcript leaves out what the command prints, with no `...` there: {left_out}"


def file_excerpts(text: str) -> list[tuple[str, dict[str, list[str]]]]:
    """(compile command, {file name: documented lines}) for every fenced block opening with
    `; $ foon2pddl compile ... -o out/`, its files introduced by `; out/NAME` lines."""
    out: list[tuple[str, dict[str, list[str]]]] = []
    for block in blocks(text):
        if block.lines and block.lines[0].startswith("; $ foon2pddl compile "):
            files: dict[str, list[str]] = {}
            current = None
            for item in block.lines[1:]:
                if item.startswith("; out/"):
                    current = files.setdefault(item[len("; out/"):], [])
                elif current is not None:
                    current.append(item)
            out.append((block.lines[0][len("; $ foon2pddl "):], files))
    return out


EXCERPTS = [case for doc in DOCS for case in file_excerpts(doc.read_text())]


def test_the_readme_shows_a_compiled_excerpt():
    assert any(command.startswith("compile --goal lemonade --network gen") for command, _ in EXCERPTS)


@pytest.mark.parametrize(("command", "files"), EXCERPTS, ids=[c for c, _ in EXCERPTS])
def test_compiled_excerpt_matches_the_files(command, files, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, shlex.split(command))
    assert result.exit_code == 0, result.stderr
    for name, expected in files.items():
        lines = (tmp_path / "out" / name).read_text().splitlines()
        position = 0
        for line in expected:
            at = next((i for i in range(position, len(lines)) if matches(line, lines[i])), None)
            assert at is not None, f"documented line of {name} not in the file (in order): {line!r}"
            position = at + 1


def test_what_the_generalization_page_says_a_cold_cache_prints_it_prints(monkeypatch, tmp_path):
    """The page's transcripts are from a warm cache; a newcomer's first `--network exp` (and the hint check of a
    first `retrieve --goal lemonade`) printed a line they do not show (stop 48's pass). The page says which, and
    each command, run on an empty cache, prints the line the page quotes for it."""
    text = " ".join((ROOT / "docs" / "generalization.md").read_text().split())
    paragraph = text[text.index("The transcripts on this page are from a warm cache."):].split(". ", 1)[1]
    quoted = re.findall(r"`(retrieve [^`]+)` (?:also )?prints `([^`]+ \.\.\.)`", paragraph[:1000])
    assert [c for c, _ in quoted] == ["retrieve --goal lemonade", "retrieve --goal lemonade --network exp"], quoted
    for k, (command, line) in enumerate(quoted):
        monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / f"cold{k}"))
        cold = CliRunner().invoke(main, shlex.split(command))
        assert cold.exit_code in (0, 1), cold.stderr
        assert line in cold.stderr.splitlines(), cold.stderr
    # in the page's order, on one cache: the second finds the matrix the first computed and scores from it
    assert "the second finds the matrix cached and scores its substitution from it (no WordNet opened" in paragraph
    from foon2pddl.cli import progress
    from foon2pddl.generalize import wordnet

    opened, real = [], wordnet.reader
    monkeypatch.setattr(wordnet, "reader", lambda: opened.append(1) or real())  # WordNet is open in this process
    monkeypatch.setattr(progress, "AFTER", 0.0)  # so every step says what it is
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cold0"))
    after = CliRunner().invoke(main, shlex.split(quoted[1][0]))
    assert after.exit_code == 0 and not opened, after.stderr
    assert not [line for line in after.stderr.splitlines() if line.startswith("scoring ")], after.stderr
