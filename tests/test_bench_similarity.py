"""The labelled substitution pairs of bench/ and the interval bench/similarity.py reports."""

from __future__ import annotations

import pytest
from conftest import SEARCH_INPUTS, SUBGRAPHS

from bench.similarity import SPLITS, Pair, read_pairs, score, search_labels, wilson
from foon2pddl.generalize.cook import reference_vocabulary
from foon2pddl.generalize.expand import vocabulary
from foon2pddl.io.inputs import load_network


def test_labelled_pairs_are_well_formed_and_from_the_shared_subgraphs_or_the_search_inputs():
    pairs = read_pairs()
    assert len(pairs) >= 800
    assert {p.label for p in pairs} == {"good", "marginal", "bad"}
    assert {p.split for p in pairs} == {"independent", "tune", "fresh", "outside", "unsampled", "lemmas", "lemmas2",
                                        "lemmas3", "lemmas4", "lemmas5", "lemmas6", "lemmas7", "lemmas8", "lemmas9"}
    assert {p.split for p in pairs} <= set(SPLITS)  # the bench reports every labelled split
    lemma_batches = ("lemmas", "lemmas2", "lemmas3", "lemmas4", "lemmas5", "lemmas6", "lemmas7", "lemmas8", "lemmas9")
    later = ("outside", "unsampled", *lemma_batches)
    assert {p.source for p in pairs if p.split in later} <= {"paper+cook", "paper", "cook", "random"}
    assert {p.source for p in pairs if p.split not in later} == {
        "paper-proposed", "cook-proposed", "random"}
    keys = [frozenset((p.a, p.b)) for p in pairs]
    assert len(set(keys)) == len(keys) and all(len(k) == 2 for k in keys)
    shared = set(vocabulary(load_network([SUBGRAPHS]).foon))
    search = set(search_labels(SEARCH_INPUTS.parent))
    reference = set(reference_vocabulary())  # the shared subgraphs' labels and the example's
    for p in pairs:
        if p.split == "outside":  # search-input labels, at least one not in the reference vocabulary
            assert {p.a, p.b} <= search and not {p.a, p.b} <= reference, p
        elif p.split == "unsampled":
            assert {p.a, p.b} <= reference, p
        elif p.split in lemma_batches:  # a drawn WordNet lemma with a drawn or reference label
            assert not {p.a, p.b} <= reference and not {p.a, p.b} & (search - reference), p
        else:
            assert {p.a, p.b} <= shared, p
    for batch in lemma_batches[1:]:  # each later batch's drawn labels are in no other split
        drawn = {x for p in pairs if p.split == batch for x in (p.a, p.b)} - reference
        assert drawn and not drawn & {x for p in pairs if p.split != batch for x in (p.a, p.b)}, batch


def test_wilson_interval_matches_the_closed_form_values():
    lo, hi = wilson(8, 10)  # textbook value: 0.4902 .. 0.9433
    assert lo == pytest.approx(0.4902, abs=1e-4) and hi == pytest.approx(0.9433, abs=1e-4)
    assert wilson(0, 10)[0] == 0.0 and wilson(10, 10)[1] == pytest.approx(1.0)
    assert wilson(0, 0) == (0.0, 1.0)


def test_score_counts_precision_and_recall_of_good_pairs():
    pairs = [Pair("a", "b", "good", "random", "tune"), Pair("a", "c", "bad", "random", "tune"),
             Pair("b", "c", "good", "random", "tune")]
    s = score(pairs, lambda x, y: x == "a")
    assert (s.accepted, s.good_accepted, s.good, s.bad_accepted) == (2, 1, 2, 1)
    assert s.precision()[0] == 0.5 and s.recall()[0] == 0.5


