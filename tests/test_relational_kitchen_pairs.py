"""A container's node and the node of what is in it, taken together, that no unit makes together: the kitchen's
(`pddl/kitchen_pairs.py`)."""

from __future__ import annotations

from collections.abc import Iterable

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal

# The greek salad dressing's pour (ACT-0085:29) takes `bowl (contains {garlic})` with `garlic (minced, in [bowl])`.
# On the universal FOON the tomato soup's pick-and-place (0011:65) makes the bowl, with the garlic peeled in it, and
# the garlic bread's add (0015:88) makes the minced garlic, in a bowl that lists the butter too: no unit makes the
# two together, and over objects no plan had the minced garlic in a bowl that lists garlic alone.
EMPTY, PEELED, MINCED = n("bowl", "empty"), n("garlic", "peeled"), n("garlic", "minced")
BOWL, IN_BOWL = n("bowl", contains("garlic")), n("garlic", "minced", inside("bowl"))
PLACE = FunctionalUnit((EMPTY, PEELED), Motion("pick-and-place"), (BOWL, n("garlic", "peeled", inside("bowl"))),
                       (Source("soup.txt", 65),))
BUTTER = n("butter", inside("packet"))
ADD = FunctionalUnit((EMPTY, MINCED, BUTTER), Motion("add"),
                     (n("bowl", contains("butter", "garlic")), IN_BOWL, n("butter", inside("bowl"))),
                     (Source("bread.txt", 88),))
CUP = n("measuring cup", "empty")
GOAL = n("garlic", "minced", inside("measuring cup"))
POUR = FunctionalUnit((CUP, BOWL, IN_BOWL), Motion("pour"),
                      (n("measuring cup", contains("garlic")), GOAL, n("bowl", "dirty")), (Source("dressing.txt", 29),))
KITCHEN = {EMPTY, PEELED, MINCED, BUTTER, CUP}


def _at_hand(notes: Iterable[str]) -> list[str]:
    """The notes that read a pair as the kitchen's."""
    return [x for x in notes if x.startswith("assumed at hand")]


def _plans_from_the_pair_at_hand(outcome, motions: list[str], notes: list[str]) -> None:
    """The plan is these steps, valid (the tree check takes the pair as the task reads it), and the pairs read at
    hand are these notes."""
    assert [s.unit.motion.label for s in outcome.trace.steps] == motions
    assert outcome.validation.ok
    assert _at_hand(outcome.compiled.notes) == notes


def test_a_pair_no_unit_makes_together_is_the_kitchens():
    outcome = clean_unit_plan((PLACE, ADD, POUR), KITCHEN, GOAL)
    _plans_from_the_pair_at_hand(outcome, ["pour"], [
        "assumed at hand: dressing.txt:29: pour takes bowl (contains {garlic}) with garlic (in [bowl], minced), "
        "which no unit makes together (pick-and-place at soup.txt:65 makes the bowl beside garlic (in [bowl], "
        "peeled); add at bread.txt:88 makes the garlic beside bowl (contains {butter, garlic})): read as the kitchen's"])


def test_a_pair_one_unit_makes_is_made():
    # a unit that makes both (the pour from the garlic press into the bowl) makes the pair: nothing is read
    press = n("garlic", "minced", inside("garlic press"))
    both = FunctionalUnit((EMPTY, press), Motion("pour"), (BOWL, IN_BOWL), (Source("bread.txt", 99),))
    outcome = clean_unit_plan((PLACE, ADD, both, POUR), KITCHEN | {press}, GOAL)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "pour"]
    assert not _at_hand(outcome.compiled.notes)


def test_a_pair_a_unit_may_finish_in_place_is_not_read():
    # the mince in the bowl turns the placed garlic into the pair's node without naming the bowl: the pair may be
    # made, so nothing is read (the pair stays made by units, as FOON's tree has it)
    mince = FunctionalUnit((n("garlic", "peeled", inside("bowl")), n("knife", "clean")), Motion("mince"),
                           (IN_BOWL,), (Source("soup.txt", 70),))
    compiled = compile_goal(Foon((PLACE, ADD, mince, POUR)), Kitchen(frozenset(KITCHEN | {n("knife", "clean")})),
                            Goal(GoalSpec("garlic"), (GOAL,)), "relational")
    assert not _at_hand(compiled.notes)
    assert BOWL not in compiled.placed and IN_BOWL not in compiled.placed


