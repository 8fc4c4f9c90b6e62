"""Plan -> task tree, `solve.plan` end to end, unified-planning problems and engines."""

from __future__ import annotations

import pytest

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import GROUND_ENCODINGS, compile_task
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Action, Atom, PlanningTask, Predicate, candidate_atoms
from foon2pddl.pddl.up_problem import build_up, to_up_problem
from foon2pddl.planners import up_engine
from foon2pddl.planners.decode import PlanDecodeError, decode, plan_units
from foon2pddl.planners.goal_replanner import GoalReplanner
from foon2pddl.planners.solve import plan


def node(label, *states):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states])


ONION, KNIFE, BOWL = node("onion", "whole"), node("knife"), node("bowl", "empty")
SLICED, CHOPPED = node("onion", "sliced"), node("onion", "chopped")
SALAD = node("bowl", ("contains", "", ["onion"]))
EGG, FRIED = node("egg", "raw"), node("egg", "fried")


def unit(motion, ins, outs):
    return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs))


FOON = Foon((
    unit("slice", [ONION, KNIFE], [SLICED, KNIFE]),
    unit("chop", [SLICED, KNIFE], [CHOPPED]),
    unit("pour", [CHOPPED, BOWL], [SALAD]),
    unit("fry", [EGG], [FRIED]),
))
KITCHEN = Kitchen(frozenset({ONION, KNIFE, BOWL}))


def goal(label, *states):
    return resolve_goal(GoalSpec(label, tuple(make_state(s) for s in states) if states else None), FOON)


# ------------------------------------------------------------------ decode


def test_plan_decodes_to_a_valid_tree_through_fd():
    out = plan(FOON, KITCHEN, goal("bowl"))
    assert out.status == "solved"
    assert [u.motion.label for u in out.tree.units] == ["slice", "chop", "pour"]
    assert out.tree.goal == SALAD
    assert out.validation.ok
    assert set(out.timings) >= {"encode", "write", "translate", "search", "decode", "validate"}


def test_goal_with_several_candidates_skips_auxiliary_actions():
    task = compile_task(FOON, KITCHEN, goal("onion"), prune=False)
    aux = [a for a in task.actions if a.unit is None]
    assert len(aux) == 2  # onion sliced / chopped
    out = plan(FOON, KITCHEN, goal("onion"))
    assert out.status == "solved"
    assert out.tree.goal == SLICED and [u.motion.label for u in out.tree.units] == ["slice"]
    assert len(out.result.plan) == 2  # slice + reach-goal


def test_unreachable_goal_is_unsolvable_without_tree():
    out = plan(FOON, KITCHEN, goal("egg"))
    assert out.status == "unsolvable" and out.tree is None


def test_wrong_order_fails_validation_and_unknown_step_fails_decoding():
    task = compile_task(FOON, KITCHEN, goal("bowl"), prune=False)
    names = {task.units[a.unit].motion.label: a.name for a in task.actions if a.unit is not None}
    good = decode(task, [names["slice"], names["chop"], names["pour"]], goal("bowl"), KITCHEN.nodes)
    assert good.ok
    bad = decode(task, [names["chop"], names["slice"], names["pour"]], goal("bowl"), KITCHEN.nodes)
    assert not bad.ok and "step 1 (chop)" in bad.validation.problems[0]
    assert not bad.plan_check.ok and "precondition false" in bad.plan_check.problems[0]
    short = decode(task, [names["slice"], names["chop"]], goal("bowl"), KITCHEN.nodes)
    assert "goal false" in short.plan_check.problems[0]
    with pytest.raises(PlanDecodeError):
        plan_units(task, ["no-such-action"])


def test_state_encoding_plans_decode_too():
    out = plan(FOON, KITCHEN, goal("bowl"), "state")
    assert out.status == "solved" and out.tree.goal == SALAD
    assert out.decoded.plan_check.ok and not out.decoded.foon_semantics


