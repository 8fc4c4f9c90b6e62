"""Interchangeable objects taken in one order: `(ready ?x)`, so a search does not try every bowl of a stack.

Objects that start alike (the same initial facts but for their own name: ten empty bowls that hold nothing and
stand in nothing, three flour mixtures not yet made) are interchangeable: renaming one into another in a plan
gives a plan. A search over them tries each in turn at every step (which empty bowl to pour the flour into), and
on the universal FOON of the 50 subgraphs of odd index lama-first's plateaus there were as wide as the stacks.
So of each such class (two or more objects, in the order the task lists them) only the first is `ready` in the
init; an action binding an object in the state the class starts in needs it `ready`, and makes the next of its
class `ready`. Any plan, renamed so that the class's objects are first bound in their order, meets this: the
objects a plan binds first in a class are still in their starting state when bound (nothing but a binding moves
an object that holds nothing and stands in nothing), so a task stays solvable exactly when it was, and its
plans name the same actions. Two facts of the relational encoding make the renaming sound: a late-bound target
binds an object by `(live ?x)` alone, not by its state, so it neither needs `ready` nor counts as a first binding
(the renaming orders a class by first bindings in its starting state); and an object named in another object's
initial fact, as `(precedes a b)` names two of one label an action binds at once in that state, is in no class. Applied by `planners.solve.plan` to the task it gives the planner (`relational`);
`compile` writes the task without it. O(init + actions x parameters).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import replace
from itertools import pairwise

from .encode_instances import IS, ROOT_TYPE
from .task import Atom, Conditional, PlanningTask, Predicate

__all__ = ["NEXT", "READY", "in_order"]

#: An object an action may bind in its class's starting state.
READY = "ready"
#: The static order of a class: `(next-alike a b)`, b is taken after a.
NEXT = "next-alike"

_ME = "?"  # an object's own name in its signature


def _classes(task: PlanningTask) -> list[list[str]]:
    """The classes of two or more objects whose initial facts differ only in their own name, in task order."""
    facts: dict[str, list[tuple[str, tuple[str, ...]]]] = defaultdict(list)
    names = {name for name, _ in task.objects}
    for a in task.init:
        for x in set(a.args) & names:
            facts[x].append((a.predicate, tuple(_ME if y == x else y for y in a.args)))
    named = {y for a in task.goal for y in a.args}
    groups: dict[tuple, list[str]] = defaultdict(list)
    for name, t in task.objects:
        sig = tuple(sorted(facts[name]))
        if name not in named and all(y == _ME or y not in names for _, args in sig for y in args):
            groups[(t, sig)].append(name)
    return [g for g in groups.values() if len(g) > 1]


def _start_state(task: PlanningTask, name: str) -> str | None:
    return next((a.args[1] for a in task.init if a.predicate == IS and a.args[0] == name), None)


def in_order(task: PlanningTask) -> PlanningTask:
    """`task` with each class of interchangeable objects taken in order (module doc); `task` when it has none."""
    classes = [c for c in _classes(task) if _start_state(task, c[0]) is not None]
    if not classes:
        return task
    starts = {_start_state(task, c[0]) for c in classes}
    later = {x for c in classes for x in c[1:]}
    init = [Atom(READY, (name,)) for name, _ in task.objects if name not in later]
    init += [Atom(NEXT, (a, b)) for c in classes for a, b in pairwise(c)]
    actions = []
    for act in task.actions:
        bound = [(v, t) for v, t in act.params if any(p.predicate == IS and p.args == (v, s) for p in act.pre
                                                         for s in starts)]
        if not bound:
            actions.append(act)
            continue
        actions.append(replace(
            act, pre=act.pre + tuple(Atom(READY, (v,)) for v, _ in bound),
            conditional=act.conditional + tuple(
                Conditional((Atom(NEXT, (v, f"{v}-next")),), add=(Atom(READY, (f"{v}-next",)),), var=f"{v}-next",
                            type=t) for v, t in bound)))
    return replace(task, actions=tuple(actions), init=tuple(sorted({*task.init, *init})),
                   predicates=(*task.predicates,
                               Predicate(READY, (("?x", ROOT_TYPE),), "?x may be bound in its class's first state"),
                               Predicate(NEXT, (("?x", ROOT_TYPE), ("?y", ROOT_TYPE)),
                                         "?y is taken after ?x, which starts alike")))