def test_a_pair_whose_maker_takes_the_other_is_not_read():
    # the homemade cheese pizza's remove (0082:466) takes the pick-and-place's `oven (contains {pizza pan}, on,
    # preheated)` with `pizza pan (contains {cheese pizza}, in [oven])`, which only the bake makes, from that very
    # oven (leaving it `oven (on)`): one oven, in FOON's words of two units (a stitch reads it), never at hand
    from foon2pddl.pddl.kitchen_pairs import kitchen_pairs

    oven, raw = n("oven", "on", "preheated"), n("pizza pan", contains("pizza dough"))
    full, raw_in = n("oven", contains("pizza pan"), "on", "preheated"), n("pizza pan", contains("pizza dough"), inside("oven"))
    baked = n("pizza pan", contains("cheese pizza"), inside("oven"))
    put = FunctionalUnit((oven, raw), Motion("pick-and-place"), (full, raw_in))
    bake = FunctionalUnit((full, raw_in), Motion("bake"), (baked, n("oven", "on")))
    remove = FunctionalUnit((full, baked), Motion("remove"), (n("pizza pan", contains("cheese pizza")),))
    assert kitchen_pairs(Foon((put, bake, remove)), frozenset({oven, raw})) == ()
    # the pair the dressing's pour takes is read
    assert [(p.box, p.held) for p in kitchen_pairs(Foon((PLACE, ADD, POUR)), frozenset(KITCHEN))] == [(BOWL, IN_BOWL)]


def test_a_task_that_takes_no_pair_reads_none():
    # on the universal FOON the black beans' pour takes `bowl (contains {garlic})` with the garlic chopped in it; read
    # for every task, the bowl of minced garlic at hand stood in for the bowl the plan fills (its tree check: input
    # not available). Only the units relevant to the goal are read.
    empty = FunctionalUnit((BOWL,), Motion("empty"), (n("bowl", "empty", "dirty"),), (Source("beans.txt", 61),))
    outcome = clean_unit_plan((PLACE, ADD, POUR, empty), KITCHEN, n("bowl", "empty", "dirty"))
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pick-and-place", "empty"]
    assert not _at_hand(outcome.compiled.notes)


# One node of the pair is the kitchen's, the other only units make, each beside another node of the pair's other
# label. On the universal FOON of the even-index subgraphs the apple turnover's sprinkle (0086:335) takes `bowl
# (contains {flour})`, which only the pancakes' pour (0031:15) makes, with the flour `powder` in it, and the
# kitchen's `flour (in [bowl])`; the tuna sandwich's pour (ACT-0024:32) takes the kitchen's `bowl (contains
# {mayonnaise, onion})` and `onion (chopped, in [bowl])`, which the black beans' pour (0059:24) makes in a bowl of
# onion alone. In each recipe's own kitchen both are at hand; on the merged FOON no plan had the pair.
FLOUR_BOWL, FLOUR_IN = n("bowl", contains("flour")), n("flour", inside("bowl"))
FLOUR_POUR = FunctionalUnit((EMPTY, n("flour", inside("bag"))), Motion("pour"),
                            (FLOUR_BOWL, n("flour", "powder", inside("bowl"))), (Source("pancakes.txt", 15),))
TABLE = n("table", "empty")
FLOURED = n("table", contains("flour"))
SPRINKLE = FunctionalUnit((TABLE, FLOUR_IN, FLOUR_BOWL), Motion("sprinkle"), (FLOURED,), (Source("pie.txt", 335),))
# another recipe takes the pancakes' flour on (the roux's pour, 0081:66): it is no end the sprinkle's flour stitches to
ROUX = FunctionalUnit((n("pot", "hot"), FLOUR_BOWL, n("flour", "powder", inside("bowl"))), Motion("pour"),
                      (n("pot", contains("flour"), "hot"), n("flour", "powder", inside("pot"))), (Source("roux.txt", 66),))


