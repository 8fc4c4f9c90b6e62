"""Counts where the way back to a node a later unit takes is a unit of the plan fired again
(`count_returns.with_returns`): the omelette's flip leaves the pan without the bacon the cook takes it with."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.count_returns import with_returns
from foon2pddl.pddl.instance_counts import derive_counts

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def _omelette():
    """0050's omelette in small: the egg poured into the pan, bacon sprinkled on, the flip (which leaves the pan
    listing the egg alone: the bacon is on the egg now) and the cook, which takes the pan listing both again."""
    both, egg_only = n("pan", contains("bacon", "egg")), n("pan", contains("egg"))
    flipped = n("egg", "flipped", contains("bacon"), inside("pan"))
    return (FunctionalUnit((n("pan", "empty"), n("egg", "whole")), Motion("crack"), (egg_only, n("egg", inside("pan")))),
            FunctionalUnit((n("bacon", "raw"), n("pan", "empty")), Motion("fry"), (n("bacon", "fried"),)),
            FunctionalUnit((egg_only, n("bacon", "fried")), Motion("sprinkle"), (both, n("bacon", inside("pan")))),
            FunctionalUnit((both, n("egg", inside("pan")), n("turner", "clean")), Motion("flip"),
                           (egg_only, flipped, n("turner", "clean"))),
            FunctionalUnit((both, flipped), Motion("cook"),
                           (egg_only, n("egg", "cooked", contains("bacon"), inside("pan")))))


def test_a_unit_of_the_plan_fired_again_brings_the_object_back_to_the_node_a_later_unit_takes():
    units = _omelette()
    kitchen = frozenset({n("pan", "empty"), n("egg", "whole"), n("bacon", "raw"), n("turner", "clean")})
    # the flip moves the pan out of `contains {bacon, egg}`, which the cook takes: the sprinkle before it takes
    # the pan from the flip's node to that one, so it fires again there (a second bacon, not a second egg)
    assert with_returns(Foon(units), (0, 1, 2, 3, 4), range(5), kitchen, stitched=True, again=True) == (
        0, 1, 2, 3, 2, 4)
    assert with_returns(Foon(units), (0, 1, 2, 3, 4), range(5), kitchen, stitched=True) == (0, 1, 2, 3, 4)
    # the unfolding adds up the sprinkle's two firings; its plan, with a unit twice, is no `unfolded` one (whose
    # units each fire `firings` times in one place)
    counts = derive_counts(Foon(units), range(5), kitchen, (units[4].outputs[1],), stitched=True)
    assert dict(counts.firings) == {0: 1, 1: 2, 2: 2, 3: 1, 4: 1} and counts.unfolded == ()


def test_the_relational_task_counts_a_second_bacon_wide_and_the_one_on_the_egg_small():
    units = _omelette()
    kitchen = {n("pan", "empty"), n("egg", "whole"), n("bacon", "raw"), n("turner", "clean")}
    goal = Goal(GoalSpec("egg"), (units[4].outputs[1],))
    wide = compile_goal(Foon(units), Kitchen(frozenset(kitchen)), goal, "relational")
    labels = sorted(x.label for x in wide.task.instances)
    assert labels.count("egg") == 1 and labels.count("bacon") == 2, labels
    # counted small, the cook takes the pan as the flip left it, a stitch's reading (`relational_reading._as_now`):
    # the bacon is the one on the flipped egg
    outcome = clean_unit_plan(units, kitchen, units[4].outputs[1])
    assert sorted(x.label for x in outcome.task.instances) == ["bacon", "egg", "pan", "turner"]
    assert sorted(s.unit.motion.label for s in outcome.trace.steps) == ["cook", "crack", "flip", "fry", "sprinkle"]


def test_the_plan_with_a_unit_fired_again_is_kept_only_when_it_counts_fewer_objects(monkeypatch):
    # 0010: the remove takes the oven out of `contains {baking tray}` that the second bake takes (the second put
    # inside is no unit of the delete-free plan); the first put inside fired again counts the first bread's whole
    # chain once more (69 objects at c759730, where the plan as it was counts 51). The oracle: the task counted
    # with each unfolding alone (review rv43: a hard-coded 51 passed before the rule too)
    import foon2pddl.pddl.instance_counts as counts_module

    foon, _ = load([DATA / "0010-cheesy_garlic_bread.txt"])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    goal = resolve_goal(spec_of_node(dish), foon)

    def objects(force: bool | None) -> int:
        if force is not None:
            monkeypatch.setattr(counts_module, "with_returns",
                                lambda *a, **k: with_returns(*a[:-1], **k, again=force and a[-2]))
        found = len(compile_goal(foon, default_kitchen(foon), goal, "relational").task.instances)
        monkeypatch.setattr(counts_module, "with_returns", with_returns)
        return found

    without, fired_again = objects(False), objects(True)
    assert fired_again > without  # here the unit fired again costs objects, so the rule must not take it
    assert objects(None) == min(without, fired_again)
