"""A container a unit fills, left in a kitchen node with what it holds, serves the later unit that takes it with
those contents (`count_reuse`): the eggs and bacon pizza's water, the odd universal half's unused measuring cup.

The turn on at `0085-mini_bacon_egg_breakfast_pizza.txt:231` fills an empty cup at the faucet, leaving
`measuring cup (contains {water})` with `water (from [faucet], in [measuring cup])`, and the pour at `:251` takes
that pair. Alone, the cup's node is no kitchen node and the pour takes the filled cup; merged with recipes whose
kitchen has a cup of water (`0054-quick_ramen_noodles.txt:180`), the node is a kitchen node, and the count gave
the pour a kitchen cup of its own, with its water, which no plan touched (46 objects in the problem, `instances`
43)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import alone_roles, clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.instance_counts import derive_counts

CUP_OF_WATER, EMPTY_CUP = n("measuring cup", contains("water")), n("measuring cup", "clean", "empty")
TAP_WATER = n("water", make_state("from", "faucet"), inside("measuring cup"))
KITCHEN = frozenset({n("faucet", "off"), EMPTY_CUP, n("bowl", contains("flour")), n("flour", inside("bowl")),
                     CUP_OF_WATER, n("water", inside("measuring cup")), n("pot", "empty")})
GOAL = n("bowl", contains("flour", "water"))
FILL = FunctionalUnit((n("faucet", "off"), EMPTY_CUP), Motion("turn on"), (n("faucet", "on"), TAP_WATER, CUP_OF_WATER))
POUR = FunctionalUnit((TAP_WATER, CUP_OF_WATER, n("bowl", contains("flour")), n("flour", inside("bowl"))),
                      Motion("pour"), (n("water", inside("bowl")), GOAL, n("flour", inside("bowl"))))
# another recipe's pour takes the kitchen's cup of water: `measuring cup (contains {water})` is a kitchen node
OTHER = FunctionalUnit((n("water", inside("measuring cup")), CUP_OF_WATER, n("pot", "empty")), Motion("pour"),
                       (n("water", inside("pot")), n("pot", contains("water"))))
UNITS = (FILL, POUR, OTHER)


def _cups(kitchen: frozenset, units=UNITS, goal=GOAL) -> int:
    """The measuring cups counted for `goal` over `units`, each unit read alone (`relational_plan.plan_unit`)."""
    counts = derive_counts(Foon(units), range(len(units)), kitchen, (goal,), roles_of=alone_roles(kitchen),
                           together=True, stitched=True, reuse=True)
    return counts.labels()["measuring cup"]


def test_a_cup_filled_in_a_kitchen_node_serves_the_unit_taking_it_with_what_the_fill_put_in_it():
    # without the other recipe's cup of water in the kitchen: one cup, filled and poured
    assert _cups(KITCHEN - {CUP_OF_WATER, n("water", inside("measuring cup"))}) == 1
    # with it: the filled cup is in the kitchen's node, holding the tap water the pour takes; still one cup
    assert _cups(KITCHEN) == 1
    outcome = clean_unit_plan(UNITS, KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("measuring cup") == 1


def test_a_filled_cup_does_not_stand_for_the_kitchens_when_the_taker_pairs_it_with_other_contents():
    # both pours in one plan: the other recipe's takes the kitchen's cup with the kitchen's water, not the tap water
    # the fill put in its cup, so two cups, however the plan orders them
    dinner = n("dinner", contains("dough", "soup"))
    serve = FunctionalUnit((GOAL, n("pot", contains("water"))), Motion("serve"), (dinner,))
    units = (*UNITS, serve)
    assert _cups(KITCHEN, units, dinner) == 2
    outcome = clean_unit_plan(units, KITCHEN, dinner)
    assert [x.label for x in outcome.task.instances].count("measuring cup") == 2


# The universal FOON of 70 subgraphs drawn with seed 56: the blueberry muffin's wide count fires the pancake
# batter's pour of flour out of the bag (`0004-pancake_batter.txt:11`) and takes the kitchen's `bowl (contains
# {flour})`; with the filled bowl taken again, the kitchen's bowl and the flour the completion starts in it go, and
# with them `flour (in [bowl], powder)`, a node the small count takes from the kitchen: it poured the flour itself
# (41 -> 44 objects in the problem, the chocolate cake 36 -> 40, the apple cake 44 -> 45).
BAG, BAG_FLOUR = n("bag", contains("flour")), n("flour", inside("bag"))
BOWL_OF_FLOUR, FLOUR = n("bowl", contains("flour")), n("flour", inside("bowl"))
SIFT = FunctionalUnit((BAG_FLOUR, BAG, n("bowl", "empty")), Motion("pour"), (FLOUR, BOWL_OF_FLOUR, n("bag", "empty")))
BATTER = n("batter", inside("bowl"))
MIX = FunctionalUnit((BOWL_OF_FLOUR, FLOUR, n("whisk")), Motion("mix"),
                     (BATTER, n("bowl", contains("batter")), n("whisk", "dirty")))
PANTRY = frozenset({BAG, BAG_FLOUR, n("bowl", "empty"), BOWL_OF_FLOUR, n("whisk")})


def test_a_filled_bowl_taken_again_in_the_wide_count_leaves_the_small_count_its_kitchen_bowl_of_flour():
    wide = compile_goal(Foon((SIFT, MIX)), Kitchen(PANTRY), Goal(GoalSpec("batter"), (BATTER,)), "relational")
    # counted wide, the bowl the pour fills serves the mix: no kitchen bowl of flour, nor its flour (5, not 7)
    assert sorted(x.name for x in wide.task.instances) == ["bag_1", "batter_1", "bowl_1", "flour_1", "whisk_1"]
    # counted small, the kitchen's bowl of flour is still there to mix in: nothing poured, one bowl, one flour
    outcome = clean_unit_plan([SIFT, MIX], PANTRY, BATTER)
    assert [s.unit for s in outcome.trace.steps] == [MIX]
    assert sorted((x.name, x.start) for x in outcome.task.instances if x.start is not None) == [
        ("bowl_1", BOWL_OF_FLOUR), ("flour_1", FLOUR), ("whisk_1", n("whisk"))]
