"""Parser: every quirk of the public FOON data, errors with places, round trips, robustness."""

from __future__ import annotations

import random
import re

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS
from foon_strategies import foons, full, full_unit, units
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.cli import main
from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.files import expand_paths
from foon2pddl.io.foon_lines import _classify, _parse_state, parse_objects, plain_state
from foon2pddl.io.parser import _comment_head, _plain, _Reader, parse_file, parse_text
from foon2pddl.io.writer import write_foon
from foon2pddl.model.foon import Motion, State, make_node, make_source, make_state, make_unit
from foon2pddl.model.node_table import node_table

UNIT = "O1\tbowl\t1\nS1\tempty\nO2\tegg\t1\nS2\twhole\nM1\tcrack\t0:01\t0:05\nO1\tbowl\t0\nS3\tcontains\t{egg}\n"


def parse(text: str):
    return parse_text(text, "t.foon")


def lines(*rows: str) -> str:
    return "\n".join(rows) + "\n"


# ---------------------------------------------------------------- quirks


def test_crlf_reads_like_lf():
    lf = parse("//\n" + UNIT + "//\n" + UNIT.replace("crack", "break") + "//\n")
    crlf = parse(("//\n" + UNIT + "//\n" + UNIT.replace("crack", "break") + "//\n").replace("\n", "\r\n"))
    assert full(crlf.foon) == full(lf.foon)
    assert len(crlf.foon.units) == 2
    assert crlf.foon.units[0].inputs[0].label == "bowl"  # no stray '\r' in labels or states
    assert crlf.foon.units[0].motion.end == "0:05"


def test_leading_separator_is_optional():
    with_sep = parse("//\n" + UNIT + "//\n")
    without = parse(UNIT + "//\n" + UNIT.replace("crack", "break"))  # no trailing '//' either
    assert full(with_sep.foon) == full(parse(UNIT).foon)
    assert [u.motion.label for u in without.foon.units] == ["crack", "break"]
    assert without.foon.units[0].sources[0].line == 1


def test_repeated_separators_make_empty_blocks_without_warnings():
    res = parse("//\n//\n" + UNIT + "//\n//\n//\n" + UNIT.replace("crack", "break") + "//\n//\n")
    assert [u.motion.label for u in res.foon.units] == ["crack", "break"]
    assert res.warnings == ()
    assert res.foon.units[1].sources[0].line == 13


def test_source_comment_is_provenance_and_other_comments_are_ignored():
    text = lines("# Source:\thttp://a.example/1.mp4  ", "# a plain comment", "# Source:\thttps://b.example/v",
                 "//") + UNIT + "//\n# Source:\thttps://c.example/w\t\n" + UNIT.replace("crack", "break")
    res = parse(text)
    assert res.urls == ("http://a.example/1.mp4", "https://b.example/v", "https://c.example/w")
    first, second = res.foon.units
    assert first.sources[0].url == "https://b.example/v"  # the latest URL before the unit
    assert second.sources[0].url == "https://c.example/w"
    assert (first.sources[0].path, first.sources[0].line) == ("t.foon", 5)


def test_dish_fourth_field_is_kept_but_not_identity():
    res = parse(UNIT.replace("O1\tbowl\t0\n", "O1\tbowl\t0\t7\n"))
    out = res.foon.units[0].outputs[0]
    assert out.dish == 7
    assert res.foon.units[0].inputs[0].dish is None
    assert out == parse(UNIT).foon.units[0].outputs[0]


@pytest.mark.parametrize(("fields", "flag", "dish", "goal"), [
    ("0\t!", 0, None, True),
    ("1!", 1, None, True),
    ("0\t3\t!", 0, 3, True),
    ("0\t3!", 0, 3, True),
    ("00", 0, None, False),
    ("1", 1, None, False),
    ("", 0, None, False),
])
def test_object_flag_dish_and_goal_mark(fields, flag, dish, goal):
    head = "O\tcream" + (f"\t{fields}" if fields else "")
    node = parse(lines("O\tmilk", "M\twhip", head)).foon.units[0].outputs[0]
    assert (node.motion_flag, node.dish, node.goal) == (flag, dish, goal)


def test_star_suffix_marks_a_composite_unit_of_the_plain_motion():
    plain = parse(UNIT).foon.units[0]
    star = parse(UNIT.replace("M1\tcrack\t", "M1\tcrack*\t")).foon.units[0]
    assert star.motion.label == "crack" and star.motion.composite
    assert not plain.motion.composite
    assert star.key == plain.key


