"""The blind relabellings of the shared subgraphs' pairs and the agreement figures bench/similarity_relabel.py reports."""

from __future__ import annotations

import hashlib

import pytest

from bench.similarity import Pair, read_pairs
from bench.similarity_relabel import (
    LABELS,
    RELAB51,
    RELAB52,
    RELAB53,
    RELAB54,
    RELABEL,
    RELABELLED,
    RELABELLINGS,
    agreement,
    agreements,
    confusion,
    paired,
    read_relabel,
    subsets,
)

RUBRIC = RELABEL.with_name("similarity_rubric.md")


def test_the_second_labelling_covers_exactly_the_shared_pairs_and_is_the_frozen_file():
    second = read_relabel()
    first = [p for p in read_pairs() if p.split in RELABELLED]
    keys = {frozenset((p.a, p.b)) for p in second}
    assert len(keys) == len(second) == len(first) and keys == {frozenset((p.a, p.b)) for p in first}
    assert {p.label for p in second} == set(LABELS)
    sha1 = hashlib.sha1(RELABEL.read_bytes()).hexdigest()
    assert sha1 in RUBRIC.read_text(encoding="utf-8")  # the rubric names the hash frozen before the key was opened
    assert len(paired(first, second)) == len(second)


def test_cohens_kappa_matches_a_hand_computed_three_way_table():
    pairs = [("good", "good")] * 2 + [("marginal", "marginal")] + [("bad", "bad")] * 3 + [
        ("good", "bad"), ("bad", "marginal")]
    table = confusion(pairs)
    assert table[("good", "bad")] == 1 and table[("bad", "good")] == 0 and table[("bad", "marginal")] == 1
    assert sum(table.values()) == 8 and len(table) == 9
    po, kappa = agreement(table)  # po 6/8; pe (3*2 + 1*2 + 4*4) / 64 = 0.375; kappa 0.375 / 0.625
    assert po == pytest.approx(0.75) and kappa == pytest.approx(0.6)


def test_kappa_is_zero_at_chance_and_one_when_the_labellers_agree():
    chance = confusion([("good", "good"), ("good", "bad"), ("bad", "good"), ("bad", "bad")])
    assert agreement(chance) == pytest.approx((0.5, 0.0))
    assert agreement(confusion([("good", "good"), ("bad", "bad")])) == pytest.approx((1.0, 1.0))


def test_pairing_takes_the_first_label_by_unordered_pair_and_rejects_different_coverage():
    first = [Pair("a", "b", "good", "random", "tune"), Pair("c", "d", "bad", "random", "tune")]
    second = [Pair("d", "c", "marginal", "relabel", "relabel"), Pair("a", "b", "good", "relabel", "relabel")]
    assert paired(first, second) == [("bad", "marginal"), ("good", "good")]
    with pytest.raises(ValueError, match="different pairs"):
        paired(first, second[:1])


@pytest.mark.parametrize(("path", "name"), [(RELAB51, "relab51"), (RELAB52, "relab52"), (RELAB53, "relab53"),
                                           (RELAB54, "relab54")])
def test_the_third_to_sixth_labellings_cover_exactly_the_shared_pairs_and_are_the_frozen_files(path, name):
    later = read_relabel(path, name)
    first = [p for p in read_pairs() if p.split in RELABELLED]
    assert {frozenset((p.a, p.b)) for p in later} == {frozenset((p.a, p.b)) for p in first}
    assert len(later) == len(first) and {p.label for p in later} == set(LABELS)
    assert {(p.source, p.split) for p in later} == {(name, name)}
    assert hashlib.sha1(path.read_bytes()).hexdigest() in RUBRIC.read_text(encoding="utf-8")
    assert [name for name, _ in RELABELLINGS] == ["relabel", "relab51", "relab52", "relab53", "relab54"]


def test_agreements_compare_every_labelling_with_each_later_one_by_ordinal():
    first = [Pair("a", "b", "good", "random", "tune"), Pair("c", "d", "bad", "random", "independent")]
    second = [Pair("b", "a", "good", "relabel", "relabel"), Pair("c", "d", "marginal", "relabel", "relabel")]
    third = [Pair("c", "d", "bad", "relab51", "relab51"), Pair("a", "b", "marginal", "relab51", "relab51")]
    got = agreements([first, second, third])
    assert [(x, y) for x, y, _ in got] == [("first", "second"), ("first", "third"), ("second", "third")]
    tables = {(x, y): t for x, y, t in got}
    assert tables[("first", "second")][("bad", "marginal")] == 1 and tables[("first", "second")][("good", "good")] == 1
    assert tables[("first", "third")][("good", "marginal")] == 1 and tables[("first", "third")][("bad", "bad")] == 1
    assert tables[("second", "third")][("marginal", "bad")] == 1 and tables[("second", "third")][("good", "marginal")] == 1
    fourth = [Pair("a", "b", "bad", "relab52", "relab52"), Pair("d", "c", "bad", "relab52", "relab52")]
    got = agreements([first, second, third, fourth])
    assert [(x, y) for x, y, _ in got] == [("first", "second"), ("first", "third"), ("first", "fourth"),
                                           ("second", "third"), ("second", "fourth"), ("third", "fourth")]
    assert got[-1][2][("marginal", "bad")] == 1 and got[-1][2][("bad", "bad")] == 1
    fifth = [Pair("b", "a", "good", "relab53", "relab53"), Pair("c", "d", "marginal", "relab53", "relab53")]
    got = agreements([first, second, third, fourth, fifth])
    assert len(got) == 10 and [x for x, y, _ in got if y == "fifth"] == ["first", "second", "third", "fourth"]
    assert got[-1][2][("bad", "good")] == 1 and got[-1][2][("bad", "marginal")] == 1
    sixth = [Pair("c", "d", "good", "relab54", "relab54"), Pair("a", "b", "bad", "relab54", "relab54")]
    got = agreements([first, second, third, fourth, fifth, sixth])
    assert len(got) == 15 and [x for x, y, _ in got if y == "sixth"] == ["first", "second", "third", "fourth", "fifth"]
    assert got[-1][2][("good", "bad")] == 1 and got[-1][2][("marginal", "good")] == 1


def test_subsets_split_a_relabelling_by_the_first_labels_splits():
    first = [Pair("a", "b", "good", "random", "tune"), Pair("c", "d", "bad", "random", "independent"),
             Pair("e", "f", "bad", "random", "fresh"), Pair("g", "h", "bad", "random", "unsampled")]
    third = [Pair("d", "c", "good", "relab51", "relab51"), Pair("a", "b", "bad", "relab51", "relab51"),
             Pair("e", "f", "marginal", "relab51", "relab51"), Pair("g", "h", "good", "relab51", "relab51")]
    got = subsets(first, third)
    assert list(got) == ["", "held-out", "tuning"]
    assert got[""] == third
    assert [(p.a, p.label) for p in got["held-out"]] == [("d", "good"), ("e", "marginal")]
    assert [(p.a, p.label) for p in got["tuning"]] == [("a", "bad"), ("g", "good")]