def test_a_pair_whose_held_node_is_the_kitchens_is_the_kitchens():
    # another recipe's kitchen bowl of butter and flour: the kitchen's flour in a bowl starts there
    kitchen = {EMPTY, n("flour", inside("bag")), TABLE, FLOUR_IN, n("bowl", contains("butter", "flour")),
               n("butter", inside("bowl"))}
    outcome = clean_unit_plan((FLOUR_POUR, ROUX, SPRINKLE), kitchen | {n("pot", "hot")}, FLOURED)
    _plans_from_the_pair_at_hand(outcome, ["sprinkle"], [
        "assumed at hand: pie.txt:335: sprinkle takes bowl (contains {flour}) with flour (in [bowl]), which no unit "
        "makes together (the flour is the kitchen's; pour at pancakes.txt:15 makes the bowl beside flour (in [bowl], "
        "powder)): read as the kitchen's"])


MAYO_BOWL, ONION_IN = n("bowl", contains("mayonnaise", "onion")), n("onion", "chopped", inside("bowl"))
KNIFE = n("knife", "clean")
CHOP = FunctionalUnit((n("onion", "peeled"), KNIFE), Motion("chop"), (n("onion", "chopped"),), (Source("beans.txt", 12),))
ONION_POUR = FunctionalUnit((EMPTY, n("onion", "chopped")), Motion("pour"), (n("bowl", contains("onion")), ONION_IN),
                            (Source("beans.txt", 24),))
TUNA_BOWL = n("bowl", contains("tuna"))
MIXED = n("bowl", contains("mayonnaise", "onion", "tuna"))
TUNA_POUR = FunctionalUnit((MAYO_BOWL, n("mayonnaise", inside("bowl")), ONION_IN, TUNA_BOWL), Motion("pour"),
                           (MIXED,), (Source("tuna.txt", 32),))


def test_a_pair_whose_container_is_the_kitchens_is_the_kitchens():
    kitchen = {EMPTY, n("onion", "peeled"), KNIFE, MAYO_BOWL, n("mayonnaise", inside("bowl")), TUNA_BOWL}
    outcome = clean_unit_plan((CHOP, ONION_POUR, TUNA_POUR), kitchen, MIXED)
    _plans_from_the_pair_at_hand(outcome, ["pour"], [
        "assumed at hand: tuna.txt:32: pour takes bowl (contains {mayonnaise, onion}) with onion (chopped, in [bowl]), "
        "which no unit makes together (the bowl is the kitchen's; pour at beans.txt:24 makes the onion beside bowl "
        "(contains {onion})): read as the kitchen's"])


def test_a_pair_of_two_kitchen_nodes_reads_nothing():
    from foon2pddl.pddl.kitchen_pairs import kitchen_pairs

    assert kitchen_pairs(Foon((SPRINKLE,)), frozenset({TABLE, FLOUR_IN, FLOUR_BOWL})) == ()


def test_a_units_pairs_are_read_once_per_network_object_and_kitchen(monkeypatch):
    # a trial's goals share one network object and a few kitchens, and their tasks hundreds of units: each unit's
    # pairs are read once per kitchen; another kitchen, or another network object with the same units, reads its own
    from foon2pddl.model.places import listed
    from foon2pddl.pddl import kitchen_pairs as module

    units = (FLOUR_POUR, ROUX, SPRINKLE, CHOP, ONION_POUR, TUNA_POUR)
    wide = frozenset({EMPTY, n("flour", inside("bag")), TABLE, FLOUR_IN, n("bowl", contains("butter", "flour")),
                      n("butter", inside("bowl")), n("pot", "hot"), n("onion", "peeled"), KNIFE, MAYO_BOWL,
                      n("mayonnaise", inside("bowl")), TUNA_BOWL})

    def pairs(foon, kitchen, takers=None):
        return [(p.taker, p.box, p.held) for p in module.kitchen_pairs(foon, kitchen, takers)]

    foon = Foon(units)
    assert pairs(foon, wide, (5,)) == [(TUNA_POUR, MAYO_BOWL, ONION_IN)]
    reads: list = []
    monkeypatch.setattr(module, "listed", lambda node: reads.append(node) or listed(node))
    both = [(SPRINKLE, FLOUR_BOWL, FLOUR_IN), (TUNA_POUR, MAYO_BOWL, ONION_IN)]
    assert pairs(foon, wide) == both and reads  # units 0-4 are read now
    reads.clear()
    assert pairs(foon, wide, (5, 2)) == both and not reads  # in unit order, each read before
    assert pairs(foon, wide - {MAYO_BOWL}) == [(SPRINKLE, FLOUR_BOWL, FLOUR_IN)] and reads
    reads.clear()
    assert pairs(Foon(units), wide - {FLOUR_IN}) == [(TUNA_POUR, MAYO_BOWL, ONION_IN)] and reads


