"""Kitchens: three file formats, the public search projects' kitchen.json, and the default-kitchen rule."""

from __future__ import annotations

import json

import pytest
from conftest import SEARCH_INPUTS

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.inputs import load_kitchen, load_network
from foon2pddl.io.kitchen_files import read_kitchen, write_kitchen
from foon2pddl.io.parser import parse_text
from foon2pddl.model.foon import make_node, make_state
from foon2pddl.model.kitchen import BASE_STATES, Kitchen, default_kitchen, starting_nodes
from foon2pddl.model.levels import project, project_node

EXPECTED = {
    make_node("bowl", [make_state("empty")]),
    make_node("knife"),
    make_node("onion", [make_state("whole"), make_state("in", "fridge")]),
    make_node("pot", [make_state("contains", "", ["salt", "water"]), make_state("on", "stove")]),
}

FOON_STYLE = """# FOON-style kitchen: objects end at '//' or at the next O line
//
O1\tBowl\t0
S1\tempty
O2\tknife\t1
//
O\tonion
S\twhole
S\tin\t[fridge]
//
O\tpot
S\tcontains\t{water,salt,}
S\ton\t[stove]
"""

JSON_STYLE = [
    {"label": "bowl", "states": ["empty"], "ingredients": [], "container": None},
    {"label": "Knife", "states": [], "ingredients": [], "container": None},
    {"label": "onion", "states": ["whole"], "ingredients": [], "container": "fridge"},
    {"label": "pot", "states": ["on [stove]"], "ingredients": ["water", "salt"], "container": None},
]

LINE_STYLE = """# one node per line, in the goal syntax
bowl: empty
knife
onion: whole, in [fridge]
pot: contains {salt, water}, on [stove]
"""


def test_three_formats_read_the_same_kitchen(tmp_path):
    (tmp_path / "k.txt").write_text(FOON_STYLE.replace("\n", "\r\n"))
    (tmp_path / "k.json").write_text(json.dumps(JSON_STYLE))
    (tmp_path / "k.kitchen").write_text(LINE_STYLE)
    kitchens = [read_kitchen(tmp_path / name) for name in ("k.txt", "k.kitchen")]
    for k in kitchens:
        assert k.nodes == EXPECTED
        assert k.level == 3 and k.source.endswith(("k.txt", "k.kitchen"))
    as_json = read_kitchen(tmp_path / "k.json")
    # the JSON convention has no related objects in `states`: "on [stove]" stays a plain state label
    assert as_json.nodes - EXPECTED == {make_node("pot", [make_state("on [stove]"),
                                                          make_state("contains", "", ["salt", "water"])])}
    assert len(as_json.nodes & EXPECTED) == 3


def test_json_convention_maps_container_and_ingredients():
    k = read_kitchen(SEARCH_INPUTS / "kitchen.json")
    raw = json.loads((SEARCH_INPUTS / "kitchen.json").read_text())
    naive = {
        (" ".join(i["label"].split()).lower(), frozenset(s.strip().lower() for s in i["states"] if s.strip()),
         (i["container"] or "").strip().lower(), frozenset(x.strip().lower() for x in i["ingredients"]))
        for i in raw
    }
    assert len(k) == len(naive)
    pot = make_node("pot", [make_state("hot"), make_state("in", "stove"),
                            make_state("contains", "", ["mushroom", "onion"])])
    assert pot in k
    with_ingredients = {t for t in naive if t[3]}
    assert sum(any(s.label == "contains" and s.ingredients for s in n.states) for n in k.nodes) == len(with_ingredients)
    in_container = {t for t in naive if t[2]}
    assert sum(any(s.label == "in" and s.related for s in n.states) for n in k.nodes) == len(in_container)


def test_json_errors_name_the_item(tmp_path):
    bad = tmp_path / "k.json"
    bad.write_text('[{"label": "bowl", "states": []},\n {"label": "cup", "states": "empty"}]')
    with pytest.raises(FoonSyntaxError, match=r"item 2 \(cup\): 'states' must be a list"):
        read_kitchen(bad)
    bad.write_text('[{"label": "bowl"},\n {"label": }]')
    with pytest.raises(FoonSyntaxError) as info:
        read_kitchen(bad)
    assert info.value.line == 2 and "invalid JSON" in info.value.message
    bad.write_text('{"label": "bowl"}')
    with pytest.raises(FoonSyntaxError, match="expected a JSON list"):
        read_kitchen(bad)
    bad.write_text('[{"states": []}]')
    with pytest.raises(FoonSyntaxError, match="item 1: expected an object with a non-empty string 'label'"):
        read_kitchen(bad)


@pytest.mark.parametrize(("text", "line", "expected"), [
    ("O\tbowl\nM\tpour\n", 2, "a motion line ('M'): this file is a FOON network"),
    ("//\nS\tempty\n", 2, "before any object"),
    ("bowl: empty\nonion: in [fridge\n", 2, "unbalanced bracket"),
    ("bowl: empty\n: whole\n", 2, "no object label"),
    ("# nothing\n", 0, "lists no object nodes"),
    # `0 x bowl` read as a bowl by retrieve and as none by plan (stop 59's newcomer pass): one reading, an error
    ("onion: whole\n0 x bowl: empty\n", 2, "a count of 0 lists no object"),
    # read as the labels `-1 x bowl`, `1.5 x bowl`, `2 x`, each a warning only (stop 60's newcomer pass)
    ("onion: whole\n-1 x bowl: empty\n", 2, "a count of -1: a count is a whole number of at least 1"),
    ("1.5 x bowl: empty\n", 1, "a count of 1.5: a count is a whole number of at least 1"),
    ("onion: whole\n2 x\n", 2, "a count of 2: a count is a whole number of at least 1, then the node"),
])
def test_kitchen_file_errors_name_the_line(tmp_path, text, line, expected):
    path = tmp_path / "k.txt"
    path.write_text(text)
    with pytest.raises(FoonSyntaxError) as info:
        read_kitchen(path)
    assert (info.value.path, info.value.line) == (str(path), line)
    assert expected in info.value.message


