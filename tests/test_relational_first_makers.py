"""First makers across recipes (issue 21, the shared universal's scrambled eggs): in a merged network a node has
makers from several recipes; the delete-free plan the relational counts unfold takes each node's first maker,
and `count_together` must not trade it for another recipe's maker that fires after the unit taking it."""

from __future__ import annotations

import pytest
from node_words import contains, inside, n

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.instance_counts import delete_free_plan, derive_counts

ON_STOVE, IN_PAN = make_state("on", "stove"), inside("pan")
PAN_MIXED = n("cooking pan", contains("egg mixture"), ON_STOVE)


def _scrambled_eggs() -> tuple[tuple[FunctionalUnit, ...], frozenset]:
    """Two recipes merged (0062's and 0056's scrambled eggs on the shared universal FOON). Recipe A puts the pan on
    the stove, heats it (the stove on), pours its egg mixture into the heated pan and cooks and stirs it there,
    taking the stove `on, with [pan]`, the pan `contains {egg mixture}, on [stove]` and the mixture `in [pan]`.
    Recipe B makes a mixture with yogurt in four units and pours it into the heated pan on the lit stove: the
    pan's node again, a round after A's cook and stir."""
    def at(f: str, line: int) -> tuple[Source, ...]:
        return (Source(f, line),)
    stove_with = make_state("with", "pan")
    a = (
        FunctionalUnit((n("cooking pan", "empty"), n("stove", "off")), Motion("pick-and-place"),
                       (n("cooking pan", "empty", ON_STOVE), n("stove", "off", stove_with)), at("a.txt", 1)),
        FunctionalUnit((n("stove", "off", stove_with), n("cooking pan", "empty", ON_STOVE)), Motion("heat"),
                       (n("stove", "on", stove_with), n("cooking pan", "heated", ON_STOVE)), at("a.txt", 13)),
        FunctionalUnit((n("bowl", contains("egg mixture")), n("egg mixture", inside("bowl")),
                        n("cooking pan", "heated", ON_STOVE)), Motion("pour"),
                       (n("bowl", "empty"), PAN_MIXED, n("egg mixture", IN_PAN)), at("a.txt", 44)),
        FunctionalUnit((n("stove", "on", stove_with), PAN_MIXED, n("spatula", "clean"), n("egg mixture", IN_PAN)),
                       Motion("cook and stir"),
                       (n("cooking pan", contains("scrambled eggs"), ON_STOVE), n("scrambled eggs", "cooked", IN_PAN)),
                       at("a.txt", 70)),
    )
    mixed = ("egg", "yogurt")
    b = (
        FunctionalUnit((n("egg", "whole"), n("jug", contains("egg white"))), Motion("crack"),
                       (n("jug", contains("egg")), n("egg", inside("jug"))), at("b.txt", 10)),
        FunctionalUnit((n("jug", contains("egg")), n("cup", contains("yogurt")), n("yogurt", inside("cup"))),
                       Motion("pour"), (n("jug", contains(*mixed)), n("yogurt", inside("jug"))), at("b.txt", 36)),
        FunctionalUnit((n("jug", contains(*mixed)), n("egg", inside("jug")), n("yogurt", inside("jug"))),
                       Motion("mix"), (n("jug", contains("egg mixture")),
                                       n("egg mixture", contains(*mixed), inside("jug"))), at("b.txt", 62)),
        FunctionalUnit((n("egg mixture", contains(*mixed), inside("jug")),), Motion("season"),
                       (n("egg mixture", contains(*mixed), "seasoned", inside("jug")),), at("b.txt", 70)),
        FunctionalUnit((n("stove", "on", stove_with), n("cooking pan", "heated", ON_STOVE),
                        n("jug", contains("egg mixture")), n("egg mixture", contains(*mixed), "seasoned", inside("jug"))),
                       Motion("pour"), (n("jug", "dirty"), PAN_MIXED,
                                        n("egg mixture", contains(*mixed), "seasoned", IN_PAN)), at("b.txt", 83)),
    )
    kitchen = frozenset({n("cooking pan", "empty"), n("stove", "off"), n("bowl", contains("egg mixture")),
                         n("egg mixture", inside("bowl")), n("spatula", "clean"), n("egg", "whole"),
                         n("jug", contains("egg white")), n("cup", contains("yogurt")), n("yogurt", inside("cup"))})
    return (*a, *b), kitchen


def test_the_pan_is_made_by_the_recipe_whose_pour_fires_before_the_cook_and_stir():
    # the stove lists the pan (`with [pan]`): read as the stove holding the pan, the pan's node was counted from
    # recipe B's pour, which fires after the cook and stir takes it; A's pour made it there, on the stove its
    # heat switched on: counted from B, the plan had two pans, two stoves and B's whole chain
    units, kitchen = _scrambled_eggs()
    goal = units[3].outputs[1:]
    assert delete_free_plan(Foon(units), kitchen, goal, together=True, first=True)[0] == (0, 1, 2, 3)
    # the counts keep, of that plan and the one with B's chain, the one counting fewer objects
    counts = derive_counts(Foon(units), range(len(units)), kitchen, goal, together=True, stitched=True, reuse=True)
    labels = counts.labels()
    assert (labels["cooking pan"], labels["stove"], "jug" in labels) == (1, 1, False)
    assert {u for u, _ in counts.firings} == {0, 1, 2, 3}


