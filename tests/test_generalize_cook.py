"""The cook's similarity (default) against the paper's (kept byte-identical), and `expand --pairs`."""

from __future__ import annotations

import hashlib
import json

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.errors import FoonInputError
from foon2pddl.generalize.categories import Category, CategoryIndex, shipped_index
from foon2pddl.generalize.classes import NAMED_SHARE, TOOL_CLASS_KINDS, kinds, named_kinds, staple
from foon2pddl.generalize.cook import (
    DEFAULT_BREADTH,
    CookSimilarity,
    cook_overrides,
    filing_similarity,
    reference_vocabulary,
)
from foon2pddl.generalize.cook_kin import CLASS_KINDS, kin
from foon2pddl.generalize.expand import expand, vocabulary
from foon2pddl.generalize.modes import SIMILARITY_MODES, make_similarity, mode_matrix
from foon2pddl.generalize.purpose import foods, held
from foon2pddl.generalize.senses import parse_overrides
from foon2pddl.generalize.wup import WupTable
from foon2pddl.io.inputs import load_network

#: sha256 of `foon2pddl expand` on the example network before the cook mode existed (the paper's rule).
PAPER_EXAMPLE_EXPAND = "651d5273a2c5aa7b76d1ebfb76e67e61c7e944f3a26b106a02ba34fce7197854"


@pytest.fixture(scope="module")
def cook(label_similarity):
    return CookSimilarity(label_similarity.reader)


def test_registry_default_is_cook_and_paper_is_kept():
    assert list(SIMILARITY_MODES) == ["cook", "paper"]


def test_paper_mode_output_is_byte_identical(tmp_path):
    out = tmp_path / "exp.foon"
    r = CliRunner().invoke(main, ["expand", "--similarity", "paper", "-o", str(out)])
    assert r.exit_code == 0, r.stderr
    assert hashlib.sha256(out.read_bytes()).hexdigest() == PAPER_EXAMPLE_EXPAND
    assert out.read_text().startswith("# FOON-EXP (threshold 0.89): 101 units + 181 expanded, 34 label")


def test_floors(cook, label_similarity):
    lemon = cook.explain("lemon", "lime")
    assert lemon.similarity >= 0.89 and (lemon.sense_a, lemon.sense_b) == ("lemon.n.01", "lime.n.06")
    assert cook.reader.synset(lemon.sense_a).lexname() == "noun.food" == cook.reader.synset(lemon.sense_b).lexname()
    for a, b in [("cilantro", "banana"), ("carrot", "strawberry"), ("grater", "masher"), ("baking tray", "pot"),
                 ("container", "spoon")]:
        assert label_similarity(a, b) >= 0.89  # what the paper's rule accepts
        assert cook(a, b) == 0.0, (a, b)
        assert cook.explain(a, b).rejected == "broad"


def test_deepest_common_ancestor_differs_from_nltk(label_similarity):
    wn = label_similarity.reader
    table = WupTable(wn)
    lemon, lime = wn.synset("lemon.n.01"), wn.synset("lime.n.06")
    assert lemon.wup_similarity(lime) == pytest.approx(0.75)  # NLTK: LCS by min_depth
    assert table.wup("lemon.n.01", "lime.n.06") == pytest.approx(0.75)
    lcs, depth, la, lb = table.deepest("lemon.n.01", "lime.n.06")
    assert (lcs, la, lb) == ("citrus.n.01", 1, 1) and depth == wn.synset("citrus.n.01").max_depth() + 1
    assert table.subsumer("lemon.n.01", "lime.n.06") != "citrus.n.01"
    # Independent oracle: the deepest common hypernym by NLTK's own max_depth.
    common = set(lemon.common_hypernyms(lime))
    assert max(common, key=lambda s: (s.max_depth(), s.name())).name() == "citrus.n.01"
    assert table.deepest("lime.n.06", "lemon.n.01")[0] == lcs  # symmetric


def test_breadth_is_the_share_of_the_vocabulary_under_the_ancestor(cook):
    vocab = reference_vocabulary()
    under = [x for x in vocab if any("citrus.n.01" in cook._wup.ancestors(s) for s in cook.resolution(x).senses)]
    assert cook.coverage("citrus.n.01") == len(under) / len(vocab)
    assert {"lemon", "lime", "orange"} <= set(under)
    assert cook.coverage("kitchen_utensil.n.01") > DEFAULT_BREADTH


