"""A node a unit already in the delete-free plan makes is taken from that unit, not from another recipe's first maker
(issue 21, the shared universal's 0050 omelette): the other recipe's chain, pulled into the plan for that one node,
made a node the plan's own chain needs later in firing order, and the unfolding fired it there, with its objects."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.instance_counts import delete_free_plan, derive_counts

ON_STOVE, IN_PAN = make_state("on", "stove"), inside("pan")
# the pan the omelette is spread in, the sprinkle takes, and the cook leaves again for the pour (`C` below)
PAN = n("pan", contains("omelette"), ON_STOVE)
BOWL_MIXED = n("bowl", contains("egg mixture"))
DISH = n("omelette", "cooked", contains("bacon"), make_state("on", "plate"))


def _units() -> tuple[FunctionalUnit, ...]:
    """The 0050 omelette's shape on the universal FOON (`0050-scrambled_eggs_with_bacon-cheese.txt:54-299`, the
    plain omelette's cook at `0063-plain_omelette_mahalo.txt:140`). Recipe A (units 1-3) salts eggs, mixes them and
    cooks them into an omelette in `PAN` by round 3, before B's spread (unit 7, round 4) makes it; B's sprinkle (8)
    takes `PAN`, the flip and cook (9, 10) leave it again and the pour (11) takes it with the cooked omelette. A's
    mix (2) makes `bowl (contains {egg mixture})` in round 2, after B's mix (0) made it in round 1."""
    def unit(ins, motion, outs) -> FunctionalUnit:
        return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs))
    egg_bowl, egg = n("bowl", contains("egg")), n("egg", inside("bowl"))
    salted = n("bowl", contains("egg", "salt"))
    salty_mix = n("egg mixture", contains("salt"), inside("bowl"))
    pan_free, greased = n("pan", "empty", ON_STOVE), n("pan", "greased", ON_STOVE)
    pan_mixed, mix_in_pan = n("pan", contains("egg mixture"), ON_STOVE), n("egg mixture", IN_PAN)
    with_bacon, partly = n("pan", contains("bacon", "omelette"), ON_STOVE), n("omelette", "partly cooked", IN_PAN)
    flipped, cooked = n("omelette", "flipped", contains("bacon"), IN_PAN), n("omelette", "cooked", contains("bacon"), IN_PAN)
    return (
        unit((egg_bowl, egg), "mix", (BOWL_MIXED, n("egg mixture", inside("bowl")))),  # 0: B, round 1
        unit((egg_bowl, egg, n("shaker", contains("salt")), n("salt", inside("shaker"))), "sprinkle",
             (salted, n("salt", inside("bowl")))),  # 1: A, round 1
        unit((salted, egg, n("salt", inside("bowl"))), "mix", (BOWL_MIXED, salty_mix)),  # 2: A, round 2
        unit((BOWL_MIXED, salty_mix, pan_free), "cook",
             (PAN, n("omelette", contains("salt"), IN_PAN), n("bowl", "empty"))),  # 3: A, round 3
        unit((pan_free, n("butter", "cubed")), "pick-and-place",
             (n("pan", contains("butter"), ON_STOVE), n("butter", IN_PAN))),  # 4: B, round 1
        unit((n("pan", contains("butter"), ON_STOVE), n("butter", IN_PAN)), "heat", (greased,)),  # 5: round 2
        unit((BOWL_MIXED, n("egg mixture", inside("bowl")), greased), "pour",
             (pan_mixed, mix_in_pan, n("bowl", "empty"))),  # 6: round 3
        unit((pan_mixed, mix_in_pan), "spread", (PAN, partly)),  # 7: round 4
        unit((PAN, n("bowl", contains("bacon")), n("bacon", "fried", inside("bowl"))), "sprinkle",
             (with_bacon, n("bowl", "empty"))),  # 8
        unit((with_bacon, partly), "flip", (flipped,)),  # 9
        unit((with_bacon, flipped), "cook", (PAN, cooked)),  # 10
        unit((PAN, cooked, n("plate", "empty")), "pour", (n("pan", "empty"), DISH, n("plate", contains("omelette")))),
    )


