"""FOON-EXP: consistent substitution, duplicates removed, provenance, the size guard."""

from __future__ import annotations

import numpy as np
import pytest
from foon_strategies import foons
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.errors import UsageError
from foon2pddl.generalize.expand import expand, is_expanded, vocabulary
from foon2pddl.generalize.similarity import SimilarityMatrix, similarity_matrix
from foon2pddl.generalize.substitute import (
    product_renames,
    rename_derived,
    replace_words,
    substitute_node,
    substitute_unit,
    unit_labels,
)
from foon2pddl.generalize.substitution import Substitution, expansion_substitutions
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state
from foon2pddl.model.tasktree import TaskTree


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
    assert substitute_unit(CUT, {"lemon": "lime"}, note="lemon", to="lime").sources == \
        (Source("r.foon", 3, None, "lemon", "lime"),)


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
    with pytest.raises(UsageError, match="exceed 2 units"):
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
        # every copy is an original with one similar object (or a derived product) substituted,
        # and the products it makes from that object renamed along
        old, new = u.sources[0].expanded_from, u.sources[0].expanded_to
        partners = {b for a, b in close if a == old} | {b for a, b in e.derived if a == old}
        assert new in partners  # the replacement is recorded, and it is the one the copy was made with
        assert any(substitute_unit(o, {old: new, **product_renames(o, {old: new})}).key == u.key
                   for o in foon.units)
    assert {u.key for u in expand(foon, m, threshold=0.92).foon.units} <= set(keys)  # monotone in threshold


SQUEEZE = FunctionalUnit((LEMON, make_node("juicer", [make_state("empty")])), Motion("squeeze"),
                         (make_node("lemon", [make_state("squeezed")]),
                          make_node("juicer", [make_state("contains", "", ["lemon juice"])]),
                          make_node("lemon juice", [make_state("in", "juicer")])))
POUR = FunctionalUnit((make_node("lemon juice", [make_state("in", "juicer")]), make_node("bowl")), Motion("pour"),
                      (make_node("bowl", [make_state("contains", "", ["lemon juice"])]),))
STIR = FunctionalUnit((make_node("bowl", [make_state("contains", "", ["lemon juice"])]), make_node("spoon")),
                      Motion("stir"), (make_node("lemonade", [make_state("contains", "", ["lemon juice"])]),))


def test_products_made_from_a_substituted_object_are_renamed_and_flow_down():
    m = matrix(["lemon", "lime", "juicer", "lemon juice", "bowl", "spoon", "lemonade"], [("lemon", "lime", 0.93)])
    e = expand(Foon((SQUEEZE, POUR, STIR)), m)
    assert ("lemon juice", "lime juice") in e.derived  # `lime juice` is not even in the vocabulary
    labels = [unit_labels(u) for u in e.foon.units if is_expanded(u)]
    squeezed = [x for x in labels if "lime" in x]
    assert squeezed and all("lime juice" in x and "lemon juice" not in x for x in squeezed)
    # the renamed juice is poured and stirred: lemonade made of lime juice
    stirred = make_node("lemonade", [make_state("contains", "", ["lime juice"])])
    assert any(stirred in u.outputs for u in e.foon.units)
    assert "lemonade" in {n.label for u in e.foon.units for n in u.outputs}  # not a whole-word match


def test_a_product_is_not_substituted_away_from_its_source():
    lime_squeeze = substitute_unit(SQUEEZE, {"lemon": "lime", "lemon juice": "lime juice"})
    m = matrix(["lime", "juicer", "lime juice", "lemon juice"], [("lime juice", "lemon juice", 0.95)])
    e = expand(Foon((lime_squeeze,)), m)
    assert len(e.foon.units) == 1  # no `squeeze lime -> lemon juice`


def test_word_replacement_is_whole_words():
    assert replace_words("lemon juice", "lemon", "lime") == "lime juice"
    assert replace_words("lemonade", "lemon", "lime") is None
    assert replace_words("lemon", "lemon", "lime") is None
    assert replace_words("juice of lemon and lemon zest", "lemon", "blood orange") == \
        "juice of blood orange and blood orange zest"


