"""The task tree a relational plan maps back to, checked as FOON's: what the plan's own steps leave that FOON's
units do not list (a holder emptied) is available to the units after them."""

from __future__ import annotations

from node_words import contains, inside, n

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.planners.decode import decode
from foon2pddl.planners.trace_check import emptied

ON_STOVE = make_state("on", "stove")
WITH_PAN = make_state("with", "cooking pan")
# the universal FOON's scrambled eggs (0050): the bacon is taken out of the pan onto a plate by a unit that does
# not name the stove (0061:54), and a second pan goes onto a `stove (on)` (0040:1), a node FOON makes only by
# turning a stove on (0037:1). The relational plan takes the pan off the stove, which it leaves `stove (on)`.
FULL, BACON = n("cooking pan", contains("bacon"), ON_STOVE), n("bacon", "fried", inside("cooking pan"))
TAKE = FunctionalUnit((FULL, BACON, n("plate", "empty")), Motion("pick-and-place"),
                      (n("cooking pan", "dirty"), n("plate", contains("bacon")), n("bacon", "fried", make_state("on", "plate"))))
PUT = FunctionalUnit((n("cooking pan", "empty"), n("stove", "on")), Motion("pick-and-place"),
                     (n("cooking pan", "heated", ON_STOVE), n("stove", "on", WITH_PAN)))
TURN_ON = FunctionalUnit((n("stove", "off"),), Motion("turn on"), (n("stove", "on"),))
WARM = n("bacon", "fried", "warm", inside("cooking pan"))
SPRINKLE = FunctionalUnit((n("plate", contains("bacon")), n("bacon", "fried", make_state("on", "plate")),
                           n("cooking pan", "heated", ON_STOVE)), Motion("sprinkle"),
                          (n("cooking pan", contains("bacon"), "heated", ON_STOVE), WARM))
KITCHEN = Kitchen(frozenset({FULL, BACON, n("plate", "empty"), n("cooking pan", "empty"), n("stove", "on", WITH_PAN),
                             n("stove", "off")}))


def test_a_holder_a_step_empties_is_available_to_the_units_after_it():
    goal = Goal(GoalSpec("bacon"), (WARM,))
    compiled = compile_goal(Foon((TAKE, PUT, TURN_ON, SPRINKLE)), KITCHEN, goal, "relational")
    stove = next(x.name for x in compiled.task.instances if x.start == n("stove", "on", WITH_PAN))
    pans = {x.start: x.name for x in compiled.task.instances if x.label == "cooking pan"}
    # no turn on: the second pan goes onto the stove the first was taken off
    steps = [f"pick-and-place_u0 {pans[FULL]} bacon_1 plate_1", f"pick-and-place_u1 {pans[n('cooking pan', 'empty')]} {stove}",
             f"sprinkle_u3 plate_1 bacon_1 {pans[n('cooking pan', 'empty')]}", "reach-goal-1"]
    decoded = decode(compiled, steps, goal, KITCHEN.nodes)
    assert decoded.plan_check.ok and decoded.trace_check.ok
    assert decoded.validation.ok, decoded.validation.problems  # before: step 2: input not available: stove (on)
    # the sprinkle leaves the plate it takes the bacon off out of its outputs too: `plate (empty)`
    assert emptied(decoded.trace) == ((n("stove", "on"),), (), (n("plate", "empty"),))
    assert [x for x in decoded.notes if x.startswith("tree check:")] == [
        "tree check: step 2 (pick-and-place, ) takes stove (on), which step 1 (pick-and-place, ) leaves by emptying "
        "it: its unit does not list it"]
