"""Objects counted small with a unit that takes a made node as it was before a later unit moved it on read as the
stitch reads it (`relational_reading._as_now`): the object as that unit left it, not the chain fired again."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_dish_plan, clean_unit_plan, instances_objects

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.input_stitch import stitches

DATA = Path(__file__).parent / "data" / "foon-subgraphs"

# the muffins' shape (ACT-0009, lines 259-300): the bake takes the pan as the scoop left it, before the put inside
# moved it into the oven, with the oven the put inside left holding it
EMPTY, FULL = n("muffin pan", "empty"), n("muffin pan", contains("batter"))
BATTER, POURED = n("batter", "raw"), n("batter", "raw", inside("muffin pan"))
IN_OVEN, OVEN_ON = n("muffin pan", contains("batter"), inside("oven")), n("oven", "on", make_state("with", "muffin pan"))
MUFFIN = n("muffin", "baked", inside("muffin pan"))
FILL = FunctionalUnit((EMPTY, BATTER), Motion("pour"), (FULL, POURED))
PUT = FunctionalUnit((FULL, n("oven", "on")), Motion("put inside"), (IN_OVEN, OVEN_ON))
BAKE = FunctionalUnit((FULL, POURED, OVEN_ON), Motion("bake"),
                      (n("muffin pan", contains("muffin"), inside("oven")), MUFFIN))
KITCHEN = (EMPTY, BATTER, n("oven", "on"))


def test_a_pan_taken_as_it_was_before_the_put_inside_is_counted_once():
    (found,) = stitches(Foon((FILL, PUT, BAKE)), range(3))
    assert (found.unit, found.node, found.reads_as) == (2, FULL, IN_OVEN)
    goal = Goal(GoalSpec("muffin"), (MUFFIN,))
    small = compile_goal(Foon((FILL, PUT, BAKE)), Kitchen(frozenset(KITCHEN)), goal, "relational", narrow=True)
    # FOON's own plan fires the fill twice (the put inside moves one pan on, the bake takes another as filled)
    assert sorted(x.label for x in small.task.instances) == ["batter", "muffin", "muffin pan", "oven"]
    outcome = clean_unit_plan((FILL, PUT, BAKE), KITCHEN, MUFFIN)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "put inside", "bake"]
    assert len(outcome.task.instances) == 4


def test_chocolate_chip_muffins_make_the_batter_once():
    # the bake at ACT-0009-chocolate_chip_muffin.txt:289 takes `muffin pan (contains {muffin batter})`: counted as
    # FOON's plan fires it, every unit making the batter fired twice (68 objects in the problem, `instances` 52)
    path = DATA / "ACT-0009-chocolate_chip_muffin.txt"
    outcome = clean_dish_plan(path)
    assert len(outcome.task.objects) < instances_objects(path) and outcome.compiled.narrowed
    assert [x.label for x in outcome.task.instances].count("muffin pan") == 1
