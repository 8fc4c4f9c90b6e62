"""0011's readings: a list's item no object of the unit is, taken there later; an input where a unit left the
object; and counts that let an object come back to a node a later unit takes."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_dish_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.pddl.count_returns import changers, with_returns
from foon2pddl.pddl.input_stitch import stitches
from foon2pddl.pddl.list_arrivals import arrivals

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def _at(units, lines):
    return tuple(FunctionalUnit(u.inputs, u.motion, u.outputs, (Source("r.txt", line),))
                 for u, line in zip(units, lines, strict=True))


def _jar():
    """0011's add and the blend after it: the add's jar lists refined sugar, no node of the add is sugar, and the
    blend takes `refined sugar (in [blender jar])`, which no unit makes."""
    sugar = n("refined sugar", "granulated", inside("blender jar"))
    full = n("blender jar", contains("tomato", "refined sugar"))
    add = FunctionalUnit((n("blender jar", "empty"), n("tomato", "whole")), Motion("add"),
                         (full, n("tomato", inside("blender jar"))))
    blend = FunctionalUnit((full, n("tomato", inside("blender jar")), sugar), Motion("blend"),
                           (n("blender jar", contains("soup")), n("soup", inside("blender jar"))))
    return sugar, add, blend


def test_a_list_item_no_object_of_the_unit_is_arrives_with_it_when_a_later_unit_takes_it_there():
    sugar, add, blend = _jar()
    found = arrivals(Foon(_at((add, blend), (10, 20))))
    assert {u: (m, t.motion.label) for u, (m, t) in found.items()} == {0: (sugar, "blend")}
    # through a unit between them that takes the jar's node on (the cover): the jar's own path
    covered = n("blender jar", contains("tomato", "refined sugar"), make_state("covered", "blender cover"))
    cover = FunctionalUnit((blend.inputs[0], n("blender cover", "clean")), Motion("cover"), (covered,))
    later = FunctionalUnit((covered, *blend.inputs[1:]), blend.motion, blend.outputs)
    found = arrivals(Foon(_at((add, cover, later), (10, 15, 20))))
    assert {u: (m, t.motion.label) for u, (m, t) in found.items()} == {0: (sugar, "blend")}
    # the blend earlier in the recipe is no evidence; nor a sugar some unit makes; nor a jar that does not list it
    assert not arrivals(Foon(_at((add, blend), (20, 10))))
    pour = FunctionalUnit((n("bag", contains("refined sugar")),), Motion("pour"), (sugar,))
    assert not arrivals(Foon(_at((add, blend, pour), (10, 20, 5))))
    bare = FunctionalUnit((n("blender jar", contains("tomato")), *blend.inputs[1:]), blend.motion, blend.outputs)
    assert not arrivals(Foon(_at((add, bare), (10, 20))))


def test_an_arrival_is_read_only_on_the_jar_the_unit_filled_not_another_recipe_of_the_same_file():
    # a universal FOON written as one file has every recipe in it: a later blend of another recipe takes a jar
    # listing sugar and sugar in the jar, but not the jar the add filled (no unit takes the add's jar on)
    sugar, add, _ = _jar()
    other = FunctionalUnit((n("blender jar", contains("banana", "refined sugar")), sugar), Motion("blend"),
                           (n("blender jar", contains("smoothie")),))
    assert not arrivals(Foon(_at((add, other), (10, 20))))


def _pot():
    """0011's pot: cooked hot, covered (still hot), uncovered from a node that no longer says hot."""
    on_stove = make_state("on", "stove")
    pot = n("pot", contains("soup"), on_stove)
    hot = n("pot", contains("soup"), "hot", on_stove)
    lid = make_state("covered", "pot lid")
    covered_hot = n("pot", contains("soup"), "hot", lid, on_stove)
    covered = n("pot", contains("soup"), lid, on_stove)
    return pot, (FunctionalUnit((n("stove", "off"), n("pot", contains("soup"))), Motion("pick-and-place"),
                                (n("stove", "off"), pot)),
                 FunctionalUnit((pot, n("spoon", "clean")), Motion("cook and stir"), (hot,)),
                 FunctionalUnit((hot, n("pot lid", "clean")), Motion("cover"),
                                (covered_hot, n("pot lid", make_state("on", "pot")))),
                 FunctionalUnit((covered, n("pot lid", make_state("on", "pot"))), Motion("uncover"),
                                (pot, n("pot lid", "dirty"))),
                 FunctionalUnit((pot, n("spoon", "clean")), Motion("stir"), (n("pot", "empty"),)))