def test_ingredient_lists_with_duplicates_trailing_commas_and_stray_spaces():
    res = parse(lines("O\tbowl", "S\tcontains\t{salt,black pepper,salt, oil,}", "M\tmix",
                      "O\tbowl", "S\tcontains\t{ Oil ,salt,,black  pepper}"))
    unit = res.foon.units[0]
    assert unit.inputs[0].states == (State("contains", "", ("black pepper", "oil", "salt")),)
    assert unit.inputs[0] == unit.outputs[0]


def test_on_without_related_object_differs_from_spatial_on():
    unit = parse(lines("O\tstove", "S\toff", "M\tturn on", "O\tstove", "S\ton", "O\tpan", "S\ton\t[stove]")).foon.units[0]
    assert unit.outputs[0].states == (State("on"),)
    assert unit.outputs[1].states == (State("on", "stove"),)
    assert unit.outputs[0].states != unit.outputs[1].states


def test_brackets_hold_a_related_object_or_a_list_read_as_ingredients():
    unit = parse(lines("O\tchicken", "S\tcoated\t[olive oil,salt, black pepper]", "S\tin\t[ Bowl ]",
                       "M\tcoat", "O\tchicken", "S\tcoated")).foon.units[0]
    assert set(unit.inputs[0].states) == {State("coated", "", ("black pepper", "olive oil", "salt")), State("in", "bowl")}


def test_empty_brackets_and_bare_contains():
    unit = parse(lines("O\tbowl", "S\tin\t[]", "S\tcontains", "M\tpour", "O\tbowl", "S\tcontains\t{}")).foon.units[0]
    assert unit.inputs[0].states == (State("contains"), State("in"))
    assert unit.outputs[0].states == (State("contains"),)


def test_state_with_related_object_and_ingredient_list():
    node = parse(lines("O\tx", "M\tm", "O\tpot", "S\tin\t[stove]\t{water, salt}")).foon.units[0].outputs[0]
    assert node.states == (State("in", "stove", ("salt", "water")),)


@pytest.mark.parametrize(("times", "start", "end"), [
    ("\tAssumed\tAssumed", "Assumed", "Assumed"),
    ("\tassumed\tassumed", "assumed", "assumed"),
    ("\tAssume\t0:12", "Assume", "0:12"),
    ("\t3:0s7\t1:116", "3:0s7", "1:116"),
    ("\t0:4:50\t0:05", "0:4:50", "0:05"),
    ("\t<0:10,0:20>", "0:10", "0:20"),
    ("\t<Assumed>", "Assumed", "Assumed"),
    ("\t<1:06-1:10>", "1:06", "1:10"),
    ("\t1:00", "1:00", "1:00"),
    ("", None, None),
])
def test_times_are_kept_as_written(times, start, end):
    motion = parse(lines("O\tx", f"M7\tstir{times}", "O\ty")).foon.units[0].motion
    assert (motion.label, motion.start, motion.end) == ("stir", start, end)


def test_labels_are_normalized_for_identity():
    a = parse(lines("O\tMixing  Bowl", "S\tEmpty", "M\tPick-and-Place", "O\tmixing bowl ", "S\tON\t[Counter  Top]")).foon
    unit = a.units[0]
    assert unit.inputs[0].label == unit.outputs[0].label == "mixing bowl"
    assert unit.motion.label == "pick-and-place"
    assert unit.outputs[0].states == (State("on", "counter top"),)


def test_states_sorted_and_deduplicated_so_order_does_not_matter():
    a = parse(lines("O\tbowl", "S\tempty", "S\tin\t[sink]", "S\tempty", "M\tm", "O\tbowl", "S\tclean")).foon
    b = parse(lines("O\tbowl", "S\tin\t[sink]", "S\tempty", "M\tm", "O\tbowl", "S\tclean")).foon
    assert a.units[0].inputs[0] == b.units[0].inputs[0]
    assert len(a.units[0].inputs[0].states) == 2


def test_object_without_states_and_same_object_twice_on_one_side():
    """A line written twice is one object: the reader keeps it once (`pairing.unit_roles` gives a role per node)."""
    unit = parse(lines("O\tknife", "O\tknife", "O\tonion", "S\twhole", "M\tslice", "O\tonion", "S\tsliced")).foon.units[0]
    assert [n.label for n in unit.inputs] == ["knife", "onion"]
    assert unit.inputs[0].states == ()


