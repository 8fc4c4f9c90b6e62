"""Action schemas whose parameters multiply are split into chains (`pddl/split_actions.py`): the planner grounds
the parts, the plan comes back with one step per unit firing, every binding in place, valid and replay-clean."""

from __future__ import annotations

from dataclasses import replace
from math import prod

from relational_checks import clean_plan
from test_relational_interchangeable import EMPTY, FOON, GOAL, JARS, KEPT

from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl import split_actions
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.split_actions import CHAIN, IDLE, split
from foon2pddl.pddl.task import Action, Atom, Conditional, PlanningTask, apply_action, type_closure
from foon2pddl.planners import solve

# Four empty bowls, three jars of salt: the mix binds a bowl of sugar, the sugar, a bowl of salt, the salt in it.
KITCHEN = Kitchen(frozenset({EMPTY, *JARS.values(), *KEPT.values()}),
                  counts=((EMPTY, 4), (KEPT["salt"], 3), (JARS["salt"], 3)))


def _task():
    return compile_goal(FOON, KITCHEN, GOAL, "relational").task


def _sizes(task):
    return {t: sum(1 for _, u in task.objects if u == t) for _, t in task.objects}


def _parts(chains, action):
    return [a for a in chains.task.actions if a.name.startswith(f"{action.name}-")]


def _changes_only_the_chain(part, action) -> bool:
    return not part.conditional and all(a.predicate == CHAIN or a.predicate.startswith(f"{action.name}-arg-")
                                        for a in (*part.add, *part.delete))


def test_a_checked_ingredient_is_bound_by_its_own_part_and_each_part_grounds_less():
    task = _task()
    mix = next(a for a in task.actions if a.name.startswith("mix"))
    chains = split(task, above=1)
    parts = _parts(chains, mix)
    assert parts[0].name == f"{mix.name}-begin" and parts[-1].name == f"{mix.name}-end"
    size = _sizes(task)
    whole = prod(size[t] for _, t in mix.params)
    assert all(prod(size[t] for _, t in a.params) < whole for a in parts)
    # the salt only needs to be in the bowl of salt (the mix consumes every salt there): one check binds it,
    # with the bowl of salt, and nothing records it
    salted = [a for a in parts if "?salt" in dict(a.params)]
    assert len(salted) == 1 and dict(salted[0].params) == {"?bowl-2": "bowl", "?salt": "salt"}
    assert "-check-" in salted[0].name and _changes_only_the_chain(salted[0], mix)
    assert not any(a.predicate == f"{mix.name}-arg-salt" for p in parts for a in p.add)
    # the sugar bowl turns dirty, so the sugar's own effects stay with the action: a part binds and records it
    # before the checks end, a later one consumes it
    assert any(a.predicate == f"{mix.name}-arg-sugar" for p in parts for a in p.add)
    # the parts that bind change only where the chain is and what it recorded; the first takes the lock
    binding = [p for p in parts if "-begin" in p.name or "-check-" in p.name]
    assert parts[:len(binding)] == binding and all(_changes_only_the_chain(p, mix) for p in binding)
    assert parts[0].add[0] == Atom(CHAIN, (f"{mix.name}-stage-0",)) and parts[0].delete == (Atom(CHAIN, (IDLE,)),)
    # nothing else applies while a chain is under way, and a plan ends with none under way
    others = [a for a in chains.task.actions if a.name not in chains.parts]
    assert all(a.pre[0] == Atom(CHAIN, (IDLE,)) for a in others) and chains.task.goal[-1] == Atom(CHAIN, (IDLE,))


def _steps(chains, action, values):
    """The plan steps of `action`'s chain bound as `values` (parameter -> object)."""
    return tuple(" ".join((p.name, *(values[v] for v, _ in p.params))) for p in _parts(chains, action))


def test_a_plan_of_the_parts_joins_back_into_the_action_with_every_binding():
    task = _task()
    chains = split(task, above=1)
    mix = next(a for a in task.actions if a.name.startswith("mix"))
    values = dict(zip((v for v, _ in mix.params), ("bowl_2", "sugar_1", "bowl_1", "salt_1", "mixture_1", "bowl_3"),
                      strict=True))
    steps = ("pour_u1 jar_1 salt_1 bowl_1", *_steps(chains, mix, values))
    assert chains.join(steps) == ("pour_u1 jar_1 salt_1 bowl_1", "mix_u2 bowl_2 sugar_1 bowl_1 salt_1 mixture_1 bowl_3")


def test_an_action_whose_every_parameter_has_effects_is_split_too():
    task = _task()
    pour = next(a for a in task.actions if a.name.startswith("pour"))
    assert not {v for v, _ in pour.params} - {x for a in (*pour.add, *pour.delete) for x in a.args}
    size = _sizes(task)
    whole = prod(size[t] for _, t in pour.params)
    parts = _parts(split(task, above=1), pour)
    assert len(parts) > 1 and all(prod(size[t] for _, t in a.params) < whole for a in parts)


# A box-to-box move whose sweep reads what the move adds: the chain must do what the action does.
ITEM, BOX = "item", "box"
MOVE = Action("move", params=(("?a", BOX), ("?b", BOX), ("?x", ITEM)),
              pre=(Atom("in", ("?a", "?x")), Atom("is", ("?a", "full")), Atom("is", ("?b", "open"))),
              add=(Atom("in", ("?b", "?x")), Atom("is", ("?a", "open")), Atom("is", ("?x", "moved"))),
              delete=(Atom("in", ("?a", "?x")), Atom("is", ("?a", "full"))),
              conditional=(Conditional((Atom("in", ("?b", "?y")),), add=(Atom("is", ("?y", "crushed")),),
                                       delete=(Atom("in", ("?b", "?y")),), var="?y", type=ITEM),
                           Conditional((Atom("is", ("?y", "moved")),), delete=(Atom("is", ("?y", "moved")),),
                                       var="?y", type=ITEM)))
