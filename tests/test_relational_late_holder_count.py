"""A holder a unit empties without naming it, the one the completed kitchen starts the object in alone, is counted
emptied (`relational_plan.count_roles` with the counting kitchen): a later taker of that holder empty takes it, and
needs no object of its own.

The eggs and bacon pizza's shape (`0085-mini_bacon_egg_breakfast_pizza.txt:12`, `:104`): the kitchen has the onion
`in [bowl]`, a bowl no node lists it in, so the completion starts it in `bowl (contains {onion})`; the pick-and-place
takes the onion out of that bowl without naming it, onto the board, and the units put onions into bowls, so the bowl
is emptied of it; a later pick-and-place takes `bowl (empty)`. Counted without the emptied bowl, the task had a
bowl for each (45 objects on the odd universal half where `instances` has 43)."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.relational_init import placed_since_start
from foon2pddl.pddl.relational_plan import count_roles, plan_unit, taken_with
from foon2pddl.pddl.relational_touched import late_empties

ON = lambda holder: make_state("on", holder)  # noqa: E731
ONION_IN = n("onion", "whole", inside("bowl"))
PLACED_BOWL = n("bowl", "empty", ON("surface"))
FLOUR_BOWL = n("bowl", contains("flour"), ON("surface"))
DISH = n("bowl", contains("flour", "onion"), ON("surface"))
UNITS = (
    # the onion out of the bowl it starts in, which the unit does not name
    FunctionalUnit((n("board", "clean", "empty"), ONION_IN), Motion("pick-and-place"),
                   (n("board", contains("onion")), n("onion", "whole", ON("board")))),
    FunctionalUnit((n("onion", "whole", ON("board")), n("knife", "clean")), Motion("chop"),
                   (n("onion", "chopped", ON("board")), n("knife", "dirty"))),
    # a bowl taken empty
    FunctionalUnit((n("bowl", "empty"),), Motion("pick-and-place"), (PLACED_BOWL,)),
    FunctionalUnit((n("bag", contains("flour")), n("flour", "powder", inside("bag")), PLACED_BOWL), Motion("pour"),
                   (FLOUR_BOWL, n("flour", "powder", inside("bowl")))),
    # onions go into bowls: a bowl the onion leaves does not keep it
    FunctionalUnit((n("board", contains("onion")), n("onion", "chopped", ON("board")), FLOUR_BOWL), Motion("pour"),
                   (DISH, n("onion", "chopped", inside("bowl")), n("board", "empty"))),
)
KITCHEN = (ONION_IN, n("bowl", "empty"), n("board", "clean", "empty"), n("knife", "clean"),
           n("bag", contains("flour")), n("flour", "powder", inside("bag")))


def test_the_bowl_the_onion_leaves_is_the_bowl_taken_empty():
    task = compile_goal(Foon(UNITS), Kitchen(frozenset(KITCHEN)), Goal(GoalSpec("bowl"), (DISH,)), "relational",
                        narrow=True).task
    # one bowl: the onion starts in it, leaves it for the board, and the bowl is placed and filled (two before)
    assert [x.label for x in task.instances].count("bowl") == 1


def test_the_one_bowl_gives_a_plan_the_replay_accepts():
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    assert [x.name for x in outcome.task.instances if x.label == "bowl"] == ["bowl_1"]
    steps = [s.unit.motion.label for s in outcome.trace.steps]
    assert steps.index("pick-and-place") < steps.index("pour")  # the onion leaves before the bowl is placed
    assert outcome.trace.steps[0].unit == UNITS[0]


def test_the_emptied_holder_is_counted_only_from_a_kitchen_that_starts_the_object_in_it():
    holder = n("bowl", contains("onion"))
    unit = plan_unit(UNITS[0], frozenset(KITCHEN), frozenset(), frozenset({("bowl", "onion")}))
    home = frozenset(KITCHEN) | {holder}
    started = placed_since_start(UNITS, home)
    moved = [(r.label, r.before, r.after) for r in count_roles(unit, kitchen=home, started=started)]
    assert ("bowl", holder, n("bowl", "empty")) in moved
    # no kitchen node holds the onion alone (the wide count's, before the completion adds one): no bowl role
    assert [r.label for r in count_roles(unit, kitchen=frozenset(KITCHEN), started=started)] == ["board", "onion"]
    shared = home | {n("bowl", contains("garlic", "onion"))}
    assert [r.label for r in count_roles(unit, kitchen=shared, started=started)].count("bowl") == 1  # lists the onion alone: that one
    # emptied to a node no kitchen has: no taker takes it again there, and the unit would be credited with making it
    no_empty = frozenset(x for x in KITCHEN if x != n("bowl", "empty")) | {holder}
    assert [r.label for r in count_roles(unit, kitchen=no_empty, started=started)] == ["board", "onion"]
    # an onion a unit put into a bowl is in that unit's bowl, not the kitchen's: no bowl role
    assert [r.label for r in count_roles(unit, kitchen=home, started=started - {ONION_IN})] == ["board", "onion"]
    # a bowl of onion a unit of the task takes is counted by its takers, the onion started in one of theirs (the
    # chocolate cake's flour sprinkled at `0058-chocolate_cake.txt:17` is in the bowl the pour at `:49` takes)
    pour = FunctionalUnit((holder, ONION_IN, n("pan", "empty")), Motion("pour"), (n("pan", contains("onion")),))
    assert [r.label for r in count_roles(unit, kitchen=home, started=started, taken=taken_with((pour,)))] == ["board", "onion"]
    assert "bowl" in [r.label for r in count_roles(unit, kitchen=home, started=started, taken=taken_with(UNITS))]
    # a unit that names a bowl too (two breads on [cutting board], one board listing bread: `0061-club_sandwich.txt:180`)
    # reads which holds what itself: no bowl beside its own
    naming = FunctionalUnit((*UNITS[0].inputs, n("bowl", contains("garlic"))), Motion("pick-and-place"),
                            (*UNITS[0].outputs, n("bowl", "empty")))
    read = plan_unit(naming, frozenset(KITCHEN), frozenset(), frozenset({("bowl", "onion")}))
    assert read.slots[1].late_empties  # the onion still leaves a bowl the unit does not name
    assert [r.label for r in count_roles(read, kitchen=home, started=started)] == ["board", "onion", "bowl"]


def test_placed_since_start_follows_units_that_leave_an_object_where_it_is():
    """The turkey sandwich's shape (`0049-turkey_sandwich.txt:1`, `:25`, `:92`): a bread a unit put on the board and
    buttered there is no kitchen bread on a board, though the kitchen has one; a peeled onion still in the kitchen's
    bowl is."""
    bread, on_board = n("bread", "sliced"), n("bread", "sliced", ON("board"))
    buttered = n("bread", "buttered", ON("board"))
    peeled = n("onion", "peeled", inside("bowl"))
    units = (FunctionalUnit((n("board", "empty"), bread), Motion("pick-and-place"), (n("board", contains("bread")), on_board)),
             FunctionalUnit((on_board, n("knife", "clean")), Motion("spread"), (buttered,)),
             FunctionalUnit((ONION_IN,), Motion("peel"), (peeled,)))
    kitchen = frozenset({bread, ONION_IN, n("bread", "toasted", ON("board"))})
    assert placed_since_start(units, kitchen) == {ONION_IN, peeled, n("bread", "toasted", ON("board"))}
    # a bread on the board from the kitchen too: the counts take that node from the kitchen, not from its maker
    assert placed_since_start(units, kitchen | {on_board}) >= {on_board, buttered}


# The pizza's shape with the bowls named `mixing bowl`: the onion starts `in [bowl]`, a name only the last pour's
# output uses for its mixing bowl (`unit_aliases`), which the task reads as the mixing bowl (`task_aliases`: no
# object of the task is a `bowl`); the completion starts the onion in `mixing bowl (contains {onion})`.
MIXING = "mixing bowl"
PLACED_MIXING = n(MIXING, "empty", ON("surface"))
FLOUR_MIXING = n(MIXING, contains("flour"), ON("surface"))
MIXED = n(MIXING, contains("flour", "onion"), ON("surface"))
RENAMED = (
    UNITS[0], UNITS[1],
    FunctionalUnit((n(MIXING, "empty"),), Motion("pick-and-place"), (PLACED_MIXING,)),
    FunctionalUnit((n("bag", contains("flour")), n("flour", "powder", inside("bag")), PLACED_MIXING), Motion("pour"),
                   (FLOUR_MIXING, n("flour", "powder", inside(MIXING)))),
    FunctionalUnit((n("board", contains("onion")), n("onion", "chopped", ON("board")), FLOUR_MIXING), Motion("pour"),
                   (MIXED, n("onion", "chopped", inside("bowl")), n("board", "empty"))),
)
RENAMED_KITCHEN = (*(x for x in KITCHEN if x.label != "bowl"), n(MIXING, "empty"))


def test_the_holder_is_read_by_the_tasks_names_as_the_action_empties_it():
    """The count reads the holder the onion leaves as the action does (`relational_plan.late_emptied` through the
    task's aliases): one mixing bowl, as one bowl above (two when the count read `bowl` by the unit's own names)."""
    outcome = clean_unit_plan(RENAMED, RENAMED_KITCHEN, MIXED, time_limit=60)
    assert [x.label for x in outcome.task.instances].count(MIXING) == 1
    holder = n(MIXING, contains("onion"))
    home = frozenset(RENAMED_KITCHEN) | {holder}
    alias = {"bowl": MIXING}
    unit = plan_unit(RENAMED[0], frozenset(RENAMED_KITCHEN), frozenset(), frozenset({(MIXING, "onion")}))
    counted = [(r.before, r.after) for r in count_roles(unit, alias, home, placed_since_start(RENAMED, home, alias),
                                                        taken_with(RENAMED, alias)) if r.label == MIXING]
    emptied = late_empties(unit, home, alias)[1]  # the action's: the onion's slot
    assert counted == emptied == [(holder, n(MIXING, "empty"))]
    # where the kitchen started the onion and what a unit takes it with read by the same names: peeled `in [mixing
    # bowl]`, it is still in the bowl it started `in`; a pot listing `rice` holds the white rice taken with it
    peeled = n("onion", "peeled", inside(MIXING))
    peel = FunctionalUnit((ONION_IN,), Motion("peel"), (peeled,))
    assert peeled in placed_since_start((peel,), home, alias) - placed_since_start((peel,), home)
    rice, pot = n("white rice", inside("pot")), n("pot", contains("rice"))
    boil = FunctionalUnit((rice, pot), Motion("boil"), (n("white rice", "boiled", inside("pot")),))
    assert (rice, pot) in taken_with((boil,), {"rice": "white rice"}) - taken_with((boil,))