def test_idless_and_idful_variants_read_the_same():
    idful = parse(UNIT)
    idless = parse(re.sub(r"^([OSM])\d+", r"\1", UNIT, flags=re.MULTILINE))
    assert full(idful.foon) == full(idless.foon)


@pytest.mark.parametrize(("block", "problem"), [
    (lines("O\tbowl", "S\tempty", "M\tpour"), "no output objects"),
    (lines("O\tbowl", "S\tempty", "O\tspoon"), "no motion line"),
    (lines("M\tpour", "O\tbowl"), "no input objects"),
])
def test_blocks_that_are_not_units_are_skipped_with_a_warning(block, problem):
    text = "//\n" + UNIT + "//\n" + block + "//\n" + UNIT.replace("crack", "break") + "//\n"
    res = parse(text)
    assert [u.motion.label for u in res.foon.units] == ["crack", "break"]
    assert len(res.warnings) == 1
    w = res.warnings[0]
    assert (w.path, w.line) == ("t.foon", 10) and problem in w.message
    assert str(w).startswith("t.foon:10: warning:")


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(("text", "line", "expected"), [
    ("//\nS1\tempty\nO1\tbowl\n", 2, "before any object"),
    (UNIT + "//\nO1\tbowl\t0\nOS1\tbowl\n", 10, "expected an 'O', 'S' or 'M' line"),
    (UNIT + "//\nO1\tbowl\t0\n\tS2\n", 10, "no label"),
    (UNIT + "//\nO278\n", 9, "no label"),
    (UNIT + "//\nO1\tbowl\nS65\tin\t[car\n", 10, "expected '[related object]'"),
    (UNIT + "//\nO1\tbowl\tmaybe\n", 9, "motion identifier"),
    (UNIT + "//\nO1\tbowl\t1\t2\t3\n", 9, "extra field"),
    (UNIT + "M2\tstir\n", 8, "second motion line"),
    ("O1\tbo\x00wl\t0\n", 1, "control character"),
    ("O1\tbowl\t0\nX\tbowl\n", 2, "expected an 'O', 'S' or 'M' line"),
    # issue 24's tried-again pass: a FOON file written with spaces said `expected an 'O', 'S' or 'M' line` of an O line
    ("//\nO bowl 0\nS empty\n", 2, "'O' line with its fields separated by spaces: FOON separates them with tabs"),
    (UNIT + "//\nO1\tbowl\t0\nS2 contains {egg}\n", 10, "'S' line with its fields separated by spaces"),
    (UNIT + "M2 stir\n", 8, "'M' line with its fields separated by spaces"),
    ("O\tx\nM\t**\nO\ty\n", 2, "no label before '*'"),
    ("O\tx\nS\tin\t[a]\t[b]\nM\tm\nO\ty\n", 2, "two related objects"),
    ("", 1, "no functional units"),
    ("# only a comment\n//\n", 2, "no functional units"),
])
def test_syntax_errors_name_path_line_and_problem(text, line, expected):
    with pytest.raises(FoonSyntaxError) as info:
        parse(text)
    err = info.value
    assert (err.path, err.line) == ("t.foon", line)
    assert expected in err.message
    assert str(err).startswith(f"t.foon:{line}: ")


def test_error_carries_the_offending_line():
    with pytest.raises(FoonSyntaxError) as info:
        parse(UNIT + "//\nO1\tbowl\r\nS65\tin\t[car\r\n")
    assert info.value.text == "S65\tin\t[car"


def test_parse_objects_reads_kitchen_style_nodes():
    nodes = parse_objects(lines("# kitchen", "O\tBowl", "S\tempty", "O\tknife", "//", "O\tonion", "S\twhole"), "k.txt")
    assert nodes == [(make_node("bowl", [make_state("empty")]), 2), (make_node("knife"), 4),
                     (make_node("onion", [make_state("whole")]), 6)]
    with pytest.raises(FoonSyntaxError, match=r"a motion line \('M'\): this file is a FOON network"):
        parse_objects(lines("O\tbowl", "M\tpour"), "k.txt")


# ---------------------------------------------------------------- real data


