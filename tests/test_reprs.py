"""Short reprs of networks and task trees, and their Jupyter (HTML) reprs."""

from __future__ import annotations

import html.parser

from foon2pddl.io.inputs import load_kitchen
from foon2pddl.model.goal import GoalSpec, resolve_goal
from foon2pddl.retrieval import retrieve


class _Tags(html.parser.HTMLParser):
    """Collects start tags and text; fails on unbalanced table markup through the counts."""

    def __init__(self) -> None:
        super().__init__()
        self.opened: list[str] = []
        self.closed: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.opened.append(tag)

    def handle_endtag(self, tag):
        self.closed.append(tag)

    def handle_data(self, data):
        self.text.append(data)


def _parse(markup: str) -> _Tags:
    p = _Tags()
    p.feed(markup)
    return p


def _tree(example, goal="guacamole"):
    foon = example.at(3)
    kitchen = load_kitchen(None, example, 3)
    return retrieve(foon, kitchen, resolve_goal(GoalSpec(goal), foon), "optimal").tree


def test_network_repr_is_short_and_counts(example):
    foon = example.foon
    text = repr(foon)
    assert len(text) < 200
    assert f"{len(foon.units)} units" in text
    assert f"{len(foon.nodes)} object nodes" in text
    assert "level 3" in text


def test_task_tree_repr_names_goal_and_unit_count(example):
    tree = _tree(example)
    text = repr(tree)
    assert len(text) < 300
    assert tree.goal.describe() in text
    assert f"{len(tree.units)} units" in text


def test_network_html_is_a_summary_table(example):
    foon = example.foon
    markup = foon._repr_html_()
    tags = _parse(markup)
    assert tags.opened.count("table") == 1 and tags.closed.count("table") == 1
    assert str(len(foon.units)) in tags.text and str(len(foon.motions)) in tags.text
    assert len(markup) < 3000


def test_task_tree_html_lists_every_step_escaped(example):
    tree = _tree(example)
    markup = tree._repr_html_()
    tags = _parse(markup)
    assert tags.opened.count("li") == len(tree.units)
    text = "".join(tags.text)
    assert all(u.motion.label in text for u in tree.units)
    # labels with markup characters are escaped, not interpreted
    from dataclasses import replace

    from foon2pddl.model.foon import make_node
    odd = replace(tree, goal=make_node("<b>x</b> & y"))
    assert "<b>x</b>" not in odd._repr_html_() and "&lt;b&gt;" in odd._repr_html_()


def test_kitchen_repr_counts_and_shows_a_few_nodes(example):
    kitchen = load_kitchen(None, example, 3)
    text = repr(kitchen)
    assert text.startswith(f"<Kitchen level 3: {len(kitchen.nodes)} nodes") and text.endswith(", ...)>")
    assert len(text) < 300 and "frozenset" not in text
