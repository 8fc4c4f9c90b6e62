"""Micro tasks solved once per shape (`skills.memo`) and effect conjuncts cut by static guards (`SkillDomain.pruned`).

Oracles: renaming a trace's objects by a random bijection must not change a step's canonical problem
(and the plan put back must name the renamed objects); problems that differ in shape must not share one;
a plan taken from an equal earlier step must pass the independent skill replay; the translator must see
none of the conjuncts whose static guard no initial fact matches, and all of the others.
"""

from __future__ import annotations

import re
from dataclasses import replace

from hypothesis import given, settings
from hypothesis import strategies as st
from skill_traces import BOARD, BOWL, KNIFE, ON, ONION_CHOPPED, ONION_WHOLE, POUR, kitchen_trace, node, trace

from foon2pddl.model.physical import ObjectState, PhysicalObject, PhysicalTrace
from foon2pddl.skills.decompose import _fd, decompose
from foon2pddl.skills.domain import TRANSPORT, parse_domain, shipped_domain
from foon2pddl.skills.memo import MicroMemo, canonical
from foon2pddl.skills.micro import Naming, micro_problem
from foon2pddl.skills.table import shipped_table

CARROT_WHOLE, CARROT_CHOPPED = node("carrot", "whole"), node("carrot", "chopped")
DOMAIN = shipped_domain()
IDS = ("onion_1", "knife_1", "board_1", "bowl_1", "cup_1", "water_1", "spoon_1", "salad_1")


def two_chops() -> PhysicalTrace:
    """An onion and a carrot, each on its own board, chopped with the one knife: two steps of one shape."""
    objects = {"onion_1": "onion", "carrot_1": "carrot", "knife_1": "knife", "board_1": "cutting board",
               "board_2": "cutting board"}
    initial = [ObjectState("onion_1", ONION_WHOLE, "board_1", ON), ObjectState("carrot_1", CARROT_WHOLE, "board_2", ON),
               ObjectState("knife_1", KNIFE), ObjectState("board_1", BOARD), ObjectState("board_2", BOARD)]
    return trace(objects, initial, [
        ("chop", [ObjectState("onion_1", ONION_CHOPPED, "board_1", ON)], ["onion_1", "knife_1", "board_1"]),
        ("chop", [ObjectState("carrot_1", CARROT_CHOPPED, "board_2", ON)], ["carrot_1", "knife_1", "board_2"])])


def renamed(t: PhysicalTrace, to: dict[str, str]) -> PhysicalTrace:
    """The same trace with every object id replaced through `to`."""
    def s(x: ObjectState) -> ObjectState:
        return replace(x, id=to[x.id], holder=None if x.holder is None else to[x.holder])

    steps = tuple(replace(k, bindings=tuple(replace(b, object=to[b.object]) for b in k.bindings),
                          changes=tuple(s(c) for c in k.changes)) for k in t.steps)
    return PhysicalTrace(tuple(PhysicalObject(to[o.id], o.label) for o in t.objects), tuple(s(x) for x in t.initial),
                         steps)


def problems(t: PhysicalTrace, skills: list[str]):
    naming = Naming(t, DOMAIN, 1)
    return [micro_problem(t, k, skill, naming, DOMAIN) for k, skill in enumerate(skills)], naming


@settings(max_examples=25, deadline=None)
@given(st.permutations(range(len(IDS))), st.sampled_from(["x", "obj-", "zz_", "a"]))
def test_renaming_the_objects_changes_no_canonical_problem_and_plans_come_back_renamed(order, prefix):
    from skill_traces import CHOP, MIX, MOVE

    before = kitchen_trace(CHOP, MOVE, POUR, MIX)
    to = {i: f"{prefix}{order[k]}" for k, i in enumerate(IDS)}
    after = renamed(before, to)
    skills = ["chop", "place", "pour", "mix"]
    (old, n1), (new, n2) = problems(before, skills), problems(after, skills)
    for p, q in zip(old, new, strict=True):
        c, d = canonical(p, (*n1.hands, n1.workspace)), canonical(q, (*n2.hands, n2.workspace))
        assert c.text == d.text
        assert "step-" not in c.text and not set(IDS) & set(re.findall(r"[a-z_]+_1", c.text)) - {"hand_1"}
        lines = tuple(f"touch hand_1 obj-{k} workspace" for k in range(len(c.names)))
        back = [y.split()[2] for y in c.decode(lines)]  # trace ids of the first trace, or phase names
        assert [x.split()[2] for x in d.decode(lines)] == [to[n1.back[x]] if x in n1.back else x for x in back]