def test_lemma_batches_draw_as_drawn_and_the_later_ones_reach_their_more_tool_roots():
    """`lemmas4` found only 14 unused tool lemmas under `TOOLS`; `MORE_TOOLS` joins them from `lemmas5` on only,
    and `KITCHEN_TOOLS` (kitchen objects FOON uses that no earlier root reaches) from `lemmas6` on only, with
    `N_TOOLS_MORE` tool lemmas instead of `N_TOOLS` (`lemmas7` too; `lemmas8` keeps those roots and finds only the
    few tool lemmas they have left); `lemmas9` adds `MORE_FOOD` and `KITCHEN_OBJECTS` and draws every kitchen
    object left under them, with `N_FOOD_MORE` food lemmas."""
    from bench.similarity_lemmas import (
        FOOD,
        KITCHEN_OBJECTS,
        KITCHEN_TOOLS,
        MORE_FOOD,
        MORE_TOOLS,
        N_FOOD,
        N_FOOD_MORE,
        N_TOOLS,
        N_TOOLS_MORE,
        TOOLS,
        _name,
        _pool,
        draws,
    )
    from foon2pddl.generalize import wordnet

    reader, shared = wordnet.reader(), SEARCH_INPUTS.parent
    reference = set(reference_vocabulary())
    pairs = read_pairs()
    drawn = draws(reader, shared, "lemmas9")  # every batch drawn once, in order, each skipping the earlier ones
    for split in drawn:  # every lemma a labelled pair uses
        labelled = {x for p in pairs if p.split == split for x in (p.a, p.b)} - reference
        assert labelled and labelled <= set(drawn[split]), split
    old, more, kitchen = ({_name(reader, s) for s in _pool(reader, roots)} for roots in (TOOLS, MORE_TOOLS, KITCHEN_TOOLS))
    tools5 = drawn["lemmas5"][N_FOOD:]
    assert len(tools5) == N_TOOLS and set(tools5) - old and set(tools5) <= old | more
    for split in ("lemmas6", "lemmas7", "lemmas8"):  # `lemmas7` and `lemmas8` keep `lemmas6`'s roots and sizes
        tools = drawn[split][N_FOOD:]
        assert set(tools) - old - more and set(tools) <= old | more | kitchen, split
        assert len(tools) == N_TOOLS_MORE or split == "lemmas8", split
        assert len(drawn[split]) == len(set(drawn[split])) and not set(drawn[split]) & {
            x for other, labels in drawn.items() if other != split for x in labels}, split
    # `lemmas8` ran the tool roots dry: it drew every tool lemma no earlier split, label or search input uses
    before9 = {"lemmas8", "lemmas9"}  # the splits drawn after lemmas8's draw (the file as lemmas8 was drawn on)
    earlier = {x for p in pairs if p.split not in before9 for x in (p.a, p.b)} | set(search_labels(shared))
    earlier |= {x for split, labels in drawn.items() if split not in before9 for x in labels}
    tools8 = drawn["lemmas8"][N_FOOD:]
    assert 0 < len(tools8) < N_TOOLS_MORE and set(tools8) == (old | more | kitchen) - earlier - reference - {""}
    # `lemmas9`: more food lemmas, some under `MORE_FOOD` only, and every kitchen object `KITCHEN_OBJECTS` has left
    food9, tools9 = drawn["lemmas9"][:N_FOOD_MORE], drawn["lemmas9"][N_FOOD_MORE:]
    only_food, more_food, objects = ({_name(reader, s) for s in _pool(reader, roots)}
                                     for roots in (FOOD, MORE_FOOD, KITCHEN_OBJECTS))
    assert set(food9) - only_food and set(food9) <= only_food | more_food
    earlier |= {x for p in pairs if p.split == "lemmas8" for x in (p.a, p.b)} | set(drawn["lemmas8"])
    assert 0 < len(tools9) < N_TOOLS_MORE and set(tools9) == objects - old - more - kitchen - earlier - reference
    assert not set(drawn["lemmas9"]) & {x for split, labels in drawn.items() if split != "lemmas9" for x in labels}
