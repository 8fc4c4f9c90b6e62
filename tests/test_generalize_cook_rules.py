"""The cook similarity's rules of stop 49: regional senses (rule 1), vessels named for what they hold (rule 7)."""

from __future__ import annotations

from pathlib import Path

import pytest

from foon2pddl.generalize.cook import CookSimilarity
from foon2pddl.generalize.senses import role_senses

SUBGRAPHS = Path(__file__).parent / "data" / "foon-subgraphs"


@pytest.fixture(scope="module")
def cook(label_similarity):
    return CookSimilarity(label_similarity.reader)


def test_a_sense_wordnet_marks_as_regional_is_not_the_labels_reading(cook):
    """Rule 1: WordNet files `cookie.n.01` ("`biscuit' is the British term") under the region United Kingdom; a
    FOON's biscuit is the American quick bread (`biscuit.n.01`), so biscuit is no cookie. A label whose every
    sense of its role is regional keeps them (cookie)."""
    assert set(role_senses(cook.reader, "biscuit")) == {"biscuit.n.01"}
    assert "cookie.n.01" in role_senses(cook.reader, "cookie")
    for a, b in [("biscuit", "oreo"), ("biscuit", "butter cookie"), ("biscuit", "fortune cookie"),
                 ("almond cookie", "biscuit"), ("biscuit dough", "cookie dough")]:
        assert cook(a, b) == 0.0, (a, b, cook.explain(a, b))
    assert cook("lemon", "lime") >= 0.89


