"""A container a unit of the task fills with an object, in a node the kitchen has too, is emptied of the whole of it
(`relational_plan.filled_by_task`, `plan_unit`'s `task_filled`): no portion is split off as if it were the
kitchen's stock. Unless the plan as counted takes the kitchen's stock in that node (`relational_reading._moved_whole`):
then the filled container's reading would make the kitchen's one an object an action can touch."""

from __future__ import annotations

from dataclasses import replace

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.instance_counts import InstanceCounts
from foon2pddl.pddl.relational_reading import _moved_whole

# the eggs and bacon pizza's water (0085-mini_bacon_egg_breakfast_pizza.txt:231, :251) on the odd half's universal
# FOON: the faucet fills `measuring cup (contains {water})` with `water (in [measuring cup], from [faucet])`; the pour
# takes that water and leaves the cup out of its outputs; another recipe's pour reads the cup of water as the kitchen's
# (`0054-quick_ramen_noodles.txt:180`), so the kitchen has that node too
FROM = make_state("from", "faucet")
CUP = n("measuring cup", contains("water"))
DRAWN = n("water", inside("measuring cup"), FROM)
DISH = n("bowl", contains("flour", "water"))
UNITS = (FunctionalUnit((n("faucet", "off"), n("measuring cup", "empty")), Motion("turn on"),
                        (n("faucet", "on"), DRAWN, CUP)),
         FunctionalUnit((DRAWN, CUP, n("bowl", contains("flour")), n("flour", inside("bowl"))), Motion("pour"),
                        (n("water", inside("bowl"), FROM), DISH, n("flour", inside("bowl")))))
KITCHEN = (n("faucet", "off"), n("measuring cup", "empty"), CUP, n("water", inside("measuring cup")),
           n("bowl", contains("flour")), n("flour", inside("bowl")))


def _labels(units, kitchen, dish, **options) -> list[str]:
    """The labels of the objects of the relational problem of `dish` (its objects no action can touch set aside)."""
    task = compile_goal(Foon(units), Kitchen(frozenset(kitchen)), Goal(GoalSpec(dish.label), (dish,)), "relational",
                        **options).task
    return sorted(label for _, label in task.objects)


def test_the_water_the_faucet_drew_is_poured_whole():
    for options in ({"narrow": True}, {}):
        task = compile_goal(Foon(UNITS), Kitchen(frozenset(KITCHEN)), Goal(GoalSpec("bowl"), (DISH,)), "relational",
                            **options).task
        labels = sorted(x.label for x in task.instances)
        assert labels.count("water") == 1, labels  # two before: the cup kept a portion of the water drawn into it


def test_the_whole_water_gives_a_plan_the_replay_accepts():
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    assert [x.name for x in outcome.task.instances if x.label == "water"] == ["water_1"]
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["turn on", "pour"]


# the egg noodle's flour on the odd half's universal FOON: the cookie's pour
# (`0030-5_easy_microwave_desserts-chocolate_chip_cookie.txt:45`) takes the kitchen's spoon of flour, leaving the spoon
# out of its outputs (a stock: a portion leaves it); the noodles' scoop (`0044-egg_noodles_from_scratch.txt:134`) fills
# a spoon with sifted flour in the same spoon node, and their pour (`:148`) makes the same jar node; the plan fires the
# cookie's pour
SPOON = n("spoon", contains("flour"))
FLOUR = n("flour", inside("spoon"), "powder")
SIFTED = n("flour", inside("spoon"), "sifted")
JAR = n("jar", contains("egg"))
MIXED = n("jar", contains("egg", "flour"))
EGG = n("egg", inside("jar"))
STOCK = (FunctionalUnit((JAR, EGG, SPOON, FLOUR), Motion("pour"), (MIXED, EGG, n("flour", inside("jar"), "powder"))),
         FunctionalUnit((n("bag", contains("flour")), n("flour", inside("bag"), "sifted"), n("spoon", "empty")),
                        Motion("scoop"), (SPOON, SIFTED)),
         FunctionalUnit((JAR, EGG, SPOON, SIFTED), Motion("pour"), (MIXED, EGG, n("flour", inside("jar"), "sifted"))))
STOCK_KITCHEN = (JAR, EGG, SPOON, FLOUR, n("bag", contains("flour")), n("flour", inside("bag"), "sifted"),
                 n("spoon", "empty"))


def test_a_kitchen_stock_the_plan_takes_stays_untouched():
    # the plan pours a portion out of the kitchen's spoon; read as emptied by the scoop's pour, which the plan does
    # not fire, that spoon and its flour were objects an action could touch: two more in the problem
    for options in ({"narrow": True}, {}):
        labels = _labels(STOCK, STOCK_KITCHEN, MIXED, **options)
        assert labels == _labels(STOCK[:1], STOCK_KITCHEN, MIXED, **options), labels


def test_a_pair_is_moved_whole_only_where_the_plan_as_counted_fills_it_and_takes_no_stock_there():
    # `_moved_whole`: the faucet's pair is kept when the plan fires the turn on and starts no object in the cup's node;
    # dropped when the plan does not fire it (the container, if any, is the kitchen's) or starts the kitchen's cup
    net, pair = Foon(UNITS), (DRAWN, CUP)
    fires = InstanceCounts(((n("faucet", "off"), 1),), (), ((0, 1), (1, 1)))
    assert _moved_whole(frozenset({pair}), [(net, fires)]) == {pair}
    assert _moved_whole(frozenset({pair}), [(net, replace(fires, firings=((1, 1),)))]) == frozenset()
    stocked = replace(fires, at_node=((n("faucet", "off"), 1), (CUP, 1)))
    assert _moved_whole(frozenset({pair}), [(net, stocked)]) == frozenset()
    assert _moved_whole(frozenset({pair}), [(net, fires), (net, stocked)]) == frozenset()  # either plan's stock
