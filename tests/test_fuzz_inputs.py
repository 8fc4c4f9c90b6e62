"""Property-based fuzzing of kitchens, goals, rates and JSON inputs with issue 11's kinds of input:
huge integers, deep nesting, lone surrogates, control characters, U+2028, hostile labels.

Every reader either returns a value or raises its documented error (FoonSyntaxError naming the file
and a line inside it; ValueError for goal text), never anything else.
"""

from __future__ import annotations

import json
import os

import pytest
from conftest import SUBGRAPHS
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.io.jsonio import parse_json, write_json
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.io.parser import parse_file, parse_text
from foon2pddl.io.rates import parse_rates

HOSTILE = ["9" * 4301, "0" * 4400 + "7", "-" + "9" * 5000, "\x00", "\x07", "\x1b", "\x7f", "\u2028", "\u2029",
           "\x85", "\ud800", "\udcff", "\ufeff", "[", "]", "{", "}", "[[x]]", "{a,{b}}", ",", ":", "\t", "\r", "//",
           "#", "!", "*", "é", "漢", "\U0001f373", " " * 200, "(", ")", ";", "?x", "-", "O\tbowl", "S\tfull"]
fragment = st.one_of(st.sampled_from(HOSTILE), st.text(max_size=12))
hostile_text = st.lists(fragment, min_size=1, max_size=5).map("".join)
FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])


def _located(exc: FoonSyntaxError, path: str, text: str) -> None:
    assert exc.path == path
    assert 0 <= exc.line <= text.count("\n") + 1, (exc.line, str(exc))


def _write(tmp_path_factory, name: str, text: str) -> str:
    path = tmp_path_factory.getbasetemp() / name
    path.write_bytes(text.encode("utf-8", "surrogatepass"))
    return str(path)


@FUZZ
@given(st.lists(st.one_of(hostile_text, st.sampled_from(["bowl: empty", "onion: chopped, in [bowl]",
                                                          "bowl: contains {a, b}", "# c", ""])), max_size=8))
def test_node_line_kitchens(tmp_path_factory, lines):
    text = "\n".join(lines)
    path = _write(tmp_path_factory, "kitchen.txt", text)
    try:
        read_kitchen(path)
    except FoonSyntaxError as exc:
        _located(exc, path, text)


@FUZZ
@given(st.lists(st.one_of(hostile_text, st.sampled_from(["O\tbowl\t0", "S\tempty", "S\tin\t[pot]", "//",
                                                          "O\tegg\t1\t3!", "S\tcontains\t{a,b}"])), max_size=10))
def test_foon_style_kitchens_and_foon_text(tmp_path_factory, lines):
    text = "O\tbowl\t0\n" + "\n".join(lines)
    path = _write(tmp_path_factory, "kitchen.foon.txt", text)
    try:
        read_kitchen(path)
    except FoonSyntaxError as exc:
        _located(exc, path, text)
    try:
        parse_text(text.replace("O\tbowl\t0\n", "O\tbowl\t0\nM\tpour\nO\tcup\t0\n", 1), "f.txt")
    except FoonSyntaxError as exc:
        assert exc.path == "f.txt" and 0 <= exc.line <= text.count("\n") + 3


json_scalar = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=False),
                        hostile_text.map(json.dumps), st.sampled_from(["9" * 4301, "-" + "9" * 4400, '"\\ud800"',
                                                                       '"a\\u0000b"', '"\\u2028"']))


def _json_text(draw_value) -> str:
    return draw_value if isinstance(draw_value, str) else json.dumps(draw_value)


json_values = st.recursive(
    json_scalar.map(_json_text),
    lambda inner: st.one_of(
        st.lists(inner, max_size=4).map(lambda xs: "[" + ", ".join(xs) + "]"),
        st.dictionaries(st.sampled_from(["label", "states", "ingredients", "container", "x"]), inner, max_size=4)
        .map(lambda d: "{" + ", ".join(f"{json.dumps(k)}: {v}" for k, v in d.items()) + "}"),
    ),
    max_leaves=12,
)


@FUZZ
@given(st.one_of(json_values, st.integers(1, 3000).map(lambda n: "[" * n + "]" * n),
                 st.integers(900, 200_000).map(lambda n: "[" * n)))
def test_json_kitchens(tmp_path_factory, text):
    path = _write(tmp_path_factory, "kitchen.json", text)
    try:
        read_kitchen(path)
    except FoonSyntaxError as exc:
        _located(exc, path, text)


@pytest.fixture(scope="module")
def json_foon() -> str:
    return write_json(parse_file(SUBGRAPHS / "0001-whipped_cream.txt").foon)


@FUZZ
@given(st.data())
def test_json_foon_with_hostile_values(json_foon, data):
    """A string or number of a real export replaced by hostile JSON (surrogates, huge ints, deep lists)."""
    import re

    tokens = list(re.finditer(r'"(?:[^"\\]|\\.)*"|-?\d+', json_foon))
    m = data.draw(st.sampled_from(tokens))
    value = data.draw(st.one_of(json_scalar.map(_json_text), json_values,
                                st.integers(1, 5000).map(lambda n: "[" * n + "]" * n)))
    text = json_foon[:m.start()] + value + json_foon[m.end():]
    try:
        parse_json(text, "f.json")
    except FoonSyntaxError as exc:
        _located(exc, "f.json", text)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.one_of(hostile_text, st.sampled_from(["onion", ":", "chopped", "[bowl]", "{a, b}", ","])),
                max_size=8).map("".join))
def test_goal_text(text):
    try:
        parse_goal_spec(text)
    except ValueError:
        pass