def test_example_exp_has_lime_copies_of_the_lemon_units(example, label_similarity):
    kitchen = read_kitchen(example_path("example_kitchen.txt"))
    m = similarity_matrix(vocabulary(example.foon, kitchen), cache=False, sim=label_similarity)
    e = expand(example.foon, m, kitchen=kitchen)
    assert ("lemon", "lime") in e.substitutions
    keys = {u.key for u in e.foon.units}
    lemon_units = [u for u in example.foon.units if "lemon" in {n.label for n in u.inputs}]
    assert lemon_units
    for u in lemon_units:  # each has its lime copy (some coincide with the guacamole recipe's own units)
        copy = substitute_unit(u, {"lemon": "lime", **product_renames(u, {"lemon": "lime"})})
        assert copy.key in keys and "lemon" not in unit_labels(copy)


def test_rename_derived_follows_what_the_substituted_object_made():
    lime_squeeze = substitute_unit(SQUEEZE, {"lemon": "lime"})  # as a lifted plan grounds it: juice keeps its name
    units = (lime_squeeze, POUR, STIR)
    assert rename_derived(units, {"lemon": "lime"}) == {"lemon juice": "lime juice"}
    assert rename_derived(units, {"lemon": "lime"}, fixed=frozenset({"lemon juice"})) == {}
    assert rename_derived((SQUEEZE, POUR, STIR), {"lemon": "lime"}) == {}  # no lime was squeezed


def test_an_exp_tree_names_the_replacement_recorded_at_expansion():
    """The note names the label the copy was made with, even when another label of the copy is closer
    to the original (reconstructing by similarity named `lemon juice`, which was there all along)."""
    m = matrix(["lemon", "lime", "cutting board", "lemon juice", "bowl", "salt"], [("lemon", "lime", 0.93)])
    e = expand(Foon((CUT,)), m)
    copy = next(u for u in e.foon.units if is_expanded(u))
    assert (copy.sources[0].expanded_from, copy.sources[0].expanded_to) == ("lemon", "lime")

    def sim(a, b):  # a similarity under which the copy's other label looks closer
        return {frozenset(("lemon", "lime")): 0.93, frozenset(("lemon", "lemon juice")): 0.99}.get(
            frozenset((a, b)), 1.0 if a == b else 0.0)

    tree = TaskTree((copy,), make_node("lime", [make_state("halved")]))
    assert expansion_substitutions(tree, sim) == (Substitution("lemon", "lime", 0.93),)
    unrecorded = FunctionalUnit(copy.inputs, copy.motion, copy.outputs, (Source("r.foon", 3, None, "lemon"),))
    assert expansion_substitutions(TaskTree((unrecorded,), tree.goal), sim)[0].replacement == "lemon juice"


def test_expansion_holds_back_full_collections(monkeypatch):
    """Stop 53's pass (nc53b): `expand tests/data/foon-subgraphs --similarity paper` makes 17,578 units, millions of
    long-lived objects, and CPython's full collections rescanned them, 1.05 s and 1.18 s each holding the GIL (load
    17): a step due to say what it did could not speak, 2.1 s silences. Expanding is a build (`model.bulk`)."""
    import gc

    from foon2pddl.generalize import expand as expand_module
    from foon2pddl.model import bulk

    thresholds = []

    def watched(*args, **kwargs):
        thresholds.append(gc.get_threshold()[2])
        return substitute_unit(*args, **kwargs)

    monkeypatch.setattr(expand_module, "substitute_unit", watched)
    e = expand(Foon((CUT,)), matrix(["lemon", "lime", "cutting board", "lemon juice"], [("lemon", "lime", 0.93)]),
               threshold=0.89)
    assert e.added_units and thresholds and set(thresholds) == {bulk._NEVER}
