"""Every `--goal` a page shows names a node of the network it is shown on.

README gave `--goal 'bowl: contains {lettuce, tomato}'` as a syntax example (so did format.md's goal table);
on the embedded example network it matches no node, and a newcomer who copies it gets exit 2. The
transcript and docs-claims tests run only `foon2pddl ...` commands, so a bare `--goal X` of prose was never
run. Here each value is resolved as its command resolves it (its PATHS, `--network`, `--level` and
encoding; a bare `--goal X` on the embedded example network, as `retrieve` reads it), without the
search, so all of them take a few seconds.
"""

from __future__ import annotations

import click
import pytest
from conftest import ROOT

from bench.doc_commands import goal_examples
from foon2pddl.cli import main
from foon2pddl.cli.loading import load_pddl_view, load_view, view_goal

EXAMPLES = goal_examples()


def test_the_pages_goal_examples_are_read():
    shown = {(e.where.split(":")[0], e.command, e.goal) for e in EXAMPLES}
    assert ("README.md", "retrieve", "onion: chopped") in shown  # a bare option example of prose
    assert ("docs/format.md", "retrieve", "frying pan: on [stove], contains {butter}") in shown  # the goal syntax table
    assert ("docs/generalization.md", "plan", "beverages") in shown  # a span of prose, past a stray backtick
    assert ("docs/retrieval.md", "retrieve", "greek salad") not in shown  # a synopsis (`[--method ...]`)
    assert not any(e.goal in ("G", "TEXT", "LABEL") for e in EXAMPLES)


def _resolve(command: str, args: tuple[str, ...], goal: str) -> None:
    """Resolve `goal` as `foon2pddl command args` does (raises its `click.BadParameter` when it names no node)."""
    with main.make_context("foon2pddl", [command, *args], resilient_parsing=True) as outer:
        cmd = main.get_command(outer, command)
        with cmd.make_context(command, list(args), parent=outer, resilient_parsing=True) as ctx:
            p = ctx.params
            if command == "retrieve":
                view, encoding = load_view(p["paths"], None, p["level"], p["network"])[1], None
            else:
                _, view, encoding = load_pddl_view(p["paths"], None, p["level"], p["network"], p["encoding"], None)
            view_goal(view, goal, None, p["level"], encoding)


@pytest.mark.parametrize("example", EXAMPLES, ids=[f"{e.where}: {e.goal}" for e in EXAMPLES])
def test_a_goal_a_page_shows_names_a_node(example, monkeypatch):
    monkeypatch.chdir(ROOT)
    try:
        _resolve(example.command, example.args, example.goal)
    except click.ClickException as exc:
        pytest.fail(f"{example.where}: --goal {example.goal!r} ({example.command} {' '.join(example.args)}): "
                    f"{exc.format_message()}")
