"""The embedded example network and kitchen: well-formed, one dish per recipe, kitchen consistent."""

from __future__ import annotations

import re

import pytest

from foon2pddl.io.files import expand_paths
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.io.parser import parse_file, read_text
from foon2pddl.model.kitchen import starting_nodes

RECIPES = expand_paths([example_path()])
HEADER = "# Source:\tfoon2pddl example network (original recipe)"


@pytest.fixture(scope="module")
def kitchen():
    return read_kitchen(example_path("example_kitchen.txt"))


def test_example_has_enough_recipes_and_units(example):
    assert len(RECIPES) >= 8
    assert all(re.fullmatch(r"\d\d-[a-z_]+\.foon", p.name) for p in RECIPES)
    assert len(example.foon.units) >= 60
    assert example.is_example
    assert example.warnings == ()


@pytest.mark.parametrize("path", RECIPES, ids=lambda p: p.name)
def test_recipe_file_is_idless_with_header_and_one_dish(path):
    text = read_text(path)
    lines = text.splitlines()
    assert lines[0] == HEADER
    assert lines[1].startswith("# ") and len(lines[1]) > 10
    assert not [ln for ln in lines if re.match(r"[OSM]\d", ln)], "object/state/motion ids in an id-less file"
    result = parse_file(path)
    assert result.warnings == ()
    dishes = [n for u in result.foon.units for n in u.outputs if n.dish is not None]
    assert len(dishes) == 1
    # the dish is the recipe's final product: no unit of the recipe consumes it
    assert dishes[0] not in result.foon.consumers


def test_dish_markers_are_distinct(example):
    dishes = [n.dish for u in example.foon.units for n in u.outputs if n.dish is not None]
    assert len(dishes) == len(RECIPES) == len(set(dishes))


def test_recipes_share_units(example):
    shared = [u for u in example.foon.units if len({s.path for s in u.sources}) > 1]
    assert len(shared) >= 5


def test_kitchen_reads_and_its_labels_are_in_the_network(example, kitchen):
    assert len(kitchen) >= 30
    labels = {n.label for n in example.foon.nodes}
    assert {n.label for n in kitchen.nodes} <= labels


def test_kitchen_holds_every_starting_node_except_lemon(example, kitchen):
    """The deliberate gap: lime but no lemon, so only the lemon units lack a starting object."""
    missing = {n.label for n in starting_nodes(example.foon) if n not in kitchen}
    assert missing == {"lemon"}
    assert "lime" in {n.label for n in kitchen.nodes}
