"""`pddl.untouched`: objects no action can touch are set aside from the problem, and no plan changes.

Two oracles: exhaustive search of small random tasks (every state reachable in the whole task, its facts that
name no object set aside and that a condition or the goal reads, is a state reachable in the smaller one, and
back), and the relational whipped
cream, whose problem leaves out the carton and the spatula while its plan still names them.
"""

from __future__ import annotations

from dataclasses import replace

from conftest import SUBGRAPHS
from hypothesis import given, settings
from hypothesis import strategies as st
from task_search import explore

from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Action, Atom, Conditional, PlanningTask, Predicate, type_closure
from foon2pddl.pddl.untouched import set_aside, untouched
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

OBJECTS = (("a", "bowl"), ("b", "bowl"), ("c", "egg"), ("d", "egg"))
STATES = ("s0", "s1", "s2")
TYPES = (("bowl", "thing"), ("egg", "thing"))


@st.composite
def tasks(draw) -> PlanningTask:
    """Four objects of two types, states `(is ?x s)`, a holder fact `(in ?h ?x)`, `(occupied s)`, and actions of
    up to two parameters (and one of the states' type, bound to the constants) with conditional effects quantified
    over a type (what the relational encoding writes)."""
    init = [Atom("is", (o, draw(st.sampled_from(STATES)))) for o, _ in OBJECTS if draw(st.booleans())]
    init += [Atom("in", (h, x)) for h, x in draw(st.lists(st.tuples(st.sampled_from("ab"), st.sampled_from("cd")),
                                                         max_size=2, unique=True))]
    init += [Atom("occupied", (s,)) for s in draw(st.lists(st.sampled_from(STATES), max_size=1))]
    actions = []
    for k in range(draw(st.integers(1, 4))):
        params = tuple((v, draw(st.sampled_from(("bowl", "egg", "thing")))) for v in ("?p", "?q")[:draw(st.integers(1, 2))])
        names = [v for v, _ in params]

        def var(names=names) -> str:
            return draw(st.sampled_from(names))
        pre = [Atom("is", (v, draw(st.sampled_from(STATES)))) for v, _ in params if draw(st.booleans())]
        if draw(st.booleans()):
            pre.append(Atom("occupied", (draw(st.sampled_from(STATES)),)))
        if len(params) == 2 and draw(st.booleans()):
            pre.append(Atom("in", ("?p", "?q")))
        add = [Atom("is", (var(), draw(st.sampled_from(STATES))))]
        if draw(st.booleans()):  # a parameter of the constants' type: the state ?p is in, or one it gets
            params += (("?s", "state"),)
            (pre if draw(st.booleans()) else add).append(Atom("is", ("?p", "?s")))
        if draw(st.booleans()):
            add.append(Atom("occupied", (draw(st.sampled_from(STATES)),)))
        cond = []
        if draw(st.booleans()):
            when = [Atom("is", ("?y", draw(st.sampled_from(STATES))))]
            if draw(st.booleans()):
                when.append(Atom("in", (var(), "?y")))
            effect = draw(st.sampled_from((Atom("is", ("?y", "s2")), Atom("occupied", ("s1",)),
                                           Atom("is", (var(), "s1")))))
            cond.append(Conditional(tuple(when), add=(effect,), delete=(when[0],), var="?y",
                                    type=draw(st.sampled_from(("bowl", "egg", "thing")))))
        actions.append(Action(f"act{k}", tuple(pre), tuple(add), params=params, conditional=tuple(cond)))
    preds = (Predicate("is", (("?x", "thing"), ("?s", "state"))), Predicate("in", (("?h", "thing"), ("?x", "thing"))),
             Predicate("occupied", (("?s", "state"),)))
    return PlanningTask("d", "p", "relational", 3, preds, tuple(actions), tuple(sorted(set(init))),
                        (Atom("occupied", ("s2",)),), types=TYPES, objects=OBJECTS,
                        constants=tuple((s, "state") for s in STATES))


def _reachable(task: PlanningTask, types: dict[str, frozenset[str]]) -> set[frozenset[Atom]]:
    """Every state reachable from `task.init`, over the objects of `types` (exhaustive search)."""
    return explore(task, types)[0]


@settings(max_examples=400, deadline=None)
@given(tasks())
def test_setting_aside_keeps_every_reachable_state_of_the_objects_kept(task):
    small = set_aside(task)
    aside = {o for o, _ in small.aside}
    assert aside == untouched(task) and {o for o, _ in small.objects} == {o for o, _ in task.objects} - aside
    whole = _reachable(task, type_closure(task))
    kept = _reachable(small, {o: ts for o, ts in type_closure(small).items() if o not in aside})
    reads = [a for act in task.actions for a in (*act.pre, *(x for c in act.conditional for x in c.when))]
    read = [*reads, *task.goal]  # a fact nothing reads (write-only) changes no plan: compared without them

    def seen(state):
        return frozenset(a for a in state if any(r.predicate == a.predicate and len(r.args) == len(a.args) and all(
            x == y or x.startswith("?") for x, y in zip(r.args, a.args, strict=True)) for r in read))
    assert {seen(a for a in s if not aside & set(a.args)) for s in whole} == {seen(s) for s in kept}
    assert set(small.initial_facts) == set(task.init)


