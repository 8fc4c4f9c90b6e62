"""Action schemas whose parameters multiply are split into chains (`pddl/split_actions.py`): the planner grounds
the parts, the plan comes back with one step per unit firing, every binding in place, valid and replay-clean."""

from __future__ import annotations

from math import prod

from relational_checks import clean_plan
from test_relational_interchangeable import EMPTY, FOON, GOAL, JARS, KEPT

from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl import split_actions
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.split_actions import CHAIN, IDLE, split
from foon2pddl.pddl.task import Atom
from foon2pddl.planners import solve

# Four empty bowls, three jars of salt: the mix binds a bowl of sugar, the sugar, a bowl of salt, the salt in it.
KITCHEN = Kitchen(frozenset({EMPTY, *JARS.values(), *KEPT.values()}),
                  counts=((EMPTY, 4), (KEPT["salt"], 3), (JARS["salt"], 3)))


def _task():
    return compile_goal(FOON, KITCHEN, GOAL, "relational").task


def _sizes(task):
    return {t: sum(1 for _, u in task.objects if u == t) for _, t in task.objects}


def test_a_checked_ingredient_is_bound_by_its_own_part_and_each_part_grounds_less():
    task = _task()
    mix = next(a for a in task.actions if a.name.startswith("mix"))
    chains = split(task, above=1)
    parts = [a for a in chains.task.actions if a.name.startswith(mix.name)]
    assert [a.name for a in parts] == [f"{mix.name}-begin", f"{mix.name}-check-1", f"{mix.name}-end"]
    size = _sizes(task)
    whole = prod(size[t] for _, t in mix.params)
    assert all(prod(size[t] for _, t in a.params) < whole for a in parts)
    # the salt only needs to be in the bowl of salt (the mix consumes every salt there): the check binds it
    assert dict(parts[1].params) == {"?bowl-2": "bowl", "?salt": "salt"}
    # the sugar bowl turns dirty, so the sugar's own effects stay with the action: begin and end bind it
    assert "?sugar" in dict(parts[0].params) and "?salt" not in dict(parts[2].params)
    # the parts before the last change only where the chain is and what it recorded
    assert parts[0].add[0] == Atom(CHAIN, (f"{mix.name}-stage-0",)) and parts[0].delete == (Atom(CHAIN, (IDLE,)),)
    assert all(a.predicate.startswith(f"{mix.name}-arg-") for a in parts[0].add[1:]) and not parts[1].conditional
    assert {a.predicate for a in (*parts[1].add, *parts[1].delete)} == {CHAIN}
    # nothing else applies while a chain is under way, and a plan ends with none under way
    others = [a for a in chains.task.actions if not a.name.startswith(mix.name)]
    assert all(a.pre[0] == Atom(CHAIN, (IDLE,)) for a in others) and chains.task.goal[-1] == Atom(CHAIN, (IDLE,))


def test_a_plan_of_the_parts_joins_back_into_the_action_with_every_binding():
    task = _task()
    chains = split(task, above=1)
    steps = ("pour_u1 jar_1 salt_1 bowl_1", "mix_u2-begin bowl_2 sugar_1 bowl_1 mixture_1 bowl_3",
             "mix_u2-check-1 bowl_1 salt_1", "mix_u2-end bowl_2 sugar_1 bowl_1 mixture_1 bowl_3")
    assert chains.join(steps) == ("pour_u1 jar_1 salt_1 bowl_1", "mix_u2 bowl_2 sugar_1 bowl_1 salt_1 mixture_1 bowl_3")


def test_a_task_whose_actions_ground_small_is_unchanged():
    task = _task()
    assert split(task).task is task and not split(task).parts


def test_the_planner_gets_the_chain_and_the_plan_fires_the_unit_once(monkeypatch):
    monkeypatch.setattr(split_actions, "SPLIT_ABOVE", 1)
    seen = []
    real = solve.run_planner

    def spy(task, domain, problem, **options):
        seen.append(domain)
        return real(task, domain, problem, **options)

    monkeypatch.setattr(solve, "run_planner", spy)
    outcome = clean_plan(FOON, KITCHEN, GOAL, time_limit=20)
    assert seen and all("mix_u2-check-1" in domain for domain in seen)
    mixes = [step.split() for step in outcome.result.plan if step.startswith("mix")]
    assert len(mixes) == 1 and mixes[0][0] == "mix_u2" and len(mixes[0]) == 7, outcome.result.plan
    assert not any("-begin" in s or "-check-" in s or "-end" in s for s in outcome.result.plan)
