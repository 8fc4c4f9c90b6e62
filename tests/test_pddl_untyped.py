"""`pddl.untyped` (`compile --untyped`): types as static predicates; the same plans, no :typing."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.render import render
from foon2pddl.pddl.untyped import untyped
from foon2pddl.planners import fd


def _task(encoding: str, goal: str):
    net = load_network([])
    return compile_task(net.at(3), load_kitchen(None, net, 3), load_goal(goal, None, net.at(3)), encoding)


def _valid(domain: str, problem: str, steps) -> bool:
    from unified_planning.io import PDDLReader
    from unified_planning.plans import ActionInstance, SequentialPlan
    from unified_planning.shortcuts import PlanValidator, get_environment

    get_environment().credits_stream = None
    up = PDDLReader().parse_problem_string(domain, problem)
    actions, objects = {a.name.lower(): a for a in up.actions}, {o.name.lower(): o for o in up.all_objects}
    try:
        plan = SequentialPlan([ActionInstance(actions[s.split()[0]], [objects[x] for x in s.split()[1:]])
                               for s in steps])
    except Exception:  # an argument of the wrong type: UP refuses the action instance itself
        return False
    with PlanValidator(name="sequential_plan_validator") as v:
        return v.validate(up, plan).status.name == "VALID"


@pytest.mark.parametrize("encoding,goal", [("instances", "guacamole"), ("gen-lifted", "lemonade"),
                                           ("relational", "whipped cream"), ("gen-lifted", "fruit salad")])
def test_untyped_tasks_have_flat_pddl_and_the_same_plans(encoding, goal):
    from unified_planning.io import PDDLReader

    typed = render(_task(encoding, goal))
    flat = render(untyped(_task(encoding, goal)))
    assert ":typing" in typed[0] and ":typing" not in flat[0] and "(:types" not in flat[0]
    kind = PDDLReader().parse_problem_string(*flat).kind
    assert not kind.has_hierarchical_typing()
    for found_on, check_on in ((flat, typed), (typed, flat)):
        found = fd.solve(*found_on, time_limit=60)
        assert found.solved, found.message
        assert _valid(*check_on, found.plan), (encoding, goal)  # a plan of one is a plan of the other


def test_a_parameter_still_takes_only_objects_of_its_type():
    task = _task("gen-lifted", "lemonade")
    squeeze = next(a for a in task.actions if a.name.startswith("squeeze") and a.params)
    flat = untyped(task)
    action = next(a for a in flat.actions if a.name == squeeze.name)
    guard = next(p for p in action.pre if p.args == (squeeze.params[0][0],))
    assert guard.predicate.startswith("type_") and action.params == ((squeeze.params[0][0], "object"),)
    citrus = {x.args[0] for x in flat.init if x.predicate == guard.predicate}
    assert "lime" in citrus and "sugar" not in citrus  # a subtype's objects are of the supertype too
    tree = _task("tree", "guacamole")
    assert untyped(tree) is tree


def test_compile_untyped_writes_pddl_without_typing(tmp_path):
    result = CliRunner().invoke(main, ["compile", "--goal", "guacamole", "--encoding", "instances", "--untyped",
                                       "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    domain = (tmp_path / "domain.pddl").read_text()
    assert "(:requirements :strips)" in domain and "(type_" in domain
    result = CliRunner().invoke(main, ["compile", "--goal", "guacamole", "--goal", "pancake", "--encoding",
                                       "gen-lifted", "--untyped", "--shared-domain", "-o", str(tmp_path / "set")])
    assert result.exit_code == 0, result.output
    assert ":typing" not in (tmp_path / "set" / "domain.pddl").read_text()