def test_a_node_of_the_held_label_in_another_container_leaves_the_pair_at_hand():
    # REG and EXP trial 9 goal 29 (ACT-0024-tuna_sandwich.txt:32): another recipe's whole onion in a bowl does not
    # say the kitchen's bowl of mayonnaise and onion holds it, when another kitchen bowl lists onion
    kitchen = {EMPTY, n("onion", "peeled"), KNIFE, MAYO_BOWL, n("mayonnaise", inside("bowl")), TUNA_BOWL,
               n("onion", "whole", inside("bowl")), n("bowl", contains("onion"))}
    outcome = clean_unit_plan((CHOP, ONION_POUR, TUNA_POUR), kitchen, MIXED)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour"]


def test_a_node_of_the_held_label_beside_a_container_the_kitchen_does_not_fill_leaves_the_pair_at_hand():
    # the trial's own kitchen: its mayonnaise is in a jar, none in a bowl (the carrot salad's scoop, 0007:92, makes
    # it in a bowl of mayonnaise alone), so its bowl of mayonnaise and onion is no bowl whose contents the kitchen
    # places; the whole onion in some bowl is not said to be in it
    jar, mayo = n("jar", contains("mayonnaise")), n("mayonnaise", inside("jar"))
    scoop = FunctionalUnit((EMPTY, jar, mayo), Motion("scoop"), (n("bowl", contains("mayonnaise")),
                                                                 n("mayonnaise", inside("bowl"))),
                           (Source("salad.txt", 92),))
    units = (CHOP, ONION_POUR, scoop, TUNA_POUR)
    kitchen = {EMPTY, n("onion", "peeled"), KNIFE, MAYO_BOWL, jar, mayo, TUNA_BOWL, n("onion", "whole", inside("bowl"))}
    outcome = clean_unit_plan(units, kitchen, MIXED)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour"]
    # a bowl whose every listed label the kitchen places in a bowl, and the one bowl listing onion, holds the
    # whole onion: the chopped one is not read at hand in it
    from foon2pddl.pddl.kitchen_pairs import kitchen_pairs

    said = frozenset(kitchen | {n("mayonnaise", inside("bowl"))})
    assert [p.held for p in kitchen_pairs(Foon(units), said)] == []


