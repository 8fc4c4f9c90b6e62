"""A role FOON leaves out of a unit's outputs, the only one listing an object that leaves a holder the unit does not
name, is counted emptied of it (`relational_plan.count_roles`, `_late_listers`): the plan empties it, so a later
taker of it empty needs no second object."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal

# the 0050 omelette's shape (0050-scrambled_eggs_with_bacon-cheese.txt:96, :242, :288): the pour leaves the bacon
# `on [sheet]` beside `plate (contains {bacon})` (a place by another name); the sprinkle takes `bacon (fried, on
# [plate])`, which no unit makes, stitched to the pour's node, so its bacon leaves a holder the unit does not name,
# while its plate, left out of the outputs, lists the bacon; the last pour takes a plate empty
ON = lambda holder: make_state("on", holder)  # noqa: E731
PLATE_BACON, ON_SHEET = n("plate", contains("bacon")), n("bacon", "fried", ON("sheet"))
SKILLET, OMELETTE = n("skillet", contains("omelette")), n("omelette", "cooked", inside("skillet"))
SPRINKLED = (n("skillet", contains("bacon", "omelette")), n("omelette", "cooked", contains("bacon"), inside("skillet")))
DISH = n("omelette", "cooked", contains("bacon"), ON("plate"))
UNITS = (FunctionalUnit((n("pan", contains("bacon")), n("bacon", "fried", inside("pan")), n("plate", "empty")),
                        Motion("pour"), (n("pan", "empty"), ON_SHEET, PLATE_BACON)),
         FunctionalUnit((PLATE_BACON, n("bacon", "fried", ON("plate")), SKILLET, OMELETTE), Motion("sprinkle"),
                        SPRINKLED),
         FunctionalUnit((*SPRINKLED, n("plate", "empty")), Motion("pour"),
                        (n("skillet", "empty"), DISH, n("plate", contains("omelette")))))
KITCHEN = (n("pan", contains("bacon")), n("bacon", "fried", inside("pan")), n("plate", "empty"), SKILLET, OMELETTE)


def test_the_plate_a_stitched_sprinkle_takes_the_bacon_off_is_counted_empty_again():
    goal, kitchen = Goal(GoalSpec("omelette"), (DISH,)), Kitchen(frozenset(KITCHEN))
    for options in ({"narrow": True, "through": True}, {}):
        task = compile_goal(Foon(UNITS), kitchen, goal, "relational", **options).task
        # one plate: the bacon is poured onto it, sprinkled off it, and the omelette poured onto it (two before)
        assert sorted(x.label for x in task.instances) == ["bacon", "omelette", "pan", "plate", "skillet"]


def test_the_one_plate_gives_a_plan_the_replay_accepts():
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    assert [x.name for x in outcome.task.instances if x.label == "plate"] == ["plate_1"]
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "sprinkle", "pour"]


def test_a_role_the_unit_keeps_listing_is_not_counted_empty():
    """The rule reads a role FOON leaves out of the outputs: one whose output node still lists the bacon (the
    sprinkle that leaves some on the plate) keeps it, and the last pour needs a second plate."""
    kept = FunctionalUnit(UNITS[1].inputs, Motion("sprinkle"), (*SPRINKLED, PLATE_BACON))
    task = compile_goal(Foon((UNITS[0], kept, UNITS[2])), Kitchen(frozenset(KITCHEN)),
                        Goal(GoalSpec("omelette"), (DISH,)), "relational").task
    assert [x.label for x in task.instances].count("plate") == 2


# the same shape with salt sprinkled onto the bacon in the pan first: the plate lists the bacon and the salt in it,
# and the bacon leaves it with the salt (`Slot.along`); the count reads that late emptying as the action does
# (`relational_plan.late_emptied`), so the plate is counted empty, not left listing the salt (F15 of stop 58)
SALTED, PAN_SALTED = n("bacon", "fried", contains("salt"), inside("pan")), n("pan", contains("bacon", "salt"))
PLATE_SALTED = n("plate", contains("bacon", "salt"))
SALTED_UNITS = (
    FunctionalUnit((n("pan", contains("bacon")), n("bacon", "fried", inside("pan")), n("shaker", contains("salt")),
                    n("salt", inside("shaker"))), Motion("sprinkle"), (PAN_SALTED, SALTED, n("shaker", "empty"))),
    FunctionalUnit((PAN_SALTED, SALTED, n("plate", "empty")), Motion("pour"),
                   (n("pan", "empty"), n("bacon", "fried", contains("salt"), ON("sheet")), PLATE_SALTED)),
    FunctionalUnit((PLATE_SALTED, n("bacon", "fried", contains("salt"), ON("plate")), SKILLET, OMELETTE),
                   Motion("sprinkle"), SPRINKLED),
    UNITS[2])
SALTED_KITCHEN = (*KITCHEN, n("shaker", contains("salt")), n("salt", inside("shaker")))


def test_the_plate_is_counted_empty_of_what_was_put_into_the_bacon_too():
    goal, kitchen = Goal(GoalSpec("omelette"), (DISH,)), Kitchen(frozenset(SALTED_KITCHEN))
    for options in ({"narrow": True, "through": True}, {}):
        task = compile_goal(Foon(SALTED_UNITS), kitchen, goal, "relational", **options).task
        # one plate (two before: the count left it listing the salt, which the action takes off it with the bacon)
        assert [x.label for x in task.instances].count("plate") == 1
    outcome = clean_unit_plan(SALTED_UNITS, SALTED_KITCHEN, DISH, time_limit=60)
    assert [x.name for x in outcome.task.instances if x.label == "plate"] == ["plate_1"]
