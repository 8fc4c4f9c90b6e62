"""The skill-level simulator: an independent replay of a skill plan on the skill domain's own actions.

Independent of Fast Downward: the domain's actions are read from its PDDL text
(`skills.domain`) and interpreted here, with PDDL's semantics (a precondition is
checked on the state before the action; effects, conditional ones included, are
evaluated on that state, deletes applied before adds). Supported: `and`, `or`,
`not`, `imply`, `forall`, `exists`, `when`, `=`, `increase` by a number (costs summed; a robot's per-skill costs replace them). A
`forall ... (when C E)` is enumerated by joining C's positive atoms against the
state (not over every tuple of objects), so a step costs about (atoms matched)
per action.

The replay starts from the trace's initial state (every object, all hands
empty); per macro step it adds the step's facts (`MicroProblem.statics`; the portions it splits off and the
phases FOON restates, `split`, `restated`), runs
the step's skills, drops the step's facts, and then requires the changing facts
(`domain.DYNAMIC`) to be exactly those the trace gives after the step. An
abstract step (no skills) jumps to the trace's state. It stops at the first
problem.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from ..model.tasktree import Validation
from ..pddl.task import Atom
from .domain import DYNAMIC, ActionSchema, SkillDomain
from .sexpr import SList, typed_list

__all__ = ["Replayer", "SkillError"]

Fact = tuple[str, ...]


class SkillError(ValueError):
    """A skill whose precondition does not hold, or that names no action or a wrong argument."""


def _fact(atom: Atom) -> Fact:
    return (atom.predicate, *atom.args)


@dataclass
class _Ctx:
    state: frozenset[Fact]
    by_pred: dict[str, list[Fact]]
    universe: Mapping[str, tuple[str, ...]]


def _ground(term: str, binding: Mapping[str, str]) -> str:
    return binding.get(term, term) if term.startswith("?") else term


def _atom(node: SList, binding: Mapping[str, str]) -> Fact:
    return tuple(_ground(x, binding) if isinstance(x, str) else "?" for x in node.items)


def _holds(node, binding: Mapping[str, str], ctx: _Ctx) -> bool:
    if not isinstance(node, SList) or not node.items:
        return True
    head = node.head
    if head == "and":
        return all(_holds(x, binding, ctx) for x in node.items[1:])
    if head == "or":
        return any(_holds(x, binding, ctx) for x in node.items[1:])
    if head == "not":
        return not _holds(node.items[1], binding, ctx)
    if head == "imply":
        return not _holds(node.items[1], binding, ctx) or _holds(node.items[2], binding, ctx)
    if head in ("forall", "exists"):
        variables = typed_list(node.items[1].items)
        found = (_holds(node.items[2], {**binding, **b}, ctx) for b in _bindings(variables, None, binding, ctx))
        return all(found) if head == "forall" else any(found)
    if head == "=":
        return _ground(node.items[1], binding) == _ground(node.items[2], binding)
    return _atom(node, binding) in ctx.state


def _positive_atoms(cond) -> list[SList]:
    if not isinstance(cond, SList):
        return []
    if cond.head == "and":
        return [a for x in cond.items[1:] for a in _positive_atoms(x)]
    if cond.head in ("not", "or", "imply", "forall", "exists", "=", None):
        return []
    return [cond]


def _bindings(variables, cond, outer: Mapping[str, str], ctx: _Ctx) -> Iterable[dict[str, str]]:
    """Bindings of `variables` (typed) that may satisfy `cond`: joined on its positive atoms, the rest enumerated."""
    names = {v for v, _ in variables}
    atoms = [a for a in _positive_atoms(cond) if any(x in names for x in a.items[1:])]

    def join(k: int, b: dict[str, str]) -> Iterable[dict[str, str]]:
        if k == len(atoms):
            free = [(v, t) for v, t in variables if v not in b]
            for combo in itertools.product(*(ctx.universe.get(t, ()) for _, t in free)):
                yield {**b, **dict(zip((v for v, _ in free), combo, strict=True))}
            return
        pattern = atoms[k].items
        for fact in ctx.by_pred.get(pattern[0], ()):
            if len(fact) != len(pattern):
                continue
            nb, ok = dict(b), True
            for term, value in zip(pattern[1:], fact[1:], strict=True):
                if term in names:
                    if nb.setdefault(term, value) != value:
                        ok = False
                        break
                elif _ground(term, outer) != value:
                    ok = False
                    break
            if ok:
                yield from join(k + 1, nb)

    seen = set()
    for b in join(0, {}):
        key = tuple(sorted(b.items()))
        if key not in seen:
            seen.add(key)
            yield b


def _effects(node, binding, ctx: _Ctx, add: set, delete: set, cost: list) -> None:
    if not isinstance(node, SList) or not node.items:
        return
    head = node.head
    if head == "and":
        for x in node.items[1:]:
            _effects(x, binding, ctx, add, delete, cost)
    elif head == "not":
        delete.add(_atom(node.items[1], binding))
    elif head == "when":
        if _holds(node.items[1], binding, ctx):
            _effects(node.items[2], binding, ctx, add, delete, cost)
    elif head == "forall":
        variables = typed_list(node.items[1].items)
        body = node.items[2]
        cond = body.items[1] if isinstance(body, SList) and body.head == "when" else None
        for b in _bindings(variables, cond, binding, ctx):
            _effects(body, {**binding, **b}, ctx, add, delete, cost)
    elif head == "increase":
        amount = node.items[2]
        cost.append(float(amount) if isinstance(amount, str) and amount.replace(".", "", 1).isdigit() else 0.0)
    else:
        add.add(_atom(node, binding))


class Replayer:
    """A replay state over one domain and universe (name -> type); `apply` runs one skill call."""

    def __init__(self, domain: SkillDomain, objects: Mapping[str, str], facts: Iterable[Atom],
                 costs: Mapping[str, int] | None = None) -> None:
        self.domain = domain
        self.types = dict(objects)
        self.types.update({k: "skill" for k in domain.skills})
        universe: dict[str, list[str]] = {}
        for name, typ in self.types.items():
            universe.setdefault(typ, []).append(name)
            universe.setdefault("object", []).append(name)
        self.universe = {t: tuple(sorted(v)) for t, v in universe.items()}
        self.state: set[Fact] = {_fact(a) for a in facts}
        self.costs = dict(costs or {})
        self.cost = 0.0

    def _ctx(self) -> _Ctx:
        by_pred: dict[str, list[Fact]] = {}
        for f in self.state:
            by_pred.setdefault(f[0], []).append(f)
        return _Ctx(frozenset(self.state), by_pred, self.universe)

    def apply(self, name: str, args: Sequence[str]) -> None:
        """Run skill `name` on `args`; SkillError when it is unknown, mistyped or not applicable."""
        schema: ActionSchema | None = self.domain.by_name.get(name)
        if schema is None:
            raise SkillError(f"{name}: no such skill in {self.domain.path}")
        if len(args) != len(schema.params):
            raise SkillError(f"{name}: {len(schema.params)} arguments expected, got {len(args)}")
        binding = {}
        for (var, typ), arg in zip(schema.params, args, strict=True):
            if self.types.get(arg) != typ:
                raise SkillError(f"{name}: {arg} is not a {typ}")
            binding[var] = arg
        ctx = self._ctx()
        if not _holds(schema.pre, binding, ctx):
            raise SkillError(f"{name} {' '.join(args)}: precondition fails: {self._failing(schema.pre, binding, ctx)}")
        add: set[Fact] = set()
        delete: set[Fact] = set()
        cost: list[float] = []
        _effects(schema.effect, binding, ctx, add, delete, cost)
        self.state = (self.state - delete) | add
        self.cost += self.costs.get(name, sum(cost))

    def _failing(self, pre, binding, ctx) -> str:
        parts = pre.items[1:] if isinstance(pre, SList) and pre.head == "and" else (pre,)
        for p in parts:
            if not _holds(p, binding, ctx):
                return "(" + " ".join(_atom(p, binding)) + ")" if p.head not in ("and", "or", "not") else str(p.head)
        return "?"

    def dynamic(self) -> set[Atom]:
        """The changing facts of the state."""
        return {Atom(f[0], f[1:]) for f in self.state if f[0] in DYNAMIC}

    def add(self, facts: Iterable[Atom]) -> None:
        self.state |= {_fact(a) for a in facts}

    def remove(self, facts: Iterable[Atom]) -> None:
        self.state -= {_fact(a) for a in facts}

    def reset_dynamic(self, facts: Iterable[Atom]) -> None:
        """Replace the changing facts by `facts` (an abstract step: the trace says what it did)."""
        self.state = {f for f in self.state if f[0] not in DYNAMIC} | {_fact(a) for a in facts}

    def holder(self, name: str) -> str | None:
        """What `name` is in or on now (a name), the hand holding it, or None."""
        for f in self.state:
            if len(f) == 3 and f[2] == name and f[0] in ("in", "on", "holding"):
                return f[1]
        return None


def check(replayer: Replayer, expected: set[Atom]) -> list[str]:
    """Differences between the replay's changing facts and `expected` (sorted, at most 4 of each kind)."""
    have = replayer.dynamic()
    missing, extra = sorted(expected - have), sorted(have - expected)
    out = []
    if missing:
        out.append("missing " + ", ".join(f"({a.predicate} {' '.join(a.args)})" for a in missing[:4]))
    if extra:
        out.append("unexpected " + ", ".join(f"({a.predicate} {' '.join(a.args)})" for a in extra[:4]))
    return out


def validation(problems: list[str]) -> Validation:
    return Validation(not problems, tuple(problems))
