"""`ObjectNode` and `State` equality: the hand-written `__eq__` (a fast path for the same object and for differing
hashes) must agree with the dataclass equality it replaces, which compares the identity fields only."""

from __future__ import annotations

import dataclasses

from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.model.foon import ObjectNode, State, make_node, make_state

# A few short words so that equal and near-equal nodes are drawn often.
_WORDS = st.sampled_from(["bowl", "egg", "whisk", "in", "whole"])
_STATES = st.builds(lambda label, related, ingredients: make_state(label, related, ingredients),
                    _WORDS, st.sampled_from(["", "bowl"]), st.lists(_WORDS, max_size=2))
_NODES = st.builds(lambda label, states, goal, dish: make_node(label, states, goal=goal, dish=dish),
                   _WORDS, st.lists(_STATES, max_size=2), st.booleans(), st.sampled_from([None, 0, 1]))


def _fields(x: ObjectNode | State) -> tuple:
    """The values of the fields dataclass equality compares (`compare=True`), read independently of `__eq__`."""
    return tuple(getattr(x, f.name) for f in dataclasses.fields(x) if f.compare)


@settings(deadline=None)  # a loaded machine stretches one example past the default 200 ms
@given(_NODES, _NODES)
def test_node_equality_is_field_equality(a, b):
    assert (a == b) == (_fields(a) == _fields(b))
    assert (a != b) == (_fields(a) != _fields(b))
    assert a == a  # noqa: PLR0124 - the same-object fast path
    if a == b:
        assert hash(a) == hash(b)


@settings(deadline=None)
@given(_STATES, _STATES)
def test_state_equality_is_field_equality(a, b):
    assert (a == b) == (_fields(a) == _fields(b))
    if a == b:
        assert hash(a) == hash(b)


def test_equality_ignores_marks_and_other_types():
    a = make_node("egg", [make_state("whole")], goal=True, dish=1)
    b = make_node("egg", [make_state("whole")])
    assert a == b and hash(a) == hash(b)
    assert a != make_node("egg", [make_state("cracked")])
    assert a != "egg" and make_state("whole") != ("whole", "", ())
    assert (a == object()) is False


@settings(deadline=None)  # a loaded machine stretches one example past the default 200 ms
@given(_NODES, _NODES)
def test_a_node_built_without_make_node_compares_by_its_fields(a, b):
    # `ObjectNode.__eq__` reads the hash `make_node` keeps; a node from the dataclass constructor has none until hashed
    c = ObjectNode(b.label, b.states)
    assert (a == c) == (c == a) == (_fields(a) == _fields(b))
    assert c == b and ObjectNode(b.label, b.states) == c


def test_equal_states_are_one_object():
    # nodes of one value from different units then compare their states by identity (`make_state`)
    one = make_state("In", "bowl", ["egg", "salt"])
    assert make_state("in", " Bowl", ["salt", "egg", "salt"]) is one
    assert make_state("in", "bowl", ["egg"]) is not one
    assert make_node("egg", [one]).states[0] is make_node("egg", [make_state("in", "bowl", ["salt", "egg"])]).states[0]
