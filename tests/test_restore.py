"""`--restore`: restoring units beyond FOON (wash, empty, switch off) and the fewer objects they allow."""

from __future__ import annotations

from dataclasses import replace

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.restore import (
    RESTORE_SOURCE,
    ready_states,
    restore_motion,
    restoring_network,
    with_restore,
)
from foon2pddl.planners import PlanResult, solve
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan, plan_restoring
from foon2pddl.status import PlanStatus


def n(label, *states):
    return make_node(label, [s if not isinstance(s, str) else make_state(s) for s in states])


CLEAN, DIRTY = n("knife", "clean"), n("knife", "dirty")
FOODS = ("onion", "carrot", "celery")


def _cuts() -> Foon:
    """Three cuts in a row, each with a clean knife it leaves dirty; a mix of the three at the end."""
    units = [FunctionalUnit((n(f, "whole"), CLEAN), Motion("chop"), (n(f, "chopped"), DIRTY)) for f in FOODS]
    units.append(FunctionalUnit(tuple(n(f, "chopped") for f in FOODS), Motion("mix"), (n("soup", "mixed"),)))
    return Foon(tuple(units))


KITCHEN = Kitchen(frozenset({CLEAN, *(n(f, "whole") for f in FOODS)}))
GOAL = Goal(GoalSpec("soup"), (n("soup", "mixed"),))


def test_restore_motion_says_what_the_unit_does():
    assert restore_motion(DIRTY) == "wash"
    assert restore_motion(n("bowl", make_state("contains", "", ["salad"]))) == "empty"
    assert restore_motion(n("stove", "on")) == "turn off"
    assert restore_motion(n("pan", "heated")) == "restore"


def test_ready_states_are_placeless_kitchen_states_of_ready_words_one_per_label():
    kitchen = {CLEAN, n("bowl", "empty"), n("bowl", "clean", "empty"), n("pan", "clean", make_state("on", "stove")),
               n("stove", "off")}
    assert ready_states(kitchen) == {"knife": CLEAN, "stove": n("stove", "off")}  # two bowls; the pan has a place


def test_the_network_gains_one_restoring_unit_per_node_it_leaves_a_ready_label_in():
    augmented, ready = restoring_network(_cuts(), KITCHEN.nodes)
    added = augmented.units[len(_cuts().units):]
    assert ready == {"knife": CLEAN}
    assert [(u.inputs, u.motion.label, u.outputs) for u in added] == [((DIRTY,), "wash", (CLEAN,))]
    assert added[0].sources[0].path == RESTORE_SOURCE


def test_one_knife_does_all_three_cuts_and_the_replay_holds():
    without = plan(_cuts(), KITCHEN, GOAL, "relational")
    assert [o.label for o in without.trace.objects].count("knife") == 3  # FOON's: a clean knife per cut
    _, counted = with_restore(_cuts(), KITCHEN, GOAL)
    assert dict(counted.counts) == {CLEAN: 1}
    outcome = plan_restoring(_cuts(), KITCHEN, GOAL, "relational")
    assert outcome.status == "solved" and replay(outcome.trace).ok
    assert [o.label for o in outcome.trace.objects].count("knife") == 1
    assert [s.unit.motion.label for s in outcome.trace.steps].count("wash") == 2
    assert any(x.startswith("restore: restoring units added") and "1 x knife (clean)" in x
               for x in outcome.decoded.notes)
    stated = Kitchen(KITCHEN.nodes, counts=((CLEAN, 2),))
    assert dict(with_restore(_cuts(), stated, GOAL)[1].counts) == {CLEAN: 2}  # the kitchen's own count wins


def test_restoring_units_are_built_at_the_networks_own_level():
    with pytest.raises(ValueError, match="network's level"):  # its unit indexes would name other units
        with_restore(_cuts(), KITCHEN, GOAL, level=2)