@settings(max_examples=150, deadline=None)
@given(st.lists(st.one_of(hostile_text, st.sampled_from(["pour\t0.5", "mix 1", "#", "x\t" + "9" * 5000,
                                                          "y\t1e999", "z\tnan"])), max_size=6).map("\n".join))
def test_rates(text):
    try:
        parse_rates(text, "r.txt")
    except FoonSyntaxError as exc:
        _located(exc, "r.txt", text)


def test_hostile_file_names_in_every_writer(tmp_path):
    """Provenance of hostile file names never adds a line to FOON text and always encodes."""
    from foon2pddl.io.atomic import atomic_write
    from foon2pddl.io.writer import write_foon

    for name in ["a\nO\tx.txt", "b\rS\ty.txt", "c\u2028d.txt", os.fsdecode(b"e\xff.txt"), "f\\ng.txt"]:
        path = tmp_path / name
        path.write_bytes((SUBGRAPHS / "0001-whipped_cream.txt").read_bytes())
        foon = parse_file(path).foon
        out = tmp_path / "out.txt"
        atomic_write(out, write_foon(foon, provenance=True))
        again = parse_file(out).foon
        assert again.units == foon.units and len(again.nodes) == len(foon.nodes)
        atomic_write(tmp_path / "out.json", write_json(foon))
        assert parse_json((tmp_path / "out.json").read_text(), "j").units == foon.units
        path.unlink()


# ---------------------------------------------------------------- constraints files, scheduler addresses,
# damaged dependencies, full disks, huge labels: the classes of the newer surfaces

constraint_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | hostile_text,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(hostile_text, inner, max_size=3), max_leaves=8)
constraint_keys = st.sampled_from(["without_motions", "without", "must_use", "rates", "costs", "name", "x"])


@FUZZ
@given(st.lists(st.tuples(constraint_keys, constraint_values), max_size=5))
def test_constraints_files(pairs):
    from foon2pddl.io.constraints_file import parse_constraints

    text = "{" + ",\n".join(f"{json.dumps(k)}: {json.dumps(v)}" for k, v in pairs) + "}"
    try:
        cons = parse_constraints(text, "c.json")
    except FoonSyntaxError as exc:
        _located(exc, "c.json", text)
        return
    assert all(0 < rate <= 1 for _, rate in cons.rates)
    keys = [k for k, _ in pairs]
    assert len(set(keys)) == len(keys)  # a key given twice never parses (it would drop a ban silently)


@settings(max_examples=400, deadline=None)
@given(st.one_of(hostile_text, st.builds(lambda h, p: f"tcp://{h}:{p}", hostile_text, st.integers(-5, 10**6)),
                 st.sampled_from(["tcp://[::1", "tcp://127.0.0.1", "nothing", "tls://h:1", "tcp://[::1]:8786"])))
def test_scheduler_addresses(address):
    from foon2pddl.errors import UsageError
    from foon2pddl.experiment.engine import parse_scheduler

    try:
        where = parse_scheduler(address)
    except UsageError:
        return
    assert where is None or (where[0] and 0 < where[1] < 65536)


@FUZZ
@given(st.sampled_from(["lexnames", "index.noun", "data.noun", "index.sense"]), st.binary(max_size=400))
def test_damaged_wordnet_files(tmp_path_factory, name, junk):
    """The first stage of opening a damaged corpus: NLTK's reader over junk raises only what
    `wordnet.reader` turns into a located error."""
    from foon2pddl.generalize import wordnet

    nltk_wn = pytest.importorskip("nltk.corpus.reader.wordnet")
    source = wordnet.locate()[1]
    base = tmp_path_factory.getbasetemp() / "wn-fuzz" / "corpora" / "wordnet"
    if not base.is_dir():
        import shutil

        shutil.copytree(source, base)
    original = (source / name).read_bytes()
    try:
        (base / name).write_bytes(junk + original[len(junk) * 97:][:200_000])
        try:
            wn = nltk_wn.WordNetCorpusReader(str(base), None)
            wordnet.check_corpus(wn)
        except wordnet._DAMAGE:
            pass
    finally:
        (base / name).write_bytes(original)


@settings(max_examples=30, deadline=None)
@given(st.integers(1, 2000))
def test_writes_on_a_full_disk_leave_the_old_file(tmp_path_factory, limit):
    """`atomic_write` past the file-size limit (as a full disk) fails and keeps the previous content."""
    import subprocess
    import sys

    from conftest import ROOT

    target = tmp_path_factory.getbasetemp() / f"full-{limit}.txt"
    target.write_text("old\n")
    code = ("import resource, sys; from foon2pddl.io.atomic import atomic_write\n"
            f"resource.setrlimit(resource.RLIMIT_FSIZE, ({limit}, {limit}))\n"
            "try:\n    atomic_write(sys.argv[1], 'x' * 5000)\nexcept OSError:\n    sys.exit(3)\n")
    proc = subprocess.run([sys.executable, "-c", code, str(target)], env=dict(os.environ, PYTHONPATH=str(ROOT)),
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 3 and "Traceback" not in proc.stderr
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in target.parent.glob(f".full-{limit}.txt.*")) == []


@settings(max_examples=20, deadline=None)
@given(st.integers(100, 40_000), hostile_text)
def test_huge_labels_through_check(tmp_path_factory, length, extra):
    from click.testing import CliRunner

    from foon2pddl.cli import main

    label = ("ab" * length)[:length] + extra.replace("\t", " ").replace("\n", " ")
    path = _write(tmp_path_factory, "huge.txt", f"O\t{label}\t0\nS\traw\nM\tslice\nO\t{label}\t0\nS\tsliced\n//\n")
    r = CliRunner().invoke(main, ["check", path])
    assert r.exit_code in (0, 1, 2) and (r.exception is None or isinstance(r.exception, SystemExit)), repr(r.exception)
