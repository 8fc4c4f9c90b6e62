"""Smallest kitchen additions for an unreachable goal, against brute force on small random FOONs."""

from __future__ import annotations

from itertools import combinations

from click.testing import CliRunner
from foon_strategies import foons
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.additions import first_additions, smallest_additions
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


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(foons(min_units=1, max_units=8), st.data())
def test_growing_sizes_find_what_one_search_of_the_largest_size_finds(foon, data):
    # a family's sets of at most k nodes come from its inputs' sets of at most k alone, and a cut keeps the
    # smallest first: trying 1, 2, 3 and stopping at the first size that finds a set gives the same smallest
    # sets as one search of size 3, even when small `keep`s cut the families
    addable = sorted(default_kitchen(foon).nodes)
    kitchen = data.draw(st.lists(st.sampled_from(addable), unique=True, max_size=len(addable))) if addable else []
    goals = data.draw(st.lists(st.sampled_from(sorted(foon.producers)), min_size=1, max_size=2, unique=True))
    keep = data.draw(st.integers(1, 4))
    inner = data.draw(st.booleans())  # the cycle question: any node the goals depend on, the goals excluded
    reach = reachable(foon, kitchen, goals)
    pool = [n for n in foon.nodes if n not in set(goals)] if inner else addable
    once = smallest_additions(reach, goals, pool, max_size=3, keep=keep)
    grown = first_additions(reach, goals, None if inner else addable, sizes=(1, 2, 3), keep=keep)
    assert grown.smallest == once.smallest
    if not once.sets:  # nothing found: exact when the one search was, or when no set of any size exists
        assert grown.exact >= once.exact
        if grown.exact and not once.exact:
            assert not any(reachable(foon, set(kitchen) | set(pool)).can_make(g) for g in goals)


def test_no_search_runs_when_even_every_addable_node_cannot_make_the_goal():
    # dough needs starter and a topping, starter needs dough: no kitchen addition enters the cycle, whatever its
    # size. With `keep=1` the topping's two makers cut its family, so the searches alone could only say they may
    # have missed a set; one fixpoint with every addable node added proves there is none: exact
    from foon2pddl.io.parser import parse_text

    foon = parse_text("//\nO\tstarter\t1\nS\tactive\nO\ttopping\t1\nS\tready\nM\tmix\nO\tdough\t1\nS\tmixed\n"
                      "//\nO\tdough\t1\nS\tmixed\nM\tferment\nO\tstarter\t1\nS\tactive\n"
                      "//\nO\tseed\t1\nS\twhole\nM\tgrind\nO\ttopping\t1\nS\tready\n"
                      "//\nO\tnut\t1\nS\twhole\nM\tchop\nO\ttopping\t1\nS\tready\n//\n", "cycle.txt").foon
    dough = next(n for n in foon.nodes if n.label == "dough")
    reach = reachable(foon, [], [dough])
    addable = default_kitchen(foon).nodes
    assert not smallest_additions(reach, [dough], addable, max_size=4, keep=1).exact  # the search alone
    found = first_additions(reach, [dough], addable, sizes=(3, 4), keep=1)
    assert found.sets == () and found.exact