def test_a_vessel_named_for_the_food_it_holds_is_still_that_vessel(cook):
    """Rule 7: a compound label whose head is the other label, a container, and whose modifier names a food is
    that container for that food (a cookie jar is a jar, a soup ladle a ladle), whatever its gloss says it is for;
    a kind whose name does not say so is still read by its gloss (pot~urn, pot~coffeepot), and a compound that
    only shares its head with the other label is too (milk can~tin can, iced-tea spoon~teaspoon)."""
    for a, b in [("cookie jar", "jar"), ("beer mug", "mug"), ("soup ladle", "ladle"), ("catsup bottle", "bottle"),
                 ("coffee mug", "mug"), ("sugar spoon", "spoon")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    for a, b in [("pot", "urn"), ("coffeepot", "pot"), ("milk can", "tin can"), ("iced-tea spoon", "teaspoon"),
                 ("spoon", "tea maker"), ("cooker", "rice cooker"), ("meat grinder", "grinder")]:
        assert cook.explain(a, b).rejected == "purpose", (a, b, cook.explain(a, b))


def test_a_filed_food_class_whose_kinds_go_by_names_of_their_own_is_no_food(cook):
    """Rule 8: a label filed by its nearest WordNet member whose food sense has at least 5 WordNet kinds, fewer than
    10 % of them named or defined after it (`classes.food_class`: citrus 1 of 19, brew 1 of 25), names a class and
    stands with none of its kinds; a filed generic whose kinds carry its name stands (bean~black bean, beer~pale ale,
    whiskey~corn whiskey), as do a label filed by its head (salad green, a green: ~lettuce) and labels of the
    category index (sweetener~sugar: the hand-made categories judge them)."""
    from foon2pddl.generalize.classes import food_class

    assert food_class(cook.reader, "citrus.n.01") and food_class(cook.reader, "brew.n.01")
    assert not food_class(cook.reader, "bean.n.01") and not food_class(cook.reader, "friedcake.n.01")
    for a, b in [("citrus", "lemon"), ("citrus", "orange"), ("brew", "ale"), ("brew", "spruce beer")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "class", (a, b, e)
    for a, b in [("bean", "black bean"), ("beer", "pale ale"), ("corn whiskey", "whiskey"), ("doughnut", "friedcake"),
                 ("lemon", "lime")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    # A label filed by its head and labels of the index are not rule 8's; since stop 51 rule 9 judges a food class
    # whose kinds are classes for every label (salad green~lettuce: 0, "food class"; sweetener~sugar, a flavorer
    # class, stands since stop 54).
    for a, b in [("lettuce", "salad green")]:
        assert cook.explain(a, b).rejected == "food class", (a, b, cook.explain(a, b))


def test_a_staple_is_a_starch_not_a_flavorer_or_a_bake(cook):
    """Rule 3's exemption: bread (a bake WordNet also files as a starch) and pasta stand with their kinds; a sauce,
    a flavorer whose kinds are its flavours as a herb's are, and a cake, a bake whose kinds are its variants, do not
    (sauce~gravy, cake~cheesecake are rejected as broad, as herb~basil is)."""
    from foon2pddl.generalize.classes import staple

    assert staple(cook.reader, "bread.n.01") and staple(cook.reader, "pasta.n.02") and staple(cook.reader, "mix.n.01")
    assert not staple(cook.reader, "sauce.n.01") and not staple(cook.reader, "cake.n.03")
    for a, b in [("sauce", "gravy"), ("cake", "cheesecake"), ("herb", "basil")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "broad", (a, b, e)
    for a, b in [("bread", "loaf"), ("pasta", "penne")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_a_label_wordnet_does_not_know_read_through_an_override_is_one_member_of_its_class(cook):
    """Rule 10: the overrides read virgin mojito, dashi and gyoza, which WordNet does not know, as soft drink,
    broth and dumpling; each is one member of that class, so it stands with the class's own label (and two labels
    of one sense stay 1.0), not with the class's other kinds: tonic, pop, chicken broth and matzo ball are other
    members. A label WordNet knows by its head (salad mix, a mix of salad
    greens) is no stand-in and keeps its kinds (lettuce)."""
    for a, b in [("virgin mojito", "tonic"), ("virgin mojito", "pop"), ("virgin mojito", "cream soda"),
                 ("dashi", "chicken broth"), ("gyoza", "matzo ball")]:
        assert cook.explain(a, b).rejected == "stand-in", (a, b, cook.explain(a, b))
    for a, b in [("soft drink", "virgin mojito"), ("broth", "dashi"), ("dumpling", "gyoza"), ("cooking spray", "olive oil")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    assert cook.explain("lettuce", "salad mix").rejected == "food class"  # no stand-in: rule 9 (stop 51) rejects it


def test_a_users_override_for_an_unknown_label_makes_a_stand_in_too(cook):
    """Rule 10 reads what the override does, not a list: a user's file reading an unknown drink as a soft drink
    makes it a member of soft drinks, a sibling of tonic, not their generic."""
    from foon2pddl.generalize.senses import parse_overrides

    mine = CookSimilarity(cook.reader, parse_overrides('{"senses": {"kombucha": ["soft_drink.n.01"]}}', "mine.json"))
    assert mine.explain("tonic", "kombucha").rejected == "stand-in"
    assert mine("soft drink", "kombucha") >= 0.89


def test_similarity_senses_names_the_stand_in_rule():
    """`similarity --senses` says why a stand-in's pair is 0 (rule 10), as for every other rule."""
    from click.testing import CliRunner

    from foon2pddl.cli import main

    run = CliRunner().invoke(main, ["similarity", "tonic", "virgin mojito", "--senses"])
    assert run.exit_code == 0, run.output
    assert "virgin mojito: soft_drink.n.01 (override)" in run.output
    assert "(rejected: a label the overrides read as its class is one member of it, not its generic)" in run.output


def test_two_labels_that_share_the_sense_the_mode_reads_are_synonyms(cook):
    """Synonyms (stop 50, issue 23): two whole terms the mode reads as one WordNet sense (club soda and soda water,
    both `soda_water.n.01`) name one thing and score 1 whatever the categories say; a compound known by its head
    shares the head's sense without being it, so bowl~food processor bowl is still held to the categories."""
    e = cook.explain("club soda", "soda water")
    assert (e.similarity, e.rejected, e.sense_a, e.sense_b) == (1.0, "", "soda_water.n.01", "soda_water.n.01")
    assert cook.explain("bowl", "food processor bowl").rejected == "category"
    # Two shared senses the categories used to hide, read as a kitchen means them (the shipped overrides): ice is
    # frozen water (`ice.n.01`), not icing; soy is soy sauce, not the bean.
    assert cook("soy", "soy sauce") == 1.0
    for a, b in [("frosting", "ice"), ("ice", "water ice"), ("soy", "soybean")]:
        assert cook(a, b) == 0.0, (a, b, cook.explain(a, b))


def test_two_dishes_are_variants_even_when_wordnet_names_each(cook):
    """Rule 4 for whole terms (stop 51, issue 23): a dish's kinds are variants of it whether named by a compound
    (greek salad) or by a word of their own (club sandwich, wrap, quesadilla: all under `dish.n.02`), so two senses
    that meet under a dish stand with neither each other nor their generic; a stock is an ingredient (rule 4's
    `INGREDIENTS`: WordNet files broth under soup), and one dish sense read by both labels stands (synonyms)."""
    for a, b in [("club sandwich", "hamburger"), ("hamburger", "wrap"), ("sandwich", "wrap"),
                 ("club sandwich", "sandwich"), ("burrito", "quesadilla")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "dishes", (a, b, e)
    for a, b in [("broth", "chicken broth"), ("beef stock", "vegetable broth"), ("bouillon", "soup broth"),
                 ("dumpling", "gyoza"), ("french toast", "matzo brei"), ("bread", "loaf"), ("lemon", "lime")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_two_prepared_foods_are_variants_not_only_two_dishes(cook):
    """Rule 4 for every prepared food (stop 52, issue 23): WordNet's food splits into foodstuffs (ingredients:
    `foodstuff.n.02`) and nutriment, what is eaten as prepared (`nutriment.n.01`: dishes, courses, sweets, meals).
    Two senses that meet under a prepared food are variants of it, as two dishes are: buckeye candy~fudge (both
    under `candy.n.01`, a sweet, no dish) and hors d'oeuvre~pigs in a blanket score 0; two ingredients under one
    foodstuff (lemon~lime, honey~sugar), stocks (`INGREDIENTS`) and one sense read by both labels stand."""
    for a, b in [("buckeye candy", "fudge"), ("buckeye candy", "marshmallow"), ("hors d'oeuvre", "pigs in a blanket")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "dishes", (a, b, e)
    for a, b in [("lemon", "lime"), ("honey", "sugar"), ("broth", "chicken broth"), ("dumpling", "gyoza"),
                 ("olive oil", "vegetable oil")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_a_class_of_foods_whose_kinds_are_classes_is_no_food(cook):
    """Rule 9 for foods (stop 51, issue 23): a kind pair whose generic is a food class (`classes.food_class`: at
    least 5 kinds, fewer than 10 % named or defined after it) whose kinds are classes of their own (at least
    `CLASS_LEVELS` levels of kinds: sweetening has sugar and syrup, each with kinds) is a category with a member:
    a salad-mix label (`salad_green.n.01`) with one green scores 0. Kinds of one thing in cuts and sizes stand
    (chicken~capon, beefsteak~strip steak: two levels), as do two members (honey~sugar), two labels of the class's own
    sense (salad mix~spring mix) and, since stop 54, a flavorer class with its kinds (sweetener~sugar: the test
    below)."""
    from foon2pddl.generalize.classes import levels

    assert levels(cook.reader, "sweetening.n.01") == 4 and levels(cook.reader, "chicken.n.01") == 2
    for a, b in [("lettuce", "salad mix"), ("escarole", "spring mix"), ("lettuce", "salad green")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "food class", (a, b, e)
    for a, b in [("honey", "sugar"), ("salad mix", "spring mix"), ("capon", "chicken"), ("beefsteak", "strip steak"),
                 ("brown sugar", "sugar"), ("lemon", "lime")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_a_stand_in_is_no_other_kind_of_its_class_named_by_the_class_head(cook):
    """Rule 10 (stop 51, issue 23): a compound known by its head (soup broth, vegetable broth: `broth.n.01` by
    `broth`) is one of its head's kinds, as chicken broth is, so a stand-in read as that class (dashi) stands with it
    no more than with chicken broth; the class's own label (broth) and a synonym of the stand-in's class stand."""
    for a, b in [("dashi", "soup broth"), ("dashi", "soup stock"), ("dashi", "vegetable broth"),
                 ("chicken broth", "dashi")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "stand-in", (a, b, e)
    for a, b in [("broth", "dashi"), ("dumpling", "gyoza"), ("soft drink", "virgin mojito")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_two_kinds_of_a_class_of_tools_are_different_tools(cook):
    """Rule 9 for siblings (stop 51, issue 23): a class of tools is no tool, and two of its kinds that meet only under
    it do different jobs: knife~scissors (under `edge_tool.n.01`) and scraper~spatula (`hand_tool.n.01`: neither
    has 10 % of its kinds named after it) score 0; siblings under a tool whose kinds carry its name stand
    (mixer~whisk, colander~strainer, spatula~turner)."""
    for a, b in [("knife", "scissors"), ("scraper", "spatula")]:
        e = cook.explain(a, b)
        assert e.similarity == 0.0 and e.rejected == "tool class", (a, b, e)
    for a, b in [("mixer", "whisk"), ("egg beater", "whisk"), ("colander", "strainer"), ("spatula", "turner"),
                 ("juicer", "squeezer")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))


def test_ramen_is_read_as_the_subgraphs_use_it_the_dish_wordnet_lacks(cook):
    """Overrides read a label as the FOON uses it (the rubric's rule 1): in 0054 ramen is a bowl of soup broth and
    noodles, the dish, which WordNet lacks (no noodle-soup sense), not the noodle the overrides read it as until
    stop 51 (noodle~ramen 1.0, pasta~ramen 0.92). It has no sense, so it substitutes for no label."""
    text = (SUBGRAPHS / "0054-quick_ramen_noodles.txt").read_text(encoding="utf-8")
    assert "O359\tramen\t1\nS23\tcontains\t{soup broth,noodle}" in text
    assert cook.resolution("ramen").senses == ()
    for a, b in [("noodle", "ramen"), ("pasta", "ramen"), ("egg noodle", "ramen")]:
        assert cook.explain(a, b).rejected == "unknown", (a, b, cook.explain(a, b))


def test_a_herb_wordnet_defines_by_another_stands_with_it(cook):
    """Rule 3's likeness exemption (stop 53): WordNet defines coriander as a "parsley-like herb", so cilantro and
    coriander (coriander.n.03) stand with parsley though `herb.n.02` covers more than 2 % of the vocabulary; herbs
    WordNet likens to nothing stay broad (basil~parsley, the rubric's marginal example; rosemary~thyme)."""
    for a, b in [("cilantro", "parsley"), ("coriander", "parsley")]:
        assert cook(a, b) >= 0.89, (a, b, cook.explain(a, b))
    for a, b in [("basil", "parsley"), ("rosemary", "thyme"), ("cilantro", "banana")]:
        assert cook(a, b) == 0.0, (a, b, cook.explain(a, b))


def test_two_compounds_of_one_head_are_not_rejected_for_their_modifiers_breadth(cook):
    """Rule 3 for modifiers (stop 53): pan lid and pot lid are one thing (`lid.n.02`) fitted to two others; the
    modifiers pan~pot meet under `cooking_utensil.n.01` (3.7 % of the vocabulary), which judges what they fit,
    not what a cook swaps, so the pair stands at the modifiers' Wu-Palmer. Heads of two senses keep rule 3
    (baking tray~pot), and a modifier pair rejected for another reason stays rejected."""
    assert cook("pan lid", "pot lid") >= 0.89, cook.explain("pan lid", "pot lid")
    for a, b in [("baking tray", "pot"), ("container", "spoon"), ("grater", "masher")]:
        assert cook(a, b) == 0.0, (a, b, cook.explain(a, b))


def test_a_class_of_foods_defined_by_its_job_stands_with_its_kinds(cook):
    """Rule 9 for foods spares a class WordNet files under `flavorer.n.01` (stop 54, issue 23): a flavorer is defined
    by what it does to food ("something added to food primarily for the savor it imparts"; sweetening: "something
    added to foods to make them taste sweeter"), so its kinds do its job: the rubric's "a label and a more specific
    kind of it that does the same job" (honey~sugar "as a sweetener"), not "a category and a member". A class filed by
    what a food is keeps rule 9 (salad green, vegetable: its kinds do different jobs); flavorer and condiment, broad,
    keep rule 3, as does sweetener with a label outside the reference vocabulary (aspartame: 2.1 %)."""
    from foon2pddl.generalize.classes import flavorer_class, food_class_of_classes

    assert flavorer_class(cook.reader, "sweetening.n.01") and flavorer_class(cook.reader, "condiment.n.01")
    assert not flavorer_class(cook.reader, "salad_green.n.01") and not flavorer_class(cook.reader, "vegetable.n.01")
    for a, b in [("sugar", "sweetener"), ("honey", "sweetener"), ("maple syrup", "sweetener"),
                 ("brown sugar", "sweetener"), ("corn syrup", "sweetener"), ("sugar syrup", "sweetener")]:
        e = cook.explain(a, b)
        assert e.similarity >= 0.89 and e.ancestor == "sweetening.n.01", (a, b, e)
        assert not food_class_of_classes(cook.reader, e)
    for a, b in [("lettuce", "salad mix"), ("escarole", "spring mix"), ("lettuce", "salad green")]:
        assert cook.explain(a, b).rejected == "food class", (a, b, cook.explain(a, b))
    for a, b in [("aspartame", "sweetener"), ("condiment", "mustard"), ("flavorer", "salt")]:
        assert cook.explain(a, b).rejected == "broad", (a, b, cook.explain(a, b))
