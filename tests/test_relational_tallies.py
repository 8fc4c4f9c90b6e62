"""A role that only checks an object in a state other actions leave: `(occupied s)` kept exact by a tally
(`pddl.tallies`), no parameter per object, and plans that still name the object."""

from __future__ import annotations

from node_words import n
from relational_checks import clean_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Atom
from foon2pddl.planners.decode import simulate_plan

CLEAN, DIRTY = n("knife", "clean"), n("knife", "dirty")
# the cut leaves its knife dirty; the slice and the peel only need a clean one
CUT = FunctionalUnit((n("tomato", "whole"), CLEAN), Motion("cut"), (n("tomato", "sliced"), DIRTY))
SLICE = FunctionalUnit((n("onion", "whole"), CLEAN), Motion("slice"), (n("onion", "sliced"), CLEAN))
PEEL = FunctionalUnit((n("garlic", "whole"), CLEAN), Motion("peel"), (n("garlic", "peeled"), CLEAN))
SALSA = n("salsa", "mixed")
MIX = FunctionalUnit((n("tomato", "sliced"), n("onion", "sliced"), n("garlic", "peeled")), Motion("mix"), (SALSA,))
FOON = Foon((CUT, SLICE, PEEL, MIX))
GOAL = Goal(GoalSpec("salsa"), (SALSA,))


def _kitchen(knives: int) -> Kitchen:
    nodes = frozenset({CLEAN, n("tomato", "whole"), n("onion", "whole"), n("garlic", "whole")})
    return Kitchen(nodes, 3, "k", ((CLEAN, knives),))


def _action(task, motion: str):
    return next(a for a in task.actions if a.unit is not None and task.units[a.unit].motion.label == motion)


def test_a_role_that_only_checks_a_state_others_leave_binds_no_parameter():
    task = compile_task(FOON, _kitchen(3), GOAL, "relational")
    state = dict((node, name) for name, node in task.nodes)[CLEAN]
    slice_, cut = _action(task, "slice"), _action(task, "cut")
    assert Atom("occupied", (state,)) in slice_.pre
    assert not any(t == "knife" for _, t in slice_.params)  # no parameter per clean knife
    assert [b for _, b in slice_.roles] == [True, False]
    # the cut takes a knife out of the state: the tally goes down, from 3 clean knives
    assert Atom("tally", (state, "count-3")) in task.init and Atom("occupied", (state,)) in task.init
    assert any(a.predicate == "tally" for a in cut.delete)
    render(task)


def test_the_check_is_exact_one_knife_cut_first_leaves_none_clean():
    task = compile_task(FOON, _kitchen(1), GOAL, "relational")
    cut, slice_, peel = (_action(task, m).name for m in ("cut", "slice", "peel"))
    mix = _action(task, "mix").name
    low = [a for a in task.init if a.predicate == "zero-count"][0].args[0]
    high = next(a.args[1] for a in task.init if a.predicate == "next-count" and a.args[0] == low)
    args = {a.name: " ".join(f"{x.label}_1" for x, b in a.roles if b) for a in task.actions if a.unit is not None}
    first = f"{cut} {args[cut]} {low} {high}"
    later = [f"{slice_} {args[slice_]}", f"{peel} {args[peel]}"]
    assert simulate_plan(task, [*later, first, f"{mix} {args[mix]}", "reach-goal-1"]).ok
    bad = simulate_plan(task, [first, *later])
    assert not bad.ok and "occupied" in bad.problems[0]  # the only knife is dirty: nothing checks clean


def test_plans_still_name_the_clean_knife_and_replay_clean():
    outcome = clean_plan(FOON, _kitchen(1), GOAL)
    steps = {s.unit.motion.label: s for s in outcome.trace.steps}
    assert [b.object for b in steps["slice"].bindings if b.object.startswith("knife")] == ["knife_1"]
    assert [s.unit.motion.label for s in outcome.trace.steps].index("cut") > 0  # cut last: the knife is dirty then