SUBGRAPH_FILES = expand_paths([SUBGRAPHS])


def test_all_shared_subgraphs_parse_and_units_match_motion_lines(universal):
    assert len(SUBGRAPH_FILES) == 100
    total = 0
    for path in SUBGRAPH_FILES:
        res = parse_file(path)
        text = path.read_text(encoding="utf-8")
        motion_lines = len(re.findall(r"^M", text, flags=re.MULTILINE))
        skipped_with_motion = sum("no output" in w.message or "no input" in w.message for w in res.warnings)
        assert len(res.foon.units) == motion_lines - skipped_with_motion, path
        assert all(u.inputs and u.outputs for u in res.foon.units)
        total += len(res.foon.units)
    assert total > len(universal[0].units)  # some units recur across recipes


def test_universal_foon_written_idless_reparses_equal(universal):
    foon, _ = universal
    text = write_foon(foon)
    assert not re.search(r"^[OSM]\d", text, flags=re.MULTILINE)  # id-less
    again = parse_text(text, "universal.foon")
    assert full(again.foon) == full(foon)
    assert again.warnings == ()


@settings(max_examples=60, deadline=None)
@given(foon=foons(), with_ids=st.booleans())
def test_parse_of_write_is_identity(foon, with_ids):
    text = write_foon(foon, with_ids=with_ids)
    assert full(parse_text(text, "gen.foon").foon) == full(foon)


# Mutations of real subgraphs: always a network or a FoonSyntaxError, nothing else.
_MUTATION_FILES = [p.read_text(encoding="utf-8").split("\n") for p in SUBGRAPH_FILES[::10]]
_INJECT = st.sampled_from(list("\t\x00\x1b\r[]{},*!/#OSM0123456789 \ufffd\u2028") + ["//", "\t[", "{", "\tAssumed"])


@st.composite
def mutated(draw):
    rows = list(draw(st.sampled_from(_MUTATION_FILES)))
    for _ in range(draw(st.integers(1, 6))):
        op = draw(st.sampled_from(["delete", "duplicate", "swap", "inject", "truncate"]))
        i = draw(st.integers(0, len(rows) - 1))
        if op == "delete" and len(rows) > 1:
            rows.pop(i)
        elif op == "duplicate":
            rows.insert(i, rows[i])
        elif op == "swap":
            j = draw(st.integers(0, len(rows) - 1))
            rows[i], rows[j] = rows[j], rows[i]
        elif op == "inject":
            pos = draw(st.integers(0, len(rows[i])))
            rows[i] = rows[i][:pos] + draw(_INJECT) + rows[i][pos:]
        elif op == "truncate":
            rows[i] = rows[i][: draw(st.integers(0, len(rows[i])))]
    return "\n".join(rows)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=mutated())
def test_mutated_subgraphs_parse_or_raise_syntax_error(text):
    try:
        res = parse_text(text, "m.txt")
    except FoonSyntaxError as err:
        assert err.path == "m.txt"
        assert 1 <= err.line <= text.count("\n") + 1
        return
    assert all(u.inputs and u.outputs for u in res.foon.units)
    for with_ids in (False, True):  # whatever was accepted can be written and read back
        assert full(parse_text(write_foon(res.foon, with_ids=with_ids)).foon) == full(res.foon)


#: A unit read after a block, so that a block holding none still reads as a file (and shows its warnings).
_SENTINEL = ["//", "O\tsentinel", "M\tsentinel", "O\tsentinel done", ""]


def _alone(rows: list[str], offset: int):
    """One block read as a file of its own, lines renumbered as in the whole text: a list [units with
    source lines, warnings], or the error as a tuple (path, line, message, text)."""
    try:
        res = parse_text("\n".join(rows + _SENTINEL), "m.txt")
    except FoonSyntaxError as err:
        return (err.path, err.line + offset, err.message, err.text)
    units = [full_unit(u) + (tuple((s.path, s.line + offset) for s in u.sources),) for u in res.foon.units[:-1]]
    return [units, [(w.path, w.line + offset, w.message) for w in res.warnings]]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=mutated())