def test_problems_of_another_shape_do_not_share_a_canonical_form():
    (pour,), naming = problems(kitchen_trace(POUR), ["pour"])
    fixed = (*naming.hands, naming.workspace)
    (again,), _ = problems(kitchen_trace(POUR), ["pour"])
    assert canonical(pour, fixed).text == canonical(again, fixed).text
    move = ("pick-and-place", [ObjectState("bowl_1", BOWL, "board_1", ON)], ["bowl_1", "board_1"])
    (_, on_board), _ = problems(kitchen_trace(move, POUR), ["place", "pour"])
    assert canonical(on_board, fixed).text != canonical(pour, fixed).text  # the bowl stands on the board


def counting(solver):
    calls = []

    def run(domain_text, problem_text):
        calls.append(problem_text)
        return solver(domain_text, problem_text)
    return run, calls


def test_a_step_equal_to_an_earlier_one_takes_its_plan_renamed_and_the_replay_checks_it():
    solver, calls = counting(_fd)
    plan = decompose(two_chops(), shipped_table(), shipped_domain(), solver=solver)
    assert plan.ok, plan.replay.problems
    assert len(calls) == 1 and [s.reused for s in plan.steps] == [False, True]
    assert [(c.skill, c.objects) for c in plan.calls] == [
        ("pick", ("knife_1", "workspace")), ("chop", ("knife_1", "onion_1")), ("place", ("knife_1", "workspace")),
        ("pick", ("knife_1", "workspace")), ("chop", ("knife_1", "carrot_1")), ("place", ("knife_1", "workspace"))]
    assert plan.steps[1].seconds > 0 and plan.steps[1].cpu >= 0


def test_a_shared_memo_changes_no_skill_plan():
    memo = MicroMemo()
    decompose(kitchen_trace(POUR), shipped_table(), shipped_domain(), memo=memo)
    shared = decompose(two_chops(), shipped_table(), shipped_domain(), memo=memo)
    fresh = decompose(two_chops(), shipped_table(), shipped_domain())
    assert memo.misses == 2 and memo.hits == 1
    assert shared.calls == fresh.calls and shared.ok


def test_a_reused_plan_is_replayed_like_any_other():
    def wrong_for_the_canonical_task(domain_text, problem_text):
        return "solved", ("chop hand_1 obj-1 obj-2",), "", 0.0  # the knife never picked up

    plan = decompose(two_chops(), shipped_table(), shipped_domain(), solver=wrong_for_the_canonical_task)
    assert not plan.replay.ok and "step 1" in plan.replay.problems[0]


def test_timeouts_and_errors_are_not_kept():
    answers = iter([("timeout", (), "time limit", 1.0), ("error", (), "crash", 0.0)])

    def flaky(domain_text, problem_text):
        return next(answers, None) or _fd(domain_text, problem_text)

    memo = MicroMemo()
    for _ in range(3):
        plan = decompose(two_chops(), shipped_table(), shipped_domain(), solver=flaky, memo=memo)
    assert plan.ok and memo.misses == 3 and memo.hits == 3


def kept_actions(text: str) -> dict[str, str]:
    return {a.name: text[a.span[0]:a.span[1]] for a in parse_domain(text, "pruned").actions}


def test_static_predicates_are_those_no_effect_changes():
    d = shipped_domain()
    assert {"target", "moves-in", "changes", "tool", "graspable"} <= d.static
    assert not {"in", "on", "state", "holding", "placed", "unmade", "consumed"} & d.static
    tweaked = parse_domain(d.text.replace("(holding ?h ?o)\n      (not (hand-empty ?h))",
                                          "(holding ?h ?o) (tool ?o)\n      (not (hand-empty ?h))", 1))
    assert "tool" not in tweaked.static  # now some action makes a tool: not static, never a guard


def test_effects_guarded_by_a_static_atom_no_fact_matches_are_cut_and_only_those():
    t = kitchen_trace(("chop", [ObjectState("onion_1", ONION_CHOPPED, "board_1", ON)], ["onion_1", "knife_1", "board_1"]))
    (chop,), _ = problems(t, ["chop"])
    d = shipped_domain()
    text = kept_actions(d.pruned({*TRANSPORT, "chop"}, None, chop.init))["chop"]
    assert "(changes sk-chop" in text and "moves-in" not in text and "makes-" not in text and "uses-up" not in text
    assert kept_actions(d.pruned({*TRANSPORT, "chop"}))["chop"] == d.text[d.by_name["chop"].span[0]:d.by_name["chop"].span[1]]
    (pour,), _ = problems(kitchen_trace(POUR), ["pour"])
    poured = kept_actions(d.pruned({*TRANSPORT, "pour"}, None, pour.init))["pour"]
    assert "(moves-in sk-pour ?x ?dst)" in poured and "(moves-on sk-pour" not in poured and "changes" not in poured
    place = kept_actions(d.pruned({*TRANSPORT, "pour"}, None, pour.init))["place"]
    assert "sk-place" not in place  # nothing set down changes, so the transport skill is plain