def test_an_input_no_unit_makes_that_says_less_than_where_a_unit_left_the_object_is_read_as_that_node():
    _, units = _pot()
    found = stitches(Foon(units), range(5))
    assert [(s.unit, s.node, s.reads_as, s.dropped) for s in found] == [(3, units[3].inputs[0], units[2].outputs[0],
                                                                         ("hot",))]
    # not when a unit goes on from the cover's node (the object is not left there), nor when the input says a
    # word the made node does not
    taken = (*units, FunctionalUnit((units[2].outputs[0],), Motion("stir"), (n("pot", "empty"),)))
    assert not [s for s in stitches(Foon(taken), range(6)) if s.unit == 3]
    wet = (*units[:3], FunctionalUnit((n("pot", "wet", *units[3].inputs[0].states), units[3].inputs[1]),
                                      units[3].motion, units[3].outputs), units[4])
    assert not stitches(Foon(wet), range(5))


def test_a_node_that_says_more_is_read_only_when_its_maker_made_another_input_of_the_unit():
    # the uncover takes the lid the cover put on the pot: the cover's unit ties the two. A lid of its own (no
    # unit made it) leaves the pot another recipe's, as far as the unit says: not stitched
    _, units = _pot()
    own_lid = n("pot lid", make_state("on", "pot"), "clean")
    loose = FunctionalUnit((units[3].inputs[0], own_lid), units[3].motion, units[3].outputs)
    assert not stitches(Foon((*units[:3], loose, units[4])), range(5))


def test_counts_bring_an_object_back_to_a_node_a_later_unit_takes_through_the_units_that_lead_there():
    _, units = _pot()
    foon = Foon(units)
    kitchen = frozenset({units[0].inputs[0], units[0].inputs[1], n("spoon", "clean"), n("pot lid", "clean")})
    # the stir takes the pot the cook and stir left hot: the cover and the uncover (read as taking the cover's
    # pot) bring it back, instead of a second pot
    assert with_returns(foon, (0, 1, 4), range(5), kitchen, stitched=True) == (0, 1, 2, 3, 4)
    # a task that does not read the uncover's pot as the cover's (`instances`) has no way back
    assert with_returns(foon, (0, 1, 4), range(5), kitchen) == (0, 1, 4)
    # with no unit leading back, the plan stays (a second pot it is)
    assert with_returns(foon, (0, 1, 4), (0, 1, 4), kitchen) == (0, 1, 4)


def test_easy_tomato_soup_is_solved_and_replay_clean_with_one_pot_and_one_of_each_ingredient():
    outcome = clean_dish_plan(DATA / "0011-easy_tomato_soup.txt")
    assert any("add's blender jar lists refined sugar" in note for note in outcome.compiled.notes)
    # one pot comes back from the cover and uncover for the second cook and stir: one tomato, one add (2 of each
    # before, and a translation that did not end)
    assert sum(1 for x in outcome.task.instances if x.label == "tomato") == 1
    assert any("uncover takes pot (" in note and "drops hot" in note for note in outcome.compiled.notes)


def test_one_changers_shared_by_many_plans_finds_the_ways_back_each_finds_alone():
    # `instance_counts.derive_counts` hands one `changers` to every plan it puts ways back in: what it keeps from a
    # node must not depend on the plan (units already in it are no step), nor on `stitched`
    _, units = _pot()
    foon = Foon(units)
    kitchen = frozenset({units[0].inputs[0], units[0].inputs[1], n("spoon", "clean"), n("pot lid", "clean")})
    shared = changers(foon, range(5))
    calls = [((0, 1, 4), True), ((0, 1, 2, 4), True), ((0, 1, 4), False), ((0, 1, 3, 4), True), ((0, 1, 4), True)]
    found = [with_returns(foon, plan, range(5), kitchen, stitched=s, changing=shared) for plan, s in calls]
    assert found == [with_returns(foon, plan, range(5), kitchen, stitched=s) for plan, s in calls]
    # the first fills what it keeps from the pot's nodes, stitched; the third reads them unstitched (no way
    # back); the second and fourth have the cover or the uncover in the plan (no way back without it)
    assert found == [(0, 1, 2, 3, 4), (0, 1, 2, 4), (0, 1, 4), (0, 1, 3, 4), (0, 1, 2, 3, 4)]