def test_a_kitchen_container_whose_held_label_the_kitchen_places_in_several_states_holds_the_pair():
    # the universal FOON of the subgraphs of sorted index 2 modulo 3 (docs/pddl.md, Unseen universal FOONs): the
    # hamburger's sprinkle (0027:74) and the cilantro-lime rice's and gyoza's scrapes (0066:49, 0070:87) take the
    # kitchen's `bowl (contains {garlic})` with `garlic (minced, in [bowl])`, which only the garlic bread's add
    # (0015:88) makes, in a bowl of butter too. The kitchen has garlic chopped in a bowl (the ramen's pour takes it,
    # 0054:33) and peeled in a bowl (the caesar salad's pour, ACT-0080:29): it does not say which garlic its one bowl
    # of garlic holds, and the taker's words do. The three dishes were unsolvable at once.
    from foon2pddl.pddl.kitchen_pairs import kitchen_pairs

    chopped, pressed = n("garlic", "chopped", inside("bowl")), n("garlic", "minced", make_state("on", "garlic press"))
    press = n("garlic", "peeled", make_state("in", "garlic press"))
    units = (FunctionalUnit((press,), Motion("squeeze"), (pressed,), (Source("bread.txt", 76),)),
             FunctionalUnit((EMPTY, pressed, BUTTER), Motion("add"), ADD.outputs, (Source("bread.txt", 88),)), POUR)
    kitchen = {EMPTY, press, BUTTER, CUP, BOWL, chopped, n("garlic", "peeled", inside("bowl"))}
    assert [(p.taker, p.box, p.held) for p in kitchen_pairs(Foon(units), frozenset(kitchen))] == [
        (POUR, BOWL, IN_BOWL)]
    outcome = clean_unit_plan(units, kitchen, GOAL)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour"]
    # one garlic the kitchen places in a bowl is what its bowl of garlic holds (GEN's plate of whole peppers)
    assert kitchen_pairs(Foon(units), frozenset(kitchen - {chopped})) == ()


# 37275f2 read a pair of two made nodes whose container's only other maker makes it from that very node
# (`_moved_on`: the crayfish wrap on an unseen universal FOON); in the experiment's GEN network, trial 8, it read new
# pairs and gave these two goals plans the relational replay rejects (`water_and_ice_1 is in bowls_1, whose node
# 'bowls (empty)' lists nothing`, at ACT-0053-lentil_kofta-1.txt:150): the experiment's run at 74b6e53 failed with
# 2 invalid plans, so 37275f2 was reverted. Whatever reads pairs next must keep these goals free of invalid plans.
def test_no_pair_read_gives_the_gen_kofta_goals_a_plan_the_replay_rejects() -> None:
    from pathlib import Path

    from foon2pddl.experiment.protocol import Protocol
    from foon2pddl.experiment.worker import Batch, Job, draw_at, fingerprint, run_batch

    paths = (str((Path(__file__).parent / "data" / "foon-subgraphs").resolve()),)
    protocol = Protocol(10, 100, 0.9, 0, 3, similarity="cook", objects_per_item=1)  # the default experiment's
    trial = next(t for t in draw_at(paths, protocol, ()).trials if t.index == 8)
    assert [trial.goals[g - 1].describe() for g in (46, 57)] == [
        "kofta mix (contains {bulgur, lentil}, in [pot])", "paprika (ground, on [kofta])"]
    records = run_batch(Batch(trial, "gen", "fd-relational", (46, 57), ()), Job(paths, fingerprint(paths), protocol, 60.0))
    assert [str(r.status) for r in records if str(r.status) not in ("solved", "unsolvable")] == [], [
        r.reason for r in records]
    assert all(r.validated for r in records if str(r.status) == "solved")


# A maker of the container's node that moves the container on from the pair's own container node (out of the
# microwave the put inside took it into) leaves the pair only where it already was: no other way to the pair. On the
# universal FOON of 70 subgraphs drawn with seed 55 the crayfish wrap's spread (ACT-0077:12) takes `bowl (contains
# {butter})` with `butter (in [bowl], stick)`, which only the blueberry muffin's pick-and-place (ACT-0003:18) makes,
# in a bowl of sugar too; the garlic bread's pick-and-place (0016:15) makes the bowl with the butter not `stick`,
# and its remove (0016:62) takes the bowl out of the microwave, naming no butter: the pair was not read, and the wrap
# was out of holder reach.
STICK_IN, BUTTER_BOWL = n("butter", "stick", inside("bowl")), n("bowl", contains("butter"))
PACKET_STICK, SUGAR_BOWL, OFF = n("butter", "stick", inside("packet")), n("bowl", contains("sugar")), n("microwave", "off")
IN_OVEN, HOLDING = n("bowl", contains("butter"), inside("microwave")), n("microwave", contains("bowl"), "off")
MUFFIN_PLACE = FunctionalUnit((SUGAR_BOWL, PACKET_STICK), Motion("pick-and-place"),
                              (n("bowl", contains("butter", "sugar")), STICK_IN), (Source("muffin.txt", 18),))
