"""The `relational` encoding's stitches: a unit's input no unit makes, read as the node the plan left it in."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_dish_plan, clean_plan

from foon2pddl.api.inputs import load_kitchen, load_network, resolve_goal
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.input_stitch import stitches, with_stitches
from foon2pddl.pddl.instance_counts import InstanceCounts
from foon2pddl.pddl.prune import restoring_units
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

DATA = Path(__file__).parent / "data" / "foon-subgraphs"

# roasted brussel sprouts: the add puts `brussel sprout (peeled, in [plastic bag])` into the bag, and the shake
# that takes the bag next takes `brussel sprout (peeled, uncooked, in [plastic bag])`, which no unit makes
EMPTY_BAG, BOARD_SPROUT = n("plastic bag", "empty"), n("brussel sprout", "peeled", "uncooked")
FULL_BAG = n("plastic bag", contains("brussel sprout", "salt"))
ADDED, SALT = n("brussel sprout", "peeled", inside("plastic bag")), n("salt", "granulated", inside("plastic bag"))
ADD = FunctionalUnit((EMPTY_BAG, BOARD_SPROUT, n("salt", "granulated")), Motion("add"), (FULL_BAG, ADDED, SALT))
TAKEN = n("brussel sprout", "peeled", "uncooked", inside("plastic bag"))
SHAKEN = n("brussel sprout", "seasoned", inside("plastic bag"))
SHAKE = FunctionalUnit((FULL_BAG, TAKEN, SALT), Motion("shake"), (n("plastic bag", contains("brussel sprout")), SHAKEN))


def test_an_input_no_unit_makes_is_read_as_the_node_the_filled_container_holds():
    (found,) = stitches(Foon((ADD, SHAKE)), (0, 1))
    assert (found.unit, found.node, found.reads_as) == (1, TAKEN, ADDED)
    assert found.assumed == ("uncooked",) and found.dropped == ()
    assert found.describe().startswith("shake takes brussel sprout") and "assumes uncooked" in found.describe()


def test_a_stitch_adds_a_unit_and_keeps_foons_own():
    net = Foon((ADD, SHAKE))
    st = with_stitches(net, lambda x: tuple(range(len(x.units))))
    assert st.units == (0, 1, 2) and st.origin == {2: 1} and st.found == stitches(net, (0, 1))
    assert st.foon.units[:2] == net.units and st.foon.units[2].inputs == (FULL_BAG, ADDED, SALT)
    assert st.through.units == (ADD, st.foon.units[2])  # the stitched unit in FOON's place


def test_a_stitched_plan_makes_the_object_and_passes_the_replay():
    net = Foon((ADD, SHAKE))
    kitchen = default_kitchen(net)
    assert TAKEN in kitchen.nodes  # FOON's semantics takes it from the kitchen: another sprout in another bag
    outcome = plan(net, kitchen, Goal(GoalSpec("brussel sprout"), (SHAKEN,)), "relational")
    assert outcome.status == "solved", outcome.message
    assert [s.unit for s in outcome.trace.steps] == [ADD, SHAKE]  # the tree shows FOON's units
    report = replay(outcome.trace)
    assert report.ok, [d.describe() for d in report.disagreements]
    shaken = outcome.trace.steps[1]
    sprout = next(b for b in shaken.bindings if b.before is not None and b.before.label == "brussel sprout")
    assert sprout.before == ADDED  # the sprout the add put in the bag, not one from the kitchen
    assert any("shake takes brussel sprout" in x and "assumes uncooked" in x for x in outcome.compiled.notes)


def test_no_stitch_reads_a_state_against_its_opposite():
    # chicken `(cooked, on [plate])` is made; a unit taking `chicken (uncooked, on [plate])` is not given it
    plate = n("plate", contains("chicken"))
    cooked = n("chicken", "cooked", "seasoned", inside("plate"))
    cook = FunctionalUnit((n("plate", "empty"), n("chicken", "raw")), Motion("cook"), (plate, cooked))
    raw = n("chicken", "uncooked", inside("plate"))
    grind = FunctionalUnit((plate, raw), Motion("grind"), (n("plate", "empty"), n("chicken", "ground")))
    assert stitches(Foon((cook, grind)), (0, 1)) == ()


def test_a_made_object_changed_later_is_not_read_for_an_earlier_node():
    # the pizza is topped after it is baked: the pick-and-place's pizza is the topped one, though the unit that
    # made the paper it lies on is the bake
    paper = n("parchment paper", contains("pizza"))
    baked = n("pizza", "baked", inside("parchment paper"))
    bake = FunctionalUnit((n("parchment paper", contains("dough")), n("dough", inside("parchment paper"))),
                          Motion("bake"), (paper, baked))
    topped = n("pizza", "baked", "topped", inside("parchment paper"))
    top = FunctionalUnit((baked, n("parsley", "chopped")), Motion("sprinkle"), (topped,))
    wanted = n("pizza", "baked", "hot", "topped", inside("parchment paper"))
    take = FunctionalUnit((paper, wanted), Motion("pick-and-place"), (n("pizza", "baked", "hot", "topped"),))
    (found,) = stitches(Foon((bake, top, take)), (0, 1, 2))
    assert found.reads_as == topped and found.assumed == ("hot",)
    # FOON's own plan takes the topped pizza from the kitchen and needs no sprinkle; the stitched one does
    net = Foon((bake, top, take))
    goal = n("pizza", "baked", "hot", "topped")

    def relevant(x: Foon) -> tuple[int, ...]:
        return restoring_units(x, default_kitchen(net).nodes, (goal,))

    st = with_stitches(net, relevant)
    assert 1 not in st.own and 1 in st.needed and st.units == (0, 1, 2, 3) and st.origin == {3: 2}


def test_roasted_brussel_sprouts_solve_replay_clean_with_the_stitch_reported():
    outcome = clean_dish_plan(DATA / "0036-roasted_brussels_sprouts.txt")
    assert any("0036-roasted_brussels_sprouts.txt:135: shake" in x and "assumes uncooked" in x
               for x in outcome.compiled.notes)


def test_a_kitchen_reading_still_solves_when_the_made_node_cannot_be_made():
    # the chocolate brownie: FOON's chain to the brownie on the board is broken elsewhere, and the cut takes the
    # brownie from the kitchen as FOON's semantics does; the stitch is one more way, not a rewrite
    board = n("cutting board", contains("brownie"))
    made = n("brownie", "baked", contains("flour"), inside("cutting board"))
    broken = FunctionalUnit((n("brownie batter", "never made"), n("cutting board", "empty")), Motion("bake"),
                            (board, made))
    loose = n("brownie", "baked", inside("cutting board"))
    cut = FunctionalUnit((loose, board), Motion("cut"), (n("brownie", "divided"), n("cutting board", "dirty")))
    net = Foon((broken, cut))
    assert len(stitches(net, (0, 1))) == 1
    kitchen = Kitchen(frozenset({loose, board, n("cutting board", "empty")}))
    outcome = plan(net, kitchen, Goal(GoalSpec("brownie"), (n("brownie", "divided"),)), "relational")
    assert outcome.status == "solved", outcome.message


def test_a_stitch_may_assume_more_items_of_a_list_but_never_one_list_for_another():
    # scrambled eggs: the cook leaves `omelette (contains {bacon}, cooked, in [pan])`; the pour takes the omelette
    # that lists the egg mixture, onion and cheese it was spread from as well
    pan = n("cooking pan", contains("omelette"))
    cooked = n("omelette", contains("bacon"), "cooked", inside("cooking pan"))
    cook = FunctionalUnit((n("cooking pan", contains("egg mixture")), n("egg mixture", inside("cooking pan"))),
                          Motion("cook"), (pan, cooked))
    full = n("omelette", contains("bacon", "cheese", "egg mixture", "onion"), "cooked", inside("cooking pan"))
    pour = FunctionalUnit((pan, full, n("plate", "empty")), Motion("pour"), (n("plate", contains("omelette")),))
    (found,) = stitches(Foon((cook, pour)), (0, 1))
    assert found.reads_as == cooked and found.assumed == ("contains {cheese, egg mixture, onion}",)
    # the buckeyes' bowl: `contains {chocolate}` is not the melted `contains {chocolate chip}`
    other = n("omelette", contains("cheese"), "cooked", inside("cooking pan"))
    swap = FunctionalUnit((pan, other, n("plate", "empty")), Motion("pour"), (n("plate", contains("omelette")),))
    assert stitches(Foon((cook, swap)), (0, 1)) == ()


def test_objects_are_counted_for_foons_plan_and_for_the_stitched_one():
    a = InstanceCounts(tuple(sorted(((BOARD_SPROUT, 1), (TAKEN, 1)))), (("plastic bag", 1),), ((1, 1),), (1,))
    b = InstanceCounts(((BOARD_SPROUT, 2),), (("plastic bag", 1), ("salt", 1)), ((0, 2),), (0, 0))
    wide = a.widest(b)
    assert dict(wide.at_node) == {BOARD_SPROUT: 2, TAKEN: 1}
    assert dict(wide.unmade) == {"plastic bag": 1, "salt": 1}
    assert wide.firings == a.firings and wide.unfolded == ()
    assert a.widest(a) == a


def test_scrambled_eggs_solve_replay_clean_through_the_cooked_omelette():
    # the pour takes the omelette the cook leaves (its list read as the cook's); FOON's own plan makes no bacon
    # (it takes that omelette from the kitchen), so the objects counted for it alone had none for the sprinkle
    outcome = clean_dish_plan(DATA / "0050-scrambled_eggs_with_bacon-cheese.txt")
    assert any(":288: pour takes omelette" in x and "assumes contains {cheese, egg mixture, onion}" in x
               for x in outcome.compiled.notes)


def test_a_made_node_taken_with_what_only_a_later_unit_makes_is_read_as_the_node_that_unit_leaves():
    # homemade cheese pizza: the bake takes `oven (contains {pizza pan}, on, preheated)` and leaves `oven (on)`;
    # the remove takes that oven node again, with `pizza pan (contains {cheese pizza}, in [oven])`, which only
    # the bake makes: the oven it finds is the one the bake left (a plan through FOON's node puts a second pizza
    # into the oven to remove the first; 0082 below)
    on_pan = make_state("on", "pizza pan")
    hot, full = n("oven", "on", "preheated"), n("oven", contains("pizza pan"), "on", "preheated")
    raw, dough = n("pizza pan", contains("pizza dough"), make_state("on", "surface")), n("pizza dough", on_pan)
    put = FunctionalUnit((hot, dough, raw), Motion("pick-and-place"),
                         (full, n("pizza pan", contains("pizza dough"), inside("oven"))))
    baked = n("pizza pan", contains("cheese pizza"), inside("oven"))
    bake = FunctionalUnit((full, dough, n("pizza pan", contains("pizza dough"), inside("oven"))), Motion("bake"),
                          (n("cheese pizza", on_pan), baked, n("oven", "on")))
    remove = FunctionalUnit((full, n("cheese pizza", on_pan), baked), Motion("remove"),
                            (n("oven", "off"), n("pizza pan", contains("cheese pizza"))))
    found = [s for s in stitches(Foon((put, bake, remove)), range(3)) if s.unit == 2]  # (the put's: an appliance's)
    assert [(s.unit, s.node, s.reads_as) for s in found] == [(2, full, n("oven", "on"))]
    assert found[0].describe() == ("remove takes oven (contains {pizza pan}, on, preheated), with what only the bake "
                                   "makes, as oven (on), which the bake leaves: assumes preheated, contains {pizza pan}")
    # not when another unit makes the pan in the oven without taking that oven node
    other = FunctionalUnit((n("oven", "on"), n("pizza pan", contains("cheese pizza"))), Motion("put inside"),
                           (baked,))
    assert [s.unit for s in stitches(Foon((put, bake, remove, other)), range(4)) if s.unit == 2] == []


def test_homemade_cheese_pizza_solves_replay_clean_with_its_two_readings_reported():
    outcome = clean_dish_plan(DATA / "0082-homemade_cheese_pizza.txt")
    notes = "\n".join(outcome.compiled.notes)
    assert "0082-homemade_cheese_pizza.txt:466: remove takes oven (contains {pizza pan}, on, preheated), with" in notes
    assert ("0082-homemade_cheese_pizza.txt:187: the kitchen's bowl (contains {pizza dough}, wrapped {plastic wrap}) "
            "is read as bowl (contains {pizza dough}, covered)") in notes
    assert [s.unit.motion.label for s in outcome.trace.steps].count("unwrap") == 1


def test_a_made_container_whose_unit_leaves_it_listing_more_than_it_brings_is_read_as_the_one_holding_that():
    # best black beans: the salt's sprinkle takes `pot (contains {black bean})` and leaves it listing cayenne
    # pepper too, which no object of the unit is; the sprinkle before it takes that pot node and puts the cayenne
    # in: the pot the salt goes into is that one (through FOON's node, two units move one pot to two nodes that
    # the stir needs together, and no plan exists)
    pot, bean = n("pot", contains("black bean")), n("black bean", inside("pot"))
    hot = n("pot", contains("black bean", "cayenne pepper"))
    cayenne = FunctionalUnit((pot, bean, n("bowl", contains("cayenne pepper")), n("cayenne pepper", inside("bowl"))),
                             Motion("sprinkle"), (hot, n("cayenne pepper", inside("pot"))))
    salted = n("pot", contains("black bean", "cayenne pepper", "salt"))
    salt = FunctionalUnit((pot, n("salt", "granulated")), Motion("sprinkle"), (salted, n("salt", inside("pot"))))
    pour = FunctionalUnit((n("pot", "empty"), n("can", contains("black bean")), n("black bean", inside("can"))),
                          Motion("pour"), (pot, bean))
    found = stitches(Foon((pour, cayenne, salt)), range(3))
    assert [(s.unit, s.node, s.reads_as) for s in found] == [(2, pot, hot)]
    assert found[0].describe() == ("sprinkle takes pot (contains {black bean}) as pot (contains {black bean, cayenne "
                                   "pepper}), which the sprinkle taking that node leaves: its output lists cayenne "
                                   "pepper too, which no object of the unit is")
    # not when the unit brings what its output lists
    brought = FunctionalUnit((pot, n("salt", "granulated"), n("cayenne pepper")), Motion("sprinkle"),
                             (salted, n("salt", inside("pot"))))
    assert stitches(Foon((pour, cayenne, brought)), range(3)) == ()


def test_best_black_beans_solve_replay_clean_with_the_salt_in_the_pot_of_cayenne():
    outcome = clean_dish_plan(DATA / "0059-best_black_beans.txt")
    assert any("0059-best_black_beans.txt:234: sprinkle takes pot (contains {black bean, cilantro, garlic, onion}, on "
               "[stove]) as pot (contains {black bean, cayenne pepper, cilantro, garlic, onion}, on [stove])" in x
               for x in outcome.compiled.notes)


def test_chocolate_chip_muffins_bake_the_pan_the_put_inside_left_in_the_oven():
    # the bake takes `muffin pan (contains {muffin batter})`, the scoop's node, with `oven (on, with [pan])`, which
    # only the put inside makes, and that leaves the pan `in [oven]`
    outcome = clean_dish_plan(DATA / "ACT-0009-chocolate_chip_muffin.txt")
    assert any("ACT-0009-chocolate_chip_muffin.txt:289: bake takes muffin pan (contains {muffin batter}), with what "
               "only the put inside makes, as muffin pan (contains {muffin batter}, in [oven])" in x
               for x in outcome.compiled.notes)
    assert [s.unit.motion.label for s in outcome.trace.steps][-2:] == ["put inside", "bake"]


def test_no_stitch_reads_an_input_the_unit_filling_its_container_took_itself():
    # grilled cheese (0012, lines 34-65) on the universal FOON: the pour puts the kitchen's `mustard (ground, in
    # [bowl])` into the bowl of cheddar, and the mix takes that node again with the bowl the pour leaves. The
    # potato salad's pour (another recipe) makes `mustard (in [bowl])`, the only other mustard in a bowl; read as
    # it, the plan through the stitches ran through the potato salad, and the task had 142 objects instead of 59.
    # The pour put that very object there (it took the node): the relational reading moves it, no stitch.
    ground = n("mustard", "ground", inside("bowl"))
    other = FunctionalUnit((n("jar", contains("mustard")), n("mustard", inside("jar")), n("bowl", "empty")),
                           Motion("pour"), (n("bowl", contains("mustard")), n("mustard", inside("bowl"))))
    both = n("bowl", contains("cheddar", "mustard"))
    pour = FunctionalUnit((n("bowl", contains("cheddar")), ground), Motion("pour"), (both,))
    mix = FunctionalUnit((both, ground, n("cheddar", inside("bowl"))), Motion("mix"),
                         (n("bowl", contains("cheese")), n("cheese", inside("bowl"))))
    assert stitches(Foon((other, pour, mix)), range(3)) == ()
    # the same mix after a pour that did not take that node: the other mustard in a bowl is the only candidate
    blind = FunctionalUnit((n("bowl", contains("cheddar")), n("mustard", "ground")), Motion("pour"), (both,))
    assert [(s.node, s.reads_as) for s in stitches(Foon((other, blind, mix)), range(3))] == [
        (ground, n("mustard", inside("bowl")))]


def test_of_several_units_making_the_container_the_stitch_reads_the_one_whose_node_the_input_only_adds_to():
    # the universal FOON's omelettes (0050:288 among 0042, 0063, 0064's): four cooks each leave `cooking pan
    # (contains {omelette})`, each with an omelette of its own; the pour takes the omelette listing bacon, cheese,
    # egg mixture and onion, which only the cook leaving `omelette (contains {bacon}, ...)` is read as (the others
    # list what the input does not say: a list for another). Before, the four were ambiguous and nothing stitched.
    pan = n("cooking pan", contains("omelette"))
    raw = n("cooking pan", contains("egg mixture"))

    def cook(*items: str) -> FunctionalUnit:
        return FunctionalUnit((raw, n("egg mixture", inside("cooking pan"))), Motion("cook"),
                              (pan, n("omelette", contains(*items), "cooked", inside("cooking pan"))))

    ours, others = cook("bacon"), [cook("black pepper", "salt"), cook("milk", "salt")]
    full = n("omelette", contains("bacon", "cheese", "egg mixture", "onion"), "cooked", inside("cooking pan"))
    pour = FunctionalUnit((pan, full, n("plate", "empty")), Motion("pour"), (n("plate", contains("omelette")),))
    net = Foon((*others, ours, pour))
    assert [(s.unit, s.reads_as) for s in stitches(net, range(4))] == [(3, ours.outputs[1])]
    # two such candidates stay ambiguous
    twin = cook("bacon", "cheese")
    assert stitches(Foon((*others, ours, twin, pour)), range(5)) == ()


# the bag with its spoon: the add and the shake each dirty a clean spoon; without the sprout the shake takes in the
# kitchen, FOON's own plan is none, and the plan through the stitch is the only one (newcomer60: the universal
# ramen in its base kitchen, `plan`'s default on a merged network)
CLEAN, DIRTY = n("spoon", "clean"), n("spoon", "dirty")
SPOONED = Foon((FunctionalUnit((*ADD.inputs, CLEAN), ADD.motion, (*ADD.outputs, DIRTY)),
                FunctionalUnit((*SHAKE.inputs, CLEAN), SHAKE.motion, (*SHAKE.outputs, DIRTY))))
NO_TAKEN = Kitchen(frozenset({EMPTY_BAG, BOARD_SPROUT, n("salt", "granulated"), CLEAN}))


def test_the_objects_notes_name_the_plan_through_the_stitches_when_foons_own_is_none():
    # the two spoons are the plan through the stitch's, where the notes said "2 given, where FOON's unfolded plan
    # takes 0" (the ramen's "8 x bowl (empty): 8 given")
    wide = compile_goal(SPOONED, NO_TAKEN, Goal(GoalSpec("brussel sprout"), (SHAKEN,)), "relational")
    (spoons,) = [x for x in wide.notes if x.startswith("objects: 2 x spoon (clean)")]
    assert "FOON's plan through its stitched units, unfolded, takes one out of that state each time it fires" in spoons
    assert "fires add, shake, and no unit puts one back" in spoons and "given" not in spoons, spoons


def test_a_small_count_of_no_objects_is_no_count():
    # counted small from FOON's own plan alone, which is none: no objects, a task the planner proves unsolvable, and
    # `plan` said "the 0 objects counted small gave no valid plan" before it planned the wide task; the plan through
    # the stitches alone is the small count, here as many objects as the wide one (the universal ramen: 65 objects
    # where the wide count has 73)
    outcome = clean_plan(SPOONED, NO_TAKEN, Goal(GoalSpec("brussel sprout"), (SHAKEN,)))
    notes = (*outcome.compiled.notes, *outcome.decoded.notes)
    assert not any("counted small" in x for x in notes), notes


def test_where_foons_own_plan_is_none_the_small_count_is_the_plan_through_the_stitches():
    # the ramen of the universal FOON in its base kitchen (`plan`'s default there): no plan of FOON's own reaches it
    # (`retrieve` says unreachable), the plan through the scoop's stitch does; counted small from FOON's own plan it
    # had no objects, and `plan` planned the wide count's 73 objects (34 units) where this one has 65 (29 units)
    net = load_network(DATA)
    kitchen, goal, memo = load_kitchen(net, "base"), resolve_goal(net, "ramen"), {}
    wide = compile_goal(net.foon, kitchen, goal, "relational", memo=memo)
    small = compile_goal(net.foon, kitchen, goal, "relational", narrow=True, memo=memo)
    assert small.narrowed.startswith("counted small, from the plan through the stitches alone"), small.narrowed
    assert 0 < len(small.task.instances) < len(wide.task.instances)


def test_the_small_count_through_the_stitches_is_encoded_once():
    # reread60's F12: where FOON's own plan is none, the narrow count is the one through the stitches, so `plan`'s
    # narrow and narrow+through compiles are one task; narrowed tasks were not in encode_relational's memo, so it
    # was encoded twice (the universal ramen in its base kitchen: 1.15 s, then 0.06 s, the same text)
    net = load_network(DATA)
    kitchen, goal, memo = load_kitchen(net, "base"), resolve_goal(net, "ramen"), {}
    small = compile_goal(net.foon, kitchen, goal, "relational", narrow=True, memo=memo)
    through = compile_goal(net.foon, kitchen, goal, "relational", narrow=True, through=True, memo=memo)
    assert through.task is small.task
