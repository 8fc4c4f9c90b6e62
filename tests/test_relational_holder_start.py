"""Where a holder the kitchen completion adds starts (`relational_init.holder_init`): in a node from which units
lead it to the node a unit takes it in with the object it holds, when the object stays at its place until then.

The even-index universal FOON's miso soup: the kitchen's pot of hot water is `on [stove]` until the cook and stir
(`0033-miso_soup.txt:149`) takes it with `stove (on, with [pot])`; the added stove started in the first stove node
listing a pot, another recipe's `stove (off, with [pot])`, which no unit switches on, so no plan existed."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import FunctionalUnit, Motion, make_state


def on(holder: str):
    return make_state("on", holder)


def with_(item: str):
    return make_state("with", item)


HOT = n("pot", contains("water"), "hot", on("stove"))  # the kitchen's pot of hot water, on a stove
STOCK = n("pot", contains("soup stock"), "hot", on("stove"))
POUR = FunctionalUnit((HOT, n("bowl", contains("dashi")), n("dashi", inside("bowl"))), Motion("pour"),
                      (STOCK, n("soup stock", inside("pot"))))
LIT = n("stove", "on", with_("pot"))
SOUP = n("soup", "cooked", inside("pot"))
STIR = FunctionalUnit((LIT, STOCK, n("soup stock", inside("pot")), n("spoon")), Motion("cook and stir"),
                      (n("pot", contains("soup"), "hot", on("stove")), SOUP))
# another recipe: a stove with a pot on it that no unit switches on (the heat leaves it off) ...
HEAT = FunctionalUnit((n("stove", "off", with_("pot")), n("pot", "empty", on("stove"))), Motion("heat"),
                      (n("pot", "hot", "empty", on("stove")),))
# ... and one its pick-and-place leaves ready, which the turn on switches on
PLACE = FunctionalUnit((n("pot", contains("broth")), n("stove", "off (ready)")), Motion("pick-and-place"),
                       (n("pot", contains("broth"), on("stove")), n("stove", "off (ready)", with_("pot"))))
TURN_ON = FunctionalUnit((n("stove", "off (ready)", with_("pot")),), Motion("turn on"), (LIT,))
KITCHEN = (HOT, n("bowl", contains("dashi")), n("dashi", inside("bowl")), n("spoon"), n("stove", "off", with_("pot")),
           n("pot", "empty", on("stove")), n("pot", contains("broth")), n("stove", "off (ready)"))


def test_the_stove_under_the_kitchen_pot_starts_where_units_switch_it_on():
    # every unit compiled (no relevance pruning), as the universal FOON's task kept the other recipe's heat
    outcome = clean_unit_plan((HEAT, PLACE, TURN_ON, POUR, STIR), KITCHEN, SOUP, prune=False)
    assert sorted(s.unit.motion.label for s in outcome.trace.steps) == ["cook and stir", "pour", "turn on"]
    assert any("the stove the kitchen's pot (contains {water}, hot, on [stove]) is on starts in stove (off (ready), "
               "with [pot]), from which units leave stove (on, with [pot]), a node only units make: this cook and stir takes "
               "that with pot (contains {soup stock}, hot, on [stove]), which units make of it" in note
               for note in outcome.compiled.notes), outcome.compiled.notes


def test_the_started_holder_note_names_only_an_object_at_that_holder():
    """Review rv45: an onion in a bowl, which the cook and stir also takes, was named in the note as the object
    the stove is under ("the stove the kitchen's onion (chopped, in [bowl]) is in starts in ...")."""
    onion = n("onion", "chopped", inside("bowl"))
    stir = FunctionalUnit((*STIR.inputs, onion), STIR.motion, STIR.outputs)
    outcome = clean_unit_plan((HEAT, PLACE, TURN_ON, POUR, stir), (*KITCHEN, onion), SOUP, prune=False)
    started = [note for note in outcome.compiled.notes if "the stove the kitchen's" in note]
    assert started and all("the kitchen's pot (contains {water}" in note for note in started), started
