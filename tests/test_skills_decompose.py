"""Decomposing macro steps into skills: micro problems, Fast Downward per step, the independent replay.

Traces are built by hand (`skill_traces`), so the expected skills follow from the trace alone.
"""

from __future__ import annotations

from dataclasses import replace

import pytest
from skill_traces import CHOP, IN, MIX, MOVE, ON, ONION_CHOPPED, POUR, WATER, kitchen_trace, node, skills

from foon2pddl.model.physical import ObjectState
from foon2pddl.skills.decompose import StepStatus, decompose
from foon2pddl.skills.domain import shipped_domain
from foon2pddl.skills.micro import Naming, micro_problem
from foon2pddl.skills.profile import Robot, robot_constraints
from foon2pddl.skills.table import parse_table, shipped_table


def test_chop_picks_the_knife_cuts_and_puts_it_back():
    plan = decompose(kitchen_trace(CHOP), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("knife_1", "workspace")), ("chop", ("knife_1", "onion_1")),
                            ("place", ("knife_1", "workspace"))]
    assert plan.calls[1].holders == ("hand_1", "board_1")  # the knife is in the hand, the onion on the board


def test_pour_holds_the_source_and_moves_only_what_was_in_it():
    plan = decompose(kitchen_trace(POUR), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert [s for s, _ in skills(plan)] == ["pick", "pour", "place"]
    assert plan.calls[1].objects == ("cup_1", "bowl_1")


def test_whole_recipe_chop_move_pour_mix_replays_end_to_end():
    plan = decompose(kitchen_trace(CHOP, MOVE, POUR, MIX), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert [s.status for s in plan.steps] == [StepStatus.DECOMPOSED] * 4
    assert [c.macro for c in plan.calls] == sorted(c.macro for c in plan.calls)
    move = [c.skill for c in plan.calls if c.macro == 1]
    assert move == ["pick", "put-in"]  # graspable onion: transport, not pour
    assert "mix" in [c.skill for c in plan.calls if c.macro == 3]
    assert all(s.source == f"r.txt:{10 * (s.index + 1)}" for s in plan.steps)


def test_an_unmapped_motion_stays_abstract_and_later_steps_still_replay():
    table = parse_table('{"motions": {"pour": "pour", "pick-and-place": "place"}}', "t.json")
    plan = decompose(kitchen_trace(CHOP, MOVE, POUR), table, shipped_domain())
    assert [s.status for s in plan.steps] == [StepStatus.ABSTRACT, StepStatus.DECOMPOSED, StepStatus.DECOMPOSED]
    assert "'chop'" in plan.steps[0].reason and plan.steps[0].calls == ()
    assert plan.replay.ok and not plan.ok and plan.share == pytest.approx(2 / 3)


def test_a_robot_without_pour_fails_the_pour_step_and_bans_every_pouring_motion():
    robot = Robot.of(without=["pour"])
    plan = decompose(kitchen_trace(POUR), shipped_table(), shipped_domain(), robot)
    assert plan.steps[0].status is StepStatus.FAILED and "no pour skill" in plan.steps[0].reason
    banned = robot_constraints(shipped_table(), robot).of(robot_constraints(shipped_table(), robot).items[0].kind)
    assert "pour" in banned and "add" in banned and "pick-and-place" not in banned


def test_costs_steer_the_micro_plan_and_are_written_into_the_domain():
    robot = Robot.of(costs={"pick": 5})
    plan = decompose(kitchen_trace(CHOP), shipped_table(), shipped_domain(), robot)
    assert plan.ok
    assert "(increase (total-cost) 5)" in shipped_domain().pruned({"pick"}, robot.cost_table)


def test_two_hands_are_named_and_the_goal_empties_both():
    t = kitchen_trace(CHOP)
    naming = Naming(t, shipped_domain(), 2)
    problem = micro_problem(t, 0, "chop", naming, shipped_domain())
    assert {a.args for a in problem.goal if a.predicate == "hand-empty"} == {("hand_1",), ("hand_2",)}
    plan = decompose(t, shipped_table(), shipped_domain(), Robot.of(hands=2))
    assert plan.ok


def test_with_two_hands_every_skill_line_names_its_hand():
    """Issue 24's last pass: `plan --skills --hands 2` printed `pick knife_1 from workspace` with no hand, so a
    reader could not tell which hand does what (the text named only a hand other than the first)."""
    from foon2pddl.skills.recipe import skill_plan_recipe
    from foon2pddl.skills.report import skill_plan_text

    t = kitchen_trace(CHOP, POUR)
    plan = decompose(t, shipped_table(), shipped_domain(), Robot.of(hands=2))
    assert plan.ok, plan.replay.problems
    said = [line.strip() for line in skill_plan_text(plan, Robot.of(hands=2)).splitlines()
            if line.startswith("   ") and not line.strip().startswith("FOON:")]
    assert len(said) == len(plan.calls)
    assert all(line.endswith(f"({c.hand.replace('_', ' ')})") for line, c in zip(said, plan.calls, strict=True)), said
    recipe = skill_plan_recipe(plan, t, hands=2)
    assert recipe.count("(hand ") == len(plan.calls), recipe
    one = decompose(t, shipped_table(), shipped_domain())
    assert "(hand" not in skill_plan_text(one, Robot()) + skill_plan_recipe(one, t)  # one hand: nothing to tell apart


def test_micro_problem_holds_the_step_objects_and_their_holders_only():
    t = kitchen_trace(CHOP, POUR)
    problem = micro_problem(t, 1, "pour", Naming(t, shipped_domain(), 1), shipped_domain())
    assert problem.objects == ("bowl_1", "cup_1", "water_1")
    assert {"(moves-in sk-pour water_1 bowl_1)", "(target sk-pour bowl_1)"} <= {
        f"({a.predicate} {' '.join(a.args)})" for a in problem.init}
    assert not any(a.predicate == "graspable" and a.args == ("water_1",) for a in problem.init)
    assert problem.text == micro_problem(t, 1, "pour", Naming(t, shipped_domain(), 1), shipped_domain()).text


def test_the_replay_rejects_a_skill_whose_precondition_fails():
    def cheat(domain_text, problem_text):
        return "solved", ("chop hand_1 knife_1 onion_1",), "", 0.0  # never picked the knife up

    plan = decompose(kitchen_trace(CHOP), shipped_table(), shipped_domain(), solver=cheat)
    assert not plan.replay.ok and "precondition fails: (holding hand_1 knife_1)" in plan.replay.problems[0]


def test_the_replay_rejects_a_plan_that_does_not_reach_the_step_effects():
    def lazy(domain_text, problem_text):
        return "solved", ("pick hand_1 knife_1 workspace", "place hand_1 knife_1 workspace"), "", 0.0

    plan = decompose(kitchen_trace(CHOP), shipped_table(), shipped_domain(), solver=lazy)
    assert not plan.replay.ok
    assert "after step 1 (r.txt:10)" in plan.replay.problems[0] and "missing (state onion_1" in plan.replay.problems[0]


def test_an_impossible_step_is_reported_failed_not_dropped():
    # the water jumps from the cup into the bowl by a "chop" with no knife: no plan, and the reason names the tool
    jump = ("chop", [ObjectState("water_1", WATER, "bowl_1", IN), ObjectState("onion_1", ONION_CHOPPED, "board_1", ON)],
            ["water_1", "onion_1", "bowl_1"])
    plan = decompose(kitchen_trace(jump), shipped_table(), shipped_domain())
    assert plan.steps[0].status is StepStatus.FAILED and "no tool to chop with" in plan.steps[0].reason
    assert plan.replay.ok  # kept as an abstract step: the replay jumps to the trace's state


ONION_PEELED = node("onion", "peeled")
PEEL_BY_HAND = ("peel", [ObjectState("onion_1", ONION_PEELED, "board_1", ON)], ["onion_1", "board_1"])
PEEL_WITH_KNIFE = ("peel", [ObjectState("onion_1", ONION_PEELED, "board_1", ON)], ["onion_1", "knife_1", "board_1"])
MIX_BY_HAND = (MIX[0], MIX[1], ["onion_1", "water_1", "bowl_1", "salad_1"])


def test_a_step_that_lists_no_tool_takes_the_motions_hand_skill():
    plan = decompose(kitchen_trace(PEEL_BY_HAND), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("peel-by-hand", ("onion_1",))] and plan.steps[0].skill == "peel-by-hand"
    with_knife = decompose(kitchen_trace(PEEL_WITH_KNIFE), shipped_table(), shipped_domain())
    assert with_knife.ok and [s for s, _ in skills(with_knife)] == ["pick", "peel", "place"]  # a listed tool is used
    mixed = decompose(kitchen_trace(CHOP, MOVE, POUR, MIX_BY_HAND), shipped_table(), shipped_domain())
    assert mixed.ok and [c.skill for c in mixed.calls if c.macro == 3] == ["mix-by-hand"]


def test_without_a_hand_variant_a_tool_less_tool_step_fails_and_a_lacked_one_says_so():
    table = parse_table('{"motions": {"peel": "peel"}}', "t.json")
    plan = decompose(kitchen_trace(PEEL_BY_HAND), table, shipped_domain())
    assert plan.steps[0].status is StepStatus.FAILED  # a knife skill with no knife: no plan, and the reason says so
    assert plan.steps[0].reason.startswith("the step lists no tool to peel with"), plan.steps[0].reason
    lacking = decompose(kitchen_trace(PEEL_BY_HAND), shipped_table(), shipped_domain(), Robot.of(without=["peel-by-hand"]))
    assert lacking.steps[0].status is StepStatus.FAILED and "no peel-by-hand skill" in lacking.steps[0].reason


def test_by_hand_entries_are_checked():
    assert parse_table('{"motions": {"peel": "peel"}, "by_hand": {"Peel": "peel-by-hand"}}').hand_skill_of("peel") \
        == "peel-by-hand"
    from foon2pddl.errors import FoonSyntaxError

    with pytest.raises(FoonSyntaxError, match="not in"):
        parse_table('{"motions": {"peel": "peel"}, "by_hand": {"mix": "mix-by-hand"}}', "t.json")
    with pytest.raises(FoonSyntaxError, match="does not define"):
        parse_table('{"motions": {"peel": "peel"}, "by_hand": {"peel": "nail"}}', "t.json").check(shipped_domain())


def test_a_tool_less_step_whose_by_hand_skill_the_domain_lacks_says_so():
    # the table names peel-by-hand, the domain has no such action: the reason said "no by-hand skill"
    domain = shipped_domain()
    lacking = replace(domain, actions=tuple(a for a in domain.actions if a.name != "peel-by-hand"))
    plan = decompose(kitchen_trace(PEEL_BY_HAND), shipped_table(), lacking)
    reason = plan.steps[0].reason
    assert plan.steps[0].status is StepStatus.FAILED and "no by-hand skill" not in reason, reason
    assert "by-hand skill 'peel-by-hand'" in reason and "not defined in" in reason, reason
