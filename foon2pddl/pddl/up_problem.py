"""A PlanningTask as a unified-planning `Problem`, for users who want UP objects.

UP checks every new action, fluent, object and type name against all names
already in the problem by scanning them: quadratic, 88 s at 20,000 actions.
The task's names are already unique within each PDDL namespace, so while
building we make every name unique ourselves (one set, one lookup) and tell UP
not to scan (`has_name` answers False until the problem is built). Across namespaces (a
predicate and an object may share a name in PDDL, not in UP) fluents and types
are renamed with a suffix, while actions and objects keep their names so plans
map back 1:1. Importing unified-planning costs ~1.5 s: only this module and the
planners that need UP import it, lazily.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .task import Atom, PlanningTask

if TYPE_CHECKING:  # pragma: no cover
    from unified_planning.model import Problem


def quiet_environment() -> Any:
    """UP's global environment with its credits banner (printed on stdout) switched off."""
    from unified_planning.shortcuts import get_environment

    env = get_environment()
    env.credits_stream = None
    return env


def _problem_class():
    from unified_planning.model import Problem

    class _UniqueNamesProblem(Problem):
        """A Problem that skips UP's scan for a taken name while `_trusted` (names made unique by `to_up_problem`)."""

        _trusted = False

        def has_name(self, name: str) -> bool:
            return False if self._trusted else super().has_name(name)

    return _UniqueNamesProblem


def _unique(name: str, used: set[str]) -> str:
    out, n = name, 1
    while out in used:
        n += 1
        out = f"{name}_{n}"
    used.add(out)
    return out


@dataclass(frozen=True)
class UpTask:
    """A UP problem with the maps between the task's names and its UP actions and objects."""

    problem: Any
    actions: dict[str, Any]  # task action name -> UP action
    objects: dict[str, Any]  # task object/constant name -> UP object
    object_names: dict[str, str]  # UP object name -> task name

    def step(self, action_instance: Any) -> str:
        """A UP ActionInstance as a plan step of the task (`action arg ...`)."""
        args = (self.object_names.get(str(p), str(p)) for p in action_instance.actual_parameters)
        return " ".join([action_instance.action.name, *args]).lower()


def to_up_problem(task: PlanningTask) -> Problem:
    """The task as a UP `Problem` (actions named as in the PDDL; see the module doc)."""
    return build_up(task).problem


def build_up(task: PlanningTask) -> UpTask:
    """The task as a UP problem, with name maps (actions first, so they keep their names)."""
    quiet_environment()
    from unified_planning.model import Fluent, InstantaneousAction, Object, Variable
    from unified_planning.model.metrics import MinimizeActionCosts
    from unified_planning.shortcuts import And, BoolType, Int, UserType

    problem = _problem_class()(task.problem)
    used: set[str] = set()
    problem._trusted = True  # every name below goes through _unique first

    action_names = [_unique(a.name, used) for a in task.actions]
    typed_objects = list(task.constants) + list(task.objects)
    object_names = [_unique(name, used) for name, _ in typed_objects]

    declared = dict(task.types)
    used_types = {t for _, t in typed_objects} | {t for p in task.predicates for _, t in p.params}
    used_types |= {t for a in task.actions for _, t in (*a.params, *(q for c in a.conditional
                                                                     for q in c.quantified))}
    # `object` is PDDL's implicit root: a type declared under it has no father unless `object` itself
    # types something (as UP's PDDL reader does), so flat typing stays flat (Tamer reads only that)
    root = "object" in used_types or not task.uses_types
    needed = used_types | set(declared) | {t for t in declared.values() if t != "object" or root}
    needed |= {"object"} if root else set()
    types: dict[str, Any] = {}

    def up_type(name: str) -> Any:
        if name not in types:
            parent = declared.get(name)
            father = up_type(parent) if parent and parent != name and name != "object" and parent in needed \
                else None
            types[name] = UserType(_unique(name, used), father)
        return types[name]

    for t in sorted(needed):
        up_type(t)

    fluents = {}
    for p in task.predicates:
        params = OrderedDict((_param(v), up_type(t)) for v, t in p.params)
        fluents[p.name] = problem.add_fluent(Fluent(_unique(p.name, used), BoolType(), **params),
                                             default_initial_value=False)
    objects = {}
    for (name, t), up_name in zip(typed_objects, object_names, strict=True):
        objects[name] = problem.add_object(Object(up_name, up_type(t)))

    costs = {}
    for action, name in zip(task.actions, action_names, strict=True):
        ua = InstantaneousAction(name, OrderedDict((_param(v), up_type(t)) for v, t in action.params))
        params = {v: ua.parameter(_param(v)) for v, _ in action.params}

        def expr(atom: Atom, params=params) -> Any:
            return fluents[atom.predicate](*(params[a] if a.startswith("?") else objects[a] for a in atom.args))

        for atom in action.pre:
            ua.add_precondition(expr(atom))
        for atom in action.delete:
            if atom not in action.add:  # PDDL: add wins over delete of the same atom
                ua.add_effect(expr(atom), False)
        for atom in action.add:
            ua.add_effect(expr(atom), True)
        for c in action.conditional:
            scope = dict(params)
            for v, t in c.quantified:
                scope[v] = Variable(_param(v), up_type(t))
            bound = tuple(scope[v] for v, _ in c.quantified)

            def fact(atom: Atom, scope=scope) -> Any:
                return fluents[atom.predicate](*(scope[a] if a.startswith("?") else objects[a] for a in atom.args))
            cond = And(*map(fact, c.when)) if len(c.when) > 1 else fact(c.when[0])
            for atom in c.delete:
                if atom not in c.add:
                    ua.add_effect(fact(atom), False, cond, forall=bound)
            for atom in c.add:
                ua.add_effect(fact(atom), True, cond, forall=bound)
        problem.add_action(ua)
        if action.cost is not None:
            costs[ua] = Int(action.cost)
    for atom in task.init:
        problem.set_initial_value(fluents[atom.predicate](*(objects[a] for a in atom.args)), True)
    for atom in task.goal:
        problem.add_goal(fluents[atom.predicate](*(objects[a] for a in atom.args)))
    if task.uses_costs:
        problem.add_quality_metric(MinimizeActionCosts(costs, default=Int(0)))
    problem._trusted = False  # from here on, UP's own checks
    actions = {a.name: ua for a, ua in zip(task.actions, problem.actions, strict=True)}
    object_names = {o.name: name for name, o in objects.items()}
    return UpTask(problem, actions, objects, object_names)


def _param(var: str) -> str:
    return var[1:] if var.startswith("?") else var
