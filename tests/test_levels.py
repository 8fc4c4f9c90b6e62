"""Hierarchy levels: what each level keeps of a node, and projecting whole networks."""

from __future__ import annotations

import pytest
from foon_strategies import foons, full, nodes
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.model.dedupe import dedupe_units
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, State, make_node, make_state
from foon2pddl.model.levels import check_level, project, project_node, project_unit

BOWL = make_node("bowl", [make_state("contains", "", ["salt", "water"]), make_state("on", "stove")],
                 motion_flag=1, dish=4, goal=True)


def test_project_node_keeps_what_each_level_defines():
    assert project_node(BOWL, 3) is BOWL
    two = project_node(BOWL, 2)
    assert two.states == (State("contains"), State("on", "stove"))
    one = project_node(BOWL, 1)
    assert (one.label, one.states) == ("bowl", ())
    for n in (one, two):
        assert (n.motion_flag, n.dish, n.goal) == (1, 4, True)


def test_level_2_merges_states_that_differ_only_in_ingredients():
    a = make_node("bowl", [make_state("contains", "", ["salt"])])
    b = make_node("bowl", [make_state("contains", "", ["salt", "pepper"])])
    c = make_node("bowl", [make_state("contains", "", ["salt"]), make_state("contains")])
    assert a != b
    assert project_node(a, 2) == project_node(b, 2) == project_node(c, 2)
    assert len(project_node(c, 2).states) == 1


@settings(max_examples=80, deadline=None)
@given(a=nodes(st.sampled_from(["x", "y"])), b=nodes(st.sampled_from(["x", "y"])))
def test_identity_is_coarser_at_lower_levels(a, b):
    if a == b:
        assert project_node(a, 2) == project_node(b, 2)
    if project_node(a, 2) == project_node(b, 2):
        assert project_node(a, 1) == project_node(b, 1)
    assert (project_node(a, 1) == project_node(b, 1)) == (a.label == b.label)
    same_2 = {(s.label, s.related) for s in a.states} == {(s.label, s.related) for s in b.states}
    assert (project_node(a, 2) == project_node(b, 2)) == (a.label == b.label and same_2)
    if a == b:
        assert hash(project_node(a, 2)) == hash(project_node(b, 2))


def test_project_unit_keeps_a_node_per_object():
    """Two bowls that differ only by their lists stay two bowls at level 2 (issue 21: the unit's objects)."""
    salty = make_node("bowl", [make_state("contains", "", ["salt"])])
    sweet = make_node("bowl", [make_state("contains", "", ["sugar"])])
    unit = FunctionalUnit((salty, sweet), Motion("mix"), (salty,), (Source("f", 3),))
    two = project_unit(unit, 2)
    assert len(two.inputs) == 2 and two.inputs[0] == two.inputs[1] and two.sources == unit.sources
    assert project_unit(unit, 3) is unit


def test_project_merges_units_that_became_equal_and_joins_provenance():
    onion = make_node("onion", [make_state("whole")])
    red = make_node("onion", [make_state("sliced"), make_state("in", "bowl", ["red"])])
    white = make_node("onion", [make_state("sliced"), make_state("in", "bowl", ["white"])])
    knife = make_node("knife")
    units = (
        FunctionalUnit((onion, knife), Motion("slice"), (red,), (Source("a", 1),)),
        FunctionalUnit((onion, knife), Motion("slice"), (white,), (Source("b", 7),)),
        FunctionalUnit((onion,), Motion("peel"), (onion,), (Source("c", 2),)),
    )
    foon = Foon(units)
    two = project(foon, 2)
    assert two.level == 2 and len(two.units) == 2
    assert [s.path for s in two.units[0].sources] == ["a", "b"]
    one = project(foon, 1)
    assert len(one.units) == 2 and len(one.nodes) == 2
    assert project(foon, 3) is foon
    assert project(one, 3) is one  # never raises a level


def test_project_memo_matches_unit_by_unit_projection(universal):
    foon, _ = universal
    for level in (1, 2):
        naive = Foon(dedupe_units(project_unit(u, level) for u in foon.units), level)
        assert full(project(foon, level), sources=True) == full(naive, sources=True)


@settings(max_examples=40, deadline=None)
@given(foon=foons(max_units=8))
def test_projecting_in_steps_equals_projecting_at_once(foon):
    direct = project(foon, 1)
    stepped = project(project(foon, 2), 1)
    assert {u.key for u in stepped.units} == {u.key for u in direct.units}
    assert {u.key: sorted(map(repr, u.sources)) for u in stepped.units} == \
           {u.key: sorted(map(repr, u.sources)) for u in direct.units}
    assert len(direct.nodes) <= len(project(foon, 2).nodes) <= len(foon.nodes)


def test_universal_counts_shrink_with_the_level(universal):
    foon, _ = universal
    counts = [(len(project(foon, lv).nodes), len(project(foon, lv).units)) for lv in (1, 2, 3)]
    assert counts[0] < counts[1] < counts[2]
    assert len({n.label for n in foon.nodes}) == counts[0][0]


@pytest.mark.parametrize("bad", [0, 4, -1, "2"])
def test_check_level_rejects_other_values(bad):
    with pytest.raises(ValueError, match="level must be 1, 2 or 3"):
        check_level(bad)
    with pytest.raises(ValueError):
        project(Foon(()), bad)