def test_breadth_does_not_depend_on_the_other_labels_compared(cook):
    """Rule 3 measures a pair's ancestor on the reference vocabulary plus the pair's own labels: a matrix that
    holds many kinds of bottle does not make `bottle.n.01` broad (lemmas6: 5 good bottle pairs rejected so)."""
    bottles = ["bottle", "beer bottle", "water bottle", "whiskey bottle", "jeroboam", "wine bottle", "pop bottle",
               "magnum", "carboy", "demijohn", "flask", "pill bottle", "spray bottle", "canteen"]
    alone = cook.explain("beer bottle", "bottle")
    assert alone.similarity >= 0.89 and alone.ancestor == "bottle.n.01"
    m = mode_matrix(bottles, "cook", cache=False)
    assert m("beer bottle", "bottle") == alone.similarity
    assert m("water bottle", "bottle") == cook("water bottle", "bottle") >= 0.89
    reference = set(reference_vocabulary())
    under = [x for x in reference if any("bottle.n.01" in cook._wup.ancestors(s) for s in cook.resolution(x).senses)]
    assert "beer bottle" not in reference and alone.breadth == (len(under) + 1) / (len(reference) + 1)


def test_a_class_of_tools_is_no_tool(cook):
    """Rule 9: kitchen appliance, drinking vessel and flatware have kinds with names of their own (oven, mug,
    plate): classes of tools with different jobs, no substitute for their kinds; a bottle's kinds are mostly
    bottles, and it stands for them."""
    for a, b in [("kitchen appliance", "stove"), ("food processor", "kitchen appliance"), ("drinking vessel", "mug"),
                 ("flatware", "plate")]:
        ev = cook.explain(a, b)
        assert ev.similarity == 0.0 and ev.rejected == "tool class", (a, b, ev)
        generic = ev.ancestor
        assert generic in (ev.sense_a, ev.sense_b) and kinds(cook.reader, generic) >= TOOL_CLASS_KINDS
        assert named_kinds(cook.reader, generic) < NAMED_SHARE
    assert named_kinds(cook.reader, "bottle.n.01") > NAMED_SHARE
    for a, b in [("beer bottle", "bottle"), ("caldron", "pot"), ("bowl", "mixing bowl"), ("spoon", "teaspoon")]:
        assert cook(a, b) >= 0.89, (a, b)
    r = CliRunner().invoke(main, ["similarity", "--senses", "drinking vessel", "mug"])
    assert "rejected: a class of tools whose kinds go by names of their own" in r.stdout, r.stdout


def test_a_staple_stands_with_its_kinds_however_broad(cook):
    """Rule 3's exemption: bread and pasta cover more than 2 % of the reference labels, but most of their WordNet
    kinds are named or defined after them (brown bread; penne, "pasta in short tubes"): staples, which stand with
    their kinds. Herb and sweetening are classes (their kinds go by names of their own); a dish's kinds are its
    variants (soup~chowder); a compound known by its head is no staple (alfredo sauce~hard sauce)."""
    for a, b, generic in [("pasta", "penne", "pasta.n.02"), ("linguine", "pasta", "pasta.n.02"),
                          ("bread", "loaf", "bread.n.01"), ("bread", "brown bread", "bread.n.01")]:
        ev = cook.explain(a, b)
        assert ev.similarity >= 0.89 and ev.ancestor == generic and ev.breadth > DEFAULT_BREADTH, (a, b, ev)
        assert staple(cook.reader, generic)
    assert not staple(cook.reader, "herb.n.02") and not staple(cook.reader, "sweetening.n.01")
    for a, b in [("herb", "basil"), ("soup", "chowder"), ("salad", "coleslaw"), ("alfredo sauce", "hard sauce")]:
        ev = cook.explain(a, b)
        assert ev.similarity == 0.0 and ev.rejected == "broad", (a, b, ev)


