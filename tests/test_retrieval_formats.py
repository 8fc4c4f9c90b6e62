"""Task tree formats on a hand-made tree, and the motion success rates reader."""

from __future__ import annotations

import json
import math
import re

import pytest
from conftest import SEARCH_INPUTS

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.parser import parse_text
from foon2pddl.io.rates import parse_rates
from foon2pddl.io.tree_formats import INPUT_COLOUR, MOTION_COLOUR, OUTPUT_COLOUR, step_text
from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.tasktree import TaskTree
from foon2pddl.retrieval import DEFAULT_RATE, read_rates, render_tree

BOARD = make_node("cutting board")
KNIFE = make_node("knife", motion_flag=1)
WHOLE = make_node("onion", [make_state("whole"), make_state("on", "cutting board")], motion_flag=1)
CHOPPED = make_node("onion", [make_state("chopped"), make_state("on", "cutting board")])
BOWL = make_node("bowl", [make_state("empty")])
IN_BOWL = make_node("onion", [make_state("chopped"), make_state("in", "bowl")])
FULL_BOWL = make_node("bowl", [make_state("contains", "", ["onion"])])
CHOP = FunctionalUnit((WHOLE, KNIFE, BOARD), Motion("chop"), (CHOPPED, KNIFE, BOARD))
MOVE = FunctionalUnit((CHOPPED, BOWL), Motion("pick-and-place"), (IN_BOWL, FULL_BOWL))
TREE = TaskTree((CHOP, MOVE), FULL_BOWL)
KITCHEN = {WHOLE, KNIFE, BOARD, BOWL}


def test_step_names_object_tool_place_and_result():
    assert step_text(CHOP) == ("chop onion (on [cutting board], whole) with knife on cutting board "
                               "-> onion (chopped, on [cutting board])")


def test_steps_are_numbered_in_tree_order_and_list_kitchen_items():
    lines = render_tree(TREE, "steps", KITCHEN).splitlines()
    assert lines[1] == "from the kitchen: bowl (empty); cutting board; knife; onion (on [cutting board], whole)"
    assert lines[2].startswith("1. chop ") and lines[3].startswith("2. pick-and-place ")
    assert lines[3].endswith("-> onion (chopped, in [bowl]), bowl (contains {onion})")


def test_foon_text_reparses_to_the_same_units():
    text = render_tree(TREE, "foon", KITCHEN)
    assert text.startswith("# task tree for bowl (contains {onion})")
    assert parse_text(text, "<tree>").foon.units == TREE.units


def test_json_holds_goal_steps_and_kitchen_items():
    data = json.loads(render_tree(TREE, "json", KITCHEN))
    assert data["goal"]["label"] == "bowl" and data["level"] == 3 and data["units"] == 2
    assert [s["motion"] for s in data["steps"]] == ["chop", "pick-and-place"]
    assert data["steps"][0]["inputs"][1] == {"label": "knife", "states": [], "motion_flag": 1}
    assert [n["label"] for n in data["from_kitchen"]] == ["bowl", "cutting board", "knife", "onion"]
    assert "from_kitchen" not in json.loads(render_tree(TREE, "json"))


def test_dot_colours_inputs_green_outputs_blue_motions_red():
    dot = render_tree(TREE, "dot")
    nodes = dict(re.findall(r'^  (o\d+) \[label="([^"]*)"', dot, re.M))
    colour = dict(re.findall(r'^  (o\d+) .*fillcolor="([^"]+)"', dot, re.M))
    by_label = {label.replace("\\n", " | "): colour[i] for i, label in nodes.items()}
    assert by_label["knife"] == INPUT_COLOUR  # passed through unchanged: not made by the tree
    assert by_label["onion | on [cutting board] | whole"] == INPUT_COLOUR
    assert by_label["onion | chopped | on [cutting board]"] == OUTPUT_COLOUR
    assert by_label["bowl | contains {onion}"] == OUTPUT_COLOUR
    assert len(re.findall(r'^  m\d+ \[.*fillcolor="' + MOTION_COLOUR, dot, re.M)) == 2
    assert "penwidth=3" in next(line for line in dot.splitlines() if 'label="bowl\\ncontains {onion}"' in line)


def test_dot_escapes_quotes_and_backslashes():
    odd = make_node('say "hi" \\ bye')
    tree = TaskTree((FunctionalUnit((BOWL,), Motion("mix"), (odd,)),), odd)
    dot = render_tree(tree, "dot")
    assert 'label="say \\"hi\\" \\\\ bye"' in dot


def test_svg_is_rendered_by_graphviz():
    svg = render_tree(TREE, "svg")
    assert "<svg" in svg and "chop" in svg


def test_shared_rates_file_reads_every_line():
    path = SEARCH_INPUTS / "motion.txt"
    rates = read_rates(path)
    lines = [ln for ln in path.read_text().splitlines() if ln.strip()]
    assert len(rates.table) == len(lines)
    label, value = lines[0].split("\t")
    assert rates.rate(label) == float(value)
    assert rates.rate("no such motion") == DEFAULT_RATE
    assert math.isclose(rates.cost(label), -math.log(float(value)))


def test_rates_normalize_labels_and_drop_the_composite_star():
    rates = parse_rates("# comment\n\n  Turn   On\t0.3\npour*\t0.9\n", default=0.25)
    assert rates.rate("turn on") == 0.3 and rates.rate("pour") == 0.9 and rates.rate("mix") == 0.25


@pytest.mark.parametrize(("text", "line", "message"), [
    ("chop\t0.5\npour\n", 2, "expected 'motion<TAB>rate'"),
    ("chop\t1.5\n", 1, "not in (0, 1]"),
    ("chop\t0\n", 1, "not in (0, 1]"),
    ("chop\t0.5\nmix\t0.2\nchop\t0.6\n", 3, "already has rate 0.5 (line 1)"),
    ("chop\tnan?\n", 1, "not a number"),
])
def test_bad_rates_name_file_and_line(text, line, message):
    with pytest.raises(FoonSyntaxError) as err:
        parse_rates(text, "rates.txt")
    assert err.value.path == "rates.txt" and err.value.line == line and message in err.value.message
