"""A typed task without types: each type becomes a static unary predicate (for planners without subtypes).

Some planners read `:typing` but not a type hierarchy (Tamer rejects an object of a subtype as the
argument of a predicate declared over its supertype). `untyped` writes the same task with every
object, constant, parameter and predicate argument of type `object`, so no `:typing` is needed: a
type `T` becomes the predicate `(type_T ?x)`, true in the initial state for every object of `T` or of
a subtype of `T` and never changed, and an action's parameter `?x - T` becomes the precondition
`(type_T ?x)`. The ground actions applicable in a state are the same, with the same names and
arguments, so plans (and how they map back to units) are unchanged. Quantified deletes keep their
condition alone (encodings quantify over the root type, whose atoms already say what they hold).
O(|objects| x type depth + |actions|).
"""

from __future__ import annotations

from dataclasses import replace

from .names import NameTable
from .task import Atom, Conditional, PlanningTask, Predicate

__all__ = ["untyped"]

ROOT = "object"


def _ancestors(parent: dict[str, str], typ: str) -> list[str]:
    """`typ` and its ancestors below `object`, most specific first."""
    out: list[str] = []
    while typ != ROOT and typ not in out:
        out.append(typ)
        typ = parent.get(typ, ROOT)
    return out


def untyped(task: PlanningTask) -> PlanningTask:
    """`task` with its types as static unary predicates (see the module doc); an untyped task is returned as is."""
    if not task.uses_types:
        return task
    parent = dict(task.types)
    table = NameTable({p.name for p in task.predicates} | {a.name for a in task.actions}
                      | {n for pair in (*task.types, *task.objects, *task.constants) for n in pair})
    used = {t for _, t in (*task.objects, *task.constants)}
    used |= {t for a in task.actions for _, t in a.params}
    used |= {c.type for a in task.actions for c in a.conditional if c.var is not None}
    names: dict[str, str] = {}
    for typ in sorted({a for t in used for a in _ancestors(parent, t)}):
        names[typ] = table.name(f"type {typ}", key=typ)

    def guard(params: tuple[tuple[str, str], ...]) -> tuple[Atom, ...]:
        return tuple(Atom(names[t], (v,)) for v, t in params if t != ROOT)

    def unguarded(c: Conditional) -> Conditional:
        if c.var is None or c.type == ROOT:
            return c
        return replace(c, when=(Atom(names[c.type], (c.var,)), *c.when), type=ROOT)

    actions = tuple(replace(a, pre=(*guard(a.params), *a.pre), params=tuple((v, ROOT) for v, _ in a.params),
                            conditional=tuple(map(unguarded, a.conditional))) for a in task.actions)
    facts = {Atom(names[a], (o,)) for o, t in (*task.objects, *task.constants) for a in _ancestors(parent, t)}
    predicates = (*(replace(p, params=tuple((v, ROOT) for v, _ in p.params)) for p in task.predicates),
                  *(Predicate(n, (("?x", ROOT),), f"?x is of type {t}") for t, n in names.items()))
    return replace(task, types=(), predicates=predicates, actions=actions,
                   init=tuple(sorted({*task.init, *facts})),
                   objects=tuple((o, ROOT) for o, _ in task.objects),
                   constants=tuple((c, ROOT) for c, _ in task.constants),
                   comments=(*task.comments, "types written as static predicates type_<T> (an untyped domain)"))