def test_an_ingredient_and_a_substance_are_not_substitutes(cook):
    """Rule 1: a label with a food sense is an ingredient; one with none but a substance sense is no ingredient,
    and the two do not stand for each other: drying oil (linseed, tung: "oxidize on exposure to air", a paint
    oil) is no cooking oil, though WordNet files it under vegetable oil."""
    for other in ("olive oil", "vegetable oil", "canola oil"):
        ev = cook.explain("drying oil", other)
        assert ev.similarity == 0.0 and ev.rejected == "role", (other, ev)
        lexnames = {cook.reader.synset(x).lexname() for x in (ev.sense_a, ev.sense_b)}
        assert lexnames == {"noun.food", "noun.substance"}
    assert cook("olive oil", "vegetable oil") >= 0.89
    r = CliRunner().invoke(main, ["similarity", "--senses", "drying oil", "olive oil"])
    assert "rejected: an ingredient and no ingredient" in r.stdout, r.stdout


def test_breadth_threshold_is_a_parameter(label_similarity):
    loose = CookSimilarity(label_similarity.reader, breadth=1.0)
    assert CookSimilarity(label_similarity.reader).explain("grater", "masher").rejected == "broad"
    # Not broad at breadth 1.0 (0.9 under kitchen_utensil.n.01), but two kinds of a class of tools (rule 9, stop 51).
    e = loose.explain("grater", "masher")
    assert (e.ancestor, e.rejected) == ("kitchen_utensil.n.01", "tool class"), e
    strict = CookSimilarity(label_similarity.reader, breadth=0.001)
    assert strict("lemon", "lime") == 0.0


def test_role_senses(cook):
    assert cook.resolution("banana").senses == ("banana.n.02",)  # the fruit, not the plant
    assert cook.resolution("cilantro").senses == ("coriander.n.03",)
    assert cook.resolution("mint").senses == ("mint.n.04",)  # override: the herb, not the candy
    assert all(cook.reader.synset(s).lexname() == "noun.artifact" for s in cook.resolution("skimmer").senses)
    assert "toilet.n.02" not in cook.resolution("pot").senses  # not a kitchen artifact


def test_variants_are_not_substitutes(cook):
    assert cook.explain("soup", "tomato soup").rejected == "variant"
    assert cook.explain("chicken", "garlic-parmesan chicken").rejected == "variant"
    assert cook("grill spatula", "spatula") >= 0.89  # a tool compound keeps the rule
    assert cook("salt", "sea salt") >= 0.89


def test_pairs_stand_only_as_kin_in_the_categories(cook, label_similarity):
    """Rule 5: every pair of two categorized labels needs FOON-GEN's categories to group them: siblings,
    compounds of one head sense and a kind with a narrower kind alike."""
    free = CookSimilarity(label_similarity.reader, categories=False)
    index = shipped_index()
    for a, b in [("microwave", "oven"), ("fork", "spoon"), ("bowl", "food processor bowl"), ("blender jar", "jar"),
                 ("cheese", "parmesan"), ("frying pan", "muffin pan"), ("sesame oil", "vegetable oil"),
                 ("lemon", "orange"), ("cream", "sour cream")]:
        assert free(a, b) >= 0.89, (a, b)
        assert not kin(index, a, b)  # the oracle: no category, and no refinement of one by the other
        assert cook(a, b) == 0.0 and cook.explain(a, b).rejected == "category", (a, b)
    for a, b in [("cooking pan", "saucepan"), ("egg beater", "hand mixer"), ("cheese", "cheddar"),
                 ("honey", "sugar"), ("lemon", "lime"), ("spoon", "teaspoon")]:
        assert kin(index, a, b) and cook(a, b) >= 0.89, (a, b)
    words = ["lemon", "lime", "orange", "fork", "spoon", "teaspoon", "wooden spoon", "oven", "toaster", "microwave",
             "pot", "saucepan", "skillet", "cooking pan", "whisk", "egg beater", "mixer", "blender", "bowl",
             "mixing bowl", "cheese", "feta cheese", "mozzarella", "honey", "sugar", "olive oil", "sesame oil"]
    for i, a in enumerate(words):
        for b in words[i + 1:]:
            e = cook.explain(a, b)
            if e.similarity > 0:
                assert kin(index, a, b), (a, b)
            elif e.rejected == "category":
                assert free(a, b) > 0 and not kin(index, a, b)


