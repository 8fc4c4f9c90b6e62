"""Counts by what is in a kitchen node at once (`count_reuse`): a measuring cup a pour leaves `empty` again
serves a later unit of the plan that takes `measuring cup (empty)`; no second cup is counted."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import alone_roles, clean_unit_plan, rejected_dish_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.pddl.instance_counts import derive_counts

FULL, EMPTY = n("measuring cup", contains("flour")), n("measuring cup", "empty")
KITCHEN = frozenset({FULL, n("flour", inside("measuring cup")), n("bowl", "empty"), EMPTY,
                     n("bag", contains("sugar")), n("sugar", inside("bag")), n("sieve")})
GOAL = n("bowl", contains("flour", "sugar"))
DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def _units(sifted: bool) -> tuple[FunctionalUnit, ...]:
    """The flour poured out of its cup into the bowl (the cup ends `empty`), sugar scooped from the bag into an
    empty cup, and poured from it into the bowl. `sifted`: the flour is sifted in its cup first, so its pour
    fires a round later, after the scoop has taken an empty cup."""
    flour_in = n("flour", inside("measuring cup"), *(("sifted",) if sifted else ()))
    flour = FunctionalUnit((FULL, flour_in, n("bowl", "empty")), Motion("pour"),
                           (EMPTY, n("flour", inside("bowl")), n("bowl", contains("flour"))))
    sift = FunctionalUnit((n("flour", inside("measuring cup")), n("sieve")), Motion("sift"), (flour_in,))
    scoop = FunctionalUnit((n("bag", contains("sugar")), n("sugar", inside("bag")), EMPTY), Motion("scoop"),
                           (n("bag", contains("sugar")), n("sugar", inside("measuring cup")),
                            n("measuring cup", contains("sugar"))))
    sugar = FunctionalUnit((n("measuring cup", contains("sugar")), n("sugar", inside("measuring cup")),
                            n("bowl", contains("flour"))), Motion("pour"),
                           (EMPTY, n("sugar", inside("bowl")), GOAL))
    return (flour, scoop, sugar, sift) if sifted else (flour, scoop, sugar)


def _cups(units, reuse: bool) -> int:
    counts = derive_counts(Foon(units), range(len(units)), KITCHEN, (GOAL,), roles_of=alone_roles(KITCHEN),
                           together=True, stitched=True, reuse=reuse)
    return counts.labels()["measuring cup"]


def test_a_cup_emptied_back_to_a_kitchen_node_is_taken_there_again():
    units = _units(sifted=False)
    # the unfolding counts one cup per taking of `measuring cup (empty)` and one for the flour: two; the pour of
    # the flour leaves its cup empty before the scoop takes an empty cup, so one cup does it all
    assert _cups(units, reuse=False) == 2
    assert _cups(units, reuse=True) == 1
    outcome = clean_unit_plan(units, KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("measuring cup") == 1


def test_a_cup_taken_before_any_is_emptied_waits_for_the_emptied_one():
    units = _units(sifted=True)  # the fixpoint fires the scoop first: no cup is empty yet but the kitchen's
    # takers last (`count_order.takers_last`): nothing before the flour's pour needs the sugar's cup, so the scoop
    # fires after it, in the cup it left empty (two cups before)
    assert _cups(units, reuse=True) == 1
    outcome = clean_unit_plan(units, KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("measuring cup") == 1


def test_an_object_left_in_a_kitchen_node_that_names_its_holder_does_not_stand_for_the_kitchens():
    # the caesar salad's pour (ACT-0080-caesar_salad.txt:29) takes the kitchen's `bowl (contains {garlic})` with
    # `garlic (in [bowl], peeled)`; the counted plan leaves another garlic in that node earlier, in a bowl of its
    # own: taken for the kitchen's, no garlic started in the pour's bowl and no state applied the pour. The replay
    # stops at the first step off FOON's nodes: the only step it rejects is the last mix (`:367`, FOON's salad mix
    # left in another bowl than the salad's: issue 21), so the pour at `:29` replays right
    rejected_dish_plan(DATA / "ACT-0080-caesar_salad.txt", "367")


def test_the_count_note_says_how_many_takings_an_object_left_there_again_serves():
    from foon2pddl.pddl.count_reasons import count_reasons
    from foon2pddl.pddl.instance_counts import InstanceCounts

    units = _units(sifted=False)  # the scoop takes an empty cup; fired 3 times on 2 cups, one came back
    counts = InstanceCounts(((EMPTY, 2),), (), ((1, 3),), reused=True)
    assert count_reasons(Foon(units), counts, KITCHEN) == (
        "2 x measuring cup (empty): FOON's plan, unfolded, takes one out of that state each time it fires scoop x3; "
        "1 of those takings use one a unit put back in it",)
    # without the reuse and with no count given, fewer objects than takings are the encoding's own count
    stated = InstanceCounts(((EMPTY, 2),), (), ((1, 3),))
    assert count_reasons(Foon(units), stated, KITCHEN) == (
        "2 x measuring cup (empty): 2 counted by the relational encoding itself (no count was given), where FOON's "
        "unfolded plan takes 3",)


def test_the_count_note_tells_a_foon_exp_copy_from_its_original():
    """Stop 56's newcomer pass: `plan SUBGRAPHS --goal "greek salad" --network exp` said `4 x cutting board
    (empty): ... fires pick-and-place at 0026-cheddar_frittata.txt:1 x2, pick-and-place at ACT-0034-greek_salad.txt:83,
    pick-and-place at 0026-cheddar_frittata.txt:1`: a FOON-EXP copy keeps its original's file:line, so one place
    read as two counts. A copy says what it was expanded from, as the PDDL's action comments do."""
    from dataclasses import replace

    from foon2pddl.model.foon import Source
    from foon2pddl.pddl.count_reasons import count_reasons
    from foon2pddl.pddl.instance_counts import InstanceCounts

    scoop = _units(sifted=False)[1]
    original = replace(scoop, sources=(Source("0026-cheddar_frittata.txt", 1),))
    copy = replace(original, sources=(Source("0026-cheddar_frittata.txt", 1, expanded_from="sugar",
                                             expanded_to="salt"),))
    counts = InstanceCounts(((EMPTY, 2),), (), ((0, 1), (1, 1)))
    assert count_reasons(Foon((original, copy)), counts, KITCHEN) == (
        "2 x measuring cup (empty): FOON's plan, unfolded, takes one out of that state each time it fires scoop at "
        "0026-cheddar_frittata.txt:1, scoop at 0026-cheddar_frittata.txt:1 (expanded from sugar), and no unit puts "
        "one back",)
