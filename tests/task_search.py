"""Exhaustive search of a small planning task: the independent oracle of the task transformations' tests."""

from __future__ import annotations

import itertools

from foon2pddl.pddl.task import Atom, PlanningTask, apply_action


def explore(task: PlanningTask, types: dict[str, frozenset[str]]) -> tuple[set[frozenset[Atom]], set[str]]:
    """Every state reachable from `task.init` over the objects of `types` (and the task's constants), and the
    names of the actions some reachable state applies."""
    constants = [c for c, _ in task.constants]
    objects = [o for o in types if o not in set(constants)]
    start = frozenset(task.init)
    seen, stack, applied = {start}, [start], set()
    while stack:
        state = stack.pop()
        for act in task.actions:
            pools = [[o for o in (*objects, *constants) if t in types[o]] for _, t in act.params]
            for values in itertools.product(*pools):
                bind = dict(zip((v for v, _ in act.params), values, strict=True))
                if all(Atom(a.predicate, tuple(bind.get(x, x) for x in a.args)) in state for a in act.pre):
                    applied.add(act.name)
                    nxt = frozenset(apply_action(set(state), act, bind, types))
                    if nxt not in seen:
                        seen.add(nxt)
                        stack.append(nxt)
    return seen, applied