def test_a_label_in_no_category_is_filed_as_categories_extend_files_it(cook, label_similarity):
    """Rule 5 for a label the index lacks: the category `extend.assign` (`categories --extend`) files it in,
    so a pair the hand-made index would reject is rejected without it too (bottle~jug: storage containers
    and pitchers); `extend=False` leaves the label unconstrained (the rule before)."""
    from foon2pddl.generalize.extend import file_labels

    full = shipped_index()
    small = CategoryIndex(tuple(Category(c.name, c.parent, c.description, tuple(m for m in c.members if m != "jug"))
                                for c in full.categories))
    filed = CookSimilarity(label_similarity.reader, categories=small)
    loose = CookSimilarity(label_similarity.reader, categories=small, extend=False)
    assert not small.of("jug") and full.of("jug") == ("pitchers and jugs",)
    files = filing_similarity(label_similarity.reader)
    assert filed.categories_of("jug") == tuple(a.category for a in file_labels(["jug"], small, files)) == (
        "pitchers and jugs",)
    assert loose("bottle", "jug") >= 0.89 and loose.categories_of("jug") == ()
    assert filed("bottle", "jug") == 0.0 and filed.explain("bottle", "jug").rejected == "category"
    assert kin(small, "jug", "pitcher", filed.categories_of) and not kin(small, "jug", "bottle", filed.categories_of)
    for label in ("sieve", "goblet"):  # the shipped index lacks them
        assert not full.of(label)
        assert cook.categories_of(label) == tuple(a.category for a in file_labels([label], full, files)) != ()


def test_a_label_naming_a_category_is_a_class_that_stands_with_nothing(cook, label_similarity):
    """A label that is a category's own name and no category's member (cutlery) is in that category: it made
    the cook mode fail with an IndexError (`assign` files no category name), so `similarity cutlery fork` and
    an EXP over a FOON with a cutlery node crashed. And, like rule 8's classes, it is no substitute for any
    label: cutlery~spoon scored 0.95 once it was kin to its members (3 of lemmas3's 6 bad accepted pairs)."""
    index = shipped_index()
    names = [n for n in index.names if not index.of(n)]
    assert "cutlery" in names
    for name in names:
        assert cook.categories_of(name) == (name,) and cook.bare_category(name) and not cook.kind_only(name)
    members = sorted(index.members_of("cutlery"))
    assert kin(index, "cutlery", members[0], cook.categories_of)
    free = CookSimilarity(label_similarity.reader, categories=False)
    accepted = [m for m in members if free("cutlery", m) >= 0.89]
    assert accepted  # WordNet alone puts cutlery near its members
    for m in accepted:
        e = cook.explain("cutlery", m)
        assert e.similarity == 0.0 and e.rejected == "class", (m, e)
    assert not cook.bare_category(members[0]) and cook(members[0], members[0]) == 1.0


def test_stocks_are_ingredients_and_a_shared_modifier_does_not_reject(cook):
    """Rule 4 leaves stocks alone (WordNet files broth under soup); two compounds with one modifier are as
    close as their heads."""
    for a, b in [("broth", "vegetable broth"), ("chicken broth", "vegetable broth"), ("soup broth", "soup stock")]:
        e = cook.explain(a, b)
        assert e.similarity >= 0.89 and not e.rejected, (a, b, e)
    assert cook("soup broth", "soup stock") == cook("broth", "stock") == 1.0
    assert cook.explain("soup", "tomato soup").rejected == "variant"  # a dish and its variant: still rejected


def test_kin_follows_refinements():
    ix = CategoryIndex((Category("food", None, "", ("bread",)), Category("fruit", "food", "", ("apple",)),
                        Category("tools", None, "", ("knife",))))
    assert kin(ix, "apple", "bread") and kin(ix, "apple", "apple") and not kin(ix, "apple", "knife")
    assert kin(ix, "apple", "unknown label")  # a label in no category is not constrained


