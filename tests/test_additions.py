"""Smallest kitchen additions for an unreachable goal, against brute force on small random FOONs."""

from __future__ import annotations

from itertools import combinations

from click.testing import CliRunner
from foon_strategies import foons
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.additions import smallest_additions
from foon2pddl.analysis.reachability import reachable
from foon2pddl.cli import main
from foon2pddl.model.kitchen import default_kitchen


def brute_force(foon, kitchen, goals, addable, max_size):
    """Every inclusion-minimal set of at most `max_size` addable nodes that lets a goal be made."""
    pool = sorted(set(addable) - set(kitchen))
    found: list[frozenset] = []
    for size in range(max_size + 1):
        for combo in combinations(pool, size):
            s = frozenset(combo)
            if any(t <= s for t in found):
                continue
            reach = reachable(foon, set(kitchen) | s)
            if any(reach.can_make(g) for g in goals):
                found.append(s)
    return set(found)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(foons(min_units=1, max_units=7), st.data())
def test_additions_equal_brute_force(foon, data):
    addable = sorted(default_kitchen(foon).nodes)
    kitchen = data.draw(st.lists(st.sampled_from(addable), unique=True, max_size=len(addable))) if addable else []
    produced = sorted(foon.producers)
    goals = data.draw(st.lists(st.sampled_from(produced), min_size=1, max_size=2, unique=True))
    targeted = data.draw(st.booleans())
    reach = reachable(foon, kitchen, goals if targeted else None)
    result = smallest_additions(reach, goals, addable, max_size=3, keep=10_000)
    assert result.exact
    expected = brute_force(foon, kitchen, goals, addable, 3)
    assert {frozenset(s) for s in result.sets} == expected
    sizes = [len(s) for s in result.sets]
    assert sizes == sorted(sizes)  # smallest first
    if result.sets:
        assert all(len(s) == sizes[0] for s in result.smallest)


def test_cut_families_are_reported_inexact_but_every_set_still_works():
    from foon2pddl.io.inputs import load_network
    from foon2pddl.model.goal import GoalSpec, resolve_goal

    net = load_network([])
    foon = net.at(3)
    goal = resolve_goal(GoalSpec("guacamole"), foon)
    reach = reachable(foon, [], goal.candidates)
    addable = default_kitchen(foon).nodes
    full = smallest_additions(reach, goal.candidates, addable, max_size=12, keep=1)
    assert not full.exact
    for s in full.sets:
        assert any(reachable(foon, set(s)).can_make(c) for c in goal.candidates)


def test_unreachable_goal_explains_with_the_smallest_additions(tmp_path):
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("knife\nbowl: empty\n")
    r = CliRunner().invoke(main, ["retrieve", "--goal", "onion: chopped", "--kitchen", str(kitchen)])
    assert r.exit_code == 1
    assert "add `cutting board (empty)` and `onion (whole)`" in r.stderr
    # the full list of every leaf of every alternative is gone
    assert "avocado" not in r.stderr and "juicer" not in r.stderr


def test_lemonade_needs_one_lemon():
    r = CliRunner().invoke(main, ["retrieve", "--goal", "lemonade"])
    assert r.exit_code == 1 and "add `lemon (whole)`" in r.stderr


def test_plan_explains_an_unsolvable_goal_with_the_smallest_additions():
    r = CliRunner().invoke(main, ["plan", "--goal", "lemonade"])
    assert r.exit_code == 1 and "reason: " in r.stderr and "add `lemon (whole)`" in r.stderr
