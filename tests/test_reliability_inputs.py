"""Issue 11 reproductions on input: huge integers, cubic goal parsing, deep JSON, lone surrogates,
provenance injection, U+2028, FIFOs. Each is an error naming `path:line` (exit 2) or a correct answer,
never a traceback."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest
from click.testing import CliRunner
from conftest import ROOT, SUBGRAPHS
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.cli import main
from foon2pddl.io.parser import parse_file, parse_text
from foon2pddl.model.foon import make_state

WHIPPED = SUBGRAPHS / "0001-whipped_cream.txt"
HUGE = "9" * 5000
LOCATED = re.compile(r"^(.+):(\d+): error: ", re.M)


def cli(*args: str):
    """Run the CLI in-process; any exception other than the exit is a traceback a user would see."""
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert "Traceback" not in result.output
    return result


def error_at(result, path, line: int) -> None:
    assert result.exit_code == 2, result.output
    assert f"{path}:{line}: error: " in result.stderr, result.stderr


# ---------------------------------------------------------------- 1. integers over 4,300 digits


def test_huge_dish_in_foon_text_is_a_located_error(tmp_path):
    f = tmp_path / "b.txt"
    f.write_text(f"O\tbowl\t{HUGE}\nM\tpour\nO\tbowl\nS\tfull\n")
    error_at(cli("stats", f), f, 1)
    g = tmp_path / "c.txt"
    g.write_text(f"O\tbowl\t0\t{HUGE}!\nM\tpour\nO\tbowl\nS\tfull\n")
    error_at(cli("stats", g), g, 1)


def test_leading_zeros_do_not_count_as_digits(tmp_path):
    f = tmp_path / "z.txt"
    f.write_text("O\tbowl\t" + "0" * 5000 + "\nM\tpour\nO\tbowl\nS\tfull\n")
    assert parse_file(f).foon.units[0].inputs[0].motion_flag == 0


def test_huge_int_in_foon_style_kitchen(tmp_path):
    k = tmp_path / "k.txt"
    k.write_text(f"O\tcream\t0\nS\tliquid\n//\nO\tbowl\t{HUGE}\n")
    error_at(cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED), k, 4)


def test_huge_int_in_json_kitchen(tmp_path):
    k = tmp_path / "k.json"
    k.write_text('[\n{"label": "bowl"},\n{"label": ' + HUGE + '}\n]\n')
    error_at(cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED), k, 3)


def test_huge_int_in_json_foon(tmp_path):
    src = tmp_path / "w.json"
    assert cli("merge", "--format", "json", "-o", src, WHIPPED).exit_code == 0
    lines = src.read_text().split("\n")
    lines[2] = lines[2].replace('"states": [', '"dish": ' + HUGE + ', "states": [', 1)
    assert HUGE in lines[2]
    src.write_text("\n".join(lines))
    error_at(cli("stats", src), src, 3)
    # a digit run inside a string is not a number, and a huge number later is still found
    text = '{"format": "x", "version": 1, "units": [], "note": "' + HUGE + '",\n"n": ' + HUGE + "}"
    src.write_text(text)
    error_at(cli("stats", src), src, 2)


# ---------------------------------------------------------------- 2. goal and state parsing in linear time

_OLD_STATE = re.compile(r"^(?P<label>[^\[\]{}]*?)\s*(?:\[(?P<rel>[^\[\]]*)\])?\s*(?:\{(?P<ing>[^{}]*)\})?$")


def _old_parse(part: str):
    """The former (backtracking) state regex, kept as an oracle on short inputs."""
    m = _OLD_STATE.match(part)
    if not m or not m.group("label").strip():
        return None
    return make_state(m.group("label"), m.group("rel") or "", [i for i in (m.group("ing") or "").split(",") if i.strip()])


@settings(max_examples=500, deadline=None)
@given(st.text(alphabet="ab []{},\t", max_size=14))
def test_state_parser_agrees_with_the_former_regex(part):
    from foon2pddl.io.goal_files import parse_state_text

    part = part.strip()  # states arrive stripped (`_split_states`)
    try:
        new = parse_state_text(part)
    except ValueError:
        new = None
    assert new == _old_parse(part)


def test_goal_parsing_uses_no_backtracking_regex():
    """Structural: the state grammar is read by a scanner, not a regular expression with lazy groups."""
    from foon2pddl.io import goal_files

    source = (ROOT / "foon2pddl" / "io" / "goal_files.py").read_text()
    assert "*?" not in source and not hasattr(goal_files, "_STATE")


def test_long_goal_and_kitchen_lines_answer(tmp_path):
    """200 KB of blanks between a state and its bracket: the cubic reader could not finish this."""
    pad = " " * 200_000
    r = cli("retrieve", "--goal", f"whipped cream: a{pad}[x]y", WHIPPED)
    assert r.exit_code == 2 and "\nError: Invalid value for '--goal': cannot read state" in r.stderr
    ok = cli("retrieve", "--goal", f"whipped cream: in{pad}[mixing bowl]", WHIPPED)
    assert ok.exit_code in (0, 1), ok.output
    k = tmp_path / "k.txt"
    k.write_text(f"bowl: empty\ncream: a{pad}[x]y\n")
    error_at(cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED), k, 2)


# ---------------------------------------------------------------- 3. deep JSON kitchen


def test_deeply_nested_json_kitchen(tmp_path):
    k = tmp_path / "k.json"
    k.write_text("[" * 100_000 + "]" * 100_000 + "\n")
    error_at(cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED), k, 1)


# ---------------------------------------------------------------- 4. lone surrogates


@pytest.fixture
def bad_name(tmp_path):
    """A copy of a subgraph under a name with an undecodable byte (a lone surrogate in Python)."""
    p = tmp_path / os.fsdecode(b"bad\xffname.txt")
    p.write_bytes(WHIPPED.read_bytes())
    return p


def test_undecodable_file_name_in_stats_output(tmp_path, bad_name):
    out = tmp_path / "s.out"
    r = cli("stats", bad_name, "-o", out)
    assert r.exit_code == 0, r.output
    assert "bad\\udcffname.txt" in out.read_text(encoding="utf-8")
    r = cli("stats", bad_name)  # standard output too
    assert r.exit_code == 0 and "bad\\udcffname.txt" in r.stdout


def test_undecodable_file_name_in_merge_outputs(tmp_path, bad_name):
    foon = tmp_path / "m.txt"
    assert cli("merge", "--provenance", bad_name, "-o", foon).exit_code == 0
    text = foon.read_text(encoding="utf-8")
    assert "# from " in text and "bad\\udcffname.txt:" in text
    assert len(parse_file(foon).foon.units) == len(parse_file(bad_name).foon.units)
    js = tmp_path / "m.json"
    assert cli("merge", "--format", "json", bad_name, "-o", js).exit_code == 0
    data = json.loads(js.read_text(encoding="utf-8"))
    assert data["units"][0]["sources"][0]["path"] == str(bad_name)  # the JSON escape round-trips


def test_lone_surrogate_label_in_json_foon(tmp_path):
    src = tmp_path / "w.json"
    assert cli("merge", "--format", "json", "-o", src, WHIPPED).exit_code == 0
    lines = src.read_text().split("\n")
    lines[3] = lines[3].replace('"label": "', '"label": "\\ud800', 1)
    src.write_text("\n".join(lines))
    for cmd in (["merge", src], ["retrieve", "--goal", "whipped cream", src]):
        r = cli(*cmd)
        error_at(r, src, 4)
        assert "surrogate" in r.stderr


def test_lone_surrogate_label_in_json_kitchen(tmp_path):
    k = tmp_path / "k.json"
    k.write_text('[\n{"label": "bowl"},\n{"label": "cre\\udc00am"}\n]\n')
    r = cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED)
    error_at(r, k, 3)


# ---------------------------------------------------------------- 11. provenance injection


def test_newline_in_file_name_does_not_inject_foon_lines(tmp_path):
    evil = tmp_path / "nl\nO\tx.txt"
    evil.write_bytes(WHIPPED.read_bytes())
    out = tmp_path / "m.txt"
    assert cli("merge", "--provenance", evil, "-o", out).exit_code == 0
    merged, original = parse_file(out).foon, parse_file(evil).foon
    assert len(merged.nodes) == len(original.nodes) and merged.units == original.units
    assert "# from " + str(tmp_path) + "/nl\\nO\\tx.txt:" in out.read_text()


def test_provenance_escapes_every_line_breaker():
    from foon2pddl.io.writer import escape_text

    for name in ("a\nb", "a\rb", "a\u2028b", "a\x85b", "a\\b", "a\x00b"):
        escaped = escape_text(name)
        assert len(escaped.splitlines()) == 1 and "\\" in escaped
    assert escape_text("a\\nb") != escape_text("a\nb")  # a backslash is escaped too
    assert escape_text("crème brûlée.txt") == "crème brûlée.txt"


# ---------------------------------------------------------------- 13. U+2028 and FIFOs


def test_line_separator_in_kitchen_keeps_line_numbers(tmp_path):
    k = tmp_path / "k.txt"
    k.write_text("bowl: empty\u2028 \ncream: liquid\nsugar: [x\n", encoding="utf-8")
    error_at(cli("retrieve", "--goal", "whipped cream", "--kitchen", k, WHIPPED), k, 3)
    r = tmp_path / "rates.txt"
    r.write_text("pour\u2028\t0.5\nmix\tx\n", encoding="utf-8")
    error_at(cli("retrieve", "--goal", "whipped cream", "--method", "weighted", "--rates", r, WHIPPED), r, 2)


@pytest.mark.parametrize("where", ["input", "kitchen", "goal-file"])
def test_fifo_is_refused_not_waited_on(tmp_path, where):
    fifo = tmp_path / "fifo.txt"
    os.mkfifo(fifo)
    args = {"input": ["stats", str(fifo)],
            "kitchen": ["retrieve", "--goal", "whipped cream", "--kitchen", str(fifo), str(WHIPPED)],
            "goal-file": ["retrieve", "--goal-file", str(fifo), str(WHIPPED)]}[where]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-m", "foon2pddl", *args], capture_output=True, text=True,
                          timeout=120, env=env)
    assert proc.returncode == 2, proc.stderr
    assert f"{fifo}: error: not a regular file" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_parse_text_still_reads_crlf_and_u2028_inside_labels():
    res = parse_text("O\tbowl\u2028x\t0\r\nM\tpour\r\nO\tbowl\t0\r\nS\tfull\r\n", "t")
    assert res.foon.units[0].inputs[0].label.startswith("bowl")


@pytest.mark.parametrize(("data", "line"), [(b'{"categories": {}}\n\xff\n', 2), (b"[" * 50_000, 1),
                                            (b'{"categories":\n' + b"9" * 5000 + b"}", 2)])
def test_bad_category_index_is_a_located_error(tmp_path, data, line):
    index = tmp_path / "cats.json"
    index.write_bytes(data)
    error_at(cli("generalize", "--categories", index, WHIPPED), index, line)


@pytest.mark.parametrize("data", ['{"without": [\n' + HUGE + "]}", "[" * 100_000])
def test_bad_constraints_and_goal_lists_are_located_errors(tmp_path, data):
    f = tmp_path / "c.json"
    f.write_text(data)
    line = 2 if HUGE in data else 1
    error_at(cli("retrieve", "--goal", "whipped cream", "--constraints", f, WHIPPED), f, line)
    error_at(cli("retrieve", "--goals", f, WHIPPED), f, line)
