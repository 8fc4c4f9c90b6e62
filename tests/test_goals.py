"""Goals: the --goal syntax, goal files, and resolution (exact states first, else a superset)."""

from __future__ import annotations

import json

import pytest

from foon2pddl.errors import FoonSyntaxError, UsageError
from foon2pddl.io.goal_files import parse_goal_spec, read_goal_file
from foon2pddl.io.inputs import load_goal, load_goal_spec
from foon2pddl.io.parser import parse_text
from foon2pddl.model.foon import State, make_node, make_state
from foon2pddl.model.goal import GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.levels import project


@pytest.mark.parametrize(("text", "label", "states"), [
    ("whipped cream", "whipped cream", None),
    ("  Whipped   Cream ", "whipped cream", None),
    ("onion: chopped", "onion", (State("chopped"),)),
    ("water: in [pot]", "water", (State("in", "pot"),)),
    ("bowl: contains {lettuce, tomato}", "bowl", (State("contains", "", ("lettuce", "tomato")),)),
    ("bowl: contains {tomato,lettuce,}, on [Table]", "bowl",
     (State("contains", "", ("lettuce", "tomato")), State("on", "table"))),
    ("pot: in [stove] {water, salt}", "pot", (State("in", "stove", ("salt", "water")),)),
    ("onion: sliced, chopped, sliced", "onion", (State("chopped"), State("sliced"))),
    ("onion:", "onion", ()),
])
def test_goal_syntax(text, label, states):
    spec = parse_goal_spec(text)
    assert (spec.label, spec.states) == (label, states)
    assert parse_goal_spec(spec.describe()) == spec


@pytest.mark.parametrize(("text", "problem"), [
    ("", "no object label"),
    (": chopped", "no object label"),
    ("bowl: contains {a, b", "unbalanced bracket"),
    ("bowl: in [pot]]", "unbalanced bracket"),
    ("bowl: [pot]", "cannot read state"),
    ("bowl: in [pot] extra", "cannot read state"),
    # issue 24's tried-again pass: a node as the tools print it, cut short, read as the label 'guacamole (in [bowl]'
    ("guacamole (in [bowl]", r"unbalanced parenthesis in the label 'guacamole \(in \[bowl\]'"),
    ("onion (chopped", "unbalanced parenthesis"),
    ("onion chopped)", "unbalanced parenthesis"),
])
def test_goal_syntax_errors(text, problem):
    with pytest.raises(ValueError, match=problem):
        parse_goal_spec(text)


FOON = parse_text("""//
O\tonion
S\twhole
O\tknife
M\tchop
O\tonion
S\tchopped
//
O\tonion
S\tchopped
O\tbowl
S\tempty
M\tpour
O\tbowl
S\tcontains\t{onion}
O\tonion
S\tchopped
S\tin\t[bowl]
//
O\tbowl
S\tcontains\t{onion}
O\ttomato
S\tchopped
M\tpour
O\tbowl
S\tcontains\t{onion, tomato}
//
O\tonion
S\twhole
O\tpeeler
M\tpeel
O\tonion
S\tpeeled
S\twhole
""", "g.foon").foon


def node(label, *states):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states])


def test_label_goal_is_the_final_products_with_that_label():
    goal = resolve_goal(parse_goal_spec("onion"), FOON)
    # no onion node is a dish: the produced ones no unit consumes are meant; the others are named
    assert set(goal.candidates) == {node("onion", "chopped", ("in", "bowl")), node("onion", "peeled", "whole")}
    assert goal.others == (node("onion", "chopped"),) and goal.preferred == "final product"
    assert "`onion (chopped)`" in goal.choice_note()
    assert node("onion", "whole") not in goal.candidates + goal.others  # only ever an input
    assert list(goal.candidates) == sorted(goal.candidates)


def test_exact_states_win_over_supersets():
    goal = resolve_goal(parse_goal_spec("onion: chopped"), FOON)
    assert goal.candidates == (node("onion", "chopped"),)


def test_superset_when_no_exact_match():
    assert resolve_goal(parse_goal_spec("onion: in [bowl]"), FOON).candidates == \
        (node("onion", "chopped", ("in", "bowl")),)
    assert resolve_goal(parse_goal_spec("onion: whole"), FOON).candidates == (node("onion", "peeled", "whole"),)


