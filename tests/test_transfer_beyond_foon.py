"""A unit that consumes an ingredient FOON's own words put in another holder than the one it makes its product in
(issue 21): the pancake batter's mix at `0004-pancake_batter.txt:58` takes `egg white and yolk (in [bowl])` while its
bowl's node does not list it, and the crack made it in another bowl. A cook pours it over first: `plan` falls back
to an assumed transfer step, named `beyond FOON` with the unit's file:line, when every count's plan is rejected."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_plan

from foon2pddl.io.tree_formats import DEFAULT_FORMAT, render_tree
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.planners.solve import plan

EMPTY, EGG = n("bowl", "empty"), n("egg", "whole")
B_YOLK, YOLK = n("bowl", contains("egg white and yolk")), n("egg white and yolk", inside("bowl"))
B_FLOUR, FLOUR = n("bowl", contains("flour")), n("flour", "powder", inside("bowl"))
WHISK = n("whisk", "clean")
B_BATTER, BATTER = n("bowl", contains("pancake batter")), n("pancake batter", "raw", inside("bowl"))
CRACK = FunctionalUnit((EMPTY, EGG), Motion("crack"), (B_YOLK, YOLK), (Source("eggs.txt", 30),))
MIX = FunctionalUnit((B_FLOUR, FLOUR, YOLK, WHISK), Motion("mix"), (B_BATTER, BATTER, n("whisk", "dirty")),
                     (Source("eggs.txt", 58),))
KITCHEN = Kitchen(frozenset({EMPTY, EGG, B_FLOUR, FLOUR, WHISK}))
GOAL = Goal(GoalSpec("pancake batter"), (BATTER,))


def test_the_egg_cracked_in_another_bowl_is_poured_into_the_flours_bowl_beyond_foon():
    outcome = clean_plan(Foon((CRACK, MIX)), KITCHEN, GOAL, time_limit=60)
    text = render_tree(outcome.tree, DEFAULT_FORMAT)
    beyond = [s for s in text.splitlines() if "beyond FOON" in s]
    assert len(beyond) == 1 and beyond[0].startswith("2. pour") and "eggs.txt:58" in beyond[0], text
    assert [n for n in outcome.decoded.notes if "beyond FOON" in n] == [
        "transfer: beyond FOON, 1 assumed pour of an ingredient into the holder the unit makes its product in, "
        "where FOON's words leave it in another: eggs.txt:58"]
    assert [s.split()[0] for s in outcome.steps][:3] == ["crack_u0", "pour_u2", "mix_u1"]


def test_a_mix_taking_its_ingredient_in_its_own_bowl_gets_no_transfer():
    """FOON's words agree (the bowl lists the yolk): the plan is `plan`'s counts' own, with no step beyond FOON."""
    listed = FunctionalUnit((n("bowl", contains("egg white and yolk", "flour")), FLOUR, YOLK, WHISK), MIX.motion,
                            MIX.outputs, MIX.sources)
    pour = FunctionalUnit((B_YOLK, YOLK, B_FLOUR), Motion("pour"), (listed.inputs[0],), (Source("eggs.txt", 46),))
    outcome = clean_plan(Foon((CRACK, pour, listed)), KITCHEN, GOAL, time_limit=60)
    assert "beyond FOON" not in render_tree(outcome.tree, DEFAULT_FORMAT)
    assert not [n for n in outcome.decoded.notes if "transfer:" in n]


def test_a_plan_rejected_for_another_reason_is_left_rejected(monkeypatch):
    """Only `consumed-elsewhere` rejections fall back; anything else is `plan`'s outcome as it was."""
    from foon2pddl.planners import solve
    from foon2pddl.planners.replay_findings import Disagreement, DisagreementKind, ReplayReport

    monkeypatch.setattr(solve, "replay", lambda trace: ReplayReport((Disagreement(
        DisagreementKind.WRONG_SOURCE, 1, ("x",), "eggs.txt:58", "wrong"),)))
    outcome = plan(Foon((CRACK, MIX)), KITCHEN, GOAL, "relational", time_limit=60)
    assert outcome.status == "error" and outcome.rejected