BOXES = PlanningTask("d", "p", "relational", 3, (), (MOVE,), (), (), types=((BOX, "object"), (ITEM, "object")),
                     objects=(("a1", BOX), ("a2", BOX), ("x1", ITEM), ("x2", ITEM), ("x3", ITEM)),
                     constants=(("full", "object"), ("open", "object"), ("moved", "object"), ("crushed", "object")))


def test_a_chain_does_what_the_action_does_whatever_its_parts_read_and_write():
    chains = split(BOXES, above=1)
    parts = _parts(chains, MOVE)
    assert len(parts) > 2 and all(len(p.params) < 3 for p in parts)
    types = type_closure(chains.task)
    start = {Atom("in", ("a1", "x1")), Atom("in", ("a2", "x2")), Atom("is", ("x3", "moved")),
             Atom("is", ("a1", "full")), Atom("is", ("a2", "open"))}
    bind = {"?a": "a1", "?b": "a2", "?x": "x1"}
    whole = apply_action(start, MOVE, bind, types)
    state = start | {Atom(CHAIN, (IDLE,))}
    for part in parts:
        assert all(a in state for a in (Atom(x.predicate, tuple(bind.get(y, y) for y in x.args)) for x in part.pre))
        state = apply_action(state, part, bind, types)
    # x2 was in a2 before the move: crushed; x1 arrives in a2 and stays whole; only x1 ends moved
    assert whole == {Atom("in", ("a2", "x1")), Atom("is", ("x2", "crushed")), Atom("is", ("a1", "open")),
                     Atom("is", ("x1", "moved")), Atom("is", ("a2", "open"))}
    assert state == whole | {Atom(CHAIN, (IDLE,))}


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


def _boxes(n: int):
    return replace(BOXES, objects=(("a1", BOX), ("a2", BOX), *((f"x{i}", ITEM) for i in range(n))))


def test_an_action_whose_sweeps_multiply_is_split_though_its_parameters_do_not():
    # 2 boxes x 2 boxes x 400 items = 1,600 bindings, under the bound, but each sweeps twice over the 400 items: a
    # planner looks at 1.28 million effects (the odd-index universal shrimp mango salad's mix: 3,600 bindings, 14
    # sweeps)
    lots = _boxes(400)
    chains = split(lots, above=2000)
    # the binding part may bind all three (no effect there); no sweep grounds once per binding
    swept = [p for p in _parts(chains, MOVE) if p.conditional]
    assert swept and all(len(p.params) < 3 for p in swept)
    # with 30 items, 120 bindings x 61 stay under what a binding's sweeps may add
    few = _boxes(30)
    assert 120 * 61 <= 1000 * split_actions.SWEEPS_PER_BINDING and split(few, above=1000).task is few


def test_an_action_whose_sweeps_weigh_eight_times_the_bound_is_split():
    # the odd-index universal FOON's chocolate cake, its small task: the blend (`ACT-0068-apple_cake.txt:199`) binds
    # a blender, its jar, an egg, a milk, a sugar, a butter and the egg mixture made, 490 ground operators each
    # sweeping over every egg, milk, sugar and butter in the jar (22,295 of the task's 87,229 ground effects; 14 times
    # the bound by the weight); split, the task translates in 4.7 s of CPU instead of 6.7 s (measured at load 4)
    # here: 160 bindings x 81 = 12,960, past 8 x 1,000
    lots = _boxes(40)
    chains = split(lots, above=1000)
    swept = [p for p in _parts(chains, MOVE) if p.conditional]
    assert swept and all(len(p.params) < 3 for p in swept)


# A move that also counts down a tally: two count parameters a static `next` fact links, ten counts, nine facts.
COUNT = "count"
COUNTED = replace(MOVE, name="counted", params=(*MOVE.params, ("?lo", COUNT), ("?hi", COUNT)),
                  pre=(*MOVE.pre, Atom("left", ("?hi",)), Atom("next", ("?lo", "?hi"))),
                  add=(*MOVE.add, Atom("left", ("?lo",))), delete=(*MOVE.delete, Atom("left", ("?hi",))))


def _counted(items: int):
    counts = tuple((f"c{i}", COUNT) for i in range(10))
    return replace(BOXES, actions=(COUNTED,), types=(*BOXES.types, (COUNT, "object")),
                   objects=(("a1", BOX), ("a2", BOX), *((f"x{i}", ITEM) for i in range(items)), *counts),
                   init=(Atom("left", ("c9",)), *(Atom("next", (f"c{i}", f"c{i + 1}")) for i in range(9))))


def test_parameters_a_static_fact_links_multiply_as_its_facts_not_as_their_objects():
    # 2 boxes x 2 boxes x 3 items x 10 x 10 counts = 1,200 combinations, but `next` (no action changes it) holds for
    # 9 pairs of counts: a planner grounds at most 2 x 2 x 3 x 9 = 108 bindings, under the bound of 200
    few = _counted(3)
    assert split(few, above=200).task is few
    # with 30 items (1,080 bindings) it splits, and every part that binds both counts checks the static fact
    lots = _counted(30)
    parts = _parts(split(lots, above=200), COUNTED)
    assert len(parts) > 1
    both = [p for p in parts if {"?lo", "?hi"} <= dict(p.params).keys()]
    assert both and all(Atom("next", ("?lo", "?hi")) in p.pre for p in both)
