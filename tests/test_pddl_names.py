"""PDDL identifiers and comments: any label gives a valid, collision-free name; nothing escapes a comment."""

from __future__ import annotations

import re

import pddl.parser.domain
import pddl.parser.problem
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, ObjectNode, Source, State
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import ENCODINGS, compile_task
from foon2pddl.pddl.names import MAX_LENGTH, RESERVED, NameTable, comment, is_valid_name, sanitize
from foon2pddl.pddl.render import render

VALID = re.compile(r"[a-z][a-z0-9_-]*\Z")

# Labels meant to break things: PDDL syntax, keywords, line breaks of every kind, unicode, digits.
NASTY = st.sampled_from([
    "and", "not", "object", "either", "define", "-", "?x", "*", "pour*", "7up", "1", "", " ", ";", ";;",
    "a;b", "(", ")", "(:action evil", ")) (:init (p))", "x\n(:action injected", "x\r(not", "\u2028(p)",
    "\x85y", "caf\u00e9", "\u00e9", "\u4e2d\u6587", "\U0001f355", "salt & pepper", "o'clock", '"quoted"',
    "a - b", "a_b", "a-b", "a__b", "total-cost", "goal-reached", "is_available", "available", "\x00", "\t",
])
labels = st.one_of(NASTY, st.text(max_size=20), st.text("ab ;()*-_?\n\u00e9", max_size=8))


@given(labels)
def test_sanitize_gives_a_valid_unreserved_bounded_name(label):
    name = sanitize(label)
    assert VALID.match(name), name
    assert name not in RESERVED
    assert len(name) <= MAX_LENGTH + 1  # `_` appended to a reserved word


def test_sanitize_is_readable_for_ordinary_labels():
    assert sanitize("Drinking Glass") == "drinking_glass"
    assert sanitize("pour*") == "pour"
    assert sanitize("7up") == "x_7up"
    assert sanitize("and") == "and_"
    assert sanitize("café") == "cafe"
    assert sanitize("中") == "u4e2d"


@given(st.lists(labels, max_size=30))
def test_name_table_is_injective_stable_and_keeps_the_mapping(items):
    table = NameTable(reserved={"goal-reached"})
    names = [table.name(label) for label in items]
    # Same label -> same name; different labels -> different names.
    assert len(set(names)) == len(set(items))
    for label, name in zip(items, names, strict=True):
        assert table.name(label) == name
        assert table.labels[name] == label
        assert VALID.match(name) and name != "goal-reached"
    again = NameTable(reserved={"goal-reached"})
    assert [again.name(label) for label in items] == names


def test_name_table_keys_separate_things_with_one_label():
    table = NameTable()
    a = table.name("on", key=("pred", "on"))
    b = table.name("on", key=("object", "on"))
    c = table.name("on-2")
    assert len({a, b, c}) == 3


@given(st.text())
def test_comment_is_one_printable_ascii_line(text):
    line = "; " + comment(text)
    assert line.splitlines() == [line]
    assert line.isascii()
    assert all(ch == "\t" or 32 <= ord(ch) < 127 for ch in line)


def _raw_node(label: str, state: str, related: str) -> ObjectNode:
    # Built without normalization, so labels keep line breaks and odd whitespace.
    states = (State(state, related, ()),) if state else ()
    return ObjectNode(label, states)