def test_a_text_reads_as_its_blocks_each_read_alone(text):
    """The reader's caches (lines, states, motions and objects, shared by every block of a file) change
    nothing: each `//`-separated block read alone, with cold caches, gives the same units (attributes and
    source lines) and warnings, or the same first error, as the whole text (URLs carry across blocks:
    `test_source_comment_is_provenance_and_other_comments_are_ignored`)."""
    rows = text.split("\n")
    ends = [i + 1 for i, row in enumerate(rows) if row.rstrip("\r").strip().startswith("//")] + [len(rows)]
    units, warnings, error, start = [], [], None, 0
    for end in ends:
        got = _alone(rows[start:end], start)
        if isinstance(got, tuple):
            error = got
            break
        units += got[0]
        warnings += got[1]
        start = end
    try:
        res = parse_text(text, "m.txt")
    except FoonSyntaxError as err:
        if err.message.startswith("no functional units in file"):
            assert error is None and not units
        else:
            assert (err.path, err.line, err.message, err.text) == error
        return
    assert error is None
    assert [full_unit(u) + (tuple((s.path, s.line) for s in u.sources),) for u in res.foon.units] == units
    assert [(w.path, w.line, w.message) for w in res.warnings] == warnings


def _line_reader(text: str):
    """What the line reader alone makes of `text`: the parse result, or the error as a tuple."""
    lines = text.split("\n")
    reader = _Reader("m.txt")
    try:
        reader.read(lines)
        return reader.finish(len(lines), text.endswith("\n"))
    except FoonSyntaxError as err:
        return (err.path, err.line, err.message, err.text)


@st.composite
def plain_mutated(draw):
    """A mutated subgraph without its comment and blank lines and carriage returns: often plain text
    (`parser._plain`), often with an error or a block that is no unit."""
    rows = [r.rstrip("\r") for r in draw(mutated()).split("\n")]
    keep = [r for r in rows if r.strip() and not r.lstrip().startswith("#")]
    return "\n".join(keep) + draw(st.sampled_from(["", "\n", "\n//", "\n//\n"]))


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=plain_mutated())
def test_block_reader_reads_what_the_line_reader_reads(text):
    """Plain text read block by block gives the line reader's network exactly (attributes, source lines), with
    the node numbering `node_table` gives; or it hands the text over (None) and `parse_text` is the line reader."""
    slow = _line_reader(text)
    fast = _Reader("m.txt").read_plain(text) if _plain(text) else None
    if fast is None:
        try:
            got = parse_text(text, "m.txt")
        except FoonSyntaxError as err:
            got = (err.path, err.line, err.message, err.text)
        if isinstance(slow, tuple):
            assert got == slow
        else:
            assert (full(got.foon, sources=True), got.warnings) == (full(slow.foon, sources=True), slow.warnings)
        return
    assert not isinstance(slow, tuple) and slow.warnings == () and slow.urls == ()
    assert full(fast.foon, sources=True) == full(slow.foon, sources=True)
    table, expected = fast.foon.table, node_table(slow.foon.units)
    assert (table.nodes, table.inputs, table.outputs) == (expected.nodes, expected.inputs, expected.outputs)
    assert [[table.nodes[i] for i in ids] for ids in table.inputs] == [list(u.inputs) for u in fast.foon.units]


@settings(max_examples=1000, deadline=None)
@given(text=st.text(alphabet="OSM/#\n\r \tx", max_size=30), skip=st.integers(0, 4))
def test_plain_means_every_line_is_an_object_state_motion_or_separator_line(text, skip):
    """`_plain` against its definition, line by line: from offset `skip` every line starts with `O`, `S`, `M` or
    `//` (a final newline ends the last line) and the text holds no carriage return."""
    rows = text[skip:].split("\n")
    if len(rows) > 1 and rows[-1] == "":
        rows.pop()
    expected = "\r" not in text and all(row.startswith(("O", "S", "M", "//")) for row in rows)
    assert _plain(text, skip) == expected


#: Fields of state lines: the usual shapes, and what sends a line to the field-by-field reader or makes it an error.
_STATE_LABELS = st.sampled_from(["in", "Chopped", "a  b", " x ", "", " ", "\u00a0", "é", "İ", "x\x01", "[a]", "{a}", "#"])
_STATE_EXTRAS = st.sampled_from(["[bowl]", "[ Bowl ]", "[ ]", "[]", "[a,b]", "[a,]", "{salt, Pepper,}", "{}", "{ , }",
                                 "{a}x", "x", "", " {a}", "[bowl", "{a\x0bb}", "[\u00a0]", "{İ}"])


