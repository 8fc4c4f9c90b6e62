"""PDDL text of a `PlanningTask` through the jinja2 templates in `foon2pddl/templates`.

Autoescape is off (PDDL is not HTML) and undefined variables are errors. Names
in the task are already valid identifiers (`names.py`); this module checks
that and passes every comment through `names.comment`, so nothing a label
contains can end a comment or inject a construct. The output depends only on
the task: same task, same bytes.
"""

from __future__ import annotations

import hashlib
from dataclasses import replace
from functools import lru_cache

import jinja2

from .names import comment, is_valid_name
from .task import Action, Atom, Conditional, PlanningTask


def _atom(atom: Atom) -> str:
    return f"({atom.predicate} {' '.join(atom.args)})" if atom.args else f"({atom.predicate})"


def _params(params: tuple[tuple[str, str], ...], typed: bool) -> str:
    if typed:
        return "".join(f" {var} - {typ}" for var, typ in params)
    return "".join(f" {var}" for var, _ in params)


def _conditional(c: Conditional, typed: bool) -> str:
    """`(when (c) (e))`, `(and ...)` around several conditions or effects; `(forall (?v - t) ...)` around it."""
    def conj(parts: list[str]) -> str:
        return parts[0] if len(parts) == 1 else f"(and {' '.join(parts)})"

    text = (f"(when {conj([_atom(a) for a in c.when])} "
            f"{conj([_atom(a) for a in c.add] + [f'(not {_atom(a)})' for a in c.delete])})")
    return text if c.var is None else f"(forall ({_params(c.quantified, typed).strip()}) {text})"


@lru_cache(maxsize=1)
def _environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.PackageLoader("foon2pddl", "templates"),
        autoescape=False,
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )
    env.filters["atom"] = _atom
    env.filters["params"] = _params
    env.filters["conditional"] = _conditional
    env.filters["comment"] = comment
    return env


def check_names(task: PlanningTask) -> None:
    """Raise ValueError naming the first identifier of `task` that is not a safe PDDL name."""
    names = [task.domain, task.problem]
    names += [n for pair in task.types for n in pair]
    names += [n for pair in (*task.constants, *task.objects) for n in pair]
    for p in task.predicates:
        names.append(p.name)
        names += [n.removeprefix("?") for pair in p.params for n in pair]
    for a in task.actions:
        names.append(a.name)
        names += [n.removeprefix("?") for pair in a.params for n in pair]
        released = tuple(atom for c in a.conditional for atom in c.atoms())
        names += [n.removeprefix("?") for c in a.conditional for pair in c.quantified for n in pair]
        names += [x for atom in (*a.pre, *a.add, *a.delete, *released) for x in (atom.predicate, *atom.args)]
    names += [x for atom in (*task.init, *task.goal) for x in (atom.predicate, *atom.args)]
    for name in set(names):
        if not is_valid_name(name.removeprefix("?")) and name != "object":
            raise ValueError(f"not a sanitized PDDL name in the planning task: {name!r}")


def distinct_variables(task: PlanningTask) -> PlanningTask:
    """`task` with every action variable named like a constant or object renamed (`?egg-2` -> `?egg-2-var`).

    PDDL tells `?egg-2` from the constant `egg-2` by the `?`, but the `pddl` package keys a term's type by its
    bare name and refuses `(is ?egg-2 egg-2)`; encodings name variables and constants in separate tables, so
    such pairs happen (two eggs, one in a state that sanitizes to nothing). Plans name actions and their
    arguments by position, so nothing maps back differently. O(atoms of the actions renamed); `task` itself
    when no name clashes."""
    taken = {name for name, _ in (*task.constants, *task.objects)}
    actions = tuple(_rename_variables(a, taken) for a in task.actions)
    if all(new is old for new, old in zip(actions, task.actions, strict=True)):
        return task
    return replace(task, actions=actions)


def _rename_variables(action: Action, taken: set[str]) -> Action:
    variables = [v for v, _ in action.params] + [v for c in action.conditional for v, _ in c.quantified]
    clashing = [v for v in dict.fromkeys(variables) if v.removeprefix("?") in taken]
    if not clashing:
        return action
    used, new = set(variables), {}
    for v in clashing:
        name, n = f"{v}-var", 1
        while name in used or name.removeprefix("?") in taken:
            n += 1
            name = f"{v}-var-{n}"
        used.add(name)
        new[v] = name

    def atoms(xs: tuple[Atom, ...]) -> tuple[Atom, ...]:
        return tuple(Atom(x.predicate, tuple(new.get(arg, arg) for arg in x.args)) for x in xs)

    def pairs(xs: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
        return tuple((new.get(v, v), t) for v, t in xs)

    conditional = tuple(replace(c, when=atoms(c.when), add=atoms(c.add), delete=atoms(c.delete),
                                var=new.get(c.var, c.var), more=pairs(c.more)) for c in action.conditional)
    return replace(action, pre=atoms(action.pre), add=atoms(action.add), delete=atoms(action.delete),
                   params=pairs(action.params), conditional=conditional)


#: Hex digits of the domain text's digest appended to the domain's name.
DOMAIN_DIGEST_LENGTH = 8


def render_domain(task: PlanningTask) -> tuple[str, str]:
    """(the domain's name, the domain text) of `task`: the name is the task's (`foon-tree`) plus `-` and a
    digest of the domain text written with the task's name (SHA-256, `DOMAIN_DIGEST_LENGTH` hex digits), so
    domains that differ (pruning, goal actions) never share a name and tools that cache domains by name
    cannot mix them up."""
    check_names(task)
    task = distinct_variables(task)
    env = _environment()
    context = {"task": task, "typed": task.uses_types, "costs": task.uses_costs}
    domain = env.get_template("domain.pddl.j2").render(context)
    name = f"{task.domain}-{hashlib.sha256(domain.encode()).hexdigest()[:DOMAIN_DIGEST_LENGTH]}"
    return name, domain.replace(f"(define (domain {task.domain})", f"(define (domain {name})", 1)


def render(task: PlanningTask) -> tuple[str, str]:
    """(domain text, problem text) of `task`: the domain named by `render_domain`, the problem's `:domain` the same."""
    name, domain = render_domain(task)
    return domain, _problem_text(replace(task, domain=name))


def render_problem(task: PlanningTask) -> str:
    """The problem text of `task` alone, its `:domain` the task's own name as given: for problems whose
    domain is a file of its own (a robot's skill domain), not one `render` writes (and names by digest)."""
    check_names(task)
    return _problem_text(task)


def _problem_text(task: PlanningTask) -> str:
    context = {"task": task, "typed": task.uses_types, "costs": task.uses_costs}
    return _environment().get_template("problem.pddl.j2").render(context)
