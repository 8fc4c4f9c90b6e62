"""Steps in a cook's words (`io.recipe_words`): where a thing goes, `into` or `onto`, as FOON says it."""

from __future__ import annotations

from conftest import SUBGRAPHS

from foon2pddl.io.parser import parse_file
from foon2pddl.io.recipe_words import recipe_text
from foon2pddl.io.tree_formats import render_tree
from foon2pddl.model.foon import FunctionalUnit
from foon2pddl.model.tasktree import TaskTree


def _steps(name: str) -> list[str]:
    """The recipe lines of one shared subgraph's units, read as one task tree (their order in the file)."""
    units = parse_file(SUBGRAPHS / name).foon.units
    return render_tree(TaskTree(units, units[-1].outputs[0]), "recipe").splitlines()[1:]


def _unit(name: str, line: int) -> FunctionalUnit:
    """The unit of one shared subgraph its file gives at `line` (its first source, as `file:line` cites it)."""
    return next(u for u in parse_file(SUBGRAPHS / name).foon.units if u.sources[0].line == line)


def test_a_thing_named_only_in_lists_goes_onto_what_the_recipe_puts_things_on():
    """Stop 58's F18: 0085's spread read `spread sour cream from the scraper into the pizza dough (flattened, ...)`
    (0085-mini_bacon_egg_breakfast_pizza.txt:435): the sour cream is named only in lists, and the destination was
    always `in`. The unit says nothing of how things sit at the dough, but the recipe does: the onion, the bacon
    and the egg go `on {pizza dough}` (:494, :498, :522). The sea salt and pepper sprinkled at :452 likewise."""
    steps = _steps("0085-mini_bacon_egg_breakfast_pizza.txt")
    assert any(". spread sour cream from the scraper onto the pizza dough (flattened, on [parchment paper])" in s
               for s in steps), steps
    assert any(". sprinkle sea salt (granulated) and pepper from the bottle onto the pizza dough (contains {sour cream}"
               in s for s in steps), steps
    assert not any("into the pizza dough" in s for s in steps), steps


def test_an_input_a_container_newly_lists_goes_onto_it_when_the_step_says_so():
    """0042's pour (0042-perfect_omelette.txt:79) read `pour onion ... and sweet pepper ... into the plate (contains
    {tomato})`, where the unit itself puts the tomato, the onion and the pepper `on [plate]`: the step's own nodes
    decide, with no recipe around it."""
    pour = _unit("0042-perfect_omelette.txt", 79)
    assert recipe_text(pour).endswith("onto the plate (contains {tomato})"), recipe_text(pour)


def test_a_bowl_things_go_in_stays_into():
    """The caesar salad's bowl (ACT-0080-caesar_salad.txt:291): its nodes say `in [bowl]` 22 times and `on` twice,
    the unit once `in`: the croutons go into it, alone or in the recipe."""
    pour = _unit("ACT-0080-caesar_salad.txt", 291)
    assert recipe_text(pour) == (
        "pour crouton from the bowl (contains {crouton}) into the bowl (coated {garlic}, contains {lettuce})")
    assert any(s.endswith(". " + recipe_text(pour)) for s in _steps("ACT-0080-caesar_salad.txt"))


def test_a_place_that_holds_a_place_is_said_as_a_place_outward():
    """Issue 24's `heat butter (in [bowl]), microwave (contains {bowl}, on)` (0016-easy_garlic_bread-one-pot-chef.txt:46):
    the microwave holds the bowl the butter is in, so it is where the butter heats, not a second thing heated; and
    the apple turnover's `bake oven (contains {baking tray}, on, preheated), apple pie (...)` (0086:594). A place
    inside another place gets its own word (`in the baking tray ..., oven (on, ...)` ran them together)."""
    heat = recipe_text(_unit("0016-easy_garlic_bread-one-pot-chef.txt", 46))
    assert heat == "heat butter, in the bowl (in [microwave]), in the microwave (contains {bowl}, on)", heat
    bake = recipe_text(_unit("0086-apple_turnover.txt", 594))
    assert bake.startswith("bake apple pie (") and bake.endswith(
        ", on the baking tray (in [oven]), in the oven (contains {baking tray}, on, preheated)"), bake
    fries = _steps("0035-oven-baked_sweet_potato_fries.txt")
    assert any(s.endswith("in the baking tray (in [oven]), in the oven (on, with [baking tray])") for s in fries), fries


def test_an_input_the_step_works_into_what_it_changes_is_used_up_not_a_tool(tmp_path):
    """newcomer60: a spread whose butter (softened) is an input and no output, the toast gaining `buttered`, read
    `spread toast, with the butter (softened), knife, on the plate`: the butter as a tool. An input no output keeps,
    whose label begins a state the step's outputs gain, is used up into what changes (0049's spread at
    0049-turkey_sandwich.txt:25, `bread (buttered {butter})`, read the same way). A tool the unit leaves out of its
    outputs gains nothing in its name, so it stays a tool (0002's chop of the rosemary)."""
    mine = tmp_path / "toast.txt"
    mine.write_text("//\nO\tbutter\t1\nS\tsoftened\nO\tknife\t0\nO\ttoast\t1\nS\ton\t[plate]\nO\tplate\t0\n"
                    "M\tspread\t<Assumed>\t<Assumed>\nO\ttoast\t1\nS\ton\t[plate]\nS\tbuttered\nO\tknife\t0\n"
                    "S\tdirty\nO\tplate\t0\n//\n")
    (unit,) = parse_file(mine).foon.units
    assert recipe_text(unit) == "spread toast, using up the butter (softened), with the knife, on the plate"
    shared = _unit("0049-turkey_sandwich.txt", 25)
    assert recipe_text(shared) == ("spread bread (sliced), using up the butter (in [bowl]), with the knife (clean), "
                                   "on the cutting board, in the bowl (contains {butter})")
    chop = next(u for u in parse_file(SUBGRAPHS / "0002-bacon_macaroni_and_cheese.txt").foon.units
                if u.motion.label == "chop" and any(i.label == "rosemary" for i in u.inputs))
    assert recipe_text(chop).endswith(", with the knife (clean)"), recipe_text(chop)
