"""Micro tasks solved once per shape: steps whose problems are equal up to renaming objects share a plan.

Many macro steps of a dish pose the same micro task over other objects (put the lime on
a board, then the avocado on another; cut either with the knife; pour from one cup or
the next). `canonical` names a micro problem's objects by the part they play in it, not
by their names: colour refinement (one-dimensional Weisfeiler-Leman) over the init and
goal facts, starting from the objects' types, until no colour class splits; while a class
still holds several objects, its first by name is given a colour of its own and the
refinement runs again (individualization: among symmetric objects, the onion and the
water a mix uses up, any choice gives the same text); objects are then numbered by
colour (`obj-0`, `obj-1`, ...). The hands, the workspace and the domain's constants keep
their names. O(objects^2 x facts x arity) at worst; a micro task has a handful of objects.

The planner is given the canonical problem, and its plan is renamed back: two problems
with the same canonical text are equal after a bijection of their objects, so the plan
of one, renamed through it, is a plan of the other, whatever the tie-break chose (a tie
between objects that are not symmetric only costs a miss, never a wrong plan). Since
the planner only ever sees canonical text, a step's skills are the same whether its
shape was solved before or not: sharing a memo between plans changes no output.
`MicroMemo` keeps, per (solver, domain text, canonical text), the first settled result
(solved, unsolvable; not a timeout or an error), a found plan post-processed once by the
caller's `finish` (`decompose` drops the skills it does not need: `skills.shorten`); the
skill-level replay still checks every renamed skill.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from functools import cached_property

from ..pddl.render import render_problem
from ..pddl.task import Atom
from .micro import MicroProblem

__all__ = ["Canonical", "MicroMemo", "canonical"]

#: (status, plan lines, message, seconds): what a micro solver returns (`decompose.Solver`).
Result = tuple[str, tuple[str, ...], str, float]
#: Outcomes that say nothing about the problem itself (a time limit on a loaded host, a crash): never kept.
UNSETTLED = frozenset({"timeout", "error"})
PREFIX = "obj-"


@dataclass(frozen=True)
class Canonical:
    """A micro problem up to renaming: its canonical `task`, and `names`, the problem's object standing at
    each canonical position (`obj-K` is `names[K]`)."""

    task: object  # pddl.task.PlanningTask
    names: tuple[str, ...]

    @cached_property
    def text(self) -> str:
        return render_problem(self.task)

    def decode(self, plan: Iterable[str]) -> tuple[str, ...]:
        """Plan lines over canonical names with this problem's objects put back (other names kept)."""
        back = {f"{PREFIX}{k}": n for k, n in enumerate(self.names)}
        return tuple(" ".join(back.get(x, x) for x in line.split()) for line in plan)


def _refined(colour: dict[str, int], facts) -> dict[str, int]:
    """Colour refinement to a stable partition: an object's next colour is its colour and the sorted facts
    it occurs in (predicate, its position, the other arguments' colours or fixed names), ranked."""
    classes = len(set(colour.values()))
    while True:
        seen: dict[str, list] = {n: [] for n in colour}
        for part, atom in facts:
            shape = tuple((0, colour[x], "") if x in colour else (1, 0, x) for x in atom.args)
            for i, x in enumerate(atom.args):
                if x in colour:
                    seen[x].append((part, atom.predicate, i, shape))
        signature = {n: (colour[n], tuple(sorted(seen[n]))) for n in colour}
        rank = {s: k for k, s in enumerate(sorted(set(signature.values())))}
        colour = {n: rank[signature[n]] for n in colour}
        if len(rank) == classes:  # refinement only splits classes: no split, stable
            return colour
        classes = len(rank)


def canonical(problem: MicroProblem, fixed: Iterable[str]) -> Canonical:
    """The canonical form of `problem`; `fixed` names (hands, workspace) keep theirs (see the module doc)."""
    keep = frozenset(fixed)
    typed = {n: t for n, t in problem.task.objects if n not in keep}
    facts = [(0, a) for a in problem.init] + [(1, a) for a in problem.goal]
    kinds = sorted(set(typed.values()))
    colour = {n: kinds.index(t) for n, t in typed.items()}
    while True:
        colour = _refined(colour, facts)
        tied = [n for n in sorted(typed, key=lambda n: (colour[n], n))
                if sum(c == colour[n] for c in colour.values()) > 1]
        if not tied:
            break
        # individualize: the first tied object (by name) gets a colour of its own, then refine again; within
        # a class of symmetric objects any choice gives the same text
        colour = {n: 2 * c + (n != tied[0] and c == colour[tied[0]]) for n, c in colour.items()}
    names = tuple(sorted(typed, key=lambda n: (colour[n], n)))
    at = {n: f"{PREFIX}{k}" for k, n in enumerate(names)}

    def renamed(atoms: Iterable[Atom]) -> tuple[Atom, ...]:
        return tuple(sorted(Atom(a.predicate, tuple(at.get(x, x) for x in a.args)) for a in atoms))

    objects = (*((n, t) for n, t in problem.task.objects if n in keep), *((at[n], typed[n]) for n in names))
    task = replace(problem.task, problem="micro", init=renamed(problem.init), goal=renamed(problem.goal),
                   objects=objects, comments=())
    return Canonical(task, names)


@dataclass
class MicroMemo:
    """Micro results by canonical problem (see the module doc); `hits` and `misses` count lookups."""

    table: dict[tuple, tuple[str, tuple[str, ...], str]] = field(default_factory=dict)
    hits: int = 0
    misses: int = 0

    def solve(self, solver: Callable[[str, str], Result], domain_text: str, problem: MicroProblem,
              fixed: Iterable[str], finish: Callable[[tuple[str, ...], object], tuple[str, ...]] | None = None
              ) -> tuple[Result, bool]:
        """(result, reused): `solver` run on the canonical form of `problem`, its plan renamed back; from the
        memo when this canonical form was solved before (seconds then 0.0), else solved now and kept.
        `finish(plan, canonical task)` post-processes a found plan once per shape (`shorten.irredundant`)."""
        canon = canonical(problem, fixed)
        key = (solver, domain_text, canon.text)
        found = self.table.get(key)
        if found is not None:
            self.hits += 1
            status, plan, message = found
            return (status, canon.decode(plan), message, 0.0), True
        self.misses += 1
        status, plan, message, seconds = solver(domain_text, canon.text)
        if status == "solved" and finish is not None:
            plan = finish(tuple(plan), canon.task)
        if status not in UNSETTLED:
            self.table[key] = (status, tuple(plan), message)
        return (status, canon.decode(plan), message, seconds), False
