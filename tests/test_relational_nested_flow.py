"""What a unit moves into an object that stays in the same holder is still in that holder, so the holder's list
keeps it (`relational_plan._stays_in`): the 0050 omelette's flip (`0050-scrambled_eggs_with_bacon-cheese.txt:255`)
turns the bacon sprinkled into the pan onto the omelette in that pan, and the cook at `:269` takes the pan listing
both. Read as emptied of the bacon, the pan needed a second sprinkle, with a second bacon, before the cook."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import FunctionalUnit, Motion, make_state

# 0050's shape (:96, :242-:286): the bacon poured onto a plate, sprinkled into the pan, the flip (the pan is no
# output), the cook
ON_STOVE = make_state("on", "stove")
PAN, PAN_BACON = n("pan", contains("omelette"), ON_STOVE), n("pan", contains("omelette", "bacon"), ON_STOVE)
RAW, PLATE, BACON = n("omelette", "partly cooked", inside("pan")), n("plate", contains("bacon")), \
    n("bacon", "fried", make_state("on", "plate"))
FLIPPED = n("omelette", "flipped", contains("bacon"), inside("pan"))
DISH = n("omelette", "cooked", contains("bacon"), inside("pan"))
SKILLET, FRIED = n("skillet", contains("bacon")), n("bacon", "fried", inside("skillet"))
UNITS = (FunctionalUnit((SKILLET, FRIED, n("plate", "empty")), Motion("pour"), (PLATE, BACON, n("skillet", "empty"))),
         FunctionalUnit((PLATE, BACON, PAN), Motion("sprinkle"), (PAN_BACON,)),
         FunctionalUnit((PAN_BACON, RAW, n("turner", "clean")), Motion("flip"), (FLIPPED,)),
         FunctionalUnit((PAN_BACON, FLIPPED, n("stove", "on")), Motion("cook"), (PAN, DISH)))
KITCHEN = (PAN, RAW, SKILLET, FRIED, n("plate", "empty"), n("turner", "clean"), n("stove", "on"))


def test_a_flow_onto_an_object_staying_in_the_holder_leaves_the_holder_listing_it():
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    assert [x.label for x in outcome.task.instances].count("bacon") == 1
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "sprinkle", "flip", "cook"]
    flip = outcome.trace.steps[2]
    bacon = next(x.name for x in outcome.task.instances if x.label == "bacon")
    omelette = next(x.name for x in outcome.task.instances if x.label == "omelette")
    assert {c.id: c.holder for c in flip.changes}[bacon] == omelette  # the bacon is on the omelette, in the pan
