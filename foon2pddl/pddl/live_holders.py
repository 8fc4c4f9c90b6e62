"""A holder bound late must exist: `(live ?x)`, kept for the objects of the labels the planner binds as holders.

Where FOON names a holder its unit does not have (`bacon (on [bread])` with no bread in the unit), the relational
encoding binds it late: a parameter of that label the planner chooses (`encode_relational`). Nothing said the
object chosen exists: on the universal FOON of the even-index subgraphs the club sandwich's bacon
(`0061-club_sandwich.txt:196`) was put on a bread the step before had consumed into the sandwich, and the replay
found it on a consumed holder (`holder-gone`). Over PDDL without negative preconditions (pyperplan has none), an
object exists when it is neither not yet made nor consumed: `(live ?x)`, true in the init for the objects that
start made, added by every effect that makes one (its `(is ?x not-yet-made)` deleted), deleted by every effect
that consumes one (`(is ?x consumed)` added), is a precondition of each late-bound target (`with_live`).

Only the objects of the types such parameters have (and their subtypes) carry it; an effect on a variable of a
wider type (`physical-object`: what is on a consumed object is consumed with it) keeps it too, which is harmless
for objects of other labels (never a precondition). A task without late-bound targets is unchanged.
"""

from __future__ import annotations

from dataclasses import replace

from .encode_instances import IS, NOT_MADE, ROOT_TYPE
from .relational_sweep import CONSUMED
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["LIVE", "with_live"]

#: The predicate of an object that exists (made, not consumed).
LIVE = "live"


def _related(types: set[str], parents: dict[str, str]) -> tuple[set[str], set[str]]:
    """(the types and their subtypes, the types and every type above or below them)."""
    def above(t: str) -> list[str]:
        out = []
        while t in parents and parents[t] not in out:
            t = parents[t]
            out.append(t)
        return out

    below = {t for t in parents if set(above(t)) & types} | types
    return below, below | {a for t in types for a in above(t)} | {ROOT_TYPE}


def _kept(atoms_add, atoms_del, typed: dict[str, str], related: set[str]) -> tuple[list[Atom], list[Atom]]:
    """The `live` atoms to add and delete beside the effects `atoms_add` and `atoms_del` on variables of `typed`."""
    add = [Atom(LIVE, (a.args[0],)) for a in atoms_del
           if a.predicate == IS and a.args[1] == NOT_MADE and typed.get(a.args[0], ROOT_TYPE) in related]
    gone = [Atom(LIVE, (a.args[0],)) for a in atoms_add
            if a.predicate == IS and a.args[1] == CONSUMED and typed.get(a.args[0], ROOT_TYPE) in related]
    return add, gone


def _action(a: Action, related: set[str]) -> Action:
    typed = dict(a.params)
    add, gone = _kept(a.add, a.delete, typed, related)
    conditional = []
    for c in a.conditional:
        more, less = _kept(c.add, c.delete, {**typed, **dict(c.quantified)}, related)
        conditional.append(replace(c, add=c.add + tuple(more), delete=c.delete + tuple(less)) if more or less else c)
    if not (add or gone or conditional != list(a.conditional)):
        return a
    return replace(a, add=a.add + tuple(add), delete=a.delete + tuple(gone), conditional=tuple(conditional))


def with_live(task: PlanningTask) -> PlanningTask:
    """`task` with `(live x)` kept (module doc) for the objects of every type a `(live ?v)` precondition binds;
    `task` itself when no action has one. O(actions x effects + objects)."""
    types = {t for a in task.actions for v, t in a.params if Atom(LIVE, (v,)) in a.pre}
    if not types:
        return task
    own, related = _related(types, dict(task.types))
    made = {x.name for x in task.instances if x.start is not None}
    init = [Atom(LIVE, (name,)) for name, t in task.objects if t in own and name in made]
    return replace(task, actions=tuple(_action(a, related) for a in task.actions),
                   init=tuple(sorted({*task.init, *init})),
                   predicates=(*task.predicates, Predicate(LIVE, (("?x", ROOT_TYPE),), "?x exists: made, not consumed")))
