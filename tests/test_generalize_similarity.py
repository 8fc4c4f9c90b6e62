"""WordNet access and label similarity (WordNet-backed: `make install` installs Debian's WordNet)."""

from __future__ import annotations

import random

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.errors import FoonInputError, FoonSyntaxError, MissingDependencyError
from foon2pddl.generalize import similarity as simmod
from foon2pddl.generalize import wordnet
from foon2pddl.generalize.senses import KITCHEN_LEXNAMES, Overrides, parse_overrides, shipped_overrides
from foon2pddl.generalize.similarity import LabelSimilarity, similarity_matrix
from foon2pddl.generalize.wup import WupTable

KITCHEN_WORDS = ["onion", "chive", "knife", "scissors", "lemon", "lime", "kale", "lettuce", "salt", "pepper",
                 "bowl", "pot", "egg", "chicken", "fork", "spoon", "water", "sugar", "box", "blueberry",
                 "corn starch", "olive oil", "mixing bowl", "egg mixture", "flour mixture", "sea salt",
                 "blueberry muffin", "blorp", "dashi", "refrigerator", "fridge"]


# -- WordNet access -------------------------------------------------------------------------------------

def test_lexnames_table_is_the_standard_one():
    lines = wordnet.lexnames_text().splitlines()
    assert len(lines) == 45
    rows = [line.split("\t") for line in lines]
    assert [int(r[0]) for r in rows] == list(range(45))
    assert rows[0][1:] == ["adj.all", "3"] and rows[3][1:] == ["noun.Tops", "1"]
    assert rows[13][1:] == ["noun.food", "1"] and rows[29][1:] == ["verb.body", "2"]
    assert rows[44][1:] == ["adj.ppl", "3"]


def test_lexnames_agree_with_the_data_files(label_similarity):
    wn = label_similarity.reader
    # Known synsets land in their lexicographer files only if the table's numbering is right.
    assert wn.synset("egg.n.02").lexname() == "noun.food"
    assert wn.synset("knife.n.01").lexname() == "noun.artifact"
    assert wn.synset("boodle.n.01").lexname() == "noun.possession"
    assert wn.synset("chives.n.01").lexname() == "noun.plant"
    assert wn.synset("run.v.01").lexname().startswith("verb.")


def test_version_is_read_without_nltk():
    assert wordnet.version() == "3.0"


def test_nltk_roots_match_nltk_data_path():
    import nltk.data

    ours = [str(p) for p in wordnet.nltk_data_roots()]
    assert [str(p) for p in nltk.data.path[: len(ours)]] == ours


def test_no_wordnet_names_both_install_routes(tmp_path):
    with pytest.raises(MissingDependencyError) as err:
        wordnet.locate(debian_dir=tmp_path / "none", cache=tmp_path / "cache", nltk_roots=[tmp_path / "nltk"])
    assert "apt-get install wordnet-base wordnet-sense-index" in err.value.message
    assert "nltk.downloader wordnet" in err.value.message


def test_debian_files_are_assembled_into_an_nltk_corpus(tmp_path):
    root, corpus = wordnet.locate(cache=tmp_path, nltk_roots=[])
    assert root == tmp_path / "nltk_data" and corpus == root / "corpora" / "wordnet"
    assert (corpus / "lexnames").read_text() == wordnet.lexnames_text()
    assert all((corpus / f).is_file() for f in wordnet.CORPUS_FILES)
    assert wordnet.corpus_version(corpus) == "3.0"
    assert wordnet.locate(cache=tmp_path, nltk_roots=[]) == (root, corpus)  # found, not rebuilt


# -- Wu-Palmer ------------------------------------------------------------------------------------------

def test_wup_table_equals_nltk(label_similarity):
    wn = label_similarity.reader
    table = WupTable(wn)
    rng = random.Random(7)
    words = [*KITCHEN_WORDS, "chef", "fireman", "dog", "car", "idea", "stone", "music", "tree", "entity", "run"]
    synsets = [s for w in words for s in wn.synsets(w.replace(" ", "_"), "n")]
    pairs = [(a, b) for a in synsets for b in synsets if rng.random() < 0.02]
    assert len(pairs) > 300
    for a, b in pairs:
        assert table.wup(a.name(), b.name()) == a.wup_similarity(b), (a, b)


# -- label similarity -----------------------------------------------------------------------------------

def test_floors(label_similarity):
    assert label_similarity("onion", "chive") >= 0.89
    assert label_similarity("onion", "knife") < 0.5
    assert label_similarity("lemon", "lime") >= 0.89  # the example's EXP and GEN goal depends on it


def test_kitchen_senses_only(label_similarity):
    """With all senses kale and lettuce meet in a money-slang synset (1.0); kitchen senses do not."""
    wn = label_similarity.reader
    assert wn.synset("boodle.n.01") in wn.synsets("kale", "n")
    assert label_similarity("kale", "lettuce") < 1.0
    assert all(k in KITCHEN_LEXNAMES for k in label_similarity.resolution("kale").lexnames)


