"""`pddl.prune.drop_unbindable`: the planner is not given actions no binding of their parameters grounds.

Two oracles: enumerating every binding of a small random task's parameters (a dropped action has none under
which its static preconditions hold in `init`), and planning the `instances` goals of the experiment as it
did before the drop (the whole compiled task given to Fast Downward): every cell comes out the same.
"""

from __future__ import annotations

import itertools
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.reachability import reachable
from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import sample_kitchen
from foon2pddl.experiment.setting import Setting
from foon2pddl.experiment.solvers import get_solver
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl import prune
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.task import Action, Atom, PlanningTask, Predicate
from foon2pddl.planners import solve

OBJECTS = ("a", "b", "c")
VARS = ("?x", "?y", "?z")


def _atoms(pred: str, arity: int, pool: tuple[str, ...]):
    return st.builds(lambda args: Atom(pred, tuple(args)), st.lists(st.sampled_from(pool), min_size=arity,
                                                                     max_size=arity))


@st.composite
def tasks(draw) -> PlanningTask:
    """A task over three objects: static predicates `s1` (unary) and `s2` (binary), a fluent `f` that one
    action adds; actions with up to three parameters, constants and repeated variables in their atoms."""
    init = draw(st.lists(st.one_of(_atoms("s1", 1, OBJECTS), _atoms("s2", 2, OBJECTS), _atoms("f", 1, OBJECTS)),
                         max_size=7, unique=True))
    actions = []
    for k in range(draw(st.integers(1, 4))):
        params = VARS[:draw(st.integers(0, 3))]
        pool = (*params, *OBJECTS)
        pre = draw(st.lists(st.one_of(_atoms("s1", 1, pool), _atoms("s2", 2, pool), _atoms("f", 1, pool)),
                            max_size=4))
        actions.append(Action(f"act{k}", tuple(pre), (Atom("f", (params[0] if params else "a",)),),
                              params=tuple((v, "object") for v in params)))
    preds = (Predicate("s1", (("?x", "object"),)), Predicate("s2", (("?x", "object"), ("?y", "object"))),
             Predicate("f", (("?x", "object"),)))
    return PlanningTask("d", "p", "tree", 3, preds, tuple(actions), tuple(sorted(init)), (Atom("f", ("a",)),),
                        objects=tuple((o, "object") for o in OBJECTS))


def _groundable(action: Action, init: set[Atom], static: set[str]) -> bool:
    """Some binding of the parameters to objects makes every static precondition an init atom."""
    names = [v for v, _ in action.params]
    for values in itertools.product(OBJECTS, repeat=len(names)):
        bind = dict(zip(names, values, strict=True))
        if all(Atom(p.predicate, tuple(bind.get(x, x) for x in p.args)) in init
               for p in action.pre if p.predicate in static):
            return True
    return False


@settings(max_examples=300, deadline=None)
@given(tasks())
def test_an_action_is_dropped_only_when_no_binding_satisfies_its_static_preconditions(task):
    kept = prune.drop_unbindable(task)
    static = {"s1", "s2"}  # `f` is added by every action
    init = set(task.init)
    dropped = [a for a in task.actions if a not in kept.actions]
    for action in dropped:
        assert not _groundable(action, init, static), action
    for action in kept.actions:  # arc consistency is exact on these: one or two atoms per variable pair
        if sum(p.predicate in static for p in action.pre) <= 1:
            assert _groundable(action, init, static), action
    assert kept.actions == tuple(a for a in task.actions if a in kept.actions)  # order kept
    assert (kept is task) == (not dropped)


def test_a_precondition_on_two_variables_narrows_both():
    init = (Atom("s1", ("a",)), Atom("s2", ("b", "c")), Atom("s2", ("a", "a")))
    pre = (Atom("s2", ("?x", "?y")), Atom("s1", ("?y",)), Atom("s2", ("?y", "?x")))
    act = Action("go", pre, (Atom("f", ("a",)),), params=(("?x", "object"), ("?y", "object")))
    task = PlanningTask("d", "p", "tree", 3, (), (act,), init, (Atom("f", ("a",)),))
    assert prune.drop_unbindable(task).actions == (act,)  # x = y = a
    gone = PlanningTask("d", "p", "tree", 3, (), (act,), init[:2], (Atom("f", ("a",)),))
    assert prune.drop_unbindable(gone).actions == ()  # s2(?x, ?y) needs y = c, s1(?y) needs y = a


@pytest.fixture(scope="module")
def reg():
    from conftest import SUBGRAPHS

    from foon2pddl.io.inputs import load_network

    return build_view("reg", load_network([str(SUBGRAPHS)]), 3)


def test_fd_instances_answers_every_goal_as_planning_the_whole_compiled_task_does(reg, monkeypatch):
    """The experiment's `fd-instances` cells on the shared subgraphs, with and without the drop: same status,
    tree, plan length and physical verdict; the drop removes schemas on some goal (the test can fail)."""
    foon = reg.foon
    kitchen = sample_kitchen(default_kitchen(foon), 0.9, 3)
    reach = reachable(foon, kitchen.project(foon.level).nodes)
    made = sorted(n for n in foon.producers if reach.can_make(n) and n not in kitchen.nodes)
    goals = random.Random(5).sample(made, 12)
    solver = get_solver("fd-instances").prepare(Setting(reg, kitchen, 60.0))
    dropped = 0
    for node in goals:
        task = compile_goal(foon, kitchen, reg.goal_of(node), "instances", foon.level).task
        dropped += len(task.actions) - len(prune.drop_unbindable(task).actions)
    new = [solver.solve(node) for node in goals]
    monkeypatch.setattr(solve, "drop_unbindable", lambda task: task)
    old = [solver.solve(node) for node in goals]
    fields = ("status", "units", "plan_length", "executable", "executable_reason", "extra_objects", "repeated")
    for node, a, b in zip(goals, new, old, strict=True):
        assert [getattr(a, f) for f in fields] == [getattr(b, f) for f in fields], node.describe()
    assert dropped > 0
    assert any(str(o.status) == "solved" for o in new)
