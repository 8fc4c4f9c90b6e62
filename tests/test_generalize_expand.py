"""FOON-EXP: consistent substitution, duplicates removed, provenance, the size guard."""

from __future__ import annotations

import numpy as np
import pytest
from foon_strategies import foons
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.errors import FoonInputError
from foon2pddl.generalize.expand import expand, is_expanded, vocabulary
from foon2pddl.generalize.similarity import SimilarityMatrix, similarity_matrix
from foon2pddl.generalize.substitute import substitute_node, substitute_unit, unit_labels
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state


def matrix(labels, pairs):
    """A similarity matrix with the given symmetric pairs (others 0)."""
    labels = tuple(sorted(labels))
    values = np.eye(len(labels))
    for a, b, v in pairs:
        i, j = labels.index(a), labels.index(b)
        values[i, j] = values[j, i] = v
    return SimilarityMatrix(labels, values)


LEMON = make_node("lemon", [make_state("whole")])
BOARD = make_node("cutting board", [make_state("contains", "", ["lemon", "salt"])])
JUICE = make_node("lemon juice", [make_state("in", "bowl")])
HALF = make_node("lemon", [make_state("halved"), make_state("on", "cutting board")])
CUT = FunctionalUnit((LEMON, BOARD, JUICE), Motion("cut"), (HALF, BOARD), (Source("r.foon", 3),))


def test_substitution_is_consistent_and_whole_label():
    new = substitute_unit(CUT, {"lemon": "lime"}, note="lemon")
    labels = unit_labels(new)
    assert "lemon" not in labels and "lime" in labels
    assert "lemon juice" in labels  # a label that merely contains `lemon` is untouched
    board = next(n for n in new.inputs if n.label == "cutting board")
    assert board.states[0].ingredients == ("lime", "salt")
    assert make_node("lime", [make_state("halved"), make_state("on", "cutting board")]) in new.outputs
    assert new.sources == (Source("r.foon", 3, None, "lemon"),)


def test_substitution_keeps_lists_sorted_and_merges_items():
    node = make_node("bowl", [make_state("contains", "", ["lemon", "lime", "zest"])])
    out = substitute_node(node, {"lemon": "lime", "zest": "apple"})
    assert out.states[0].ingredients == ("apple", "lime")


def test_expand_copies_units_onto_similar_objects():
    foon = Foon((CUT,))
    m = matrix(["lemon", "lime", "orange", "cutting board", "lemon juice", "bowl", "salt"],
               [("lemon", "lime", 0.93), ("lemon", "orange", 0.92), ("salt", "bowl", 0.5)])
    e = expand(foon, m, threshold=0.89)
    assert e.original_units == 1 and len(e.foon.units) == 3 and e.added_units == 2
    assert set(e.substitutions) == {("lemon", "lime"), ("lemon", "orange")}
    expanded = [u for u in e.foon.units if is_expanded(u)]
    assert {u.sources[0].expanded_from for u in expanded} == {"lemon"}
    assert e.foon.units[0] is CUT and not is_expanded(CUT)
    higher = expand(foon, m, threshold=0.925)
    assert len(higher.foon.units) == 2  # only lime passes


def test_a_label_the_unit_already_mentions_is_not_substituted_in():
    both = FunctionalUnit((LEMON, make_node("lime")), Motion("mix"), (make_node("bowl"),))
    m = matrix(["lemon", "lime", "bowl"], [("lemon", "lime", 0.95)])
    assert len(expand(Foon((both,)), m).foon.units) == 1


def test_max_units_guard():
    m = matrix(["lemon", "lime", "orange", "cutting board", "lemon juice", "bowl", "salt"],
               [("lemon", "lime", 0.93), ("lemon", "orange", 0.92)])
    with pytest.raises(FoonInputError, match="exceed 2 units"):
        expand(Foon((CUT,)), m, max_units=2)
    assert len(expand(Foon((CUT,)), m, max_units=3).foon.units) == 3


@settings(max_examples=40, deadline=None)
@given(foons(max_units=5), st.data())
def test_expansion_properties(foon, data):
    labels = vocabulary(foon)
    pairs = data.draw(st.lists(st.tuples(st.sampled_from(labels), st.sampled_from(labels),
                                         st.sampled_from([0.5, 0.9, 0.95])), max_size=4))
    pairs = [(a, b, v) for a, b, v in pairs if a != b]
    m = matrix(labels, pairs)
    e = expand(foon, m)
    keys = [u.key for u in e.foon.units]
    assert len(keys) == len(set(keys))  # duplicates removed
    assert {u.key for u in foon.units} <= set(keys)  # originals kept
    close = {(a, b) for a, b, v in pairs if v >= 0.89} | {(b, a) for a, b, v in pairs if v >= 0.89}
    originals = {u.key for u in foon.units}
    for u in e.foon.units:
        if u.key in originals:
            continue
        # every copy is an original with one similar object substituted
        old = u.sources[0].expanded_from
        assert any(substitute_unit(o, {old: new}).key == u.key
                   for o in foon.units for new in {b for a, b in close if a == old})
    assert {u.key for u in expand(foon, m, threshold=0.92).foon.units} <= set(keys)  # monotone in threshold


def test_example_exp_has_lime_copies_of_the_lemon_units(example, label_similarity):
    kitchen = read_kitchen(example_path("example_kitchen.txt"))
    m = similarity_matrix(vocabulary(example.foon, kitchen), cache=False, sim=label_similarity)
    e = expand(example.foon, m, kitchen=kitchen)
    assert ("lemon", "lime") in e.substitutions
    lime_units = [u for u in e.foon.units if is_expanded(u) and "lime" in unit_labels(u)
                  and u.sources[0].expanded_from == "lemon"]
    assert lime_units and all("lemon" not in unit_labels(u) for u in lime_units)