@st.composite
def hostile_tasks(draw):
    """A small FOON whose labels, motion and source path are all hostile."""
    pool = draw(st.lists(st.builds(_raw_node, labels, labels, labels), min_size=2, max_size=5, unique=True))
    units = []
    for _ in range(draw(st.integers(1, 4))):
        ins = tuple(draw(st.lists(st.sampled_from(pool), min_size=1, max_size=3, unique=True)))
        outs = tuple(draw(st.lists(st.sampled_from(pool), min_size=1, max_size=3, unique=True)))
        src = Source(draw(labels) + "/" + draw(labels), draw(st.integers(0, 9)))
        units.append(FunctionalUnit(ins, Motion(draw(labels), composite=draw(st.booleans())), outs, (src,)))
    foon = Foon(tuple(units))
    produced = sorted({n for u in units for n in u.outputs})
    cands = tuple(sorted(draw(st.lists(st.sampled_from(produced), min_size=1, max_size=2, unique=True))))
    goal = Goal(GoalSpec(draw(labels)), cands, 3)
    kitchen = Kitchen(frozenset(draw(st.lists(st.sampled_from(pool), max_size=3))), 3, draw(labels))
    return foon, kitchen, goal


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(hostile_tasks(), st.sampled_from(list(ENCODINGS)), st.sampled_from([None, "unit"]))
def test_hostile_labels_render_to_pddl_that_parses_with_the_same_structure(case, encoding, costs):
    foon, kitchen, goal = case
    costs = costs if ENCODINGS[encoding].costs else None  # (an encoding may not support action costs)
    task = compile_task(foon, kitchen, goal, encoding, 3, prune=False, costs=costs)
    domain_text, problem_text = render(task)
    # fresh parsers: the `pddl` package's parser keeps state when a parse raises, so a shared one would fail every
    # later example with 'parser is in an unexpected state' and hide the first example's own error while shrinking
    domain = pddl.parser.domain.DomainParser()(domain_text)
    problem = pddl.parser.problem.ProblemParser()(problem_text)
    assert len(domain.actions) == len(task.actions)
    assert {a.name for a in domain.actions} == {a.name for a in task.actions}
    assert len(domain.predicates) == len(task.predicates)
    assert len(problem.init) == len(task.init) + (1 if costs else 0)
    # Every line is either a comment, or PDDL made of names, parentheses, `?`, `-`, `:` and numbers.
    for line in (domain_text + problem_text).splitlines():
        code = line.split(";", 1)[0]
        assert re.fullmatch(r"[a-z0-9_\-?:() =]*", code), line


# labels whose names are cut: a long shared prefix (the collision case) or long random letters, then any text
_LONG = st.tuples(st.one_of(st.just("bloody mary contains " + "celery salt lemon juice " * 3),
                            st.text(alphabet="abcdefghij", min_size=85, max_size=120)),
                  st.text(alphabet="abcdefghij ,()_-\u00e9", max_size=40)).map("".join)


@settings(max_examples=200, deadline=None)
@given(st.lists(_LONG, min_size=2, max_size=8, unique=True), st.lists(_LONG, max_size=6))
def test_truncated_names_are_distinct_and_independent_of_the_table(labels, others):
    alone = {label: NameTable().name(label) for label in labels}
    crowded = NameTable()
    for other in others:
        crowded.name(other)
    names = {label: crowded.name(label) for label in labels}
    assert len(set(alone.values())) == len(labels)
    assert names == alone
    assert all(len(n) <= 80 and is_valid_name(n) for n in alone.values())


def test_truncated_name_ends_with_a_digest_of_the_whole_label():
    stem = "stir-fried rice contains " + ", ".join(f"ingredient {i}" for i in range(12))
    a, b = NameTable().name(stem + " to a"), NameTable().name(stem + " to b")
    assert a != b and a[:60] == b[:60] and "-2" not in a + b
    assert a.rsplit("__", 1)[1] != b.rsplit("__", 1)[1]


@pytest.mark.parametrize("encoding", sorted(ENCODINGS))
def test_no_variable_shares_its_name_with_a_constant(encoding):
    """Hypothesis found it (stop 47): a unit making two eggs, the second in state "-" (nothing once sanitized), named that node's
    state constant `egg-2` (the type took `egg`) and the second egg's parameter `?egg-2`, so an atom read
    `(is ?egg-2 egg-2)`. PDDL tells them apart by the `?`; the `pddl` package does not (a term's name keys
    its type), and refused the domain. No action's variable is named like a constant or object."""
    ins = (_raw_node("egg", "raw", ""), _raw_node("egg", "whole", ""))
    outs = (_raw_node("egg", "cooked", ""), _raw_node("egg", "-", ""))
    foon = Foon((FunctionalUnit(ins, Motion("crack"), outs, (Source("t.txt", 1),)),))
    goal = Goal(GoalSpec("egg"), (outs[0],), 3)
    task = compile_task(foon, Kitchen(frozenset(ins), 3, "k"), goal, encoding, 3, prune=False)
    domain_text, problem_text = render(task)
    pddl.parser.domain.DomainParser()(domain_text)
    pddl.parser.problem.ProblemParser()(problem_text)
    constants = {name for name, _ in (*task.constants, *task.objects)}
    variables = set(re.findall(r"\?([a-z][a-z0-9_-]*)", domain_text))
    assert not constants & variables
