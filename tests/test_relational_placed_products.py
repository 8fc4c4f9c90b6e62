"""A product whose node names no place, beside the one container the unit leaves listing it, is in that container
(`list_placed`): the apple turnover's pour and stir (`0086-apple_turnover.txt:291`) makes `filling (contains {...})`
and `cooking pan (contains {filling})`, and the pour after it takes `filling (..., in [cooking pan])`."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import FunctionalUnit, Motion
from foon2pddl.pddl.holders import placed_products

PAN, APPLE = n("cooking pan", contains("apple")), n("apple", "chopped", inside("cooking pan"))
BOWL, WATER = n("bowl", contains("water")), n("water", inside("bowl"))
FULL = n("cooking pan", contains("filling"))
FILLING = n("filling", contains("apple", "water"))  # FOON names no place
STIR = FunctionalUnit((PAN, APPLE, BOWL, WATER), Motion("pour and stir"), (FULL, FILLING))
PLATE = n("plate", "empty")
IN_PAN = n("filling", contains("apple", "water"), inside("cooking pan"))
ON_PLATE = n("filling", contains("apple", "water"), inside("plate"))
POUR = FunctionalUnit((PLATE, FULL, IN_PAN), Motion("pour"), (n("plate", contains("filling")), ON_PLATE,
                                                              n("cooking pan", "dirty")))
KITCHEN = (PAN, APPLE, BOWL, WATER, PLATE)


def test_a_product_naming_no_place_is_read_in_the_one_role_that_newly_lists_it():
    assert placed_products(STIR) == ((FILLING, IN_PAN),)
    assert placed_products(POUR) == ()  # its filling names its place
    # two roles newly listing it: FOON does not say which holds it
    two = FunctionalUnit((*STIR.inputs, n("plate", "empty")), Motion("pour and stir"),
                         (*STIR.outputs, n("plate", contains("filling"))))
    assert placed_products(two) == ()


def test_the_filling_made_in_the_pan_is_poured_out_of_it_and_the_plan_is_replay_clean():
    # before: the pour and stir left the filling in nothing while the pan listed it (`missing-content`), and on GEN
    # trial 7 goal 14 the pour took it from a pan that did not hold it (`claimed-twice`)
    outcome = clean_unit_plan((STIR, POUR), KITCHEN, ON_PLATE)
    states = list(outcome.trace.states())
    made = next(k for k, s in enumerate(outcome.trace.steps) if s.unit.motion.label == "pour and stir")
    filling = next(o.id for o in outcome.trace.objects if o.label == "filling")
    pan = next(o.id for o in outcome.trace.objects if o.label == "cooking pan")
    assert states[made + 1][filling].holder == pan
    assert outcome.trace.final[filling].holder == next(o.id for o in outcome.trace.objects if o.label == "plate")


def test_a_second_filling_in_the_kitchen_is_not_the_one_poured():
    # GEN trial 7 goal 14: the kitchen holds a filling of its own; the one the plan makes is the one it pours
    kitchen = (*KITCHEN, n("cooking pan", contains("filling"), "cold"),
               n("filling", contains("apple", "water"), inside("cooking pan"), "cold"))
    outcome = clean_unit_plan((STIR, POUR), kitchen, ON_PLATE)
    assert {b.object for s in outcome.trace.steps for b in s.bindings if s.unit.motion.label == "pour"} >= {
        next(o.id for o in outcome.trace.objects if o.label == "filling" and outcome.trace.final[o.id].holder
             and outcome.trace.final[o.id].node == ON_PLATE)}