@st.composite
def state_lines(draw):
    """`S<id>`, a label and up to three extra fields; sometimes a character inserted anywhere."""
    raw = "\t".join([draw(st.sampled_from(["S", "S12", "S ", "s", "O"])), draw(_STATE_LABELS),
                     *draw(st.lists(_STATE_EXTRAS, max_size=3))])
    if draw(st.booleans()):
        at = draw(st.integers(0, len(raw)))
        raw = raw[:at] + draw(st.sampled_from(["\t", " ", ",", "[", "}", "\x1f", "\u2028"])) + raw[at:]
    return raw


@settings(max_examples=1000, deadline=None)
@given(raw=state_lines())
def test_plain_state_reads_what_the_field_reader_reads(raw):
    """A state line `plain_state` reads is one the field-by-field reader (`_classify`, `_parse_state`) reads
    without error, to the same state; any other line it leaves to that reader (None)."""
    fast = plain_state(raw)

    def fail(message):
        return ValueError(message)

    try:
        entry = _classify(raw, fail)
        slow = _parse_state(("S",) + entry[1], fail) if entry[0] == "S" else None
    except ValueError:
        slow = None
    assert fast is None or (fast.label, fast.related, fast.ingredients) == (slow.label, slow.related, slow.ingredients)
    if re.fullmatch(r"S\d*\t[a-z ]*[a-z][a-z ]*(\t\[ ?[a-z]+ ?\])?(\t\{[a-z ,]*\})?", raw):  # usual shapes are read
        assert fast is not None


def test_states_nodes_and_units_keep_their_hashes_across_pickling():
    """States, nodes and units cache their hash; a pickle carries no hash (string hashes differ per process) and
    the copy hashes and compares as the original."""
    import pickle

    state = make_state("Contains", "", ["b", "a"])
    node = make_node("Bowl", [state, make_state("in", "sink")], motion_flag=1)
    unit = make_unit((node,), Motion("stir"), (make_node("bowl"),), (make_source("r.txt", 3),))
    assert hash(state) == hash((state.label, state.related, state.ingredients))
    assert hash(node) == hash((node.label, node.states))
    assert hash(unit) == hash((unit.inputs, unit.motion, unit.outputs))
    assert unit.key is unit.key == (unit.motion.label, frozenset(unit.inputs), frozenset(unit.outputs))  # cached
    for x in (state, node, unit):
        copy = pickle.loads(pickle.dumps(x))
        assert b"_hash" not in pickle.dumps(x)
        assert copy == x and hash(copy) == hash(x) and {copy: 1}[x] == 1


def test_block_reader_takes_exported_networks_and_leaves_the_rest():
    """Written networks are plain and read block by block; comments, blank lines, CRs and indentation are not."""
    text = write_foon(parse_text(UNIT + "//\n" + UNIT.replace("crack", "break")).foon)
    skip, first = _comment_head(text)  # its header comment is skipped, its lines still counted
    assert text.startswith("#") and _plain(text, skip)
    fast = _Reader("m.txt").read_plain(text[skip:], first)
    assert full(fast.foon, sources=True) == full(_line_reader(text).foon, sources=True)
    assert _comment_head("# Source: x\n" + text) == (0, 1)  # a URL line: the line reader keeps it
    for other in ("# note\n" + text, text.replace("//\n", "//\n\n", 1), text.replace("\n", "\r\n"),
                  text.replace("\nS", "\n S", 1)):
        assert not _plain(other)
        assert full(parse_text(other).foon) == full(parse_text(text).foon)
    # a block the line reader warns about (no outputs) sends plain text to it: the warning is kept
    bad = text + "O\tbowl\nS\tempty\nM\tstir\n//\n"
    skip, first = _comment_head(bad)
    assert _plain(bad, skip) and _Reader("w").read_plain(bad[skip:], first) is None
    res = parse_text(bad, "w")
    assert [w.message for w in res.warnings] == ["unit has no output objects after its motion line; skipped"]


# ---------------------------------------------------------------- malformed input through the CLI


def _real_lines() -> list[str]:
    return SUBGRAPH_FILES[0].read_text(encoding="utf-8").split("\n")


def _truncated(tmp_path):
    rows = _real_lines()
    i = next(k for k, r in enumerate(rows) if r.startswith("S") and "[" in r)
    rows[i] = rows[i][: rows[i].index("[") + 3]
    return "\n".join(rows).encode(), i + 1