def test_write_kitchen_reads_back(tmp_path):
    k = Kitchen(frozenset(EXPECTED))
    (tmp_path / "k.txt").write_text(write_kitchen(k))
    assert read_kitchen(tmp_path / "k.txt").nodes == k.nodes
    assert write_kitchen(k) == write_kitchen(Kitchen(frozenset(reversed(list(EXPECTED)))))


def test_kitchen_projects_to_lower_levels():
    k = Kitchen(frozenset(EXPECTED))
    two = k.project(2)
    assert two.level == 2 and make_node("pot", [make_state("contains"), make_state("on", "stove")]) in two
    one = k.project(1)
    assert one.nodes == {make_node(label) for label in ("bowl", "knife", "onion", "pot")}
    assert one.project(3) is one


# ---------------------------------------------------------------- default kitchen

MIXER = """//
O\tmixer
S\toff
O\tbowl
S\tcontains\t{cream}
M\tturn on
O\tmixer
S\ton
O\tbowl
S\tcontains\t{cream}
//
O\tmixer
S\ton
O\tbowl
S\tcontains\t{cream}
M\tmix
O\tbowl
S\tcontains\t{whipped cream}
//
O\tmixer
S\ton
M\tturn off
O\tmixer
S\toff
//
O\tbowl
S\tcontains\t{whipped cream}
O\tspoon
M\tstir
O\tbowl
S\tcontains\t{whipped cream}
O\tspoon
S\tdirty
"""


def node(label, *states):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states])


def test_starting_nodes_are_inputs_no_unit_creates():
    foon = parse_text(MIXER).foon
    # mixer (off) is produced by 'turn off'; the bowl is passed through unchanged by 'turn on' and 'stir'
    assert starting_nodes(foon) == {node("bowl", ("contains", "", ["cream"])), node("spoon")}


def test_default_kitchen_adds_inputs_in_base_states():
    foon = parse_text(MIXER).foon
    kitchen = default_kitchen(foon)
    assert kitchen.nodes == starting_nodes(foon) | {node("mixer", "off")}
    assert node("mixer", "on") not in kitchen
    assert default_kitchen(foon, base_states=()).nodes == starting_nodes(foon)
    assert "off" in BASE_STATES and "on" not in BASE_STATES


def test_base_state_rule_needs_every_state_plain_and_basic():
    text = MIXER + "//\nO\tmixer\nS\toff\nS\tin\t[cupboard]\nM\ttake\nO\tmixer\nS\toff\n"
    kitchen = default_kitchen(parse_text(text).foon)
    assert node("mixer", "off", ("in", "cupboard")) in kitchen  # a starting node anyway
    produced = parse_text("O\tx\nM\tm\nO\tpan\nS\tempty\nS\thot\n//\nO\tpan\nS\tempty\nS\thot\nM\tn\nO\ty\n").foon
    assert node("pan", "empty", "hot") not in default_kitchen(produced)


def test_default_kitchen_of_a_projected_network_is_at_its_level(universal):
    foon, _ = universal
    for level in (1, 2):
        k = default_kitchen(project(foon, level))
        assert k.level == level
        assert k.nodes <= set(project(foon, level).nodes)
        assert all(n.states == () for n in k.nodes) == (level == 1)


def test_load_kitchen_chooses_file_example_or_default(tmp_path, example):
    (tmp_path / "r.foon").write_text(MIXER)
    net = load_network([str(tmp_path / "r.foon")])
    assert load_kitchen(None, net, 3).nodes == default_kitchen(net.foon).nodes
    assert load_kitchen(None, net, 1).level == 1
    (tmp_path / "k.txt").write_text(LINE_STYLE)
    assert load_kitchen(tmp_path / "k.txt", net, 2).nodes == {project_node(n, 2) for n in EXPECTED}
    ex = load_kitchen(None, example, 3)
    assert ex.source.endswith("example_kitchen.txt") and ex.nodes != default_kitchen(example.foon).nodes


def test_the_first_line_that_lists_each_node_one_rule_for_files_levels_and_scenes():
    """`Kitchen.project` (nodes of a file's lines merging at a level) and `Kitchen.line_numbers` (a scene's objects)
    computed "the first line listing each node" apart: one helper over (node, line) pairs keeps the smallest."""
    from foon2pddl.model.kitchen import first_lines, scene_kitchen
    from foon2pddl.model.scene import SceneObject

    chopped, whole = make_node("onion", [make_state("chopped")]), make_node("onion", [make_state("whole")])
    assert first_lines([(chopped, 7), (whole, 3), (chopped, 2)]) == {chopped: 2, whole: 3}
    kitchen = Kitchen(frozenset({chopped, whole}), lines=((chopped, 7), (whole, 3)))
    assert kitchen.project(1).line_numbers() == {make_node("onion"): 3}
    bowl = make_node("bowl", [make_state("empty")])
    scene = scene_kitchen([SceneObject("bowl_2", "bowl", bowl, line=9), SceneObject("bowl_1", "bowl", bowl, line=4)])
    assert scene.line_numbers() == {bowl: 4}