def test_level_3_goal_with_ingredients_and_its_level_2_reading():
    spec = parse_goal_spec("bowl: contains {tomato, onion}")
    assert resolve_goal(spec, FOON).candidates == (node("bowl", ("contains", "", ["onion", "tomato"])),)
    one_ingredient = parse_goal_spec("bowl: contains {onion}")
    assert resolve_goal(one_ingredient, FOON).candidates == (node("bowl", ("contains", "", ["onion"])),)
    two = resolve_goal(one_ingredient, project(FOON, 2))
    assert two.level == 2 and two.candidates == (node("bowl", "contains"),)  # ingredients are not level-2 identity


def test_goal_at_level_1_ignores_states():
    foon1 = project(FOON, 1)
    goal = resolve_goal(parse_goal_spec("onion: chopped"), foon1)
    assert goal.candidates == (make_node("onion"),) and goal.level == 1


def test_unknown_label_lists_close_matches():
    with pytest.raises(UsageError) as info:
        resolve_goal(parse_goal_spec("onoin"), FOON)
    assert "unknown object label 'onoin'" in info.value.message and "close matches: onion" in info.value.message
    with pytest.raises(UsageError) as info:
        resolve_goal(parse_goal_spec("zzzz"), FOON)
    assert "close matches" not in info.value.message


def test_label_that_is_only_an_input_or_states_not_produced():
    with pytest.raises(UsageError, match="no unit produces 'knife'"):
        resolve_goal(parse_goal_spec("knife"), FOON)
    with pytest.raises(UsageError) as info:
        resolve_goal(parse_goal_spec("onion: diced"), FOON)
    assert "no produced 'onion' node is in states" in info.value.message
    assert "(chopped)" in info.value.message


def test_satisfied_by_returns_the_first_available_candidate():
    goal = resolve_goal(parse_goal_spec("onion"), FOON)
    assert goal.satisfied_by({node("onion", "whole")}) is None
    have = {node("onion", "peeled", "whole"), node("onion", "chopped"), node("onion", "chopped", ("in", "bowl"))}
    assert goal.satisfied_by(have) == goal.candidates[0] == node("onion", "chopped", ("in", "bowl"))


def test_goal_file_holds_one_object_node(tmp_path):
    path = tmp_path / "goal.txt"
    path.write_text("# the goal\r\nO7\tBowl\t0\r\nS1\tcontains\t{tomato,onion}\r\n")
    spec = read_goal_file(path)
    assert spec == GoalSpec("bowl", (State("contains", "", ("onion", "tomato")),))
    assert spec == spec_of_node(node("bowl", ("contains", "", ["onion", "tomato"])))
    path.write_text("O\tbowl\n//\nO\tonion\n")
    with pytest.raises(FoonSyntaxError, match="exactly one object node, found 2") as info:
        read_goal_file(path)
    assert info.value.line == 3
    path.write_text("# nothing\n")
    with pytest.raises(FoonSyntaxError, match="found 0"):
        read_goal_file(path)


def test_load_goal_spec_needs_exactly_one_source(tmp_path):
    with pytest.raises(UsageError, match="exactly one goal"):
        load_goal_spec(None, None)
    with pytest.raises(UsageError, match="exactly one"):
        load_goal_spec("onion", tmp_path / "g.txt")
    with pytest.raises(UsageError, match="unbalanced"):
        load_goal_spec("onion: in [bowl", None)
    assert load_goal("onion: chopped", None, FOON).candidates == (node("onion", "chopped"),)


def test_an_unknown_goal_names_the_command_listing_this_networks_goals():
    """Stop 45's pass: `plan --network gen --goal beverage` (GEN's label is `beverages`) said '`foon2pddl goals`
    lists every goal', which lists the regular network's goals; each network's error names its own listing."""
    from click.testing import CliRunner

    from foon2pddl.cli import main

    runner = CliRunner()
    reg = runner.invoke(main, ["plan", "--goal", "beverage"])
    assert reg.exit_code == 2 and "`foon2pddl goals` lists every goal" in reg.stderr, reg.stderr
    gen = runner.invoke(main, ["retrieve", "--network", "gen", "--goal", "beverage"])
    assert gen.exit_code == 2 and "`foon2pddl goals --network gen` lists every goal" in gen.stderr, gen.stderr
    lifted = runner.invoke(main, ["plan", "--network", "gen", "--goal", "beverage"])
    assert lifted.exit_code == 2 and "`foon2pddl goals --network gen` lists the categories" in lifted.stderr
    listed = runner.invoke(main, ["goals", "--network", "gen"])
    assert listed.exit_code == 0 and " beverages" in listed.stdout
    # the lifted encoding on the regular network: its categories are listed on GEN, not by the regular listing
    # (15c195c named the run's network there: `foon2pddl goals` lists no category)
    regular = runner.invoke(main, ["plan", "--encoding", "gen-lifted", "--goal", "beverage drink"])
    assert regular.exit_code == 2, regular.stderr
    assert "`foon2pddl goals` lists every goal" in regular.stderr, regular.stderr
    assert "`foon2pddl goals --network gen` lists the categories" in regular.stderr, regular.stderr


