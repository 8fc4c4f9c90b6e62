"""The apple turnover (`0086-apple_turnover.txt`), the one shared subgraph FOON's tree solved that the relational
encoding did not: two readings, each from the unit's own nodes (docs/pddl.md, Names and A kitchen container
whose contents only units make)."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_dish_plan

from foon2pddl.model.aliases import unit_aliases
from foon2pddl.model.foon import FunctionalUnit, Motion, make_state
from foon2pddl.pddl.relational_stitch import kitchen_stitches

SUBGRAPHS = Path(__file__).parent / "data" / "foon-subgraphs"


def on(holder: str):
    return make_state("on", holder)


def test_a_place_only_an_input_names_is_the_role_the_unit_leaves_the_object_on_and_lists_it():
    # the sprinkle (0086:523) takes the pie `on [baking try]` with the `baking tray (contains {apple pie})` and
    # leaves it `on [baking tray]`: the misspelt tray is that tray
    sprinkle = FunctionalUnit((n("apple pie", "uncooked", on("baking try")), n("baking tray", contains("apple pie")),
                               n("bowl", contains("sugar")), n("sugar", inside("bowl"))), Motion("sprinkle"),
                              (n("apple pie", "uncooked", contains("sugar"), on("baking tray")),
                               n("sugar", on("apple pie"))))
    assert ("baking try", "baking tray") in unit_aliases(sprinkle)
    # not a wrapping: the unwrap (0016) leaves the bread on the foil that covered it, off the board
    unwrap = FunctionalUnit((n("garlic bread", on("cutting board"), make_state("wrapped", "aluminium foil")),
                             n("aluminium foil", make_state("covering", "", ("garlic bread",)))), Motion("unwrap"),
                            (n("garlic bread", on("aluminium foil")), n("aluminium foil", "dirty")))
    assert "cutting board" not in dict(unit_aliases(unwrap))


OVEN = n("oven", "on", "preheated")
TRAY_IN = n("baking tray", contains("apple pie"), inside("oven"))
RAW = n("apple pie", "uncooked", on("baking tray"))
PLACE = FunctionalUnit((OVEN, RAW, n("baking tray", contains("apple pie"))), Motion("pick-and-place"),
                       (n("oven", "on", "preheated", contains("baking tray")), TRAY_IN))
BAKED = n("oven", "on", contains("baking tray"))
BAKE = FunctionalUnit((n("oven", "on", "preheated", contains("baking tray")), TRAY_IN, RAW), Motion("bake"),
                      (n("apple pie", "cooked", on("baking tray")), BAKED))
LISTING_PIE = n("oven", "on", contains("apple pie"))  # the remove's oven: no unit makes it
REMOVE = FunctionalUnit((LISTING_PIE, n("apple pie", "cooked", on("baking tray")), TRAY_IN), Motion("remove"),
                        (n("oven", "off"), n("baking tray", contains("apple pie"))))


def test_a_kitchen_container_listing_what_is_on_an_object_in_it_is_the_output_of_the_unit_taking_that_object():
    # the remove (0086:614) takes `oven (contains {apple pie}, on)` with the pie on the tray and the tray in the
    # oven: the oven holds the tray, as the bake, which takes that tray, leaves it (not the pick-and-place's
    # preheated oven, which makes the tray node)
    kitchen = (OVEN, RAW, LISTING_PIE)
    assert kitchen_stitches((PLACE, BAKE, REMOVE), kitchen) == {LISTING_PIE: (BAKED, BAKE)}


def test_the_apple_turnover_is_valid_and_replay_clean():
    clean_dish_plan(SUBGRAPHS / "0086-apple_turnover.txt")
