"""A container node a unit takes and leaves in the same words, listing what the unit puts in (`pddl/list_brought.py`):
the easy pancakes' oil pour (`0031-easy_pancakes.txt:178`)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.encoding import at_level
from foon2pddl.pddl.list_brought import read_brought

WHISK = n("whisk", "clean")
MIXTURE = n("flour mixture", contains("flour", "sugar"), inside("bowl"))
FULL = n("bowl", contains("flour mixture", "milk", "vegetable oil"))
FIRST = FunctionalUnit((n("bowl", contains("flour", "sugar")), n("flour", inside("bowl")), n("sugar", inside("bowl")),
                        WHISK), Motion("mix"), (n("bowl", contains("flour mixture")), MIXTURE),
                       (Source("pancakes.txt", 111),))
MILK = FunctionalUnit((n("measuring cup", contains("milk")), n("milk", inside("measuring cup")),
                       n("bowl", contains("flour mixture"))), Motion("pour"), (n("bowl", contains("flour mixture", "milk")),),
                      (Source("pancakes.txt", 134),))
OIL = FunctionalUnit((n("bowl", contains("vegetable oil")), n("vegetable oil", inside("bowl")), FULL), Motion("pour"),
                     (FULL,), (Source("pancakes.txt", 176),))
MIX = FunctionalUnit((FULL, MIXTURE, WHISK), Motion("mix"),
                     (n("bowl", contains("pancake batter")), n("pancake batter", inside("bowl"))),
                     (Source("pancakes.txt", 188),))
UNITS = (FIRST, MILK, OIL, MIX)
# FOON's kitchen: every input no unit makes without taking it, the oil pour's bowl among them
KITCHEN = {i for u in UNITS for i in u.inputs if i not in {o for v in UNITS if i not in v.inputs for o in v.outputs}}


def test_the_bowl_the_oil_is_poured_into_is_the_one_the_milk_was_poured_into():
    # FOON's kitchen holds the bowl listing the oil, with a flour mixture in no node a unit makes; the mix takes the
    # flour mixture the first mix made in the bowl the milk is poured into: over objects no state applied the mix
    assert FULL in KITCHEN
    outcome = clean_unit_plan(UNITS, KITCHEN, MIX.outputs[1])
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["mix", "pour", "pour", "mix"]


def test_the_reading_is_noted_with_the_units_file_and_line():
    goal = Goal(GoalSpec("pancake batter"), (MIX.outputs[1],))
    notes = compile_goal(Foon(UNITS), Kitchen(frozenset(KITCHEN)), goal, "relational").notes
    assert [x for x in notes if "takes and leaves" in x] == [
        "label mismatch: pancakes.txt:176: pour takes and leaves bowl (contains {flour mixture, milk, vegetable oil}), "
        "which no other unit makes, as bowl (contains {flour mixture, milk}), which another unit makes: vegetable oil "
        "put in by it"]


def test_a_node_left_as_it_was_taken_is_read_only_with_what_the_unit_puts_in_and_no_other_maker():
    from foon2pddl.pddl.list_brought import brought

    assert list(brought(Foon(UNITS)).values()) == [(FULL, MILK.outputs[0], ("vegetable oil",))]
    stir = FunctionalUnit((FULL, n("spoon", "clean")), Motion("stir"), (FULL,))  # it puts nothing in: FOON's words
    assert brought(Foon((FIRST, MILK, stir, MIX))) == {}
    again = FunctionalUnit((n("bowl", contains("flour mixture", "milk")), n("vegetable oil", "fresh")), Motion("pour"),
                           (FULL,))  # another unit makes the bowl listing the oil: no reading
    assert brought(Foon((*UNITS, again))) == {}


def test_a_node_is_read_only_as_one_a_unit_can_make_from_the_kitchen():
    # no flour or milk at hand: no unit makes the bowl the milk was poured into, and the kitchen's full bowl with the
    # flour mixture in it stays the kitchen's; the mix applies at once, as in FOON's tree (read, the kitchen's bowl
    # was gone and the dish unsolvable)
    outcome = clean_unit_plan(UNITS, {FULL, MIXTURE, WHISK}, MIX.outputs[1])
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["mix"]


def _copy(units, tag: str):
    """`units` with every label of every node tagged (another recipe, sharing nothing with the first)."""
    def node(x):
        return make_node(x.label + tag, [make_state(s.label, s.related + tag if s.related else "",
                                                    [i + tag for i in s.ingredients]) for s in x.states])
    return tuple(FunctionalUnit(tuple(map(node, u.inputs)), u.motion, tuple(map(node, u.outputs)), u.sources)
                 for u in units)


def test_goals_over_one_kitchen_share_the_network_of_the_readings_it_keeps():
    """A kitchen keeping some readings (here the first recipe's, not the second's) gives every goal the same network
    object, so what is kept per network object is not computed again per goal (EXP trials 2, 4, 10 of the default
    experiment: encode median 1.0 s per goal, was 0.02 s before 3428f2b)."""
    other = _copy(UNITS, " b")
    foon = Foon(UNITS + other)
    kitchen = Kitchen(frozenset(KITCHEN) | {other[3].inputs[0], other[3].inputs[1], other[3].inputs[2]})
    got = []
    for target in (MIX.outputs[1], other[3].outputs[1]):
        inp = at_level(foon, kitchen, Goal(GoalSpec(target.label), (target,)), 3)
        read, notes = read_brought(inp)
        assert sorted(notes) == [2]  # the first recipe's oil pour only: the second's M is made of nothing at hand
        got.append(read.foon)
    assert got[0] is got[1]
