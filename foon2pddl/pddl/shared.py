"""One domain, many problems: a benchmark set whose problems all read one domain file.

Every goal is compiled without relevance pruning, so the domains differ only in
their goal actions (a goal with several candidate nodes, or an encoding that
reaches goals through an action, adds `reach-goal-<i>` actions making
`(goal-reached)`). `share_domain` keeps one copy of the rest (predicates: their
union, as a lifted task declares those its kitchen and goal atoms need), checks the
types and unit actions are the same for every goal (else the encoding's domain depends on the goal, and a
shared domain would be wrong: UsageError), and renames each goal's goal
actions and goal predicate after the goal (`reach-<goal>-<i>` making
`(reached-<goal>)`), so they coexist in the one domain and each problem's
`:goal` names its own goal. A goal whose task reaches it without goal actions
keeps its atoms in `:goal`. Constants are the union over the goals; a problem
no longer declares as an object what the domain declares as a constant (some
readers reject a name declared twice). O(total size of the tasks).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from ..errors import UsageError
from .arg_types import common_type
from .encoding import GOAL_REACHED
from .names import NameTable
from .render import render_domain, render_problem
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["SharedSet", "render_shared", "share_domain"]


@dataclass(frozen=True)
class SharedSet:
    """The one domain (a task whose problem parts are unused) and one problem task per goal, in goal order."""

    domain: PlanningTask
    problems: tuple[PlanningTask, ...]


def _domain_part(task: PlanningTask) -> tuple:
    """What must be the same in every goal's task: types and unit actions (not goal actions)."""
    return (task.encoding, task.level, task.types, tuple(a for a in task.actions if a.unit is not None))


def _predicates(tasks: Sequence[PlanningTask]) -> dict[str, Predicate]:
    """Every predicate some task declares (a lifted task declares those its kitchen and goal need), by name, in
    order of first declaration; argument types that differ between goals (`arg_types.narrow_arguments` types an
    argument by its uses, goal atoms included) widen to their common type; UsageError when two declare one name
    otherwise differently."""
    out: dict[str, Predicate] = {}
    for t in tasks:
        for p in t.predicates:
            if p.name == GOAL_REACHED or out.setdefault(p.name, p) == p:
                continue
            q = out[p.name]
            if [v for v, _ in q.params] != [v for v, _ in p.params] or q.comment != p.comment:
                raise UsageError(f"the {t.encoding} encoding declares predicate {p.name!r} differently for two goals")
            out[p.name] = replace(q, params=tuple((v, common_type(dict(t.types), (a, b)))
                                                  for (v, a), (_, b) in zip(q.params, p.params, strict=True)))
    return out


def _first_difference(a: tuple, b: tuple) -> str:
    what = ("encoding", "level", "types", "unit actions")
    return next(w for w, x, y in zip(what, a, b, strict=True) if x != y)


def _reserved(tasks: Sequence[PlanningTask]) -> set[str]:
    """Every name some task declares (the new goal names must not take one)."""
    names = {GOAL_REACHED}
    for t in tasks:
        names.update(n for pair in (*t.types, *t.constants, *t.objects) for n in pair)
        names.update(p.name for p in t.predicates)
        names.update(a.name for a in t.actions)
    return names


def share_domain(goals: Sequence[tuple[str, PlanningTask]]) -> SharedSet:
    """One domain for the unpruned tasks of `goals` ((goal description, task), at least one), and their problems.

    Raises UsageError when the tasks' domains differ beyond their goal actions (the first difference named).
    """
    if not goals:
        raise ValueError("share_domain needs at least one goal")
    tasks = [t for _, t in goals]
    base = _domain_part(tasks[0])
    for (text, t) in goals[1:]:
        if (part := _domain_part(t)) != base:
            raise UsageError(f"the {t.encoding} encoding's domain for {text!r} differs from the first goal's "
                             f"({_first_difference(base, part)}): a shared domain needs an encoding whose "
                             f"unpruned domain is the same for every goal")
    table = NameTable(_reserved(tasks))
    actions: list[Action] = list(base[3])
    predicates: list[Predicate] = list(_predicates(tasks).values())
    goal_atoms: list[tuple[Atom, ...]] = []
    inits: list[tuple[Atom, ...]] = []  # a goal the kitchen holds starts reached (`task.settle_goal`)
    for text, t in goals:
        aux = [a for a in t.actions if a.unit is None]
        if not aux:
            goal_atoms.append(t.goal)
            inits.append(t.init)
            continue
        reached = Atom(table.name(f"reached {text}", key=("reached", len(goal_atoms))))
        predicates.append(Predicate(reached.predicate, comment=f"goal {text} was made"))
        for i, a in enumerate(aux, start=1):
            actions.append(replace(
                a, name=table.name(f"reach {text} {i}", key=("reach", len(goal_atoms), i)),
                add=tuple(reached if x == Atom(GOAL_REACHED) else x for x in a.add),
                comment=(f"goal {text}", *a.comment)))
        goal_atoms.append(tuple(reached if x == Atom(GOAL_REACHED) else x for x in t.goal))
        inits.append(tuple(reached if x == Atom(GOAL_REACHED) else x for x in t.init))
    constants = dict(c for t in tasks for c in t.constants)
    shared_comments = tuple(line for line in tasks[0].comments if all(line in t.comments for t in tasks[1:]))
    domain = replace(tasks[0], actions=tuple(actions), predicates=tuple(predicates),
                     constants=tuple(constants.items()),
                     comments=(*shared_comments, f"shared domain of {len(goals)} problems, one per goal"),
                     objects=(), init=(), goal=())
    problems = tuple(replace(domain, problem=t.problem, comments=t.comments, labels=t.labels, instances=t.instances,
                             objects=tuple(o for o in t.objects if o[0] not in constants), init=i, goal=g)
                     for t, i, g in zip(tasks, inits, goal_atoms, strict=True))
    return SharedSet(domain, problems)


def render_shared(shared: SharedSet) -> tuple[str, tuple[str, ...]]:
    """(domain text, problem texts): every problem's `:domain` names the domain (named by its digest, `render`)."""
    name, text = render_domain(shared.domain)
    return text, tuple(render_problem(replace(p, domain=name)) for p in shared.problems)