def test_tools_drop_plant_senses(label_similarity):
    box = label_similarity.resolution("box")
    assert "noun.plant" not in box.lexnames and "noun.artifact" in box.lexnames
    assert label_similarity("box", "blueberry") < 0.89


def test_multiword_labels(label_similarity):
    r = label_similarity.resolution("corn starch")
    assert (r.term, r.senses, r.modifier) == ("cornstarch", ("cornstarch.n.01",), None)
    r = label_similarity.resolution("olive oil")
    assert r.term == "olive_oil" and r.modifier is None
    r = label_similarity.resolution("blueberry muffin")
    assert (r.source, r.term, r.modifier) == ("head", "muffin", "blueberry")


def test_compounds_compare_heads_and_modifiers(label_similarity):
    s = label_similarity
    # same head: the modifiers decide
    assert s("lemon mixture", "lime mixture") == pytest.approx(s("lemon", "lime"))
    assert s("egg mixture", "flour mixture") == pytest.approx(s("egg", "flour"))
    # a compound against its own head: one level below it, close but not identical
    assert s("salt", "salt") == 1.0 and 0.89 <= s("sea salt", "salt") < 1.0


def test_unknown_label_is_similar_to_nothing(label_similarity):
    assert label_similarity.resolution("blorpish zork").senses == ()
    assert label_similarity("blorpish zork", "fork") == 0.0
    assert label_similarity("blorpish zork", "blorpish zork") == 1.0


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(KITCHEN_WORDS), st.sampled_from(KITCHEN_WORDS))
def test_similarity_is_symmetric_and_bounded(label_similarity, a, b):
    v = label_similarity(a, b)
    assert v == label_similarity(b, a)
    assert 0.0 <= v <= 1.0
    assert (v == 1.0) if a == b else True


# -- overrides ------------------------------------------------------------------------------------------

def test_shipped_overrides_name_senses_wordnet_lacks(label_similarity):
    assert "dashi" in shipped_overrides().senses
    assert label_similarity.resolution("dashi").source == "override"
    assert label_similarity("dashi", "broth") == 1.0


def test_pair_override_and_sense_override(label_similarity):
    custom = Overrides({"zzkale": ("kale.n.03",)}, {frozenset(("onion", "knife")): 0.25})
    sim = LabelSimilarity(label_similarity.reader, custom)
    assert sim("knife", "onion") == 0.25
    assert sim("zzkale", "kale") == 1.0


def test_bad_overrides_are_reported_with_their_file(label_similarity):
    with pytest.raises(FoonInputError) as err:
        parse_overrides('{"pairs": [["a", "b", 3]]}', "over.json")
    assert err.value.path == "over.json" and "0..1" in err.value.message
    with pytest.raises(FoonSyntaxError) as err:  # invalid JSON names its line (load_json, as every JSON input)
        parse_overrides("{not json", "over.json")
    assert err.value.line == 1
    bad = Overrides({"thing": ("nosuch.n.01",)}, {})
    with pytest.raises(FoonInputError):
        LabelSimilarity(label_similarity.reader, bad).resolution("thing")


# -- matrix and its cache -------------------------------------------------------------------------------

def test_matrix_is_symmetric_and_cached(label_similarity, tmp_path, monkeypatch):
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path))
    words = KITCHEN_WORDS[:12]
    m = similarity_matrix(words, sim=label_similarity)
    assert np.array_equal(m.values, m.values.T) and np.all(np.diag(m.values) == 1.0)
    assert m("onion", "chive") == label_similarity("onion", "chive")
    files = list((tmp_path / "similarity").glob("*.npz"))
    assert len(files) == 1

    def boom(*args, **kwargs):
        raise AssertionError("recomputed despite the cache")

    monkeypatch.setattr(simmod, "compute_matrix", boom)
    again = similarity_matrix(reversed(words), sim=label_similarity)  # order does not matter
    assert again.labels == m.labels and np.array_equal(again.values, m.values)
    with pytest.raises(AssertionError):
        similarity_matrix([*words, "bowl of soup"], sim=label_similarity)  # another vocabulary, another key


def test_corrupt_cache_entry_is_recomputed(label_similarity, tmp_path, monkeypatch):
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path))
    words = ["lemon", "lime", "knife"]
    first = similarity_matrix(words, sim=label_similarity)
    (path,) = (tmp_path / "similarity").glob("*.npz")
    path.write_bytes(b"garbage")
    second = similarity_matrix(words, sim=label_similarity)
    assert np.array_equal(first.values, second.values)


def test_similar_lists_neighbours_above_threshold(label_similarity):
    m = similarity_matrix(["lemon", "lime", "orange", "knife"], cache=False, sim=label_similarity)
    near = m.similar("lemon", 0.89)
    assert [x for x, _ in near] == sorted((x for x, _ in near), key=lambda x: (-m("lemon", x), x))
    assert "lime" in dict(near) and "knife" not in dict(near) and "lemon" not in dict(near)
