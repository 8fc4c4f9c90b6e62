"""A task whose FOON plan, counted small, is out of holder reach is counted small from the plan through the stitches
alone before it is planned wide (`relational_objects.task_objects`' `through`, `planners.solve.plan`)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan, compiled_counts

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl import relational_objects, relational_reading
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.holder_reach import drop_unreachable

# the 0050 omelette's shape (0050-scrambled_eggs_with_bacon-cheese.txt:227-299): the pour takes the cooked omelette
# listing bacon, which no unit makes, out of the pan on the stove the cook leaves; the sprinkle lists the bacon
ON_STOVE = make_state("on", "stove")
PAN_EGG, EGG = n("pan", contains("egg"), ON_STOVE), n("egg", "beaten", inside("pan"))
PAN = n("pan", contains("omelette"), ON_STOVE)
BOWL, BACON = n("bowl", contains("bacon")), n("bacon", "fried", inside("bowl"))
TAKEN = n("omelette", "cooked", contains("bacon"), inside("pan"))
DISH = n("omelette", "cooked", contains("bacon"), make_state("on", "plate"))
UNITS = (FunctionalUnit((PAN_EGG, EGG), Motion("cook"), (PAN, n("omelette", inside("pan")))),
         FunctionalUnit((PAN, n("omelette", inside("pan")), BOWL, BACON), Motion("sprinkle"),
                        (PAN, n("omelette", contains("bacon"), inside("pan")), n("bowl", "empty"))),
         FunctionalUnit((PAN, TAKEN, n("plate", "empty")), Motion("pour"),
                        (n("pan", "empty"), DISH, n("plate", contains("omelette")))))
KITCHEN = (PAN_EGG, EGG, BOWL, BACON, n("plate", "empty"), TAKEN)
OBJECTS = ["bacon", "bowl", "egg", "omelette", "pan", "plate", "stove"]


def test_foon_s_plan_out_of_holder_reach_is_counted_again_through_the_stitches_alone(monkeypatch):
    goal, kitchen = Goal(GoalSpec("omelette"), (DISH,)), Kitchen(frozenset(KITCHEN))
    own = compile_goal(Foon(UNITS), kitchen, goal, "relational", narrow=True)
    wide = compile_goal(Foon(UNITS), kitchen, goal, "relational")
    # FOON's own plan pours the kitchen's omelette, which starts in a pan of its own, off no stove: out of reach
    assert own.narrowed and drop_unreachable(own.task)[1] is not None
    through = compile_goal(Foon(UNITS), kitchen, goal, "relational", narrow=True, through=True)
    assert sorted(x.label for x in through.task.instances) == OBJECTS
    assert len(wide.task.instances) == 10 and drop_unreachable(through.task)[1] is None
    assert through.narrowed.startswith("counted small, from the plan through the stitches alone")
    counts = compiled_counts(monkeypatch)
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    # `plan`'s gate: small first, out of holder reach, so through the stitches; that one solved: not counted again
    # with makers by holder reach (`placed`), nor wide
    assert counts == ["small", "small through"]
    assert sorted(x.label for x in outcome.task.instances) == OBJECTS
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["cook", "sprinkle", "pour"]
    assert any(x.startswith("objects: counted small, from the plan through the stitches alone")
               for x in outcome.decoded.notes)


def test_a_task_with_no_stitch_is_not_counted_through_them():
    units = UNITS[:1]
    goal, kitchen = Goal(GoalSpec("pan"), (PAN,)), Kitchen(frozenset(KITCHEN))
    assert not compile_goal(Foon(units), kitchen, goal, "relational", narrow=True, through=True).narrowed


def test_a_plan_counted_through_an_appliance_s_stitch_names_the_task_s_units(monkeypatch):
    """The plan through the stitches is counted in `Stitched.through`, which has each appliance's stitched unit of
    the network after FOON's units, while the task adds only the stitched units it keeps: the odd universal half's
    caesar salad, counted small through the stitches, fired the stitched sprinkle (`ACT-0080-caesar_salad.txt:345`)
    at through index 988 of a task of 979 units: an IndexError. Here the lamp's stitch is the network's first, not
    the task's; the oven's is the plan's: through index 5, the task's index 4 (`Stitched.in_task`)."""
    units = (FunctionalUnit((n("lamp", "on"),), Motion("turn off"), (n("lamp", "off"),)),
             FunctionalUnit((n("lamp", "off (ready)"),), Motion("turn on"), (n("lamp", "on", "bright"),)),
             FunctionalUnit((n("oven", "on"),), Motion("remove"), (n("oven", "off"),)),
             FunctionalUnit((n("oven", "off (ready)"),), Motion("turn on"), (n("oven", "on", "hot"),)))
    goal = Goal(GoalSpec("oven"), (n("oven", "on", "hot"),))
    read = []

    def recording(inp, st, *args):
        read.append((st, args, relational_reading.read_units(inp, st, *args)))
        return read[-1][2]

    monkeypatch.setattr(relational_objects, "read_units", recording)
    through = compile_goal(Foon(units), Kitchen(frozenset({n("oven", "on")})), goal, "relational", narrow=True,
                           through=True)
    assert [x.label for x in through.task.instances] == ["oven"]
    (st, _, rd), = [x for x in read if x[1][5]]  # the reading counted through the stitches (`through`)
    assert len(st.foon.units) == 5 and len(st.through.units) == 6
    fired = [st.foon.units[u] for u, _ in rd.counts.firings]
    assert [(u.motion.label, u.inputs) for u in fired] == [("remove", (n("oven", "on"),)),
                                                           ("turn on", (n("oven", "off"),))]
