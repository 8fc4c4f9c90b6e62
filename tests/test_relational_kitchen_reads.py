"""The `relational` encoding reads a kitchen container whose contents only units make as the unit output it is
by another wording (`pddl.relational_stitch`), so its plans map back to FOON trees that validate."""

from __future__ import annotations

from pathlib import Path

import pytest
from node_words import contains, inside, n
from relational_checks import clean_dish_plan, clean_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.relational_stitch import kitchen_stitches
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

SUBGRAPHS = Path(__file__).parent / "data" / "foon-subgraphs"

# dalgona coffee: the pour makes `mixing bowl (contains {refined sugar, water})`; the beat takes the bowl as
# `mixing bowl (contains {sugar, hot water})`, a node no unit makes, with the sugar and water the pour makes
SUGAR, WATER = n("refined sugar", inside("bowl")), n("water", "hot", inside("bowl"))
POURED = n("mixing bowl", contains("refined sugar", "water"))
IN_SUGAR, IN_WATER = n("refined sugar", inside("mixing bowl")), n("water", inside("mixing bowl"))
POUR = FunctionalUnit((n("mixing bowl", "empty"), n("bowl", contains("refined sugar")), SUGAR,
                       n("bowl", contains("water")), WATER), Motion("pour"), (POURED, IN_SUGAR, IN_WATER))
WORDED = n("mixing bowl", contains("sugar", "hot water"))
WHIPPED = n("whipped coffee", inside("mixing bowl"))
BEAT = FunctionalUnit((WORDED, IN_SUGAR, IN_WATER, n("whisk")), Motion("beat"),
                      (n("mixing bowl", contains("whipped coffee")), WHIPPED))


def test_a_kitchen_container_whose_contents_only_a_unit_makes_is_read_as_that_units_output():
    foon = Foon((POUR, BEAT))
    assert kitchen_stitches(foon.units, default_kitchen(foon).nodes) == {WORDED: (POURED, POUR)}


def test_the_plan_makes_what_the_kitchen_container_lists_and_its_tree_validates():
    foon = Foon((POUR, BEAT))
    kitchen = default_kitchen(foon)
    assert WORDED in kitchen.nodes  # FOON's kitchen has the worded bowl, not the water in it
    outcome = plan(foon, kitchen, Goal(GoalSpec("whipped coffee"), (WHIPPED,)), "relational")
    assert outcome.status == "solved", outcome.message
    assert [s.unit for s in outcome.trace.steps] == [POUR, BEAT]
    assert outcome.tree.units == (POUR, BEAT)
    report = replay(outcome.trace)
    assert report.ok, [d.describe() for d in report.disagreements]
    assert any("the kitchen's mixing bowl (contains {hot water, sugar}) is read as mixing bowl (contains "
               "{refined sugar, water}), which this pour makes" in note for note in outcome.compiled.notes)


def test_a_container_that_held_more_before_the_unit_is_no_other_wording():
    # the egg is poured into a bowl of flour: `bowl (contains {egg})` is not that bowl, which also holds the flour
    egg, flour = n("egg", "beaten", inside("cup")), n("flour", inside("bowl"))
    full, beaten_in = n("bowl", contains("egg", "flour")), n("egg", "beaten", inside("bowl"))
    pour = FunctionalUnit((n("bowl", contains("flour")), flour, n("cup", contains("egg")), egg), Motion("pour"),
                          (full, beaten_in))
    whisk = FunctionalUnit((n("bowl", contains("egg")), beaten_in, n("whisk")), Motion("whisk"),
                           (n("bowl", contains("batter")), n("batter", inside("bowl"))))
    foon = Foon((pour, whisk))
    assert kitchen_stitches(foon.units, default_kitchen(foon).nodes) == {}


@pytest.mark.parametrize("name", ["0067-onigiri.txt", "0079-dalgona_coffee.txt"])
def test_shared_dishes_whose_kitchen_container_only_units_fill_validate(name):
    clean_dish_plan(SUBGRAPHS / name)


def test_names_are_read_as_in_the_goals_task_not_the_whole_network():
    # a universal FOON: another recipe has `sugar` objects of its own, so the network reads no `sugar` as
    # `refined sugar`; the whipped coffee's task, which has none, does
    other = FunctionalUnit((n("bag", contains("sugar")), n("sugar", inside("bag")), n("cup", "empty")), Motion("pour"),
                           (n("cup", contains("sugar")), n("sugar", inside("cup"))))
    foon = Foon((other, POUR, BEAT))
    outcome = plan(foon, default_kitchen(foon), Goal(GoalSpec("whipped coffee"), (WHIPPED,)), "relational")
    assert outcome.status == "solved", outcome.message
    assert outcome.tree.units == (POUR, BEAT)


