"""The `instances` encoding's PDDL has flat types (issue 27): engines without a type hierarchy read it.

Tamer (through unified-planning) supports only FLAT_TYPING: an object of a subtype (`bowl_1 - bowl`,
`bowl - physical-object`) as the argument of a predicate declared over the supertype (`is ?x -
physical-object`) is a TypeCheckingError there, and UP's support check refuses the task. The oracle
here is unified-planning's own classification of the task (`ProblemKind`), which is what Tamer's
`supports` compares with its FLAT_TYPING, on the PDDL text as UP's reader reads it and on
`to_up_problem`. The second half checks, from the task's own facts, that flattening the labels left
every role binding exactly the instances of its label (the types' job before).
"""

from __future__ import annotations

import pytest

from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.examples import GOALS, LEVEL
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import PlanningTask, type_closure
from foon2pddl.pddl.up_problem import quiet_environment, to_up_problem

CATEGORIES = (("bowl", ("bowls", "containers")), ("plate", ("plates", "containers")),
              ("knife", ("cutlery", "utensil")), ("whisk", ("utensil",)))


def _task(goal: str, **options) -> PlanningTask:
    net = load_network([])
    foon = net.at(LEVEL)
    return compile_task(foon, load_kitchen(None, net, LEVEL), load_goal(goal, None, foon), "instances", LEVEL,
                        **options)


@pytest.mark.parametrize("goal", GOALS)
def test_instances_pddl_has_flat_types_as_up_reads_it(goal):
    from unified_planning.io import PDDLReader

    quiet_environment()
    for task in (_task(goal), _task(goal, categories=CATEGORIES)):
        for kind in (PDDLReader().parse_problem_string(*render(task)).kind, to_up_problem(task).kind):
            assert kind.has_flat_typing() and not kind.has_hierarchical_typing(), goal


@pytest.mark.parametrize("goal,categories", [(g, ()) for g in GOALS] + [("greek salad", CATEGORIES)])
def test_a_role_binds_exactly_the_instances_of_its_label(goal, categories):
    task = _task(goal, categories=categories)
    static = {p.name for p in task.predicates} - {a.predicate for x in task.actions for a in (*x.add, *x.delete)}
    kinds = type_closure(task)
    label = {x.name: x.label for x in task.instances}
    checked = 0
    for action in task.actions:
        if action.unit is None:
            continue
        roles = [r for r, bound in action.roles if bound]
        assert len(roles) == len(action.params)
        for (var, typ), role in zip(action.params, roles, strict=True):
            guards = [a.predicate for a in action.pre if a.args == (var,) and a.predicate in static]
            fits = {o for o in label if typ in kinds[o]
                    and all(any(f.predicate == g and f.args == (o,) for f in task.init) for g in guards)}
            assert fits == {o for o, lab in label.items() if lab == role.label}, (action.name, var)
            checked += 1
    assert checked > 0
