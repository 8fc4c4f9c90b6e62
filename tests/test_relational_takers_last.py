"""Takers last (`count_order.takers_last`): a unit that takes an object out of a kitchen node fires, in the plan the
counts unfold, after a later unit that leaves an object there, where nothing between needs it; the object is then
taken again (`count_reuse`) instead of a second one counted. The shared universal's watermelon lemonade filled a
second measuring cup with water at the faucet before the pour and stir emptied the first (24 objects in the
problem against `instances`' 23)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import alone_roles, clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.count_order import takers_last
from foon2pddl.pddl.instance_counts import derive_counts

KITCHEN = frozenset({n("cup", "empty"), n("jug", contains("water")), n("water", inside("jug")),
                     n("cup", contains("juice")), n("juice", inside("cup")), n("pitcher", "dirty")})
GOAL = n("pitcher", contains("juice", "water"))


def _units() -> tuple[FunctionalUnit, ...]:
    """Water poured from the jug into an empty cup (unit 0), the pitcher washed (unit 1), the juice poured out of
    its cup into the pitcher, leaving that cup empty (unit 2), the water poured after it (unit 3): the fixpoint
    fires the water's pour in the first round, the juice's in the second, after the wash."""
    return (
        FunctionalUnit((n("cup", "empty"), n("jug", contains("water")), n("water", inside("jug"))), Motion("pour"),
                       (n("cup", contains("water")), n("water", inside("cup")))),
        FunctionalUnit((n("pitcher", "dirty"),), Motion("wash"), (n("pitcher", "empty"),)),
        FunctionalUnit((n("pitcher", "empty"), n("cup", contains("juice")), n("juice", inside("cup"))),
                       Motion("pour"), (n("pitcher", contains("juice")), n("juice", inside("pitcher")),
                                        n("cup", "empty"))),
        FunctionalUnit((n("pitcher", contains("juice")), n("juice", inside("pitcher")), n("cup", contains("water")),
                        n("water", inside("cup"))), Motion("pour"),
                       (GOAL, n("water", inside("pitcher")), n("cup", "empty"))),
    )


_roles_of = alone_roles(KITCHEN)  # the relational reading of each unit alone


def test_the_water_is_poured_after_the_juice_left_its_cup_empty():
    assert takers_last(Foon(_units()), (0, 1, 2, 3), _roles_of) == (1, 2, 0, 3)
    assert takers_last(Foon(_units()), (1, 2, 0, 3), _roles_of) == (1, 2, 0, 3)  # nothing later leaves a cup empty


def test_one_cup_when_the_water_goes_into_the_cup_the_juice_left():
    units = _units()
    counts = derive_counts(Foon(units), range(len(units)), KITCHEN, (GOAL,), roles_of=_roles_of, together=True,
                           stitched=True, reuse=True)
    assert counts.labels()["cup"] == 1
    outcome = clean_unit_plan(units, KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("cup") == 1


def test_the_universal_watermelon_lemonade_fills_the_measuring_cup_it_poured_the_juice_out_of(universal):
    foon = universal[0]
    dish = next(x for x in sorted(foon.dishes) if x.describe().startswith("watermelon lemonade"))
    kitchen, goal = default_kitchen(foon), resolve_goal(spec_of_node(dish), foon)
    compiled = compile_goal(foon, kitchen, goal, "relational")
    # the fill at 0075-pesto_linguine.txt:13 (water for the pour at 0084-watermelon_lemonade.txt:296) takes
    # `measuring cup (empty)`, which the pour and stir at 0084-watermelon_lemonade.txt:277 leaves its cup in
    assert [x.label for x in compiled.task.instances].count("measuring cup") == 1
    assert len(compiled.task.objects) <= len(compile_goal(foon, kitchen, goal, "instances").task.objects)