def _smeared_cuts() -> Foon:
    """Each food chopped with a clean knife left smeared with it, then all mixed with the three smeared knives
    (a node no restoring unit turns back: the mix takes it)."""
    smeared = [n("knife", "dirty", make_state("smeared", "", [f])) for f in FOODS]
    units = [FunctionalUnit((n(f, "whole"), CLEAN), Motion("chop"), (n(f, "chopped"), knife))
             for f, knife in zip(FOODS, smeared, strict=True)]
    units.append(FunctionalUnit((*(n(f, "chopped") for f in FOODS), *smeared), Motion("mix"), (n("soup", "mixed"),)))
    return Foon(tuple(units))


def test_counts_too_low_for_the_encoding_fall_back_to_planning_without_restoring(monkeypatch):
    # the three knives are needed at once (the mix takes them dirty): one knife cannot do, the derived three can
    foon = _smeared_cuts()
    augmented, _ = with_restore(foon, KITCHEN, GOAL)
    monkeypatch.setattr(solve, "with_restore", lambda *a, **k: (augmented, Kitchen(KITCHEN.nodes, counts=((CLEAN, 1),))))
    outcome = plan_restoring(foon, KITCHEN, GOAL, "instances", time_limit=30)
    assert outcome.status == "solved" and [o.label for o in outcome.trace.objects].count("knife") == 3
    assert any("1 x knife (clean) gave no valid plan" in x and "planned without them" in x
               for x in outcome.decoded.notes)


def test_counts_above_what_the_plan_has_in_use_at_once_are_planned_again_lower(monkeypatch):
    # three clean knives (FOON's counts, say): the plan cuts with each once and washes none; each knife ends
    # dirty, a node the wash turns back, so one knife is in use at a time and the plan is made again with one
    augmented, _ = with_restore(_cuts(), KITCHEN, GOAL)
    monkeypatch.setattr(solve, "with_restore", lambda *a, **k: (augmented, Kitchen(KITCHEN.nodes, counts=((CLEAN, 3),))))
    outcome = plan_restoring(_cuts(), KITCHEN, GOAL, "relational", time_limit=30)
    assert outcome.status == "solved" and replay(outcome.trace).ok
    assert [o.label for o in outcome.trace.objects].count("knife") == 1
    assert [s.unit.motion.label for s in outcome.trace.steps].count("wash") == 2
    assert any("planned again with them and the most the plan had in use at once: 1 x knife (clean)" in x
               for x in outcome.decoded.notes)


def test_a_lower_count_with_no_plan_keeps_the_first_plan(monkeypatch):
    # each knife ends smeared, a node no restoring unit turns back (the mix takes it): all three stay in use
    foon = _smeared_cuts()
    outcome = plan_restoring(foon, KITCHEN, GOAL, "relational", time_limit=30)
    assert outcome.status == "solved" and [o.label for o in outcome.trace.objects].count("knife") == 3
    assert not any("planned again" in x for x in outcome.decoded.notes)


def test_a_plan_without_restoring_units_is_planned_again_with_them_at_the_most_it_had_in_use_at_once(monkeypatch):
    real, calls = solve.plan, []

    def first_fails(*args, **kwargs):  # the counts the restoring units allow give no plan (say)
        calls.append(args)
        out = real(*args, **kwargs)
        return replace(out, result=PlanResult(PlanStatus.UNSOLVABLE, (), "fd", "")) if len(calls) == 1 else out

    monkeypatch.setattr(solve, "plan", first_fails)
    outcome = plan_restoring(_cuts(), KITCHEN, GOAL, "relational", time_limit=30)
    assert len(calls) == 3  # with them, without them (three knives, one after another), with them and one knife
    assert outcome.status == "solved" and [o.label for o in outcome.trace.objects].count("knife") == 1
    assert [s.unit.motion.label for s in outcome.trace.steps].count("wash") == 2
    assert any("gave no valid plan (unsolvable): planned without them; planned again with them and the most the "
               "plan had in use at once: 1 x knife (clean)" in x for x in outcome.decoded.notes)