def test_an_object_on_a_holder_no_node_lists_it_on_is_on_the_one_the_unit_takes_with_it():
    # watermelon lemonade: the pour takes `strainer (clean, empty, on [measuring cup])` from the kitchen with
    # `measuring cup (clean, empty)`; no measuring cup lists the strainer, and none is added for it
    strainer, cup = n("strainer", "clean", "empty", make_state("on", "measuring cup")), n("measuring cup", "clean", "empty")
    juice, strained = n("juice", inside("blender cup")), n("juice", inside("strainer"))
    pour = FunctionalUnit((strainer, cup, n("blender cup", contains("juice")), juice), Motion("pour"),
                          (n("strainer", contains("juice"), make_state("on", "measuring cup")), strained))
    foon = Foon((pour,))
    outcome = plan(foon, default_kitchen(foon), Goal(GoalSpec("juice"), (strained,)), "relational")
    assert outcome.status == "solved", outcome.message
    assert [o.id for o in outcome.trace.objects if o.label == "measuring cup"] == ["measuring_cup_1"]
    assert {s.id: s.holder for s in outcome.trace.initial}["strainer_1"] == "measuring_cup_1"


def test_a_unit_that_takes_the_kitchen_container_does_not_make_its_other_wording():
    # a universal FOON: the buckeye candy opens the kitchen's `jar (contains {peanut butter})`, making `jar
    # (contains {peanut butter}, opened)`; that is the jar after a unit, not the kitchen's jar in other words
    jar, pb = n("jar", contains("peanut butter")), n("peanut butter", inside("jar"))
    opened = FunctionalUnit((jar,), Motion("open"), (n("jar", contains("peanut butter"), "opened"), pb))
    bread = n("bread", "sliced")
    spread = FunctionalUnit((jar, pb, bread, n("knife")), Motion("spread"), (n("bread", contains("peanut butter")),))
    foon = Foon((opened, spread))
    assert kitchen_stitches(foon.units, default_kitchen(foon).nodes) == {}


def test_an_object_a_unit_takes_off_a_container_without_naming_its_place_is_the_one_on_it():
    # watermelon lemonade: the uncover takes a plain `blender lid` with `blender cup (contains {watermelon juice},
    # covered {blender lid})`; the lid it takes off is the one the cover put on the cup, not a second lid
    cup, juice, lid = n("blender cup", contains("juice")), n("juice", inside("blender cup")), n("blender lid", "clean")
    covered = n("blender cup", contains("juice"), make_state("covered", "", ("blender lid",)))
    cover = FunctionalUnit((cup, juice, lid), Motion("cover"), (covered, n("blender lid", make_state("on", "blender cup"))))
    dirty = n("blender lid", "dirty")
    uncover = FunctionalUnit((covered, juice, n("blender lid")), Motion("uncover"),
                             (n("blender cup", contains("juice"), "open"), dirty))
    foon = Foon((cover, uncover))
    outcome = clean_plan(foon, default_kitchen(foon), Goal(GoalSpec("blender lid"), (dirty,)))
    assert [o.id for o in outcome.trace.objects if o.label == "blender lid"] == ["blender_lid_1"]
    assert outcome.tree.units == (cover, uncover)


def test_the_unit_that_puts_a_kitchen_object_on_the_holder_keeps_it_and_the_others_take_what_it_made():
    # watermelon lemonade: the pick-and-place puts the kitchen's `watermelon (whole)` on the board; the slice
    # takes `watermelon (whole)` with `cutting board (contains {watermelon})`: the one on the board, not a second
    whole, board = n("watermelon", "whole"), n("cutting board", "empty")
    full, placed = n("cutting board", contains("watermelon")), n("watermelon", "whole", make_state("on", "cutting board"))
    put = FunctionalUnit((whole, board), Motion("pick-and-place"), (full, placed))
    halved = n("watermelon", "halved", make_state("on", "cutting board"))
    cut = FunctionalUnit((full, whole, n("knife")), Motion("slice"), (halved,))
    foon = Foon((put, cut))
    outcome = clean_plan(foon, default_kitchen(foon), Goal(GoalSpec("watermelon"), (halved,)))
    assert [o.id for o in outcome.trace.objects if o.label == "watermelon"] == ["watermelon_1"]
    assert outcome.tree.units == (put, cut)



