"""An object a unit of the task made, leaving a holder the unit does not name that no node of the task says holds
its label, moves whole (`relational_plan.plan_unit`): nothing says that holder keeps some, so no portion is split
off and no second object of its label is made; unless FOON's plan as counted fires the unit again
(`relational_reading._fired_again`): the second firing takes what the first left."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.io.parser import parse_text
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl import relational_reading
from foon2pddl.pddl.compile import compile_goal

# the shape of the easy garlic bread (0016-easy_garlic_bread-one-pot-chef.txt:141, :157, :197, :221, :245): the
# attach makes the loaf `on [cutting board]`, a board it does not name (the kitchen's board lists the bread); the pick-and-place takes it off that board
# onto the foil (no node lists a loaf on a board); the bake makes the garlic bread `in [oven]`, an oven whose nodes
# list the loaf, never the garlic bread; the remove takes it out of that oven
ON = lambda holder: make_state("on", holder)  # noqa: E731
BREAD = n("bread", contains("garlic butter"), ON("cutting board"))
LOAF, ON_FOIL = n("loaf", contains("garlic butter"), ON("cutting board")), n("loaf", contains("garlic butter"), ON("foil"))
FOIL = n("foil", contains("loaf"), ON("cutting board"))
OVEN = n("oven", "on", contains("loaf"))
DISH = n("garlic bread", ON("plate"))
UNITS = (FunctionalUnit((BREAD,), Motion("attach"), (LOAF,)),
         FunctionalUnit((LOAF, n("foil", "sheet")), Motion("pick-and-place"), (ON_FOIL, FOIL)),
         FunctionalUnit((ON_FOIL, FOIL, n("oven", "on")), Motion("put inside"),
                        (n("loaf", contains("garlic butter"), inside("oven")), OVEN)),
         FunctionalUnit((n("loaf", contains("garlic butter"), inside("oven")), OVEN), Motion("bake"),
                        (n("garlic bread", inside("oven")),)),
         FunctionalUnit((OVEN, n("garlic bread", inside("oven"))), Motion("remove"),
                        (n("garlic bread", ON("cutting board")), n("oven", "off"))),
         FunctionalUnit((n("garlic bread", ON("cutting board")), n("plate", "empty")), Motion("pick-and-place"),
                        (DISH, n("plate", contains("garlic bread")))))
KITCHEN = (BREAD, n("cutting board", contains("bread")), n("foil", "sheet"), n("oven", "on"), n("plate", "empty"))


def _labels(**options) -> list[str]:
    task = compile_goal(Foon(UNITS), Kitchen(frozenset(KITCHEN)), Goal(GoalSpec("garlic bread"), (DISH,)),
                        "relational", **options).task
    return sorted(x.label for x in task.instances)


def test_a_made_object_leaves_a_holder_that_never_lists_it_whole():
    for options in ({"narrow": True}, {}):
        labels = _labels(**options)
        # one loaf and one garlic bread: the loaf leaves the board whole, the garlic bread the oven (two each before)
        assert labels.count("loaf") == 1 and labels.count("garlic bread") == 1, labels


def test_the_whole_loaf_gives_a_plan_the_replay_accepts():
    outcome = clean_unit_plan(UNITS, KITCHEN, DISH, time_limit=60)
    named = [x.name for x in outcome.task.instances if x.label in ("loaf", "garlic bread")]
    assert sorted(named) == ["garlic_bread_1", "loaf_1"], named


# the pigs in a blanket from the cheese on (`0052-pigs_in_a_blanket.txt:44`-`:171`, FOON's text): the roll (`:80`)
# makes the pigs `on [cutting board]`; the pick-and-place onto the tray (`:89`) takes them off a board whose node lists
# the dough, no node listing pigs on a board; FOON's plan unfolded fires it twice (the last pick-and-place, `:154`,
# takes the tray node it makes, before the remove makes it again)
PIGS = """//
O143	cutting board	0
S23	contains	{dough}
O149	dough	0
S45	flattened
S81	on	[cutting board]
O344	plate	0
S23	contains	{cheese}
O78	cheese	1
S117	sliced
S81	on	[plate]
M50	pick-and-place	1:04	1:08
O149	dough	0
S23	contains	{cheese}
S81	on	[cutting board]
O78	cheese	1
S117	sliced
S81	on	[dough]
//
O143	cutting board	0
S23	contains	{dough}
O149	dough	0
S23	contains	{cheese}
S81	on	[cutting board]
O344	plate	1
S23	contains	{sausage}
O382	sausage	1
S24	cooked
S81	on	[plate]
M50	pick-and-place	1:09	1:13
O149	dough	0
S23	contains	{cheese,sausage}
S81	on	[cutting board]
O382	sausage	1
S24	cooked
S81	on	[dough]
//
O149	dough	0
S23	contains	{cheese,sausage}
S81	on	[cutting board]
M66	roll	1:14	1:22
O334	pigs in a blanket	0
S133	uncooked
S23	contains	{cheese,sausage}
S81	on	[cutting board]
//
O143	cutting board	0
S23	contains	{dough}
O12	baking tray	0
S41	empty
O334	pigs in a blanket	1
S133	uncooked
S23	contains	{cheese,sausage}
S81	on	[cutting board]
M50	pick-and-place	1:24	1:32
O12	baking tray	0
S23	contains	{pigs in a blanket}
O334	pigs in a blanket	1
S133	uncooked
S23	contains	{cheese,sausage}
S65	in	[baking tray]
O143	cutting board	0
S38	dirty
//
O306	oven	0
S81	on
O12	baking tray	1
S23	contains	{pigs in a blanket}
M62	put inside	1:38:50	1:43
O12	baking tray	1
S23	contains	{pigs in a blanket}
S65	in	[oven]
O306	oven	0
S81	on
S142	with	[baking tray]
//
O12	baking tray	0
S23	contains	{pigs in a blanket}
S65	in	[oven]
O334	pigs in a blanket	1
S133	uncooked
S23	contains	{cheese,sausage}
S65	in	[baking tray]
O306	oven	0
S81	on
S142	with	[baking tray]
M2	bake	Assumed	Assumed
O334	pigs in a blanket	1
S24	cooked
S23	contains	{cheese,sausage}
S65	in	[baking tray]
O12	baking tray	0
S23	contains	{pigs in a blanket}
S65	in	[oven]
//
O306	oven	0
S81	on
S142	with	[baking tray]
O334	pigs in a blanket	1
S24	cooked
S23	contains	{cheese,sausage}
S65	in	[baking tray]
O12	baking tray	1
S23	contains	{pigs in a blanket}
S65	in	[oven]
M63	remove	Assumed	Assumed
O306	oven	0
S78	off
O12	baking tray	1
S23	contains	{pigs in a blanket}
//
O334	pigs in a blanket	1
S24	cooked
S23	contains	{cheese,sausage}
S65	in	[baking tray]
O12	baking tray	0
S23	contains	{pigs in a blanket}
O344	plate	0
S41	empty
O452	tongs	1
S16	clean
M50	pick-and-place	Assumed	Assumed
O344	plate	0
S23	contains	{pigs in a blanket}
O334	pigs in a blanket	1	29
S24	cooked
S23	contains	{dough,cheese,sausage}
S81	on	[plate]
//
"""


def _pigs_task(**options):
    foon = parse_text(PIGS, "pigs.txt").foon
    dish = next(x for x in foon.nodes if x.label == "pigs in a blanket" and ON("plate") in x.states)
    return compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational",
                        **options).task


def test_a_unit_the_plan_fires_again_takes_a_portion_of_a_made_object(monkeypatch):
    """The exception to the rule (`relational_reading._fired_again`): the pick-and-place onto the tray that FOON's
    plan unfolded fires twice takes a portion of the pigs, and switched off, the roll and what it takes fire again."""
    for options in ({"narrow": True}, {}):
        task = _pigs_task(**options)
        # the second firing takes a portion of the pigs the first left on the board: 13 objects in the problem
        assert len(task.objects) == 13 and [x.label for x in task.instances].count("pigs in a blanket") == 3
    monkeypatch.setattr(relational_reading, "_fired_again", lambda counted: frozenset())
    # read whole there too, the roll and the cheese and sausage it takes are fired again: one object more
    assert len(_pigs_task(narrow=True).objects) == 14
