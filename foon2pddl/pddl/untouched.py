"""Objects no action can ever touch, and that touch nothing: set aside from the PDDL problem, plans unchanged.

`untouched(task)` over-approximates, per object, the states it can reach (its `(is ?x ?s)` facts; every
other fact of objects, `in`/`on` holders among them, is taken as possible, but a static one of one object,
`(goal-object ?x)`, as the init says), and the objects each action parameter can take: one of the
parameter's type with every `(is ?p s)` the action requires reachable, when every parameter of the action
has one and every ground precondition (`(occupied s)`) is reachable; a parameter of a constant's type (a
state) takes the constants, and `(is ?p ?s)` over such a parameter needs only some state of `?p`. The fixpoint adds each such action's
effects for the objects its parameters can take, and each conditional effect's, for the objects its
quantified variables can take. An object is *untouched* when no parameter of any action can take it, and
every conditional effect quantified over it that it can meet changes only facts that name it or that no
condition and no goal can read (*write-only*: an atom no precondition, effect condition or goal atom
matches, a variable matching anything); one that would set an `(occupied s)` some precondition reads, or
change a fact of another object, keeps it: a carton a portion of cream is poured from while it stays in
the carton, a spatula only an `(occupied s)` precondition checks, the water in a kitchen bowl that only a
quantified effect carries along, the bloody mary's glass of ice, which the pour empties, setting an
`(occupied glass_empty)` nothing reads.

Why leaving them out keeps every plan (the PDDL has no negative condition, no quantified precondition,
and a 0-ary goal): no applicable ground action binds an untouched object, so every ground action a plan
can apply is one of the smaller task; each effect of it on an untouched object changes only facts that
name that object or write-only ones; so the facts that name no untouched object and are not write-only
evolve alike in both tasks, step by step, and the goal and every precondition a plan meets are such
facts.

`set_aside(task)` moves them and their initial facts to `PlanningTask.aside`/`aside_init`: the problem
the planner is given leaves them out, the plan's replay (`initial_facts`) still holds them, so a plan
still names the carton and the spatula. O(rounds x actions x parameters x objects).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable
from dataclasses import replace

from .task import Atom, PlanningTask, type_closure

__all__ = ["set_aside", "untouched"]

IS = "is"


def _ground(a: Atom) -> bool:
    return not any(x.startswith("?") for x in a.args)


def _met(atoms: Iterable[Atom], ground: set[Atom], objects: dict) -> bool:
    """Whether every ground atom of `atoms` that names no object is reached (one naming an object may be)."""
    return all(a in ground for a in atoms if _ground(a) and not any(x in objects for x in a.args))


def _read(atom: Atom, reads: Iterable[Atom]) -> bool:
    """Whether a condition or the goal can read `atom`: an atom of its predicate whose every argument is a
    variable or `atom`'s own."""
    return any(r.predicate == atom.predicate and len(r.args) == len(atom.args)
               and all(x == y or x.startswith("?") or y.startswith("?") for x, y in zip(r.args, atom.args, strict=True))
               for r in reads)


def untouched(task: PlanningTask) -> frozenset[str]:
    """The task's objects (names) no action can touch and that touch nothing (module doc)."""
    types = type_closure(task)
    objects = [name for name, _ in task.objects]
    of_type: dict[str, list[str]] = {}
    for x in (*objects, *(c for c, _ in task.constants)):  # a parameter of a constant's type takes the constants
        for t in types[x]:
            of_type.setdefault(t, []).append(x)
    states: dict[str, set[str]] = {x: set() for x in objects}
    ground: set[Atom] = set()
    for a in task.init:
        if a.predicate == IS and len(a.args) == 2 and a.args[0] in states:
            states[a.args[0]].add(a.args[1])
        elif not any(x in states for x in a.args):
            ground.add(a)
    changing = {a.predicate for act in task.actions
                for a in (*act.add, *act.delete, *(x for c in act.conditional for x in (*c.add, *c.delete)))}
    unary = {a for a in task.init if a.predicate not in changing and len(a.args) == 1}

    def takers(var: str, typ: str, conds: Iterable[Atom]) -> list[str]:
        need = [a.args[1] for a in conds if a.predicate == IS and len(a.args) == 2 and a.args[0] == var]
        static = [a.predicate for a in conds if a.predicate not in changing and a.args == (var,)]
        return [x for x in of_type.get(typ, ()) if all(s in states.get(x, ()) or (s.startswith("?") and states.get(x))
                                                        for s in need)  # a state a parameter names: any it has
                and all(Atom(p, (x,)) in unary for p in static)]

    reads = [a for act in task.actions for a in (*act.pre, *(x for c in act.conditional for x in c.when))]
    reads += task.goal
    # an object an action names itself is kept, and a fact naming it is taken as possible
    touched: set[str] = {x for act in task.actions for c in (act.pre, act.add, act.delete, *(
        y.atoms() for y in act.conditional)) for a in c for x in a.args if x in states}
    touched.update(x for a in task.goal for x in a.args if x in states)  # so is one the goal names
    leaky: set[str] = set()
    grew = True
    while grew:
        grew = False

        def add(atoms: Iterable[Atom], bind: dict[str, list[str]]) -> None:
            nonlocal grew
            for a in atoms:
                if a.predicate == IS and len(a.args) == 2 and (a.args[0] in bind or a.args[0] in states):
                    for x, s in itertools.product(bind.get(a.args[0], [a.args[0]]), bind.get(a.args[1], [a.args[1]])):
                        if x in states and s not in states[x]:
                            states[x].add(s)
                            grew = True
                elif _ground(a) and a not in ground and not any(x in states for x in a.args):
                    ground.add(a)
                    grew = True

        for act in task.actions:
            if not _met(act.pre, ground, states):
                continue
            bind = {v: takers(v, t, act.pre) for v, t in act.params}
            if any(not xs for xs in bind.values()):
                continue
            touched.update(x for xs in bind.values() for x in xs)
            add(act.add, bind)
            for c in act.conditional:
                if not _met(c.when, ground, states):
                    continue
                quant = {v: takers(v, t, c.when) for v, t in c.quantified}
                add(c.add, {**bind, **quant})
                for v, xs in quant.items():
                    if any(v not in a.args and _read(a, reads) for a in (*c.add, *c.delete)):
                        leaky.update(xs)
    return frozenset(x for x in objects if x not in touched and x not in leaky)


def set_aside(task: PlanningTask) -> PlanningTask:
    """`task` with its untouched objects and their initial facts set aside (module doc); `task` itself when
    there are none."""
    out = untouched(task)
    if not out:
        return task
    facts = [a for a in task.init if any(x in out for x in a.args)]
    return replace(task, objects=tuple(o for o in task.objects if o[0] not in out),
                   init=tuple(a for a in task.init if not any(x in out for x in a.args)),
                   aside=task.aside + tuple(o for o in task.objects if o[0] in out),
                   aside_init=task.aside_init + tuple(facts))