def test_values_are_symmetric_and_bounded(cook):
    words = ["lemon", "lime", "pot", "saucepan", "bowl", "mixing bowl", "sugar", "honey", "greek salad", "salad"]
    for a in words:
        for b in words:
            v = cook(a, b)
            assert 0.0 <= v <= 1.0 and v == cook(b, a)
            assert (v == 1.0) == (a == b) or cook.resolution(a).senses == cook.resolution(b).senses


def test_forbidden_pairs_and_user_extension(label_similarity):
    assert cook_overrides().forbids("food processor", "oven")
    extra = parse_overrides(json.dumps({"forbidden": [["lemon", "lime"]]}), "mine.json")
    sim = make_similarity("cook", reader=label_similarity.reader, extra=extra)
    assert sim("lemon", "lime") == 0.0 and sim.explain("lemon", "lime").rejected == "forbidden"
    with pytest.raises(FoonInputError, match="forbidden"):
        parse_overrides('{"forbidden": [["a", "b", "c"]]}', "bad.json")


def test_matrix_is_cached_per_mode(tmp_path, monkeypatch, example, label_similarity):
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path))
    labels = ["lemon", "lime", "knife", "banana", "cilantro"]
    cook_m = mode_matrix(labels, "cook")
    paper_m = mode_matrix(labels, "paper")
    assert cook_m.key != paper_m.key
    assert cook_m("banana", "cilantro") == 0.0 and paper_m("banana", "cilantro") == pytest.approx(0.9)
    assert mode_matrix(labels, "cook").values.tolist() == cook_m.values.tolist()  # from the cache


def test_cook_expansion_is_smaller_and_keeps_lemon_lime(example):
    from foon2pddl.io.inputs import load_kitchen

    kit = load_kitchen(None, example, 3)
    e = expand(example.foon, kitchen=kit)
    assert e.similarity == "cook" and ("lemon", "lime") in e.substitutions
    paper = expand(example.foon, kitchen=kit, similarity="paper")
    assert len(e.foon.units) < len(paper.foon.units)
    assert len(e.substitutions) < len(paper.substitutions)
    assert reference_vocabulary() and set(vocabulary(example.foon, kit)) <= set(reference_vocabulary())


def test_shared_subgraphs_expansion_sizes_per_mode():
    """The paper's rule keeps its published size on the shared subgraphs; the cook mode's is smaller."""
    net = load_network([SUBGRAPHS])
    paper = expand(net.foon, similarity="paper")
    assert (paper.original_units, len(paper.foon.units)) == (1845, 19423)
    cook = expand(net.foon)
    assert (cook.original_units, len(cook.foon.units)) == (1845, 7908)
    assert ("lemon", "lime") in cook.substitutions
    assert not {("cilantro", "banana"), ("banana", "cilantro")} & set(cook.substitutions)


def test_a_label_filed_through_one_member_stands_only_as_a_kind(cook):
    """Rule 6: a label the index lacks, filed by its head or its nearest WordNet member, is a kind of that
    member: it stands with a label whose sense is its own or a WordNet ancestor or descendant of it, not with a
    sibling under a third ancestor; a synonym of a member and a label filed by a category's name keep rule 5."""
    assert cook.filing("runcible spoon").how == "head" and cook.filing("chestnut").how == "wordnet"
    for a, b in [("runcible spoon", "spoon"), ("chestnut", "edible nut"), ("gas oven", "oven")]:  # kinds stand
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    for a, b in [("sugar spoon", "wooden spoon"), ("sugar spoon", "teaspoon"), ("chestnut", "walnut"),
                 ("chestnut", "peanut")]:  # siblings under spoon.n.01 and edible_nut.n.01
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "sibling" and e.ancestor not in (e.sense_a, e.sense_b), (a, b)
    assert cook.filing("eggbeater").similarity == 1.0 and cook("eggbeater", "whisk") >= 0.89  # egg beater's synonym
    assert cook.filing("hickory nut").how == "name" and cook("hickory nut", "walnut") >= 0.89  # "nuts and seeds"
    assert cook.filing("walnut") is None  # in the index


