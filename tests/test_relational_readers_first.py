"""Readers first (`count_order.readers_first`): a unit that moves an object out of a node fires, in the plan the
counts unfold, after the units that only read that node, where nothing between needs it; the chocolate cake's
turn off no longer comes before the mix that needs the mixer on, and the mixer's chain is counted once."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.count_order import readers_first
from foon2pddl.pddl.instance_counts import derive_counts
from foon2pddl.pddl.relational_plan import count_roles, plan_unit

KITCHEN = frozenset({n("mixer", "off"), n("bowl", "empty"), n("bag", contains("flour")), n("flour", inside("bag")),
                     n("box", contains("sugar")), n("sugar", inside("box"))})
GOAL = n("bowl", contains("batter"), "detached")
DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def _units() -> tuple[FunctionalUnit, ...]:
    """The mixer turned on, flour and then sugar poured into the bowl, the mix with the mixer on, the mixer turned
    off (a round before the mix: it needs only the mixer on), the bowl detached from the stopped mixer."""
    on, stopped = n("mixer", "on"), n("mixer", "stopped")
    return (
        FunctionalUnit((n("mixer", "off"),), Motion("turn on"), (on,)),
        FunctionalUnit((n("bowl", "empty"), n("bag", contains("flour")), n("flour", inside("bag"))), Motion("pour"),
                       (n("bowl", contains("flour")), n("flour", inside("bowl")))),
        FunctionalUnit((n("bowl", contains("flour")), n("box", contains("sugar")), n("sugar", inside("box"))),
                       Motion("pour"), (n("bowl", contains("flour", "sugar")), n("sugar", inside("bowl")))),
        FunctionalUnit((on,), Motion("turn off"), (stopped,)),
        FunctionalUnit((on, n("bowl", contains("flour", "sugar")), n("flour", inside("bowl")),
                        n("sugar", inside("bowl"))), Motion("mix"),
                       (on, n("bowl", contains("batter")), n("batter", inside("bowl")))),
        FunctionalUnit((stopped, n("bowl", contains("batter"))), Motion("detach"), (GOAL,)),
    )


def _roles_of(unit):  # the relational reading of each unit alone
    return count_roles(plan_unit(unit, KITCHEN, frozenset(), frozenset(), frozenset(), frozenset(), frozenset()))


def _counted_small(name: str):
    """The relational task of a recipe file's (first) dish from its default kitchen, counted small as `plan` first
    plans it."""
    foon, _ = load([DATA / name])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    return compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational",
                        narrow=True)


def test_the_turn_off_moves_after_the_mix_that_reads_the_mixer_on():
    units = _units()
    assert readers_first(Foon(units), (0, 1, 3, 2, 4, 5), _roles_of) == (0, 1, 2, 4, 3, 5)


def test_one_mixer_when_the_mix_reads_it_on_before_it_is_turned_off():
    units = _units()
    # the fixpoint fires the turn off a round before the mix; unfolded in that order the mix needed a second mixer
    # on, and its turn on counted a second mixer
    counts = derive_counts(Foon(units), range(len(units)), KITCHEN, (GOAL,), roles_of=_roles_of, together=True,
                           stitched=True, reuse=True)
    assert counts.labels()["mixer"] == 1
    assert dict(counts.firings)[0] == 1
    outcome = clean_unit_plan(units, KITCHEN, GOAL)
    assert [x.label for x in outcome.task.instances].count("mixer") == 1


def test_the_reader_moves_before_when_a_unit_between_needs_the_mover():
    # the stopped mixer wiped (unit 6) before the detach takes it: the turn off cannot move after the mix, the mix moves before it
    wiped = n("mixer", "stopped", "wiped")
    units = (*_units()[:5], FunctionalUnit((wiped, n("bowl", contains("batter"))), Motion("detach"), (GOAL,)),
             FunctionalUnit((n("mixer", "stopped"),), Motion("wipe"), (wiped,)))
    assert readers_first(Foon(units), (0, 1, 2, 3, 6, 4, 5), _roles_of) == (0, 1, 2, 4, 3, 6, 5)
    # the second pour between makes what the mix takes too: neither moves
    assert readers_first(Foon(units), (0, 1, 3, 6, 2, 4, 5), _roles_of) == (0, 1, 3, 6, 2, 4, 5)


def test_the_chocolate_cakes_mixer_chain_is_counted_once():
    compiled = _counted_small("0058-chocolate_cake.txt")
    labels = [x.label for x in compiled.task.instances]
    # the turn off at 0058-chocolate_cake.txt:242 before the mix at :228 counted a second mixer on, and with it
    # every pour and sprinkle of the bowl the mixer holds again (50 objects in the problem; `instances` 43)
    assert labels.count("baking powder") == 1  # sprinkled out of its kitchen bowl whole, once (test_relational_taken_once)
    assert len(compiled.task.objects) <= 43


def test_the_fries_tray_comes_back_out_of_the_oven_after_the_bake():
    compiled = _counted_small("0035-oven-baked_sweet_potato_fries.txt")
    labels = [x.label for x in compiled.task.instances]
    # the last pick-and-place (0035-oven-baked_sweet_potato_fries.txt:224) takes `baking tray (contains {sweet
    # potato fries})`, which the put inside (:181) moves into the oven; the remove (:212) brings it back, taking
    # the oven the put inside leaves `with [baking tray]`, after the bake that reads the tray in the oven. Without
    # that way back the tray's whole chain was counted twice: two sweet potatoes peeled, two bags, three portions
    # of garlic powder (30 objects in the problem; `instances` 27)
    assert labels.count("sweet potato") == 1
    assert labels.count("garlic powder") == 1  # sprinkled out of its kitchen bowl whole, once (test_relational_taken_once)
    assert len(compiled.task.objects) <= 27


def test_of_the_orders_the_one_that_counts_fewest_is_kept():
    compiled = _counted_small("0018-barbecue-style_country_ribs.txt")
    labels = [x.label for x in compiled.task.instances]
    # readers first fires the remove the ribs' way back puts in (0018-barbecue-style_country_ribs.txt:197) after
    # the second cook, which leaves the oven `off`, so the second cook counted an oven of its own (11 objects in
    # the problem); FOON's own order counts one oven (10): of the orders, the one that counts fewest is kept
    assert labels.count("oven") == 1
    assert len(compiled.task.objects) <= 10
