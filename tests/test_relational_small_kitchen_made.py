"""A node the small count's kitchen adds (where the objects the wide count's completion implies start) that a unit
the small plan fires makes anyway gets no kitchen object, when the count without it fires the same units and has
fewer objects (`relational_objects.task_objects`, `_made_anyway`)."""

from __future__ import annotations

from pathlib import Path

from relational_checks import clean_plan

from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal

SUBGRAPHS = Path(__file__).parent / "data" / "foon-subgraphs"


def _dish(names: tuple[str, ...], label: str):
    """The universal FOON of these subgraphs, its default kitchen and the dish whose node starts with `label`."""
    foon, _ = load([SUBGRAPHS / x for x in names])
    dish = next(x for x in foon.nodes if x.dish is not None and x.describe().startswith(label))
    return foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon)


def test_the_kitchen_s_stove_the_plan_makes_anyway_is_not_counted_small():
    """The 0050 omelette beside the plain omelette (the `same` set's shape): the plain omelette's kitchen pan
    `cooking pan (empty, on [stove])` starts on a stove, so the small count's kitchen has `stove (on, with [pan])`;
    the plan through the stitches places the pans on stoves itself (the pick-and-place at
    `0050-scrambled_eggs_with_bacon-cheese.txt:123`), which makes that very node its cooks take."""
    foon, kitchen, goal = _dish(("0050-scrambled_eggs_with_bacon-cheese.txt", "0063-plain_omelette_mahalo.txt"),
                                "omelette (contains {bacon")
    through = compile_goal(foon, kitchen, goal, "relational", narrow=True, through=True)
    # two stoves, those the pick-and-place puts a pan on (before: a third, with a pan of its own in it: 34 objects,
    # 18 in the problem)
    assert [x.label for x in through.task.instances].count("stove") == 2
    assert (len(through.task.instances), len(through.task.objects)) == (32, 17)
    assert "stove (on, with [pan])" not in through.narrowed
    outcome = clean_plan(foon, kitchen, goal, time_limit=60)
    assert (len(outcome.task.instances), len(outcome.task.objects)) == (32, 17)  # the task planned, valid


def test_a_node_the_plan_makes_only_by_firing_more_stays_the_kitchen_s():
    """The cheesy garlic bread beside two other garlic breads: without the kitchen's `baking tray (contains {bread})`
    the small count fires another recipe's chain twice (56 -> 53 objects, but 44 -> 47 in the problem)."""
    foon, kitchen, goal = _dish(("0010-cheesy_garlic_bread.txt", "0016-easy_garlic_bread-one-pot-chef.txt",
                                 "0017-garfield_garlic_bread.txt"), "garlic bread (baked")
    own = compile_goal(foon, kitchen, goal, "relational", narrow=True)
    assert "baking tray (contains {bread})" in own.narrowed
    assert (len(own.task.instances), len(own.task.objects)) == (55, 45)
