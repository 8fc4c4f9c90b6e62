"""A place an input names by a shorter name of the role the unit pours it into is where it comes from, not that
role (rule 0, `model.aliases.unit_aliases`; the kitchen's start nodes, `holder_words.task_aliases`).

The bloody mary (`0076-bloody_mary.txt:25`) pours `water ice (cubed, in [glass])` into the highball glass, whose
input node does not list the ice and whose output node does: the ice was in a glass, not in the highball glass.
Read as `highball glass`, the kitchen's ice started in a second highball glass, an object the task's actions can
take (12 objects in the problem against `instances`' 10); read as a glass of its own, nothing but the pour's
quantified effect touches it and it is set aside (11)."""

from __future__ import annotations

from conftest import SUBGRAPHS
from node_words import contains, inside, n
from relational_checks import clean_dish_plan, clean_unit_plan

from foon2pddl.model.aliases import unit_aliases
from foon2pddl.model.foon import FunctionalUnit, Motion
from foon2pddl.pddl.holder_words import task_aliases

ICE = n("water ice", "cubed", inside("glass"))
POUR = FunctionalUnit((n("highball glass", contains("vodka")), ICE), Motion("pour"),
                      (n("highball glass", contains("vodka", "water ice")),))


def test_a_source_place_is_no_other_name_of_the_role_the_unit_pours_into():
    assert unit_aliases(POUR) == ()
    # the same name where the role already lists the object is still read as that role (`oil (in [pan])`)
    stir = FunctionalUnit((n("cooking pan", contains("oil")), n("oil", inside("pan")), n("spoon")), Motion("stir"),
                          (n("cooking pan", contains("oil"), "hot"),))
    assert unit_aliases(stir) == (("pan", "cooking pan"),)


def test_a_kitchen_place_is_read_by_the_head_noun_rule_only_where_a_holder_of_that_label_lists_the_object():
    starts = (n("highball glass", "empty"), ICE)
    assert task_aliases((POUR,), ("highball glass", "water ice"), starts) == ()
    oil = (n("cooking pan", contains("oil")), n("oil", inside("pan")))
    assert task_aliases((), ("cooking pan", "oil"), oil) == (("pan", "cooking pan"),)


def test_the_ice_is_poured_out_of_a_glass_of_its_own():
    drink = n("highball glass", contains("vodka", "water ice"))
    outcome = clean_unit_plan((POUR,), (n("highball glass", contains("vodka")), n("vodka", inside("highball glass")),
                                        ICE), drink)
    step = outcome.trace.steps[0]
    assert {b.object for b in step.bindings} >= {"highball_glass_1", "glass_1", "water_ice_1"}
    assert "highball_glass_2" not in {x.name for x in outcome.task.instances}


def test_bloody_mary_has_one_highball_glass_and_eleven_objects_in_its_problem():
    outcome = clean_dish_plan(SUBGRAPHS / "0076-bloody_mary.txt")
    assert [x.label for x in outcome.task.instances].count("highball glass") == 1
    assert len(outcome.task.objects) == 11 and "glass_1" in {o for o, _ in outcome.task.aside}


