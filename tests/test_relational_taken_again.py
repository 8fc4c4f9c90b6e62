"""A container FOON takes again after a unit poured out of it (`list_drops.taken_again`): the pour took a portion.

The blueberry muffin (`ACT-0003-blueberry_muffin.txt:182`) pours the flour mixture from its bowl into the wet
ingredients, leaving the bowl out of its outputs, and `:207`, after the mix of what it poured into, takes `bowl (contains
{flour mixture})` again and pours it into the batter. Read as emptied by the first pour, the bowl of flour mixture
was made again, its mix and every pour before it fired once more per taking."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.holder_flows import gained
from foon2pddl.pddl.list_drops import taken_again
from foon2pddl.pddl.relational_plan import plan_unit

MIX_IN = n("bowl", contains("flour", "salt"))
KITCHEN = frozenset({MIX_IN, n("flour", inside("bowl")), n("salt", inside("bowl")), n("whisk"), n("spoon"),
                     n("bowl", contains("milk")), n("milk", inside("bowl"))})
FM = n("flour mixture", inside("bowl"))
FM_BOWL = n("bowl", contains("flour mixture"))
GOAL = n("bowl", contains("batter", "flour mixture"))


def _units(recipe: str | None = "muffin.txt") -> tuple[FunctionalUnit, ...]:
    """Mix the flour mixture; pour it into the milk (the bowl left out of the outputs); mix the batter; then take
    the flour mixture's bowl again and pour it into the batter. Lines 10, 20, ... of `recipe` (None:
    units of no recipe file)."""
    wet = n("bowl", contains("milk", "flour mixture"))
    poured = make_node("bowl", FM_BOWL.states, motion_flag=1)  # the bowl in motion, as FOON marks it
    batter_bowl = n("bowl", contains("batter"))
    units = [FunctionalUnit((MIX_IN, n("flour", inside("bowl")), n("salt", inside("bowl")), n("whisk")), Motion("mix"),
                            (FM_BOWL, FM)),
             FunctionalUnit((n("bowl", contains("milk")), poured, FM), Motion("pour"), (wet,)),
             FunctionalUnit((FM, wet, n("spoon")), Motion("mix"), (batter_bowl, n("batter", inside("bowl")))),
             FunctionalUnit((batter_bowl, poured), Motion("pour"), (GOAL, n("batter", inside("bowl")), n("bowl", "dirty")))]
    return tuple(u if recipe is None else FunctionalUnit(u.inputs, u.motion, u.outputs, (make_source(recipe, 10 * k),))
                 for k, u in enumerate(units, 1))


def test_a_bowl_taken_again_after_a_pour_out_of_it_kept_what_it_lists():
    outcome = clean_unit_plan(_units(), KITCHEN, GOAL)
    labels = [x.label for x in outcome.task.instances]
    # one flour mixture made (and its portion poured into the milk), one mix of it: one flour, one salt
    assert labels.count("flour") == 1 and labels.count("salt") == 1
    assert any("takes again" in note for note in outcome.compiled.notes), outcome.compiled.notes


def test_units_of_no_recipe_file_are_not_read_as_one_recipe():
    # two pours of one bowl's butter by units with no source (tests/test_relational_experiment_cells.py) may be
    # two recipes' pours: each empties its bowl, and the flour mixture is made once per taking
    outcome = clean_unit_plan(_units(recipe=None), KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("flour") == 2
    assert not any("takes again" in note for note in outcome.compiled.notes)


def _readings(units) -> dict[int, str]:
    """`taken_again`'s readings over all of `units`, unit index -> the taker's place named in the note."""
    foon = Foon(tuple(units))
    us = range(len(units))
    filled = frozenset().union(*(gained(u) for u in units))
    plans = {u: plan_unit(x, Kitchen(KITCHEN), frozenset(), filled) for u, x in enumerate(units)}
    return {u: note.split(" at ")[1].split(" takes")[0] for u, (_, note) in taken_again(foon, us, plans)[1].items()}


def _elsewhere(path: str, line: int) -> FunctionalUnit:
    """Another recipe's pour of the flour mixture's bowl into a bowl of water, at `path`:`line`."""
    water = n("bowl", contains("water"))
    poured = make_node("bowl", FM_BOWL.states, motion_flag=1)
    return FunctionalUnit((water, poured, FM), Motion("pour"), (n("bowl", contains("water", "flour mixture")),),
                          (make_source(path, line),))


def test_the_taker_is_one_the_pours_unit_leads_to_not_any_later_unit_of_the_file():
    own = _units()
    assert _readings(own) == {1: "muffin.txt:40"}
    # a universal FOON written as one file: another recipe's pour of the same node, later in the file, that no
    # path of units from the muffin's pour leads to, is no evidence that the muffin's bowl kept the rest
    merged = (*own[:3], _elsewhere("muffin.txt", 50))
    assert _readings(merged) == {}
    # the same with the recipes in two files: the readings agree
    assert _readings((*own[:3], _elsewhere("other.txt", 10))) == {}
    assert _readings((*own, _elsewhere("muffin.txt", 50))) == _readings((*own, _elsewhere("other.txt", 10)))


def _fired_before(recipe: str = "muffin.txt") -> tuple[FunctionalUnit, ...]:
    """The muffin's mix and pour (the pour scrapes with a spatula, left dirty), the batter mixed (30) and stirred
    (35); the flour mixture's bowl poured into the stirred batter (40), and into a bowl of water with the dirty
    spatula (50), the next taker of that spatula; both mixed (60). The pour at 50 needs nothing the batter's units
    make: FOON's plan, unfolded as counted, fires it before the stir and the pour at 40."""
    wet = n("bowl", contains("milk", "flour mixture"))
    poured = make_node("bowl", FM_BOWL.states, motion_flag=1)
    batter_bowl, stirred = n("bowl", contains("batter")), n("bowl", contains("batter"), "stirred")
    into_batter, into_water = n("bowl", contains("batter", "flour mixture")), n("bowl", contains("water", "flour mixture"))
    units = [FunctionalUnit((MIX_IN, n("flour", inside("bowl")), n("salt", inside("bowl")), n("whisk")), Motion("mix"),
                            (FM_BOWL, FM)),
             FunctionalUnit((n("bowl", contains("milk")), poured, FM, n("spatula")), Motion("pour"),
                            (wet, n("spatula", "dirty"))),
             FunctionalUnit((FM, wet, n("spoon")), Motion("mix"), (batter_bowl, n("batter", inside("bowl")))),
             FunctionalUnit((batter_bowl, n("batter", inside("bowl")), n("spoon")), Motion("stir"),
                            (stirred, n("batter", inside("bowl"), "stirred"))),
             FunctionalUnit((stirred, poured), Motion("pour"), (into_batter,)),
             FunctionalUnit((n("bowl", contains("water")), poured, n("spatula", "dirty")), Motion("pour"), (into_water,)),
             FunctionalUnit((into_batter, into_water), Motion("mix"), (DOUGH,))]
    return tuple(FunctionalUnit(u.inputs, u.motion, u.outputs, (make_source(recipe, line),))
                 for u, line in zip(units, (10, 20, 30, 35, 40, 50, 60), strict=True))


DOUGH = n("bowl", contains("dough"))


def test_the_taker_named_is_the_one_the_counted_plan_fires_first_not_the_first_of_the_file():
    units = _fired_before()
    # both pours of the flour mixture's bowl are on paths from the first pour; the file has the one at 40 first
    assert _readings(units) == {1: "muffin.txt:40"}
    kitchen = Kitchen(KITCHEN | {n("spatula"), n("bowl", contains("water"))})
    compiled = compile_goal(Foon(units), kitchen, Goal(GoalSpec("bowl"), (DOUGH,)), "relational")
    said = [note for note in compiled.notes if "takes again" in note]
    # FOON's plan unfolded fires the pour at 50 (it needs the dirty spatula and the bowl alone) before the stir
    assert said and all("pour at muffin.txt:50 takes again" in note for note in said), said