def _truncated_label(tmp_path):
    rows = _real_lines()
    i = next(k for k, r in enumerate(rows) if r.startswith("O") and k > 20)
    rows[i] = rows[i].split("\t")[0]
    return "\n".join(rows).encode(), i + 1


MALFORMED = {
    "truncated-state": _truncated,
    "truncated-object": _truncated_label,
    "state-first": lambda tmp: (b"# Source:\thttp://x\r\n//\r\nS41\tempty\r\nO278\tbowl\t1\r\n", 3),
    "garbage": lambda tmp: (b"O1\tbowl\t0\r\nM1\tpour\r\nO1\tbowl\t0\r\n\x13\x00\x7f\x01\x02garbage\r\n", 4),
    "non-utf8": lambda tmp: (b"//\nO1\tbowl\t0\nM1\tpour\nO1\tcr\xe8me\t0\n", 4),
    "empty": lambda tmp: (b"", 1),
}


def _run(args):
    return CliRunner().invoke(main, args, catch_exceptions=False)


def _check_one_error(result, path, line):
    assert result.exit_code == 2
    assert "Traceback" not in result.output + result.stderr
    assert result.stdout == ""
    located = [r for r in result.stderr.splitlines() if re.match(r"\S.*?: error: ", r)]
    assert len(located) == 1, result.stderr
    prefix = f"{path}:{line}: error: " if line is not None else f"{path}: error: "  # the file as a whole: no line
    assert located[0].startswith(prefix), (located, prefix)


@pytest.mark.parametrize("case", sorted(MALFORMED))
@pytest.mark.parametrize("command", ["stats", "merge"])
def test_malformed_files_give_one_located_error_and_exit_2(tmp_path, case, command):
    data, line = MALFORMED[case](tmp_path)
    bad = tmp_path / f"{case}.txt"
    bad.write_bytes(data)
    out = tmp_path / "out" / "result.txt"
    result = _run([command, str(SUBGRAPH_FILES[1]), str(bad), "-o", str(out)])
    _check_one_error(result, bad, line)
    assert not out.parent.exists()


@pytest.mark.parametrize("command", ["stats", "merge"])
def test_directory_without_foon_files_and_missing_path(tmp_path, command):
    empty = tmp_path / "notes"
    empty.mkdir()
    (empty / "README.md").write_text("not a FOON\n")
    out = tmp_path / "out.txt"
    _check_one_error(_run([command, str(empty), "-o", str(out)]), empty, None)
    _check_one_error(_run([command, str(tmp_path / "missing.txt"), "-o", str(out)]), tmp_path / "missing.txt", None)
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes"]


def test_random_garbage_files_never_traceback(tmp_path):
    rng = random.Random(7)
    for k in range(5):
        bad = tmp_path / f"g{k}.foon"
        bad.write_bytes(bytes(rng.randrange(256) for _ in range(200)))
        result = _run(["stats", str(bad)])
        assert result.exit_code == 2 and "Traceback" not in result.stderr
        assert result.stderr.startswith(f"{bad}:")


@settings(max_examples=50, suppress_health_check=[HealthCheck.too_slow])
@given(units())
def test_the_fast_builders_make_what_the_dataclass_constructors_make(unit):
    """`make_unit`/`make_source` fill `__dict__` directly: equal, equally hashed, every field set, as built by
    the frozen dataclass's own `__init__` (a new field on Source or FunctionalUnit must reach them)."""
    from dataclasses import fields

    from foon2pddl.model.foon import FunctionalUnit, Source, make_source, make_unit

    built = make_unit(unit.inputs, unit.motion, unit.outputs, (make_source("f.txt", 3),))
    plain = FunctionalUnit(unit.inputs, unit.motion, unit.outputs, (Source("f.txt", 3),))
    assert built == plain and hash(built) == hash(plain) and built.key == plain.key
    for made, ref in ((built, plain), (built.sources[0], plain.sources[0])):
        assert {f.name: getattr(made, f.name) for f in fields(ref)} == {f.name: getattr(ref, f.name) for f in fields(ref)}
    node = unit.inputs[0] if unit.inputs else unit.outputs[0]
    again = make_node(node.label, node.states, motion_flag=node.motion_flag, goal=node.goal, dish=node.dish)
    assert again == node and hash(again) == hash(node)
