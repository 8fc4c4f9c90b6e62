"""A typed task with fewer types: types become static unary predicates (for planners without subtypes).

Some planners read `:typing` but not a type hierarchy (Tamer rejects an object of a subtype as the
argument of a predicate declared over its supertype). `untyped` writes the same task with every
object, constant, parameter and predicate argument of type `object`, so no `:typing` is needed: a
type `T` becomes the predicate `(type_T ?x)`, true in the initial state for every object of `T` or of
a subtype of `T` and never changed, and an action's parameter `?x - T` becomes the precondition
`(type_T ?x)`. The ground actions applicable in a state are the same, with the same names and
arguments, so plans (and how they map back to units) are unchanged. Quantified deletes keep their
condition alone (encodings quantify over the root type, whose atoms already say what they hold).
`flat_typed` does the same for the subtypes only: the top-level types (directly under `object`) stay
types, so the task has flat typing (what Tamer reads) and grounding by type still keeps, say, objects
and state constants apart. O(|objects| x type depth + |actions|).
"""

from __future__ import annotations

from dataclasses import replace

from .names import NameTable
from .task import Atom, Conditional, PlanningTask, Predicate

__all__ = ["flat_typed", "untyped"]

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
    return _as_predicates(task, top=False)


def flat_typed(task: PlanningTask) -> PlanningTask:
    """`task` with only its top-level types (those directly under `object`) kept as types and every subtype
    written as a static predicate `(type_T ?x)`: flat typing (UP's FLAT_TYPING, all Tamer reads), where each
    object, parameter and argument has its top-level ancestor's type, and a parameter `?x - T` of a subtype
    becomes that type plus the precondition `(type_T ?x)`. Same ground actions and plans as `untyped`, but
    grounding by type still separates the top-level kinds (objects from states). A task with flat types
    already is returned as is."""
    return _as_predicates(task, top=True)


def _as_predicates(task: PlanningTask, top: bool) -> PlanningTask:
    """Types below the kept level as static unary predicates: every type (`top` false, the result is
    untyped) or every type that is not top-level (`top` true)."""
    parent = dict(task.types)
    if not task.uses_types or (top and all(p == ROOT for p in parent.values())):
        return task

    def base(typ: str) -> str:
        return _ancestors(parent, typ)[-1] if top and typ != ROOT else ROOT

    def folded(typ: str) -> list[str]:
        """The types of `typ`'s chain written as predicates, most specific first."""
        chain = _ancestors(parent, typ)
        return chain[:-1] if top else chain

    table = NameTable({p.name for p in task.predicates} | {a.name for a in task.actions}
                      | {n for pair in (*task.types, *task.objects, *task.constants) for n in pair})
    used = {t for _, t in (*task.objects, *task.constants)}
    used |= {t for a in task.actions for _, t in a.params}
    used |= {t for a in task.actions for c in a.conditional for _, t in c.quantified}
    names: dict[str, str] = {}
    for typ in sorted({a for t in used for a in folded(t)}):
        names[typ] = table.name(f"type {typ}", key=typ)

    def guard(params: tuple[tuple[str, str], ...]) -> tuple[Atom, ...]:
        return tuple(Atom(names[t], (v,)) for v, t in params if t in names)

    def unguarded(c: Conditional) -> Conditional:
        if c.var is None:
            return c
        return replace(c, when=(*guard(c.quantified), *c.when), type=base(c.type), more=retyped(c.more))

    def retyped(pairs: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
        return tuple((v, base(t)) for v, t in pairs)

    actions = tuple(replace(a, pre=(*guard(a.params), *a.pre), params=retyped(a.params),
                            conditional=tuple(map(unguarded, a.conditional))) for a in task.actions)
    facts = {Atom(names[a], (o,)) for o, t in (*task.objects, *task.constants) for a in folded(t)}
    predicates = (*(replace(p, params=retyped(p.params)) for p in task.predicates),
                  *(Predicate(n, (("?x", base(t)),), f"?x is of type {t}") for t, n in names.items()))
    note = ("subtypes written as static predicates type_<T> (flat types, for planners without a type hierarchy)"
            if top else "types written as static predicates type_<T> (an untyped domain)")
    return replace(task, types=tuple((t, p) for t, p in task.types if top and p == ROOT),
                   predicates=predicates, actions=actions, init=tuple(sorted({*task.init, *facts})),
                   objects=retyped(task.objects), constants=retyped(task.constants),
                   comments=(*task.comments, note))