def test_a_kind_of_tool_for_another_food_is_not_its_generic(cook):
    """Rule 7: a kind of tool that rule 6 holds to its kinds stands with its generic only if its name and
    gloss name no food the generic's do not: an urn is "a large pot for making coffee or tea"; a rice cooker
    (a compound known by its head) is a cooker for rice. Kinds whose glosses name no food stand; labels of the
    category index keep rule 5 alone (spoon~teaspoon, although a teaspoon is for tea or coffee)."""
    assert foods(cook.reader, "urn.n.02") == {"coffee.n.01", "tea.n.01"}
    assert foods(cook.reader, "caldron.n.01") == frozenset()
    for a, b in [("pot", "urn"), ("spoon", "tea maker"), ("bowl", "slop basin"), ("percolator", "pot"),
                 ("cooker", "rice cooker")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "purpose", (a, b, e)
    for a, b in [("caldron", "pot"), ("gas oven", "oven"), ("cookstove", "stove"),
                 ("electric frying pan", "frying pan"), ("spoon", "teaspoon")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_a_vessel_named_for_the_liquid_it_holds_is_still_its_generic(cook):
    """Rule 7: a container whose gloss says it holds liquids (a bottle "for storing drinks or other liquids", a
    drinking glass "for holding liquids") holds any of them, so a kind named for one drink (wine, soft drink,
    beer: WordNet kinds of liquid) is no kind for another food; a food that is no liquid still is (a parfait
    glass), and a container whose gloss names no liquid gets nothing from it (a pot for making coffee)."""
    assert held(cook.reader, "bottle.n.01") == {"liquid.n.01"} and held(cook.reader, "glass.n.02") == {"liquid.n.01"}
    assert held(cook.reader, "pot.n.01") == frozenset()
    assert held(cook.reader, "teaspoon.n.02") == frozenset()  # "holds about one fluid dram": fluid is no liquid kind
    for a, b in [("bottle", "wine bottle"), ("bottle", "pop bottle"), ("bottle", "magnum"),
                 ("drinking glass", "schooner")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    for a, b in [("drinking glass", "parfait glass"), ("pot", "urn"), ("bowl", "punch bowl"),
                 ("iced-tea spoon", "teaspoon")]:
        assert cook.explain(a, b).rejected == "purpose", (a, b, cook.explain(a, b))


def test_a_hyphenated_wordnet_lemma_is_read_whole_in_cook_mode(cook, label_similarity):
    """The cook mode reads `iced-tea spoon` as WordNet's iced-tea_spoon (a kind of teaspoon), not as some
    spoon known by its head; the paper's rule still reads its head, byte-identical."""
    assert cook.resolution("iced-tea spoon").senses == ("iced-tea_spoon.n.01",)
    assert cook.resolution("patty-pan").senses == ("patty-pan.n.01",)
    assert label_similarity.resolution("iced-tea spoon").modifier == "iced tea"
    assert cook.resolution("garlic-parmesan chicken").modifier == "garlic parmesan"  # no such lemma: its head
    assert cook.explain("iced-tea spoon", "table spoon").rejected == "sibling"
    assert cook.explain("iced-tea spoon", "teaspoon").rejected == "purpose"


def test_a_filed_class_with_many_wordnet_kinds_stands_with_none_of_them(cook):
    """Rule 8: a label rule 6 holds to its kinds whose sense has at least CLASS_KINDS WordNet kinds is a
    class (saltwater fish: 57 kinds), not a thing a recipe uses, and stands with none of its kinds; one with
    fewer (chop: 3, salad green: 18) is not rule 8's class (salad green~lettuce: rule 9, a food class of classes,
    rejects it since stop 51)."""
    assert kinds(cook.reader, "saltwater_fish.n.01") >= CLASS_KINDS > kinds(cook.reader, "salad_green.n.01")
    for a, b in [("saltwater fish", "tuna"), ("mixed drink", "bullshot")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "class", (a, b, e)
    assert cook("chop", "porkchop") >= 0.89, cook.explain("chop", "porkchop")
    assert cook.explain("salad green", "lettuce").rejected == "food class"


def test_a_modifier_wordnet_tags_mostly_as_an_adjective_is_no_food(cook):
    """Rule 4 reads a compound's modifier as a food only when WordNet does not tag the word more often as an
    adjective: `green` (26 adjective tags, 7 noun tags; its noun senses include leafy greens) describes the
    olive oil, `peanut` and `garlic` (no adjective tags) name the food a dish is made with."""
    for a, b in [("green olive oil", "olive oil"), ("green olive oil", "vegetable oil"), ("green olive oil", "oil")]:
        assert cook(a, b) >= 0.89, (a, b)
    assert cook.variant(cook.resolution("peanut mixture"))  # an unchanged reading: peanut is a food here
    assert cook.explain("chicken", "garlic chicken").rejected == "variant"


def test_a_whole_wordnet_term_is_filed_by_its_head_only_as_a_kind_of_it(cook, label_similarity):
    """Rule 5's filing: `pepper` is the spice (the index files it with black and white pepper; a shipped sense),
    and `chili pepper`, which WordNet knows whole as a capsicum (`chili.n.02`, no kind of `pepper.n.03`), is not
    filed with it by its head but by a category's name (`peppers`); a compound known only by its head still is
    (`categories --extend` files it so too: `extend.file_labels`)."""
    from foon2pddl.generalize.extend import file_labels

    assert cook.resolution("pepper").senses == ("pepper.n.03",)
    assert cook.filing("chili pepper").how == "name" and cook.categories_of("chili pepper") == ("peppers",)
    assert file_labels(["chili pepper"], shipped_index(), filing_similarity(label_similarity.reader))[0].how == "name"
    assert cook.filing("smoked pepper").how == "head"  # known by its head: a kind of it by its reading
    assert cook("chili pepper", "jalapeno") >= 0.89 and cook("hot pepper", "jalapeno") >= 0.89
    assert cook("hot pepper", "pepper") == 0.0 and cook("chili pepper", "pepper") == 0.0


def test_a_label_equally_near_members_of_several_categories_is_in_each(cook):
    """Rule 5's filing: `chili` is as near cayenne pepper (chili spices) as jalapeno (peppers), 0.957; it was
    filed with the first by label order alone, and is now in both."""
    filed = cook.filing("chili")
    assert filed.how == "wordnet" and {filed.category, *filed.also} == {"chili spices", "peppers"}
    assert set(cook.categories_of("chili")) == {"chili spices", "peppers"}
    assert cook("chili", "jalapeno") >= 0.89 and cook("chili", "cayenne pepper") >= 0.89


def test_a_words_tagged_counts_are_read_from_wordnet_once():
    """Rule 4's adjective check reads the tagged counts of the modifier's lemmas (nltk searches WordNet's
    count file on disk for each): a matrix asks it of the same few modifiers tens of thousands of times, so
    one word's counts are read once (at 7edb3f9 they were read 85,860 times building EXP on the test corpus)."""
    from foon2pddl.generalize.senses import adjective

    class Lemma:
        def __init__(self, pos):
            self.pos = pos

        def name(self):
            return "verdant"

        def count(self):
            read.append(self.pos)
            return 3 if self.pos == "a" else 1

    class Synset:
        def __init__(self, pos):
            self.pos = pos

        def lemmas(self):
            return [Lemma(self.pos)]

    class Reader:
        def synsets(self, word, pos):
            return [Synset(pos)]

    read: list[str] = []
    reader = Reader()
    assert all(adjective(reader, "verdant") for _ in range(5))
    assert sorted(read) == ["a", "n"]


def test_a_food_class_and_its_kinds_keep_the_breadth_rule(cook):
    """Rule 3 holds for a generic and its own kind as for siblings: `herb.n.02` covers 2.8 % of the reference
    vocabulary, so herb~basil and herb~parsley are rejected as broad. A 3 % breadth for a food generic and its
    kinds (ea5a9b3, for pasta~penne, 2.4 %) accepted them, and on the blind batch `lemmas5` it added 14 accepted
    pairs, all bad (herb with its herbs, sweetener with aspartame), and no good one: reverted."""
    assert DEFAULT_BREADTH < cook.coverage("herb.n.02") < 0.03
    for kind in ("basil", "parsley"):
        assert cook.explain("herb", kind).rejected == "broad", kind
    assert cook.explain("pasta", "penne").rejected == ""  # the miss the 3 % was for: a staple now, not by breadth
    assert cook.explain("pasta", "penne").breadth > DEFAULT_BREADTH