def test_every_unit_that_puts_the_kitchen_object_on_the_holder_keeps_it():
    # the universal FOON's watermelon lemonade: the smoothie (0021, line 19) puts `watermelon (whole)` on a
    # `cutting board (clean)` too, and makes the same node as the lemonade's own pick-and-place. It took K and no
    # container, so the reading was dropped and the slice cut a second watermelon while the first stayed on the
    # board it empties. Each unit making the output keeps K; the others take what they made.
    whole, placed = n("watermelon", "whole"), n("watermelon", "whole", make_state("on", "cutting board"))
    full = n("cutting board", contains("watermelon"))
    put = FunctionalUnit((whole, n("cutting board", "empty")), Motion("pick-and-place"), (full, placed))
    also = FunctionalUnit((whole, n("cutting board", "clean")), Motion("pick-and-place"), (full, placed))
    halved = n("watermelon", "halved", make_state("on", "cutting board"))
    cut = FunctionalUnit((full, whole, n("knife")), Motion("slice"), (halved,))
    foon = Foon((also, put, cut))
    assert kitchen_stitches(foon.units, default_kitchen(foon).nodes)[whole][0] == placed
    outcome = clean_plan(foon, default_kitchen(foon), Goal(GoalSpec("watermelon"), (halved,)))
    assert [o.id for o in outcome.trace.objects if o.label == "watermelon"] == ["watermelon_1"]


def test_what_a_unit_makes_in_a_kitchen_container_is_a_goal_only_once_the_unit_has_made_it():
    # the experiment's chipotle: the kitchen's closed packet lists a chipotle, whose object starts in the one
    # node of its label in a packet, `chipotle (dried, in [packet])`; FOON makes that node by opening the packet
    # (0005-chipotle-bean_sandwich.txt:75), so the goal is reached by the open, not by the kitchen's object
    closed, dried = n("packet", contains("chipotle")), n("chipotle", "dried", inside("packet"))
    opening = FunctionalUnit((closed,), Motion("open"), (n("packet", contains("chipotle"), "opened"), dried))
    outcome = clean_plan(Foon((opening,)), Kitchen(frozenset({closed})), Goal(GoalSpec("chipotle"), (dried,)))
    assert [u.motion.label for u in outcome.tree.units] == ["open"]
    assert outcome.validation.ok, outcome.validation.problems

def test_a_word_for_what_lies_on_the_kitchen_container_is_read_as_the_word_of_the_unit_that_put_it_there():
    # homemade cheese pizza: the pick-and-place puts `plastic wrap (on [bowl])` on the dough's bowl, making `bowl
    # (contains {pizza dough}, covered)`; the unwrap takes that wrap, `plastic wrap (on [bowl])`, with `bowl
    # (contains {pizza dough}, wrapped {plastic wrap})`, a node no unit makes: the wrap on it, in other words
    dough, wrap_on = n("pizza dough", inside("bowl")), n("plastic wrap", make_state("on", "bowl"))
    knead = FunctionalUnit((n("bowl", "empty"), n("flour", inside("bag"))), Motion("knead"),
                           (n("bowl", contains("pizza dough")), dough))
    covered = n("bowl", contains("pizza dough"), "covered")
    cover = FunctionalUnit((n("bowl", contains("pizza dough")), dough, n("plastic wrap")), Motion("pick-and-place"),
                           (covered, wrap_on))
    fermented = n("pizza dough", "fermented", inside("bowl"))
    ferment = FunctionalUnit((covered, dough, wrap_on), Motion("ferment"), (fermented,))
    wrapped = n("bowl", contains("pizza dough"), make_state("wrapped", "", ("plastic wrap",)))
    dirty = n("plastic wrap", "dirty")
    unwrap = FunctionalUnit((wrapped, wrap_on, fermented), Motion("unwrap"),
                            (n("bowl", contains("pizza dough")), dirty))
    foon = Foon((knead, cover, ferment, unwrap))
    assert kitchen_stitches(foon.units, default_kitchen(foon).nodes) == {wrapped: (covered, cover)}
    outcome = clean_plan(foon, default_kitchen(foon), Goal(GoalSpec("plastic wrap"), (dirty,)))
    assert outcome.tree.units == (knead, cover, ferment, unwrap)
    assert [o.id for o in outcome.trace.objects if o.label == "bowl"] == ["bowl_1"]
    assert any("is read as bowl (contains {pizza dough}, covered), which this pick-and-place makes" in note
               and "assumes covered, drops wrapped {plastic wrap}: plastic wrap (on [bowl]) in both units" in note
               for note in outcome.compiled.notes), outcome.compiled.notes