def test_plan_cli_restore_needs_a_physical_encoding_and_one_goal():
    runner = CliRunner()
    result = runner.invoke(main, ["plan", "--goal", "guacamole", "--encoding", "tree", "--restore"])
    assert result.exit_code == 2 and "--restore needs a physical encoding" in result.output
    result = runner.invoke(main, ["plan", "--goal", "guacamole", "--encoding", "relational", "--restore"])
    assert result.exit_code == 0 and "note: restore: restoring units added" in result.output


def test_compile_cli_restore_writes_the_restoring_actions_marked_as_assumed(tmp_path):
    runner = CliRunner()
    args = ["compile", "--goal", "guacamole", "--encoding", "relational", "-o"]
    plain = runner.invoke(main, [*args, str(tmp_path / "plain")])
    result = runner.invoke(main, [*args, str(tmp_path / "restore"), "--restore"])
    assert plain.exit_code == 0 and result.exit_code == 0, result.output
    domain = (tmp_path / "restore" / "domain.pddl").read_text()
    assert "assumed-restore:1" in domain and "assumed-restore" not in (tmp_path / "plain" / "domain.pddl").read_text()
    batch = runner.invoke(main, ["compile", "--goal", "guacamole", "--goal", "salsa", "--encoding", "relational",
                                 "--restore", "-o", str(tmp_path / "batch")])
    assert batch.exit_code == 2 and "one goal at a time" in batch.output


def test_the_plan_again_with_fewer_is_bounded_by_cpu_not_by_a_shorter_wall_limit(monkeypatch):
    # a loaded machine: the planner's wall time runs out whenever it has RETRY_SECONDS of it or less, whatever its
    # CPU does. The plan again with one knife must not depend on that: it has the caller's wall limit and
    # RETRY_SECONDS of the planner's CPU (docs/pddl.md says CPU), so the result is the same at any load
    real, runs = solve.run_planner, []

    def loaded(*args, time_limit=None, cpu_limit=None, **kwargs):
        runs.append((time_limit, cpu_limit))
        if time_limit is not None and time_limit <= solve.RETRY_SECONDS:
            return PlanResult(PlanStatus.TIMEOUT, (), "fd", "time limit (wall)")
        return real(*args, time_limit=time_limit, cpu_limit=cpu_limit, **kwargs)

    augmented, _ = with_restore(_cuts(), KITCHEN, GOAL)
    monkeypatch.setattr(solve, "with_restore", lambda *a, **k: (augmented, Kitchen(KITCHEN.nodes, counts=((CLEAN, 3),))))
    monkeypatch.setattr(solve, "run_planner", loaded)
    outcome = plan_restoring(_cuts(), KITCHEN, GOAL, "relational", time_limit=30)
    assert [o.label for o in outcome.trace.objects].count("knife") == 1, outcome.decoded.notes
    assert all(cpu is not None and cpu <= solve.RETRY_SECONDS for _, cpu in runs[1:])  # the retry's runs


def test_a_kitchen_projected_to_a_coarser_level_keeps_which_counts_restoring_units_set():
    """`Kitchen.restored` (`with_restore`: the counts the restoring units' peak set, for the note that says who gave
    a count) survives `project`: a level-3 kitchen handed to an encoder at level 2 was rebuilt without it, and the
    note said "given by the kitchen file" for a count no file stated (rv61's bfb2310 nit, reread61's F4)."""
    from foon2pddl.model.levels import project_node
    from foon2pddl.pddl.count_reasons import given_by

    board = n("cutting board", "empty", make_state("with", "", ("onion",)))
    kitchen = Kitchen(frozenset({board}), counts=((board, 3),), restored=frozenset({board}))
    low = kitchen.project(2)
    assert low.restored == {project_node(board, 2)} and low.restored <= low.stated_counts().keys()
    assert given_by(project_node(board, 2), low, {}) == "set by the restoring units' peak"