def test_state_encoding_combines_facts_foon_does_not():
    # The kitchen has an opened jar and a jar of cream as two nodes; FOON needs one node with both.
    jar_open, jar_cream = node("jar", "opened"), node("jar", ("contains", "", ["cream"]))
    jar_both = node("jar", "opened", ("contains", "", ["cream"]))
    foon = Foon((unit("scoop", [jar_both], [node("cream", "scooped")]),))
    kitchen = Kitchen(frozenset({jar_open, jar_cream}))
    target = resolve_goal(GoalSpec("cream"), foon)
    assert plan(foon, kitchen, target, "tree").status == "unsolvable"
    out = plan(foon, kitchen, target, "state")
    assert out.status == "solved"
    assert out.decoded.plan_check.ok and not out.validation.ok


def test_planner_error_and_timeout_statuses_come_through():
    assert plan(FOON, KITCHEN, goal("bowl"), planner_cmd="/nonexistent {domain}").status == "error"
    assert plan(FOON, KITCHEN, goal("bowl"), time_limit=0.001).status == "timeout"


@pytest.mark.parametrize("encoding", GROUND_ENCODINGS)
def test_every_goal_action_names_its_candidate(encoding):
    nodes = tuple(sorted(FOON.nodes))
    task = compile_task(FOON, KITCHEN, Goal(GoalSpec("any node"), nodes, 3), encoding, prune=False)
    atoms = candidate_atoms(task, nodes)
    assert list(atoms) == list(nodes)
    for action in task.actions:
        if action.candidate is not None:
            assert action.unit is None and action.comment[0].endswith(action.candidate.describe())
            assert atoms[action.candidate] == action.pre


@pytest.mark.parametrize("encoding", ["tree", "state", "foon-compat"])
def test_replanner_agrees_with_fresh_plans(encoding):
    rp = GoalReplanner(FOON, KITCHEN, encoding)
    for spec in (("bowl",), ("onion",), ("onion", "chopped"), ("egg",)):
        fresh, reused = plan(FOON, KITCHEN, goal(*spec), encoding), rp.plan(goal(*spec))
        assert fresh.status == reused.status == ("unsolvable" if spec == ("egg",) else "solved")
        if reused.tree is not None:
            assert reused.validation.ok


# ------------------------------------------------------------------ unified-planning


def test_up_validator_accepts_fd_plans_and_rejects_bad_ones():
    out = plan(FOON, KITCHEN, goal("onion"), up_validate=True)
    assert out.decoded.up_validation is not None and out.decoded.up_validation.ok
    task = compile_task(FOON, KITCHEN, goal("bowl"))
    pour = next(a.name for a in task.actions if a.unit is not None and task.units[a.unit].motion.label == "pour")
    bad = decode(task, [pour], goal("bowl"), KITCHEN.nodes, up_validate=True)
    assert not bad.up_validation.ok and "UP validator" in bad.up_validation.problems[0]


def test_to_up_problem_keeps_action_names_and_renames_clashing_fluents():
    task = PlanningTask(
        "d", "p", "state", 3, (Predicate("go"), Predicate("at", (("?x", "place"),))),
        (Action("go", (), (Atom("go"),), cost=3, unit=0),
         Action("move", (Atom("at", ("?x",)),), (Atom("go"),), (Atom("at", ("?x",)),), params=(("?x", "place"),),
                unit=1)),
        (Atom("at", ("home",)),), (Atom("go"),), objects=(("home", "place"),),
    )
    up = build_up(task)
    assert sorted(a.name for a in up.problem.actions) == ["go", "move"]
    assert len({f.name for f in up.problem.fluents}) == 2 and "go" not in {f.name for f in up.problem.fluents}
    assert up.problem.quality_metrics  # action costs carried over
    assert to_up_problem(task).name == "p"