BREAD_PLACE = FunctionalUnit((EMPTY, PACKET_STICK), Motion("pick-and-place"),
                             (BUTTER_BOWL, n("butter", inside("bowl"))), (Source("bread.txt", 15),))
PUT_INSIDE = FunctionalUnit((BUTTER_BOWL, OFF), Motion("put inside"), (IN_OVEN, HOLDING), (Source("bread.txt", 26),))
REMOVE = FunctionalUnit((HOLDING, IN_OVEN), Motion("remove"), (OFF, BUTTER_BOWL), (Source("bread.txt", 62),))
BUTTERED = n("tortilla", "buttered")
SPREAD = FunctionalUnit((n("tortilla", "plain"), BUTTER_BOWL, STICK_IN, KNIFE), Motion("spread"), (BUTTERED,),
                        (Source("wrap.txt", 12),))


def test_a_container_moved_on_from_the_pairs_own_node_makes_no_other_way_to_it():
    units = (MUFFIN_PLACE, BREAD_PLACE, PUT_INSIDE, REMOVE, SPREAD)
    outcome = clean_unit_plan(units, {EMPTY, SUGAR_BOWL, PACKET_STICK, OFF, n("tortilla", "plain"), KNIFE}, BUTTERED)
    _plans_from_the_pair_at_hand(outcome, ["spread"], [
        "assumed at hand: wrap.txt:12: spread takes bowl (contains {butter}) with butter (in [bowl], stick), which no "
        "unit makes together (pick-and-place at bread.txt:15 makes the bowl beside butter (in [bowl]); pick-and-place "
        "at muffin.txt:18 makes the butter beside bowl (contains {butter, sugar})): read as the kitchen's"])


# The cycle is no other way only between two made nodes: with the held node the kitchen's, the pair stays unread.
# On the shared universal FOON the french toast's pour (0037:63) and the italian sausage's (0041:115) take `bowl
# (contains {butter})` with the kitchen's `butter (cubed, in [bowl])`; every maker of the bowl but the garlic bread's
# remove (0016:62) leaves another butter beside it. Read as the kitchen's, its bowl of butter was taken for the
# turkey sandwich's spread (0049:25) and the garlic bread's add (0016:74), which take that bowl node with other
# butter: FOON's plan, unfolded for the counts, fired the pick-and-place (0016:15) once, not twice, and each task
# held one object more (the sandwich 14 -> 15, the garlic bread with parsley 19 -> 20), none of them needing the pour.
CUBED, SKILLET = n("butter", "cubed", inside("bowl")), n("skillet", "heated")
TOAST_POUR = FunctionalUnit((BUTTER_BOWL, CUBED, SKILLET), Motion("pour"),
                            (n("butter", "cubed", inside("pan")), n("skillet", contains("butter"))),
                            (Source("toast.txt", 63),))
HEAT = FunctionalUnit((IN_OVEN, n("butter", inside("bowl")), HOLDING), Motion("heat"),
                      (n("butter", "softened", inside("bowl")), HOLDING), (Source("bread.txt", 46),))


def test_a_container_moved_on_is_no_other_way_to_a_pair_of_a_kitchen_node():
    from foon2pddl.pddl.kitchen_pairs import kitchen_pairs
    units = (BREAD_PLACE, PUT_INSIDE, HEAT, REMOVE, TOAST_POUR)  # no stitch: the heat moves the butter on
    assert kitchen_pairs(Foon(units), frozenset({EMPTY, PACKET_STICK, OFF, CUBED, SKILLET})) == ()
    # both made (the butter of the pair from another unit's pick-and-place): the cycle is set aside, the pair read
    made = FunctionalUnit((EMPTY, n("butter", "cubed")), Motion("pick-and-place"),
                          (n("bowl", contains("butter", "sugar")), CUBED), (Source("muffin.txt", 18),))
    assert [(p.taker, p.held) for p in kitchen_pairs(Foon((*units, made)), frozenset(
        {EMPTY, PACKET_STICK, OFF, n("butter", "cubed"), SKILLET}))] == [(TOAST_POUR, CUBED)]
