"""Relational plans of experiment cells that failed the replay (issue 25): each rule read from one cell of
`foon2pddl experiment tests/data/foon-subgraphs --trials 1 --goals 100 --solvers fd-relational`."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.relational_init import holder_init
from foon2pddl.pddl.task import Instance

# the french toast's pour (0037-make_quick_french_toast.txt:63) takes `bowl (contains {butter})`, which the
# garlic bread's pick-and-place fills, and leaves it out of its outputs: the bowl is emptied of the butter
BUTTER_BOWL, BUTTER = n("bowl", contains("butter")), n("butter", "cubed", inside("bowl"))
PACKED = n("butter", "stick", inside("packet"))
FILL = FunctionalUnit((n("bowl", "empty"), PACKED), Motion("pick-and-place"), (BUTTER_BOWL, n("butter", inside("bowl"))))


def _pour_into(pan: str) -> FunctionalUnit:
    return FunctionalUnit((BUTTER_BOWL, BUTTER, n(pan, "heated")), Motion("pour"),
                          (n("butter", "cubed", inside(pan)), n(pan, contains("butter"))))


def test_a_holder_the_kitchen_implies_is_added_once_per_object_it_holds():
    # EXP, trial 1, goal 12: the trial's kitchen has `butter (cubed, in [bowl])` and no bowl listing butter; a
    # plan pouring butter into two pans needs two such butters, which went into one added bowl: the first
    # pour left that bowl empty with the second butter in it [held-by-empty]. Each butter gets a bowl.
    dish = n("toast", "buttered")
    serve = FunctionalUnit((n("skillet", contains("butter")), n("pot", contains("butter"))), Motion("serve"), (dish,))
    outcome = clean_unit_plan([FILL, _pour_into("skillet"), _pour_into("pot"), serve],
                              [BUTTER, n("bowl", "empty"), PACKED, n("packet", contains("butter")),
                               n("skillet", "heated"), n("pot", "heated")], dish)
    holders = [s.holder for s in outcome.trace.initial if s.node == BUTTER]
    assert len(holders) == len(set(holders)) == 2 and all(h.startswith("bowl_") for h in holders)


def test_what_the_units_fill_is_read_through_the_task_aliases_when_holders_are_added():
    # a unit's list names `oil` where the task's object is `olive oil` (`holder_words.task_aliases`): two olive
    # oils `in [bowl]`, of a label the units put into bowls, get a bowl each, as the two butters above do
    oil = n("olive oil", inside("bowl"))
    xs = [Instance(f"olive_oil_{k}", "olive oil", oil) for k in (1, 2)]
    _, implied = holder_init(xs, {"oil": "olive oil"}, filled=frozenset({("bowl", "oil")}))
    assert implied == [n("bowl", contains("olive oil"))] * 2


def test_an_object_that_holds_others_leaves_a_holder_the_unit_does_not_name_whole():
    # REG and EXP, trial 1, goal 69 (0077-bread_toast.txt:28): the pick-and-place takes `bread (contains
    # {butter}, on [plate])` with no plate; the trial's kitchen has a plate that lists its contents, so a plate
    # may be a stock: a portion of the bread went onto the pan, listing the butter still in the bread on the
    # plate [claimed-twice]. An object whose node lists what is in or on it leaves whole.
    bread, buttered = n("bread", make_state("on", "plate")), n("bread", contains("butter"), make_state("on", "plate"))
    spread = FunctionalUnit((bread, n("bowl", contains("butter")), n("butter", inside("bowl")), n("knife")),
                            Motion("spread"), (buttered, n("butter", inside("bread")), n("bowl", "empty")))
    toast = n("bread", contains("butter"), make_state("on", "cooking pan"))
    place = FunctionalUnit((buttered, n("cooking pan", "empty")), Motion("pick-and-place"),
                           (toast, n("cooking pan", make_state("with", "bread"))))
    outcome = clean_unit_plan([spread, place], [bread, n("plate"), n("plate", contains("cheese")),
                                                n("bowl", contains("butter")), n("butter", inside("bowl")),
                                                n("knife"), n("cooking pan", "empty")], toast)
    assert [o.id for o in outcome.trace.objects if o.label == "bread"] == ["bread_1"]


def test_a_portion_comes_out_of_the_holder_the_unit_binds():
    # GEN, trial 1, goal 42 (0044-egg_noodles_from_scratch.txt:79): the pour takes `bowls (contains {dairy})`,
    # which it binds (another unit leaves that node), and `dairy (in [bowls])`, which it only reads: a portion
    # went into the eggs from the dairy the plan had put into another bowl [holder-not-bound]. The object the
    # portion comes from is bound too, in the bound holder.
    from foon2pddl.model.foon import Foon
    from foon2pddl.model.goal import Goal, GoalSpec
    from foon2pddl.model.kitchen import Kitchen
    from foon2pddl.pddl.compile import compile_task

    milk_bowl, milk = n("bowl", contains("milk")), n("milk", inside("bowl"))
    fill = FunctionalUnit((n("bowl", "empty"), n("milk", inside("carton"))), Motion("pour"), (milk_bowl, milk))
    pour = FunctionalUnit((milk_bowl, milk, n("cup", "empty")), Motion("pour"),
                          (n("cup", contains("milk")), n("milk", inside("cup"))))
    drink = n("milk", "warm", inside("cup"))
    heat = FunctionalUnit((n("milk", inside("cup")),), Motion("heat"), (drink,))
    wash = FunctionalUnit((milk_bowl, n("sponge")), Motion("wash"), (n("bowl", "clean"),))
    meal = n("breakfast")
    serve = FunctionalUnit((drink, n("bowl", "clean")), Motion("serve"), (meal,))  # the wash is needed too
    kitchen = Kitchen(frozenset([milk_bowl, milk, n("bowl", "empty"), n("milk", inside("carton")),
                                 n("carton", contains("milk")), n("cup", "empty"), n("sponge")]))
    task = compile_task(Foon((fill, pour, heat, wash, serve)), kitchen, Goal(GoalSpec("breakfast"), (meal,)),
                        encoding="relational", level=3, prune=False, costs=None, rates=None)
    action = next(a for a in task.actions if a.unit is not None and task.units[a.unit] == pour)
    assert ("?bowl", "?milk") in {p.args for p in action.pre if p.predicate == "in"}


def test_an_object_a_kitchen_container_lists_starts_in_a_node_that_lists_nothing_of_its_own():
    # GEN, trial 1, goal 27: a kitchen mixer lists the bowl in it, and the network's only bowl in a mixer is
    # the one a unit fills (`bowls (contains {...}, in [mixing tools])`): the bowl added there listed contents
    # nothing stood for [claimed-twice, in the initial state]; goals 5, 7, 36: a mixture a unit makes, added
    # in its made node, let the plan skip the unit [input not available]. The object starts in `bowl (in [mixer])`.
    flour_bag, flour, whisked = n("bag", contains("flour")), n("flour", inside("bag")), n("flour", "whisked", inside("bowl"))
    add = FunctionalUnit((n("bowl", "empty"), flour_bag, flour), Motion("pour"),
                         (n("bowl", contains("flour")), n("flour", inside("bowl"))))
    running = n("mixer", "on", make_state("with", "bowl"))  # the kitchen's: a bowl in it, and no node of that bowl
    whisk = FunctionalUnit((n("flour", inside("bowl")), running), Motion("whisk"), (whisked,))
    mounted = n("bowl", contains("flour"), inside("mixer"))
    mount = FunctionalUnit((n("bowl", contains("flour")), whisked, n("mixer", "off")), Motion("insert"),
                           (mounted, n("mixer", "off", make_state("with", "bowl"))))
    outcome = clean_unit_plan([add, whisk, mount], [n("bowl", "empty"), flour_bag, flour, n("mixer", "off"), running],
                              mounted)
    assert n("bowl", inside("mixer")) in {s.node for s in outcome.trace.initial}


def test_an_object_a_unit_only_implies_in_the_goal_node_does_not_reach_the_goal():
    # GEN, trial 1, goal 34 (0001-whipped_cream.txt:39 and :59): the pour gives no node of the cream it pours
    # into the bowl, so its node there is implied (`creams (in [bowls])`, holders rule 3), and that is the node
    # the mix makes, the goal: the plan poured and stopped [goal not produced]. The cream the pour leaves is in
    # the bowl before the mix; only the mix's cream reaches the goal.
    cup, cream = n("cup", contains("cream")), n("cream", inside("cup"))
    pour = FunctionalUnit((n("bowl", "empty"), cup, cream), Motion("pour"), (n("bowl", contains("cream")),))
    whipped = n("cream", inside("bowl"))
    mix = FunctionalUnit((n("bowl", contains("cream")), n("whisk")), Motion("mix"),
                         (n("bowl", contains("cream"), "whipped"), whipped))
    outcome = clean_unit_plan([pour, mix], [n("bowl", "empty"), cup, cream, n("whisk")], whipped)
    assert [s.split("_u")[0] for s in outcome.result.plan if "_u" in s] == ["pour", "mix"]
    # the reading names a node FOON does not have (`cream (in [bowl], before mix)`): the task says so, once
    compiled = compile_goal(Foon((pour, mix)), Kitchen(frozenset({n("bowl", "empty"), cup, cream, n("whisk")})),
                            Goal(GoalSpec("cream"), (whipped,)), "relational", 3)
    assert [x for x in compiled.notes if "before mix" in x] == [
        "label mismatch: ?: pour implies cream (in [bowl]), the goal's node mix at ? makes: read as the cream before mix"]


def test_an_object_a_kitchen_container_lists_never_starts_in_a_node_only_a_unit_makes():
    # GEN, trial 2, goal 97: the kitchen's `measuring cups (contains {water and ice})` holds one water, and the only
    # node of water in a measuring cup is the fill's `water and ice (from [kitchen fixtures], in [measuring cups])`:
    # the water added there was poured without the fill, and FOON's tree did not validate [input not available].
    # It starts in `water (in [cup])`, which the kitchen's cup says; the pour takes the water the fill makes.
    fill = FunctionalUnit((n("cup", "empty"), n("faucet", "on")), Motion("fill"),
                          (n("cup", contains("water")), n("water", make_state("from", "faucet"), inside("cup"))))
    turn_on = FunctionalUnit((n("faucet", "off"),), Motion("turn on"), (n("faucet", "on"),))
    dough = n("bowl", contains("flour", "water"))
    pour = FunctionalUnit((n("cup", contains("water")), n("water", make_state("from", "faucet"), inside("cup")),
                           n("bowl", contains("flour")), n("flour", inside("bowl"))), Motion("pour"),
                          (dough, n("water", inside("bowl"))))
    outcome = clean_unit_plan([turn_on, fill, pour], [n("cup", contains("water")), n("cup", "empty"),
                                                      n("faucet", "off"), n("bowl", contains("flour")),
                                                      n("flour", inside("bowl"))], dough)
    assert n("water", inside("cup")) in {s.node for s in outcome.trace.initial}
    assert [u.motion.label for u in outcome.tree.units] == ["turn on", "fill", "pour"]


def test_a_kitchen_container_s_object_starts_in_a_node_the_kitchen_has_in_another_place():
    # The universal FOON's tuna sandwich (ACT-0024-tuna_sandwich.txt:32): the kitchen's `bowl (contains
    # {mayonnaise, onion})` (no unit makes it) is mixed with `onion (chopped, in [bowl])`, which units make only
    # in another bowl; the kitchen has `onion (chopped, in [tray])`, that onion in another place, which FOON's
    # tree takes (`kitchen_implied` over the whole kitchen, `Compiled.placed`). Read against the task's starting
    # objects alone, the onion started in `onion (in [bowl])` and the mix was out of reach [unsolvable].
    box, chopped = n("bowl", contains("mayonnaise", "onion")), n("onion", "chopped", inside("bowl"))
    on_tray, mayo = n("onion", "chopped", inside("tray")), n("mayonnaise", inside("bowl"))  # no unit takes it
    whole, cut = (n("onion", s, make_state("on", "cutting board")) for s in ("whole", "chopped"))
    chop = FunctionalUnit((whole, n("knife")), Motion("chop"), (cut,))
    move = FunctionalUnit((n("bowl", "empty"), cut), Motion("pick-and-place"), (n("bowl", contains("onion")), chopped))
    spread = n("bowl", contains("spread"))
    mix = FunctionalUnit((box, mayo, chopped), Motion("mix"), (spread,))
    outcome = clean_unit_plan([chop, move, mix], [box, mayo, on_tray, whole, n("bowl", "empty"), n("knife")], spread)
    assert chopped in {s.node for s in outcome.trace.initial}
