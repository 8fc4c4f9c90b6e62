"""The cook similarity's rules of stop 49: regional senses (rule 1), vessels named for what they hold (rule 7)."""

from __future__ import annotations

import pytest

from foon2pddl.generalize.cook import CookSimilarity
from foon2pddl.generalize.senses import role_senses


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
