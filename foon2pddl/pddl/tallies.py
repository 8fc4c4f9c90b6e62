"""Roles that only check some object is in a state that objects enter and leave: `(occupied s)`, kept exact by a
tally, instead of a parameter per object.

A role whose parameter appears only in its `(is ?x s)` precondition (a clean knife the add only needs, never
changes, places or names again) is satisfied by any object in `s`, so each of them is a grounding of its own:
four clean knives times every other parameter's candidates (the universal FOON's black bean with jalapeno: the
garlic bread's add, 9,984 of the task's 19,045 ground operators). For a stable `s` (no action leaves it) the
encodings already check `(occupied s)`. Here a state that actions do leave gets the same check, kept exact by a
count: `(tally s n)` says exactly n objects are in `s`; an action whose parameters bring one object into `s`
moves the tally up (`(tally s ?n) (next-count ?n ?m)`: from ?n to ?m) and adds `(occupied s)`; one that takes one
out moves it down and, at zero (`(zero-count ?n)`), deletes `(occupied s)`; one that brings one in and takes one out
leaves it (a tally has a grounding per count, so a state is tallied only where more actions check it than move
objects into or out of it). So `(occupied s)` holds exactly when some object is in `s`, in every state a plan reaches, and the
checking role binds no parameter: a plan of the task applies in the task with the parameter (bind the role to
an object in `s`, which exists), and back (the tally only restates the `is` facts). The plan's replay binds the
role to an object in its node, as for a stable one.

Only states whose every change is an action parameter's, one in or out per action (no conditional effect adds
or deletes `(is ? s)`: a container a quantified effect empties is left alone), and only roles that are the
action's one `(is ? s)` precondition (two objects in one state need two), of unit actions (goal actions keep
theirs). Count constants go from 0 to the most objects that can be in a state: those there at first and every
object of a type some parameter brings into it. O(actions x atoms + objects x states).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace

from .encode_instances import NOT_MADE, OCCUPIED
from .task import Action, Atom, Conditional, PlanningTask, Predicate, type_closure

__all__ = ["COUNT_TYPE", "tallied"]

IS = "is"
TALLY = "tally"
NEXT = "next-count"
ZERO = "zero-count"
COUNT_TYPE = "count"


def _checks(a: Action) -> dict[str, str]:
    """`a`'s parameters that appear only in one `(is ?x s)` precondition -> s."""
    if a.unit is None:
        return {}
    uses = Counter(x for atom in (*a.pre, *a.add, *a.delete, *(y for c in a.conditional for y in c.atoms()))
                   for x in atom.args)
    out = {}
    for atom in a.pre:
        if atom.predicate == IS and len(atom.args) == 2 and uses[atom.args[0]] == 1 \
                and any(atom.args[0] == v for v, _ in a.params):
            out[atom.args[0]] = atom.args[1]
    return out


def _net(a: Action) -> Counter:
    """State -> objects `a`'s unconditional effects bring into it less those they take out of it."""
    pre = set(a.pre)
    net: Counter = Counter()
    for atom in a.add:
        if atom.predicate == IS and atom not in pre:
            net[atom.args[1]] += 1
    for atom in a.delete:
        if atom.predicate == IS and atom not in a.add:
            net[atom.args[1]] -= 1
    return net


def _unsure(task: PlanningTask) -> set[str] | None:
    """States some effect changes other than through an action parameter (a conditional effect, an `is` fact of
    a named object); None when an effect's state is a variable (any state may change so)."""
    out: set[str] = set()
    for a in task.actions:
        said = [(x, False) for x in (*a.add, *a.delete)] + [(x, True) for c in a.conditional for x in (*c.add, *c.delete)]
        for atom, conditional in said:
            if atom.predicate != IS:
                continue
            if len(atom.args) != 2 or atom.args[1].startswith("?"):
                return None
            if conditional or not atom.args[0].startswith("?"):
                out.add(atom.args[1])
    return out


