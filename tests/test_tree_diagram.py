"""DOT/SVG task trees: a legend, and kitchen utensils drawn once per use (read back through Graphviz)."""

from __future__ import annotations

import json
import subprocess
from collections import Counter

import pytest

from foon2pddl.io.inputs import load_kitchen
from foon2pddl.io.tree_formats import render_tree
from foon2pddl.model.goal import GoalSpec, resolve_goal
from foon2pddl.retrieval import retrieve


@pytest.fixture(scope="module")
def guacamole(example):
    foon = example.at(3)
    kitchen = load_kitchen(None, example, 3)
    return retrieve(foon, kitchen, resolve_goal(GoalSpec("guacamole"), foon), "optimal").tree, kitchen


def graph(dot_text: str) -> dict:
    """The graph as Graphviz itself reads it (an independent parser)."""
    done = subprocess.run(["dot", "-Tjson0"], input=dot_text, capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def test_dot_has_a_legend_naming_every_colour(guacamole):
    tree, kitchen = guacamole
    g = graph(render_tree(tree, "dot", kitchen=kitchen))
    legend = [s for s in g.get("objects", []) if s.get("name") == "cluster_legend"]
    assert legend, "no legend cluster"
    labels = {o.get("label") for o in g["objects"] if o.get("name", "").startswith("legend_")}
    assert {"from the kitchen", "made by a step", "step (motion)", "goal", "utensil (drawn once per use)"} <= labels


def test_utensils_are_drawn_once_per_use(guacamole):
    tree, kitchen = guacamole
    g = graph(render_tree(tree, "dot", kitchen=kitchen))
    objects = g["objects"]
    degree = Counter()
    for e in g.get("edges", []):
        degree[e["tail"]] += 1
        degree[e["head"]] += 1
    made = {n for u in tree.units for n in u.outputs if n not in u.inputs}
    uses = Counter(n for u in tree.units for n in dict.fromkeys(u.inputs) if n not in made)
    shared = [n for n, k in uses.items() if k > 1]
    assert shared, "the guacamole tree reuses kitchen utensils"
    for node in shared:
        label = node.label + ("\\n" + "\\n".join(s.describe() for s in node.states) if node.states else "")
        copies = [i for i, o in enumerate(objects) if o.get("label") == label and not o["name"].startswith("legend")]
        assert len(copies) == uses[node], node.describe()
        assert all(degree[i] == 1 for i in copies)  # each copy touches its one step


def test_svg_renders_with_legend(guacamole):
    tree, kitchen = guacamole
    svg = render_tree(tree, "svg", kitchen=kitchen)
    assert svg.lstrip().startswith("<?xml") and "from the kitchen" in svg