KITCHEN = (n("bowl", contains("egg")), n("egg", inside("bowl")), n("shaker", contains("salt")),
           n("salt", inside("shaker")), n("pan", "empty", ON_STOVE), n("butter", "cubed"), n("bowl", contains("bacon")),
           n("bacon", "fried", inside("bowl")), n("plate", "empty"))


def test_the_sprinkle_takes_the_pan_from_the_spread_already_in_the_plan():
    units = _units()
    first, _ = delete_free_plan(Foon(units), frozenset(KITCHEN), (DISH,), together=True)
    assert {1, 2, 3} <= set(first)  # the first maker of the pan the sprinkle takes is A's cook, met first
    plan, _ = delete_free_plan(Foon(units), frozenset(KITCHEN), (DISH,), together=True, in_plan=True)
    assert plan == (0, 4, 5, 6, 7, 8, 9, 10, 11)  # A's cook, and its chain with it, stay out


def test_one_egg_one_bowl_of_it_and_no_salt_for_the_omelette():
    units = _units()
    goal, kitchen = Goal(GoalSpec("omelette"), (DISH,)), Kitchen(frozenset(KITCHEN))
    labels = sorted(x.label for x in compile_goal(Foon(units), kitchen, goal, "relational").task.instances)
    # before: A's mix fired for the bowl of egg mixture B's pour takes, with a second egg, bowl and the salt
    assert labels.count("egg") == 1 and "salt" not in labels and "shaker" not in labels
    outcome = clean_unit_plan(units, KITCHEN, DISH, time_limit=60)
    assert sorted(s.unit.motion.label for s in outcome.trace.steps) == sorted(
        ["mix", "pick-and-place", "heat", "pour", "spread", "sprinkle", "flip", "cook", "pour"])  # B's units alone
    assert sorted(x.label for x in outcome.task.instances) == labels


def test_the_swaps_counting_fewer_are_tried_together_and_leave_the_knife_out():
    # the shared universal's 0050 omelette (20 objects in the problem against `instances`' 18): the plan with makers
    # it has peels the onion at `0013-creamy_potato_soup.txt:105`, which takes a clean knife and leaves it dirty;
    # `0026-cheddar_frittata.txt:79` peels it with no knife. Another maker was tried only when the plan had fewer
    # units, one swap at a time: the first-achiever plan keeps A's chain, and the swap leaving it out keeps the
    # knife. Units 12 and 13 make the kitchen's cubed butter B's pick-and-place takes; 13 takes the butter alone.
    block, cubed = n("butter", "block"), n("butter", "cubed")
    units = (*_units(),
             FunctionalUnit((block, n("knife", "clean")), Motion("chop"), (cubed, n("knife", "dirty"))),  # 12
             FunctionalUnit((block,), Motion("crumble"), (cubed,)))  # 13: the same node, no knife
    kitchen = tuple(k for k in KITCHEN if k != cubed) + (block, n("knife", "clean"))
    plan, _ = delete_free_plan(Foon(units), frozenset(kitchen), (DISH,), together=True, in_plan=True)
    assert 12 in plan and 13 not in plan  # the first achiever of the cubed butter: content order (`rank`)
    counts = derive_counts(Foon(units), range(len(units)), frozenset(kitchen), (DISH,), together=True, stitched=True,
                           reuse=True, other_makers=True)
    assert {u for u, _ in counts.firings} == {0, 4, 5, 6, 7, 8, 9, 10, 11, 13}
    goal = Goal(GoalSpec("omelette"), (DISH,))
    small = compile_goal(Foon(units), Kitchen(frozenset(kitchen)), goal, "relational", narrow=True)
    labels = sorted(x.label for x in small.task.instances)
    assert "knife" not in labels and labels.count("egg") == 1 and "salt" not in labels
    outcome = clean_unit_plan(units, kitchen, DISH, time_limit=60)
    assert "crumble" in [s.unit.motion.label for s in outcome.trace.steps]
    assert sorted(x.label for x in outcome.task.instances) == labels
