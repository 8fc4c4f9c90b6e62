"""Interchangeable objects are taken in one order (`pddl/interchangeable.py`): objects that start alike are bound
first in the task's order, so a search does not try every bowl of a stack; the task stays solvable."""

from __future__ import annotations

from itertools import pairwise

from node_words import contains, inside, n
from relational_checks import clean_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.interchangeable import NEXT, READY, in_order
from foon2pddl.planners import solve

# Sugar and salt each poured from a jar into an empty bowl, then both bowls mixed: four empty bowls in the kitchen.
EMPTY = n("bowl", "empty")
JARS = {x: n("jar", contains(x)) for x in ("sugar", "salt")}
KEPT = {x: n(x, inside("jar")) for x in ("sugar", "salt")}
POURS = [FunctionalUnit((JARS[x], KEPT[x], EMPTY), Motion("pour"),
                        (n("jar", "empty"), n(x, inside("bowl")), n("bowl", contains(x))), (Source("mix.txt", k),))
         for k, x in enumerate(("sugar", "salt"), 1)]
MIXED = n("mixture", inside("bowl"))
MIX = FunctionalUnit((n("bowl", contains("sugar")), n("sugar", inside("bowl")), n("bowl", contains("salt")),
                      n("salt", inside("bowl"))), Motion("mix"), (MIXED, n("bowl", "dirty")), (Source("mix.txt", 3),))
FOON = Foon((*POURS, MIX))
KITCHEN = Kitchen(frozenset({EMPTY, *JARS.values(), *KEPT.values()}), counts=((EMPTY, 4),))
GOAL = Goal(GoalSpec("mixture"), (MIXED,))


def _task():
    return compile_goal(FOON, KITCHEN, GOAL, "relational").task


def test_objects_that_start_alike_are_taken_in_the_tasks_order():
    task = in_order(_task())
    bowls = sorted(name for name, t in task.objects if t == "bowl")
    assert len(bowls) == 4
    assert {a.args for a in task.init if a.predicate == NEXT} >= set(pairwise(bowls))
    ready = {a.args[0] for a in task.init if a.predicate == READY}
    assert bowls[0] in ready and not ready & set(bowls[1:])
    # the jars each hold an ingredient: no two of them start alike
    assert not any(a.args[0].startswith("jar") for a in task.init if a.predicate == NEXT)
    pour = next(a for a in task.actions if a.name.startswith("pour"))
    assert any(p.predicate == READY for p in pour.pre) and any(c.add and c.add[0].predicate == READY
                                                                 for c in pour.conditional)


def test_a_task_without_objects_alike_is_unchanged():
    single = Kitchen(frozenset({EMPTY, *JARS.values(), *KEPT.values()}), counts=((EMPTY, 1),))
    task = compile_goal(Foon(tuple(POURS[:1])), single, Goal(GoalSpec("bowl"), (POURS[0].outputs[2],)),
                        "relational").task
    assert in_order(task) == task


def test_the_planner_gets_the_order_and_its_plan_stays_valid_and_replay_clean(monkeypatch):
    seen = []
    real = solve.run_planner

    def spy(task, domain, problem, **options):
        seen.append((domain, problem))
        return real(task, domain, problem, **options)

    monkeypatch.setattr(solve, "run_planner", spy)
    outcome = clean_plan(FOON, KITCHEN, GOAL, time_limit=20)
    assert seen and all(f"({NEXT} " in problem and f"({READY} ?" in domain for domain, problem in seen)
    pours = [step for step in outcome.result.plan if step.startswith("pour")]
    assert len(pours) == 2 and "bowl_1" in pours[0] and "bowl_2" in pours[1], outcome.result.plan
    assert not any(a.predicate == READY for a in outcome.task.init)  # the outcome keeps `compile`'s task