def tallied(task: PlanningTask) -> PlanningTask:
    """`task` with its check-only roles on states objects enter and leave checked by `(occupied s)`, kept exact by
    a tally (module doc); `task` itself when there are none."""
    unsure = _unsure(task)
    if unsure is None:
        return task
    nets = [_net(a) for a in task.actions]
    wide = {s for net in nets for s, k in net.items() if abs(k) > 1}
    states: set[str] = set()
    checks: list[dict[str, str]] = []
    for a in task.actions:
        found = {}
        for v, s in _checks(a).items():
            if s in (NOT_MADE,) or s in unsure or s in wide:
                continue
            if sum(1 for atom in a.pre if atom.predicate == IS and len(atom.args) == 2 and atom.args[1] == s) != 1:
                continue
            found[v] = s
        checks.append(found)
        states.update(found.values())
    movers = Counter(s for net in nets for s, k in net.items() if k)
    checkers = Counter(s for found in checks for s in set(found.values()))
    states = {s for s in states if checkers[s] > movers[s]}  # else the tally's own groundings outweigh the checks'
    checks = [{v: s for v, s in found.items() if s in states} for found in checks]
    if not states:
        return task
    facts = Counter(atom.args[1] for atom in task.initial_facts if atom.predicate == IS and len(atom.args) == 2)
    # the most objects that can be in a state: those there at first and those of a type a parameter brings in
    types = type_closure(task)
    entering = {(s, t) for a, net in zip(task.actions, nets, strict=True) for s, k in net.items() if k > 0
                for atom in a.add if atom.predicate == IS and atom.args[1] == s
                for v, t in a.params if v == atom.args[0]}
    there = {(atom.args[1], atom.args[0]) for atom in task.initial_facts if atom.predicate == IS and len(atom.args) == 2}
    top = max(len({x for x, ts in types.items() if (s, x) in there or any((s, t) in entering for t in ts)})
              for s in states)
    taken = {name for name, _ in (*task.constants, *task.objects, *task.aside)} | {x.name for x in task.instances}
    prefix = "count"
    while any(f"{prefix}-{i}" in taken for i in range(top + 1)):
        prefix += "-"
    num = [f"{prefix}-{i}" for i in range(top + 1)]
    init = [Atom(TALLY, (s, num[facts[s]])) for s in sorted(states)]
    init += [Atom(OCCUPIED, (s,)) for s in sorted(states) if facts[s]]
    init += [Atom(NEXT, (num[i], num[i + 1])) for i in range(top)] + [Atom(ZERO, (num[0],))]
    actions = []
    for a, net, found in zip(task.actions, nets, checks, strict=True):
        moves = {s: k for s, k in net.items() if s in states and k}
        if not found and not moves:
            actions.append(a)
            continue
        drop = set(found)
        params = [(v, t) for v, t in a.params if v not in drop]
        pre = [atom for atom in a.pre if not (atom.predicate == IS and atom.args[0] in drop)]
        pre += [Atom(OCCUPIED, (s,)) for s in dict.fromkeys(found.values())]
        add, delete, cond = list(a.add), list(a.delete), list(a.conditional)
        for i, (s, k) in enumerate(sorted(moves.items())):
            low, high = f"?tally-{i}-low", f"?tally-{i}-high"
            params += [(low, COUNT_TYPE), (high, COUNT_TYPE)]
            pre += [Atom(TALLY, (s, low if k > 0 else high)), Atom(NEXT, (low, high))]
            add.append(Atom(TALLY, (s, high if k > 0 else low)))
            delete.append(Atom(TALLY, (s, low if k > 0 else high)))
            if k > 0:
                add.append(Atom(OCCUPIED, (s,)))
            else:
                cond.append(Conditional((Atom(ZERO, (low,)),), delete=(Atom(OCCUPIED, (s,)),)))
        bound = iter(v for v, _ in a.params)
        roles = tuple((role, b and next(bound) not in drop) for role, b in a.roles)
        actions.append(replace(a, params=tuple(params), pre=tuple(dict.fromkeys(pre)), add=tuple(dict.fromkeys(add)),
                               delete=tuple(dict.fromkeys(delete)), conditional=tuple(cond), roles=roles))
    state_type = next(t for name, t in task.constants if name == NOT_MADE)
    said = "some object is in state ?s (no action leaves it, or a tally counts its objects)"
    predicates = (*(replace(p, comment=said) if p.name == OCCUPIED else p for p in task.predicates),
                  Predicate(TALLY, (("?s", state_type), ("?n", COUNT_TYPE)), "exactly ?n objects are in state ?s"),
                  Predicate(NEXT, (("?n", COUNT_TYPE), ("?m", COUNT_TYPE)), "static: ?m is ?n + 1"),
                  Predicate(ZERO, (("?n", COUNT_TYPE),), "static: ?n is 0"))
    return replace(task, actions=tuple(actions), predicates=predicates,
                   init=tuple(sorted({*task.init, *init})), types=(*task.types, (COUNT_TYPE, "object")),
                   constants=(*task.constants, *((n, COUNT_TYPE) for n in num)))