@pytest.mark.parametrize("prefix", [
    "garlic bread (contains {bread, butter, garlic salt}",
    "garlic bread (contains {bread, butter, garlic, parsley, pepper, salt}",
    "scrambled eggs (contains {egg white and yolk, milk}",
])
def test_the_universal_dish_counted_small_has_no_more_objects_than_instances(universal, prefix):
    # issue 21's floor per task: counted from the later recipe's maker (the garlic breads' oven from 0010's bake,
    # `0010-cheesy_garlic_bread.txt:274`; the scrambled eggs' pan from 0056's pour), the garlic breads had 37
    # objects in the problem against 25 and the scrambled eggs 20 against 13
    foon = universal[0]
    dish = next(x for x in sorted(foon.dishes) if x.describe().startswith(prefix))
    goal = resolve_goal(spec_of_node(dish), foon)
    sizes = {enc: len(compile_goal(foon, default_kitchen(foon), goal, enc, narrow=True).task.objects)
             for enc in ("instances", "relational")}
    assert sizes["relational"] <= sizes["instances"], sizes


def _garlic_breads() -> tuple[tuple[FunctionalUnit, ...], frozenset]:
    """Two makers of one node (0010's and 0016's garlic breads on a universal FOON): `bread (contains {garlic
    butter}, on [cutting board])`. 0010's spread, first in FOON order and so its first achiever, takes the bowl of
    garlic butter (first made by 0016's mix) and the garlic butter still `in [food processor bowl]` (0010's blend):
    both chains. 0016's spread makes the node from 0016's mix alone."""
    fpb, board = "food processor bowl", make_state("on", "cutting board")
    bowl_gb, in_fpb, in_bowl = n("bowl", contains("garlic butter")), n("garlic butter", inside(fpb)), n(
        "garlic butter", inside("bowl"))
    spread = n("bread", contains("garlic butter"), board)
    units = (
        FunctionalUnit((n(fpb, contains("butter", "garlic")), n("garlic", "minced", inside(fpb)),
                        n("butter", inside(fpb))), Motion("blend"), (n(fpb, contains("garlic butter")), in_fpb)),
        FunctionalUnit((n("bowl", contains("butter", "garlic")), n("garlic", "minced", inside("bowl")),
                        n("butter", inside("bowl")), n("spoon", "clean")), Motion("mix"),
                       (bowl_gb, in_bowl, n("spoon", "dirty"))),
        FunctionalUnit((n("bread", "halved", board), bowl_gb, in_fpb, n("knife", "clean")), Motion("spread"),
                       (spread, n("garlic butter", make_state("on", "bread")), n("knife", "dirty"))),
        FunctionalUnit((n("bread", "sliced", board), bowl_gb, in_bowl, n("knife", "clean")), Motion("spread"),
                       (spread, n("garlic butter", make_state("on", "bread")), n("knife", "dirty"))),
        FunctionalUnit((spread, n("oven", "on")), Motion("bake"), (n("bread", "baked", contains("garlic butter")),)),
    )
    made = {o for u in units for o in u.outputs}
    return units, frozenset(i for u in units for i in u.inputs if i not in made)


def test_of_two_makers_of_one_node_the_counts_keep_the_one_counting_fewer():
    # the universal FOON's baked garlic bread (odd half 63 objects in the problem against `instances`' 60): counted
    # from 0010's spread (`0010-cheesy_garlic_bread.txt:176`) the plan had both garlic-butter chains; its plan used
    # 23 of its 63 objects. Counted with each maker, the one from 0016's spread alone counts fewer.
    units, kitchen = _garlic_breads()
    goal = units[-1].outputs
    assert delete_free_plan(Foon(units), kitchen, goal, together=True)[0] == (0, 1, 2, 4)  # the first achievers
    counts = derive_counts(Foon(units), range(len(units)), kitchen, goal, together=True, stitched=True, reuse=True)
    assert {u for u, _ in counts.firings} == {1, 3, 4}
    assert counts.other_maker  # the counts say so: without other makers' plans they differ
    assert "food processor bowl" not in counts.labels() and counts.labels()["garlic"] == 1
    # without them, FOON's own plan unfolded: what `plan` falls back on last when a task counted with them has no
    # valid plan (the experiment's REG trial 6 lost goals when nothing did, tests/test_relational_wide_count.py)
    counts = derive_counts(Foon(units), range(len(units)), kitchen, goal, together=True, stitched=True, reuse=True,
                           other_makers=False)
    assert {u for u, _ in counts.firings} == {0, 1, 2, 4} and not counts.other_maker
    compiled = [compile_goal(Foon(units), Kitchen(kitchen), Goal(GoalSpec("bread"), goal), "relational", own=own)
                for own in (False, True)]
    assert ["food processor bowl" in {x.label for x in c.task.instances} for c in compiled] == [False, True]
