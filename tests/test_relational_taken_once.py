"""A kitchen container FOON leaves out of a unit's outputs, which no other unit of the task takes: its contents
leave whole, no portion stays behind.

The hamburger (`0027-best_hamburger_ever.txt:167`) sprinkles the kitchen's `bowl (contains {salt})` into the
mixing bowl and gives no node of the salt's bowl after; no other unit takes that bowl. Read as keeping what it
lists, the bowl kept a salt and a portion of it went into the mix: two salts, and fifteen seasonings so, 57
objects in the problem against 44 for `instances`. Where another unit takes the bowl again, the rest stays."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import FunctionalUnit, Motion

SALT_BOWL, SALT = n("bowl", contains("salt")), n("salt", inside("bowl"))
BEEF_BOWL, BEEF = n("bowl", contains("beef")), n("beef", inside("bowl"))
SALTED = n("bowl", contains("beef", "salt"))
MIX, MIXED = n("bowl", contains("meat mix")), n("meat mix", inside("bowl"))
KITCHEN = frozenset({SALT_BOWL, SALT, BEEF_BOWL, BEEF, n("spoon")})
SPRINKLE = FunctionalUnit((BEEF_BOWL, SALT_BOWL, SALT), Motion("sprinkle"), (SALTED,))  # the salt's bowl left out
STIR = FunctionalUnit((SALTED, BEEF, n("salt", inside("bowl")), n("spoon")), Motion("mix"), (MIX, MIXED))


def _labels(units, goal=MIX) -> list[str]:
    return [x.label for x in clean_unit_plan(units, KITCHEN, goal).task.instances]


def test_a_kitchen_bowl_no_other_unit_takes_is_sprinkled_out_whole():
    labels = _labels((SPRINKLE, STIR))
    assert labels.count("salt") == 1  # the kitchen's salt, all of it in the mix: no portion, no rest in the bowl


def test_a_kitchen_bowl_another_unit_takes_again_keeps_the_rest():
    # a second sprinkle takes the salt's bowl as the kitchen has it: the first left salt in it
    eggs, egg = n("bowl", contains("egg")), n("egg", inside("bowl"))
    again = FunctionalUnit((eggs, SALT_BOWL, SALT), Motion("sprinkle"), (n("bowl", contains("egg", "salt")),))
    both = n("plate", contains("egg", "meat mix"))
    serve = FunctionalUnit((MIX, MIXED, n("bowl", contains("egg", "salt")), egg, n("plate")), Motion("serve"),
                           (both,))
    units = (SPRINKLE, STIR, again, serve)
    labels = [x.label for x in clean_unit_plan(units, KITCHEN | {eggs, egg, n("plate")}, both).task.instances]
    assert labels.count("salt") >= 2  # a portion went in each time; the kitchen's salt stays in its bowl



def test_a_kitchen_bowl_holding_what_another_unit_takes_keeps_the_rest():
    # the chocolate cake (`0058-chocolate_cake.txt:49` and `:17`): the pour is the one unit naming the kitchen's bowl
    # of flour and fires once, but a sprinkle takes flour `in [bowl]` from a bowl it does not name, so FOON's plan
    # as counted starts two flours in that bowl; read as poured out whole, the pour left it `bowl (empty)` with the
    # other flour still in it (held-by-empty), where the sprinkle took it from
    flour_bowl, flour = n("bowl", contains("flour")), n("flour", inside("bowl"))
    sugar_bowl, sugar = n("bowl", contains("sugar")), n("sugar", inside("bowl"))
    both, batter = n("bowl", contains("flour", "sugar")), n("bowl", contains("cake mix"))
    tray, lined = n("baking tray", "empty"), n("baking tray", contains("cake mix"))
    dusted = n("baking tray", contains("cake mix", "flour"))
    units = (FunctionalUnit((sugar_bowl, flour_bowl, flour), Motion("pour"), (both,)),  # the flour's bowl left out
             FunctionalUnit((both, flour, sugar, n("whisk")), Motion("mix"), (batter, n("cake mix", inside("bowl")))),
             FunctionalUnit((batter, n("cake mix", inside("bowl")), tray), Motion("pour"),
                            (lined, n("cake mix", inside("baking tray")))),
             FunctionalUnit((lined, flour), Motion("sprinkle"), (dusted, n("flour", inside("baking tray")))))
    outcome = clean_unit_plan(units, {flour_bowl, flour, sugar_bowl, sugar, n("whisk"), tray}, dusted)
    assert [x.label for x in outcome.task.instances].count("flour") == 2  # one mixed, one sprinkled
    pour = outcome.trace.steps[0]
    assert [b.after for b in pour.bindings if b.before == flour_bowl] == [None]  # the bowl keeps the rest: no change