def test_up_problem_of_a_compiled_task_plans_with_pyperplan():
    task = compile_task(FOON, KITCHEN, goal("onion"))
    result = up_engine.solve(task, "pyperplan", time_limit=60)
    assert result.status == "solved"
    assert decode(task, result.plan, goal("onion"), KITCHEN.nodes).ok


def test_up_engine_errors_and_timeouts():
    task = compile_task(FOON, KITCHEN, goal("bowl"))
    unknown = up_engine.solve(task, "no-such-engine", time_limit=60)
    assert unknown.status == "error" and "pyperplan" in unknown.message
    # Many single-use tokens, more products than tokens: pyperplan's blind search exhausts a large space.
    tokens, products = [f"t{i}" for i in range(9)], [f"p{i}" for i in range(10)]
    hard = PlanningTask(
        "tok", "p", "state", 3, tuple(Predicate(x) for x in tokens + products),
        tuple(Action(f"use-{t}-{p}", (Atom(t),), (Atom(p),), (Atom(t),), unit=0) for t in tokens for p in products),
        tuple(Atom(t) for t in tokens), tuple(Atom(p) for p in products),
    )
    assert up_engine.solve(hard, "pyperplan", time_limit=1.0).status == "timeout"
    render(hard)  # the same task is valid PDDL


def test_doubled_plan_decodes_to_the_same_tree_and_says_so():
    """Issue 11: every step doubled was accepted as a 26-unit tree with repeated units."""
    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.planners.result import PlanResult
    from foon2pddl.planners.solve import outcome_of

    net = load_network([])
    foon = net.at(3)
    kitchen, goal = load_kitchen(None, net, 3), load_goal("guacamole", None, foon)
    once = plan(foon, kitchen, goal, "tree")
    doubled = tuple(s for s in once.result.plan for _ in (0, 1))
    twice = outcome_of(PlanResult("solved", doubled, "test"), once.compiled, goal, kitchen.project(3).nodes, {}, False)
    assert twice.status == "solved" and twice.tree == once.tree
    assert len(set(twice.tree.units)) == len(twice.tree.units)
    units = sum(once.task.action_for(s.split()[0]).unit is not None for s in once.result.plan)
    assert twice.decoded.notes[0] == (f"dropped {units} plan steps repeating a unit already applied "
                                      "(no effect in this delete-free encoding)")
    # the steps the goal does not need are named once, at their first position, either way
    left_out = tuple(n for n in once.decoded.notes if n.startswith("the planner's plan has "))
    assert once.decoded.notes == left_out and len(twice.decoded.notes) == 1 + len(left_out)


@pytest.mark.parametrize(("encoding", "dish"), [("tree", "guacamole"), ("foon-compat", "guacamole"), ("ocp", "pancake"),
                                               ("state", "pancake"), ("instances", "guacamole")])
def test_the_plan_reported_is_a_valid_subplan_of_the_planners_that_makes_the_tree(encoding, dish):
    """Issue 24: the steps a plan reports are the ones the tree needs, in the planner's order, and still a plan."""
    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.planners.decode import simulate_plan

    net = load_network([])
    foon = net.at(3)
    kitchen, goal = load_kitchen(None, net, 3), load_goal(dish, None, foon)
    out = plan(foon, kitchen, goal, encoding)
    assert out.status == "solved", out.message
    raw, used = out.result.plan, out.steps
    assert simulate_plan(out.task, used).ok
    walk = iter(raw)
    assert all(step in walk for step in used)  # a subsequence of the planner's plan
    if out.compiled.every_step or not out.compiled.foon_semantics:
        assert used == tuple(raw)  # every step is a firing (or the tree is no FOON tree): nothing left out
    else:
        units = [out.compiled.unit_of(out.task.action_for(s.split()[0]), tuple(s.split()[1:])) for s in used]
        assert len([u for u in units if u is not None]) == len(out.decoded.tree.units)
        assert len(used) < len(raw)  # lama-first's guacamole plan has detours (named in a note)
