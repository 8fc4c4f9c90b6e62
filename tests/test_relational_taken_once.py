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
