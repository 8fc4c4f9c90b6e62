"""A container's node and its content's node that one unit takes, made together only by a unit taking the content
out of a kitchen container (issue 21, the universal FOON of 70 subgraphs drawn with seed 56): the lemonade's pour
(`0072-old-fashioned_lemonade.txt:109`) takes `measuring cup (contains {water})`, first made by the mini pizza's
turn on (its water `from [faucet], in [measuring cup]`), with `water (in [measuring cup])`, first made by the
macaroni's fill into a cup `below [faucet]`. Only the kofta's pour (`ACT-0053-lentil_kofta-1.txt:1`) makes both,
out of the kitchen's `pitcher (contains {water})` with `water (in [pitcher])`, a node only the watermelon
lemonade's pour makes (of the very water in the cup): in FOON's tree the kofta's pour fires late. The kitchen
completion starts a water in the kitchen's pitcher in that node, so the pour can fire at once: counted from it,
one cup holds the water the lemonade pours (unsolvable before, out of holder reach)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.instance_counts import delete_free_plan

BELOW = make_state("below", "faucet")
CUP_WATER, WATER_IN_CUP = n("measuring cup", contains("water")), n("water", inside("measuring cup"))


def _units() -> tuple[FunctionalUnit, ...]:
    """The fill into a cup below the faucet (0), the turn on filling a clean cup (1), the pour out of the
    kitchen's pitcher (2), the pour of the cup's water into a pitcher of juice (3, the only maker of `water (in
    [pitcher])`), and the pour of the cup's water into a saucepan (4)."""
    def at(f: str, line: int) -> tuple[Source, ...]:
        return (Source(f, line),)

    return (
        FunctionalUnit((n("water", make_state("from", "faucet")), n("measuring cup", "empty", BELOW)), Motion("fill"),
                       (n("measuring cup", contains("water"), BELOW), WATER_IN_CUP), at("macaroni.txt", 21)),
        FunctionalUnit((n("faucet", "off"), n("measuring cup", "clean", "empty")), Motion("turn on"),
                       (n("faucet", "on"), n("water", make_state("from", "faucet"), inside("measuring cup")),
                        CUP_WATER), at("pizza.txt", 231)),
        FunctionalUnit((n("pitcher", contains("water")), n("water", inside("pitcher")), n("measuring cup", "empty")),
                       Motion("pour"), (CUP_WATER, WATER_IN_CUP, n("pitcher", "empty")), at("kofta.txt", 1)),
        FunctionalUnit((n("pitcher", contains("juice")), n("juice", inside("pitcher")), CUP_WATER, WATER_IN_CUP),
                       Motion("pour"), (n("pitcher", contains("juice", "water")), n("water", inside("pitcher")),
                                        n("measuring cup", "empty")), at("watermelon.txt", 296)),
        FunctionalUnit((n("saucepan", "empty"), CUP_WATER, WATER_IN_CUP), Motion("pour"),
                       (n("saucepan", contains("water")), n("water", inside("saucepan")), n("measuring cup", "empty")),
                       at("lemonade.txt", 109)),
    )


def test_the_pair_is_made_by_the_pour_out_of_the_kitchen_pitcher():
    units = _units()
    foon = Foon(units)
    kitchen = default_kitchen(foon)
    assert n("water", inside("pitcher")) not in kitchen.nodes  # the watermelon lemonade's pour makes it
    assert n("pitcher", contains("water")) in kitchen.nodes
    goal = units[4].outputs[1]
    plan = delete_free_plan(foon, kitchen.nodes, (goal,), together=True)[0]
    assert 2 in plan and not {0, 1, 3} & set(plan), plan  # one cup, filled from the pitcher
    outcome = clean_plan(foon, kitchen, Goal(GoalSpec(goal.label), (goal,)), time_limit=60)
    assert sorted((x.name, x.start.describe()) for x in outcome.task.instances) == [
        ("measuring_cup_1", "measuring cup (empty)"), ("pitcher_1", "pitcher (contains {water})"),
        ("saucepan_1", "saucepan (empty)"), ("water_1", "water (in [pitcher])")]
    assert [a.split()[0] for a in outcome.result.plan] == ["pour_u2", "pour_u4", "reach-goal-1"]

def test_a_kitchen_that_holds_the_pair_needs_no_pitcher():
    # where the kitchen has the cup of water itself, nothing changes: the pour takes it
    units = _units()
    kitchen = Kitchen(default_kitchen(Foon(units)).nodes | {CUP_WATER, WATER_IN_CUP})
    goal = units[4].outputs[1]
    assert delete_free_plan(Foon(units), kitchen.nodes, (goal,), together=True)[0] == (4,)