def test_an_object_whose_quantified_effect_sets_a_fact_of_no_object_is_kept():
    empties = Conditional((Atom("is", ("?y", "s0")),), add=(Atom("occupied", ("s1",)),), var="?y", type="egg")
    act = Action("go", (Atom("is", ("?p", "s0")),), (Atom("is", ("?p", "s2")),), params=(("?p", "bowl"),),
                 conditional=(empties,))
    init = (Atom("is", ("a", "s0")), Atom("is", ("c", "s0")), Atom("is", ("d", "s1")))
    task = PlanningTask("d", "p", "relational", 3, (), (act,), init, (Atom("occupied", ("s1",)),), types=TYPES,
                        objects=OBJECTS)
    assert untouched(task) == {"b", "d"}  # c sets (occupied s1); b is in no state a parameter needs


def test_a_parameter_of_a_constants_type_takes_the_constants():
    # `?s - state` is bound to the task's constants: the action applies (a in s0), so it touches a
    act = Action("go", (Atom("is", ("?p", "?s")),), (Atom("is", ("?p", "s1")),), params=(("?p", "bowl"), ("?s", "state")))
    init = (Atom("is", ("a", "s0")),)
    task = PlanningTask("d", "p", "relational", 3, (), (act,), init, (Atom("is", ("a", "s1")),), types=TYPES,
                        objects=OBJECTS, constants=tuple((s, "state") for s in STATES))
    assert untouched(task) == {"b", "c", "d"}
    again = Action("on", (Atom("is", ("?p", "s1")),), (Atom("is", ("?p", "?s")),), params=(("?p", "bowl"), ("?s", "state")))
    later = Action("off", (Atom("is", ("?p", "s2")), Atom("is", ("?q", "s0"))), (Atom("is", ("?q", "s2")),),
                   params=(("?p", "bowl"), ("?q", "egg")))
    task = replace(task, actions=(act, again, later), init=(*init, Atom("is", ("c", "s0"))))
    assert untouched(task) == {"b", "d"}  # a reaches s2 through `on`'s ?s: `off` takes c


def test_an_object_the_goal_names_is_kept():
    # relational goals are 0-ary (`goal-reached`); a task whose goal names an object must still declare it
    act = Action("go", (Atom("is", ("?p", "s0")),), (Atom("is", ("?p", "s1")),), params=(("?p", "bowl"),))
    init = (Atom("is", ("a", "s0")), Atom("is", ("c", "s2")))
    task = PlanningTask("d", "p", "relational", 3, (), (act,), init, (Atom("is", ("c", "s2")),), types=TYPES,
                        objects=OBJECTS)
    assert untouched(task) == {"b", "d"}
    assert "c" in {name for name, _ in set_aside(task).objects}


def test_whipped_cream_problem_leaves_out_the_carton_and_spatula_and_the_plan_still_names_them():
    foon, _ = load([SUBGRAPHS / "0001-whipped_cream.txt"])
    goal = resolve_goal(spec_of_node(sorted(x for x in foon.nodes if x.dish is not None)[0]), foon)
    kitchen = default_kitchen(foon)
    task = compile_goal(foon, kitchen, goal, "relational").task
    problem = render(task)[1]
    assert {"carton_1", "spatula_1", "heavy_cream_1"} <= {o for o, _ in task.aside}
    assert "carton_1" not in problem and "spatula_1" not in problem and "mixing_bowl_1" in problem
    assert "carton_1" in render(compile_goal(foon, kitchen, goal, "relational", prune=False).task)[1]
    out = plan(foon, kitchen, goal, "relational", time_limit=60)
    assert str(out.status) == "solved" and not replay(out.trace).disagreements
    named = {b.object for s in out.trace.steps for b in s.bindings}
    assert {"carton_1", "spatula_1"} <= named


def test_an_object_whose_quantified_effect_sets_a_fact_nothing_reads_is_set_aside():
    # (occupied s1) is in no precondition, no conditional effect's condition and not the goal: setting it changes
    # no plan, so the egg that would set it is no reason to keep the egg (the bloody mary's glass of ice, emptied
    # by the pour that takes the ice out of it, sets `(occupied glass_empty)`, which no unit reads)
    empties = Conditional((Atom("is", ("?y", "s0")),), add=(Atom("occupied", ("s1",)),), var="?y", type="egg")
    act = Action("go", (Atom("is", ("?p", "s0")),), (Atom("is", ("?p", "s2")),), params=(("?p", "bowl"),),
                 conditional=(empties,))
    init = (Atom("is", ("a", "s0")), Atom("is", ("c", "s0")), Atom("is", ("d", "s1")))
    task = PlanningTask("d", "p", "relational", 3, (), (act,), init, (Atom("is", ("a", "s2")),), types=TYPES,
                        objects=OBJECTS)
    assert untouched(task) == {"b", "c", "d"}
    reader = Action("read", (Atom("occupied", ("?s",)),), (Atom("is", ("?p", "s1")),),
                    params=(("?p", "bowl"), ("?s", "state")))
    assert untouched(replace(task, actions=(act, reader))) == {"b", "d"}  # a condition over any state reads it


def test_teriyaki_patty_problem_leaves_out_the_bowl_its_sugar_is_poured_out_of_and_plans():
    foon, _ = load([SUBGRAPHS / "0057-teriyaki_burger_patty.txt"])
    goal = resolve_goal(spec_of_node(sorted(x for x in foon.nodes if x.dish is not None)[0]), foon)
    kitchen = default_kitchen(foon)
    task = compile_goal(foon, kitchen, goal, "relational", narrow=True).task
    assert "bowl_2" in {o for o, _ in task.aside} and len(task.objects) == 14
    out = plan(foon, kitchen, goal, "relational", time_limit=60)
    assert str(out.status) == "solved" and not replay(out.trace).disagreements
