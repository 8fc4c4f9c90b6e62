"""A container FOON takes again after a unit poured out of it (`list_drops.taken_again`): the pour took a portion.

The blueberry muffin (`ACT-0003-blueberry_muffin.txt:182`) pours the flour mixture from its bowl into the wet
ingredients, leaving the bowl out of its outputs, and `:220`, later in the same recipe, takes `bowl (contains
{flour mixture})` again and pours it into the batter. Read as emptied by the first pour, the bowl of flour mixture
was made again, its mix and every pour before it fired once more per taking."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_source

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