def test_the_legend_names_the_embedded_kitchen_by_its_path_in_the_package():
    """Where the package is installed is no part of the output (as notes name example units): the legend and
    the JSON name the embedded kitchen `foon2pddl/data/example_kitchen.txt`, not an absolute path."""
    from click.testing import CliRunner

    from foon2pddl.cli import main

    text = CliRunner().invoke(main, ["goals", "--dishes"])
    assert text.exit_code == 0, text.output
    assert " can be made from foon2pddl/data/example_kitchen.txt (round" in text.stdout.splitlines()[0]
    data = CliRunner().invoke(main, ["goals", "--dishes", "--json"])
    assert json.loads(data.stdout)["kitchen"] == "foon2pddl/data/example_kitchen.txt"


def test_a_bare_label_with_no_dish_and_no_final_product_says_any_of_its_nodes_will_do():
    """docs/format.md: the command says which nodes a bare label was read as. Every `avocado` node of the example
    is used by some unit (none is a dish or a final product), so any of them satisfies the goal and retrieval
    makes the one it reaches first (the avocado put on the board, 1 unit): a note says so and names them."""
    from click.testing import CliRunner

    from foon2pddl.cli import main

    result = CliRunner().invoke(main, ["retrieve", "--goal", "avocado"])
    assert result.exit_code == 0, result.output
    notes = [x for x in result.stderr.splitlines() if x.startswith("note: goal 'avocado'")]
    assert len(notes) == 1, result.stderr
    assert notes[0].startswith("note: goal 'avocado' names no recipe's dish and no final product (a unit uses each "
                               "'avocado' node): any of its 4 nodes will do, the method chooses which "
                               "(give the states to ask for one): `avocado (halved, on [cutting board])`; "), notes
    single = CliRunner().invoke(main, ["retrieve", "--goal", "guacamole: in [bowl]"])  # states given: no note
    assert "note: goal" not in single.stderr


def test_dishes_of_a_network_that_marks_none_say_so_and_name_the_whole_list():
    """`goals FOON-0076-bloody_mary.txt --dishes` (the converter's example) printed `0 of 0 dishes` and nothing
    else (newcomer pass nc50b): a network whose O lines mark no dish gets a note saying so and naming `goals`
    without --dishes, which lists its 20 goal candidates."""
    from click.testing import CliRunner
    from conftest import ROOT

    from foon2pddl.cli import main

    net = str(ROOT / "tests/data/foon_to_pddl-examples/FOON-0076-bloody_mary.txt")
    r = CliRunner().invoke(main, ["goals", net, "--dishes"])
    assert r.exit_code == 0 and r.stdout.startswith("reachable: 0 of 0 dishes"), r.output
    assert "note: no node of this network is marked as a recipe's dish" in r.stderr, r.stderr
    assert "`goals` without --dishes lists every goal candidate" in r.stderr, r.stderr
    marked = CliRunner().invoke(main, ["goals", "--dishes"])
    assert marked.exit_code == 0 and "marked as a recipe's dish" not in marked.stderr


def test_the_legend_names_a_network_not_taken_as_read():
    """The legend says which network it counts on (` on FOON-GEN`), and nothing for the one taken as read; the slow
    step (` of FOON-EXP`, tests/test_slow_steps.py) names it through the same helper."""
    from click.testing import CliRunner

    from foon2pddl.cli import main
    from foon2pddl.cli.goals_cmd import _which_foon

    for network, said in (("gen", " on FOON-GEN (round"), ("reg", " can be made from foon2pddl/data/example_kitchen.txt (round")):
        r = CliRunner().invoke(main, ["goals", "--dishes", "--network", network])
        assert r.exit_code == 0 and said in r.stdout.splitlines()[0], r.output
    assert (_which_foon("of", "exp"), _which_foon("on", "reg")) == (" of FOON-EXP", "")
