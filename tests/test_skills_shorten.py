"""Micro plans rid of skills that do nothing (`skills.shorten.irredundant`), and its place in `decompose`.

Oracles: a shortest plan of a step (pick the knife, chop, put it back) with detours inserted where the
hand is empty (an object picked up and put back where it was) or a skill repeated where it changes
nothing comes back as that shortest plan; a plan the replay rejects, or that misses the goal, comes back
unchanged; whatever comes back replays and ends in exactly the state the given plan ends in (not
merely one that meets the goal).
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from skill_traces import CHOP, MOVE, POUR, kitchen_trace

from foon2pddl.skills.decompose import _fd, decompose
from foon2pddl.skills.domain import shipped_domain
from foon2pddl.skills.micro import Naming, micro_problem
from foon2pddl.skills.replay import Replayer
from foon2pddl.skills.shorten import irredundant
from foon2pddl.skills.table import shipped_table

DOMAIN = shipped_domain()
SHORTEST = ("pick hand_1 knife_1 workspace", "chop hand_1 knife_1 onion_1", "place hand_1 knife_1 workspace")
DETOURS = (("pick hand_1 knife_1 workspace", "place hand_1 knife_1 workspace"),
           ("pick hand_1 board_1 workspace", "place hand_1 board_1 workspace"),
           ("pick hand_1 knife_1 workspace", "place hand_1 knife_1 board_1",
            "pick hand_1 knife_1 board_1", "place hand_1 knife_1 workspace"))


def chop_task():
    t = kitchen_trace(CHOP)
    p = micro_problem(t, 0, "chop", Naming(t, DOMAIN, 1), DOMAIN)
    return dict(p.task.objects), p.task.init, p.task.goal


def end_state(plan, objects, init):
    rep = Replayer(DOMAIN, objects, init)
    for line in plan:
        name, *args = line.split()
        rep.apply(name, args)  # raises SkillError when a skill does not apply
    return rep.state


@settings(max_examples=30, deadline=None)
@given(st.lists(st.sampled_from(range(len(DETOURS))), max_size=2), st.lists(st.sampled_from(range(len(DETOURS))),
       max_size=2), st.booleans())
def test_detours_and_skills_that_change_nothing_are_dropped(before, after, chop_twice):
    objects, init, goal = chop_task()
    core = [SHORTEST[0], SHORTEST[1], SHORTEST[1], SHORTEST[2]] if chop_twice else list(SHORTEST)  # chopped twice:
    # the onion is chopped already, the second chop changes nothing
    plan = [*(x for d in before for x in DETOURS[d]), *core, *(x for d in after for x in DETOURS[d])]  # hand empty
    assert end_state(plan, objects, init) == end_state(SHORTEST, objects, init)
    assert irredundant(plan, DOMAIN, objects, init, goal) == SHORTEST


def test_a_plan_the_replay_rejects_or_that_misses_the_goal_comes_back_unchanged():
    objects, init, goal = chop_task()
    broken = ("chop hand_1 knife_1 onion_1", *SHORTEST)  # the first chop has no knife in the hand
    assert irredundant(broken, DOMAIN, objects, init, goal) == broken
    short = DETOURS[0]  # replays, but the onion is never chopped
    assert irredundant(short, DOMAIN, objects, init, goal) == short
    assert irredundant(SHORTEST, DOMAIN, objects, init, goal) == SHORTEST


def test_a_plan_that_ends_elsewhere_keeps_its_end():
    # the knife ends on the board: the shorter plan puts it there straight away, never back on the workspace
    objects, init, goal = chop_task()
    plan = (*SHORTEST, "pick hand_1 knife_1 workspace", "place hand_1 knife_1 board_1")
    loose = tuple(a for a in goal if "knife_1" not in a.args)
    out = irredundant(plan, DOMAIN, objects, init, loose)
    assert out == (*SHORTEST[:2], "place hand_1 knife_1 board_1")
    assert end_state(out, objects, init) == end_state(plan, objects, init) != end_state(SHORTEST, objects, init)


def test_decompose_shortens_what_the_planner_returns_once_per_shape():
    calls = []

    def roundabout(domain_text, problem_text):
        status, plan, message, seconds = _fd(domain_text, problem_text)
        calls.append(problem_text)
        hand_empty_detour = (f"pick hand_1 {x} workspace" for x in ("obj-0", "obj-1", "obj-2")
                             if f"(on workspace {x})" in problem_text and f"(graspable {x})" in problem_text)
        first = next(hand_empty_detour, None)
        if first is None:
            return status, plan, message, seconds
        return status, (first, first.replace("pick", "place", 1), *plan), message, seconds

    plain = decompose(kitchen_trace(CHOP, MOVE, POUR), shipped_table(), DOMAIN)
    shortened = decompose(kitchen_trace(CHOP, MOVE, POUR), shipped_table(), DOMAIN, solver=roundabout)
    assert shortened.ok and shortened.calls == plain.calls and len(calls) == 3


def test_micro_tasks_are_searched_by_astar_and_fall_back_to_lama_first(monkeypatch):
    from foon2pddl.skills import fd_micro

    t = kitchen_trace(CHOP)
    p = micro_problem(t, 0, "chop", Naming(t, DOMAIN, 1), DOMAIN)
    domain = DOMAIN.pruned({"pick", "take-out", "place", "put-in", "chop"}, None, p.init)
    first = fd_micro.solve_micro(domain, p.text)
    assert (str(first.status), first.planner, first.plan) == ("solved", fd_micro.OPTIMAL_NAME, SHORTEST)
    monkeypatch.setattr(fd_micro, "OPTIMAL_SECONDS", 0.0)  # A* out of time at once: lama-first plans it
    late = fd_micro.solve_micro(domain, p.text)
    assert (str(late.status), late.planner) == ("solved", fd_micro.NAME) and "search" in late.timings
    monkeypatch.setattr(fd_micro, "OPTIMAL_SECONDS", 5.0)
    monkeypatch.setattr(fd_micro, "OPTIMAL_MAX_GRASPABLE", 1)  # the knife and the onion: too many for A*
    big = fd_micro.solve_micro(domain, p.text)
    assert (str(big.status), big.planner) == ("solved", fd_micro.NAME)
