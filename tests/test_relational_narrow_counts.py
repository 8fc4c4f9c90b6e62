"""Objects counted small first (`pddl/relational_objects.py`), and the wide count when that task has no plan
(`planners.solve.plan`)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from node_words import contains, inside, n
from relational_checks import clean_dish_plan, clean_unit_plan

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.planners import solve
from foon2pddl.status import PlanStatus

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def _dish(name: str):
    foon, _ = load([DATA / name])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    return foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon)


def test_the_brownie_cut_from_the_kitchen_is_counted_from_its_one_unit():
    # ACT-0010: the cut takes the kitchen's `brownie (baked, on [cutting board])` with `cutting board (contains
    # {brownie})`, which only the whole recipe makes; the init puts the kitchen's brownie on a board of its own in
    # that node, so the plan is the cut alone, yet FOON's plan unfolded (and the stitched one) counts 55 objects (92
    # before its units were ordered readers first, `count_order`; 56 before the pour at :227 poured the kitchen's
    # bowl of melted chocolate out whole, no rest beside a portion: `tests/test_relational_taken_once.py`)
    foon, kitchen, goal = _dish("ACT-0010-choco_brownie.txt")
    wide = compile_goal(foon, kitchen, goal, "relational")
    small = compile_goal(foon, kitchen, goal, "relational", narrow=True)
    assert len(wide.task.instances) > 50 and not wide.narrowed
    # the baking tray is the place the cut's output names (`in [baking tray]`), which no object of it is
    assert sorted(x.label for x in small.task.instances) == ["baking tray", "brownie", "cutting board", "knife"]
    assert f"4 objects, where FOON's plan unfolded counts {len(wide.task.instances)}" in small.narrowed
    assert any(x.startswith("objects: counted small") for x in small.notes)
    outcome = clean_dish_plan(DATA / "ACT-0010-choco_brownie.txt")
    assert len(outcome.task.instances) == 4 and [s.unit.motion.label for s in outcome.trace.steps] == ["cut"]


def test_a_task_counted_small_out_of_holder_reach_is_planned_counted_through_the_stitches():
    # 0050: FOON's own plan takes the finished omelette from the kitchen (no bacon), in a pan of its own off the
    # stove: the task counted from it is out of holder reach at once; the one counted from the plan through the
    # stitches alone (bacon sprinkled) has a plan, with fewer objects than FOON's plan and the stitched one counted
    # together (`tests/test_relational_counted_through.py`)
    foon, kitchen, goal = _dish("0050-scrambled_eggs_with_bacon-cheese.txt")
    small = compile_goal(foon, kitchen, goal, "relational", narrow=True)
    through = compile_goal(foon, kitchen, goal, "relational", narrow=True, through=True)
    wide = compile_goal(foon, kitchen, goal, "relational")
    assert small.narrowed and len(small.task.instances) < len(through.task.instances) < len(wide.task.instances)
    outcome = clean_dish_plan(DATA / "0050-scrambled_eggs_with_bacon-cheese.txt")
    assert len(outcome.task.instances) == len(through.task.instances)
    assert len(outcome.task.objects) < len(wide.task.objects)
    assert through.narrowed in (x.removeprefix("objects: ") for x in outcome.decoded.notes)


def test_the_small_task_gets_the_short_cpu_limit_and_the_wide_one_what_is_left_of_the_wall_time(monkeypatch):
    # found in review: the wide task got the whole limit again, so a call could run 10 s past it; the small task's
    # limit is CPU time (at load 4-5 the odd-index universal chocolate cake's small task spent its 10 s of wall time
    # translating, 7 s of CPU, and the cake was planned wide), its wall time bounded by the caller's limit
    real, limits, clock = solve.run_planner, [], iter(range(0, 1000, 7))
    monkeypatch.setattr(solve, "_now", lambda: next(clock))  # 7 s pass between two looks at the clock

    def first_times_out(*args, **kwargs):
        limits.append((kwargs["time_limit"], kwargs["cpu_limit"]))
        out = real(*args, **kwargs)
        return replace(out, status=PlanStatus.TIMEOUT, plan=()) if len(limits) == 1 else out

    monkeypatch.setattr(solve, "run_planner", first_times_out)
    foon, kitchen, goal = _dish("ACT-0010-choco_brownie.txt")
    outcome = solve.plan(foon, kitchen, goal, "relational", time_limit=60)
    assert limits == [(60, solve.RETRY_SECONDS), (60 - 7, None)] and outcome.status == "solved"
    assert len(outcome.task.instances) > 50
    assert any("counted small gave no valid plan within 10 s of CPU (timeout)" in x for x in outcome.decoded.notes)
    limits.clear()
    solve.plan(foon, kitchen, goal, "relational", time_limit=4)  # a caller's shorter limit bounds both
    assert limits[0] == (4, 4)


def test_other_encodings_and_counts_that_do_not_shrink_plan_once(monkeypatch):
    real, calls = solve.run_planner, []
    monkeypatch.setattr(solve, "run_planner", lambda *a, **k: calls.append(k["time_limit"]) or real(*a, **k))
    foon, kitchen, goal = _dish("0001-whipped_cream.txt")
    for encoding in ("instances", "relational"):
        outcome = solve.plan(foon, kitchen, goal, encoding, time_limit=60)
        assert outcome.status == "solved" and not outcome.compiled.narrowed
    assert calls == [60, 60]


def test_what_a_kitchen_container_lists_is_counted_small_from_where_it_starts_not_made_again():
    # the universal kofta mix (issue 21, odd/even halves): the pour takes `water (in [measuring cup])` out of the
    # kitchen's cup below the faucet, which lists water and holds it in the init; FOON's plan unfolded makes that
    # node again (the faucet turned on, another cup filled): a faucet, a cup and two waters that no step needs
    below = make_state("below", "faucet")
    cup, in_cup, pot = n("measuring cup", below, contains("water")), n("water", inside("measuring cup")), n(
        "pot", contains("water"))
    from_faucet = n("water", make_state("from", "faucet"))
    units = (FunctionalUnit((n("faucet", "off"),), Motion("turn on"), (n("faucet", "on"), from_faucet)),
             FunctionalUnit((n("faucet", "on"), from_faucet, n("measuring cup", "empty")), Motion("fill"),
                            (in_cup, n("measuring cup", contains("water")))),
             FunctionalUnit((n("pot", "empty"), cup, in_cup), Motion("pour"), (pot, n("water", inside("pot")))))
    kitchen = Kitchen(frozenset({n("faucet", "off"), n("measuring cup", "empty"), cup, n("pot", "empty")}))
    goal = Goal(GoalSpec("pot"), (pot,))
    wide = compile_goal(Foon(units), kitchen, goal, "relational")
    small = compile_goal(Foon(units), kitchen, goal, "relational", narrow=True)
    assert len(wide.task.instances) == 7
    assert sorted(x.name for x in small.task.instances) == ["measuring_cup_1", "pot_1", "water_1", "water_2"]
    assert "kitchen with water (in [measuring cup])" in small.narrowed
    outcome = clean_unit_plan(units, kitchen.nodes, pot)
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour"] and len(outcome.task.instances) == 4


def test_a_task_counted_small_keeps_the_contradictions_of_the_units_it_starts_after():
    # 0086 (and the apple pie of the universal FOON's even half, issue 21's objects floor): counted small, the pie
    # starts uncooked with `filling (in [apple pie])` in it, a node the fold at 0086-apple_turnover.txt:418 leads
    # to while its pie lists filling, which the dish's list drops; the wide task reads that pair as FOON's own
    # contradiction (not checked), the small one checked it and its plan, the wide one's 8 steps, did not validate:
    # planned wide, 66 objects in the problem where `instances` has 41
    foon, kitchen, goal = _dish("0086-apple_turnover.txt")
    small = compile_goal(foon, kitchen, goal, "relational", narrow=True)
    wide = compile_goal(foon, kitchen, goal, "relational")
    assert ("apple pie", "filling") in wide.task.gaps and ("apple pie", "filling") in small.task.gaps
    outcome = clean_dish_plan(DATA / "0086-apple_turnover.txt")
    assert len(outcome.task.instances) == len(small.task.instances) and len(outcome.task.objects) < 10
    assert not any("counted small gave no valid plan" in x for x in outcome.decoded.notes)
