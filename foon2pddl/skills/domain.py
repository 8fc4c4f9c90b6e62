"""The skill domain: a PDDL file of robot skills, read and checked against what the decomposer writes.

The decomposer (`skills.micro`) writes problems over a fixed vocabulary (docs/skills.md):
the types `hand`, `thing`, `phase`, `skill`; the predicates of `PREDICATES` with their
arities; and, for every action K (every action is a skill, its first parameter the
hand), a `skill` constant `sk-K` that tags the step facts K carries out. A domain that
lacks any of them is rejected with the file and line, before anything is planned.
`pruned` gives the domain text with only some actions (their exact text), so a micro
task is translated with the few skills its step can use, and with a robot's per-skill
costs written into each kept action's `(increase (total-cost) N)`. Given the task's
initial facts, it also cuts every effect conjunct of a kept action that is guarded by a
static atom no initial fact matches (`(forall (?x ?w ?d - thing) (when (and (moves-in
sk-cut ?x ?d) ...) ...))` in a step that moves nothing): a static predicate (one no
action's effect names) false in the initial state stays false, so the conjunct never
fires, and the translator need not ground it (an n^3 forall for nothing).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cached_property
from importlib import resources
from pathlib import Path

from ..errors import FoonSyntaxError
from ..io.parser import read_text
from ..model.where import shown_path
from ..model.words import count
from ..pddl.task import Atom
from .sexpr import SexprError, SList, parse, typed_list

__all__ = ["DEFAULT_DOMAIN", "PREDICATES", "SKILL_PREFIX", "TRANSPORT", "ActionSchema", "SkillDomain", "parse_domain",
           "read_domain", "shipped_domain"]

#: The predicates the decomposer writes, with their arities (docs/skills.md says what each means).
PREDICATES: dict[str, int] = {
    "in": 2, "on": 2, "holding": 2, "hand-empty": 1, "placed": 1, "state": 2, "unmade": 1, "consumed": 1,
    "graspable": 1, "tool": 1, "container": 1, "surface": 1, "target": 2, "changes": 4,
    "moves-in": 3, "moves-on": 3, "makes-in": 4, "makes-on": 4, "uses-up": 2,
}
#: Predicates that change during a plan (the replay compares them with the trace); the rest are per step.
DYNAMIC = frozenset({"in", "on", "holding", "hand-empty", "placed", "state", "unmade", "consumed"})
TYPES = ("hand", "thing", "phase", "skill")
#: Skills that carry graspable objects; every domain has them (a step's moves of graspable objects use them).
TRANSPORT = ("pick", "take-out", "place", "put-in")
DEFAULT_DOMAIN = "skills.pddl"
SKILL_PREFIX = "sk-"


@dataclass(frozen=True)
class ActionSchema:
    """One skill: its name, typed parameters, precondition and effect trees, and where its text is."""

    name: str
    params: tuple[tuple[str, str], ...]
    pre: SList | None
    effect: SList | None
    line: int
    span: tuple[int, int]
    cost_span: tuple[int, int] | None = None  # the `(increase (total-cost) N)` effect


Pattern = tuple[str, tuple[str | None, ...]]  # a static atom: predicate, constants (None: a variable)


def _effect_atoms(node, out: set[str]) -> None:
    """Heads of the atoms `node` (an effect) adds or deletes (not those its `when` conditions test)."""
    if not isinstance(node, SList) or not node.items:
        return
    if node.head in ("and", "not"):
        for x in node.items[1:]:
            _effect_atoms(x, out)
    elif node.head == "forall" and len(node) > 2:
        _effect_atoms(node.items[2], out)
    elif node.head == "when" and len(node) > 2:
        _effect_atoms(node.items[2], out)
    elif node.head not in ("increase", "decrease", "assign", "scale-up", "scale-down", None):
        out.add(node.head)


def _guards(part, static: frozenset[str]) -> tuple[Pattern, ...]:
    """The static atoms a top-level effect conjunct `(when C E)` or `(forall V (when C E))` needs: C's
    positive atoms (through `and`) whose predicate is static."""
    if isinstance(part, SList) and part.head == "forall" and len(part) > 2:
        part = part.items[2]
    if not (isinstance(part, SList) and part.head == "when" and len(part) > 2):
        return ()
    out, todo = [], [part.items[1]]
    while todo:
        c = todo.pop()
        if not isinstance(c, SList) or not c.items:
            continue
        if c.head == "and":
            todo += c.items[1:]
        elif c.head in static and all(isinstance(x, str) for x in c.items):
            out.append((c.head, tuple(None if x.startswith("?") else x for x in c.items[1:])))
    return tuple(out)


def _matched(pattern: Pattern, facts: Mapping[str, list[tuple[str, ...]]]) -> bool:
    pred, args = pattern
    return any(len(f) == len(args) and all(a is None or a == x for a, x in zip(args, f, strict=True))
               for f in facts.get(pred, ()))


@dataclass(frozen=True)
class SkillDomain:
    """A checked skill domain: its text and path, name, `skill` constants (sorted) and actions (in file order)."""

    text: str
    path: str
    name: str
    skills: tuple[str, ...]
    actions: tuple[ActionSchema, ...]

    @cached_property
    def by_name(self) -> dict[str, ActionSchema]:
        return {a.name: a for a in self.actions}

    @cached_property
    def static(self) -> frozenset[str]:
        """Predicates no action's effect adds or deletes: true or false for a whole task, as its init says."""
        changed: set[str] = set()
        for a in self.actions:
            _effect_atoms(a.effect, changed)
        return frozenset(PREDICATES) - changed

    @cached_property
    def guarded(self) -> dict[str, tuple[tuple[tuple[int, int], tuple[Pattern, ...]], ...]]:
        """Per action, the (span, static guards) of each top-level effect conjunct that has guards."""
        out = {}
        for a in self.actions:
            parts = a.effect.items[1:] if a.effect is not None and a.effect.head == "and" else ()
            out[a.name] = tuple(((p.start, p.end), g) for p in parts if isinstance(p, SList) and (g := _guards(p, self.static)))
        return out

    def pruned(self, keep: set[str] | frozenset[str], costs: Mapping[str, int] | None = None,
               init: Iterable[Atom] | None = None) -> str:
        """The domain text with only the actions named in `keep` (the others cut out), and the cost of
        each kept action in `costs` written into its `(increase (total-cost) N)`; given a task's `init`,
        the kept actions' effect conjuncts with a static guard no init fact matches cut out too (see the
        module doc). Nothing else changed. O(domain text + guards x matching facts)."""
        cuts = [(a.span, "") for a in self.actions if a.name not in keep]
        if init is not None:
            facts: dict[str, list[tuple[str, ...]]] = {}
            for atom in init:
                facts.setdefault(atom.predicate, []).append(atom.args)
            cuts += [(span, "") for a in self.actions if a.name in keep for span, guards in self.guarded[a.name]
                     if not all(_matched(g, facts) for g in guards)]
        cuts += [(a.cost_span, f"(increase (total-cost) {int(costs[a.name])})") for a in self.actions
                 if a.name in keep and costs and a.name in costs and a.cost_span is not None]
        out, at = [], 0
        for (start, end), text in sorted(cuts):
            out += [self.text[at:start], text]
            at = end
        out.append(self.text[at:])
        return "".join(out)

    def constant(self, skill: str) -> str:
        """The `skill` constant that tags the step facts `skill` carries out (`sk-pour`)."""
        return SKILL_PREFIX + skill


def _fail(path: str, line: int, message: str) -> FoonSyntaxError:
    return FoonSyntaxError(path, line, message)


def _section(define: SList, key: str) -> SList | None:
    return next((x for x in define.items if isinstance(x, SList) and x.head == key), None)


def _action(node: SList, path: str) -> ActionSchema:
    items = node.items
    if len(items) < 2 or not isinstance(items[1], str):
        raise _fail(path, node.line, "an action needs a name")
    fields: dict[str, object] = {}
    for k in range(2, len(items) - 1, 2):
        if isinstance(items[k], str):
            fields[items[k]] = items[k + 1]
    params = fields.get(":parameters")
    pre, eff = fields.get(":precondition"), fields.get(":effect")
    eff = eff if isinstance(eff, SList) else None
    parts = eff.items[1:] if eff is not None and eff.head == "and" else (eff,) if eff is not None else ()
    cost = next((x for x in parts if isinstance(x, SList) and x.head == "increase" and len(x) == 3
                 and isinstance(x[1], SList) and x[1].head == "total-cost"), None)
    return ActionSchema(items[1], tuple(typed_list(params.items)) if isinstance(params, SList) else (),
                        pre if isinstance(pre, SList) else None, eff, node.line, (node.start, node.end),
                        (cost.start, cost.end) if cost is not None else None)


def parse_domain(text: str, path: str = "<skills>") -> SkillDomain:
    """Read and check a skill domain; FoonSyntaxError (path, line) when it lacks what the decomposer writes."""
    try:
        top = parse(text)
    except SexprError as exc:
        raise _fail(path, exc.line, f"not PDDL: {exc}") from None
    define = next((x for x in top if x.head == "define"), None)
    if define is None or len(define) < 2 or not isinstance(define[1], SList) or define[1].head != "domain":
        raise _fail(path, top[0].line if top else 1, "expected (define (domain NAME) ...)")
    name = define[1][1] if len(define[1]) > 1 else ""
    types = _section(define, ":types")
    declared = {n for n, _ in typed_list(types.items[1:])} if types else set()
    declared |= {t for n, t in typed_list(types.items[1:])} if types else set()
    missing = [t for t in TYPES if t not in declared]
    if missing:
        raise _fail(path, types.line if types else define.line, f"the domain must declare the types {', '.join(missing)}")
    preds = _section(define, ":predicates")
    arity = {p.head: len(typed_list(p.items[1:])) for p in (preds.items[1:] if preds else ()) if isinstance(p, SList)}
    for pred, n in PREDICATES.items():
        if arity.get(pred) != n:
            raise _fail(path, preds.line if preds else define.line,
                        f"the domain must declare the predicate {pred} with {count(n, 'parameter')}")
    consts = _section(define, ":constants")
    constants = {n for n, t in typed_list(consts.items[1:]) if t == "skill"} if consts else set()
    actions = tuple(_action(x, path) for x in define.items if isinstance(x, SList) and x.head == ":action")
    names = [a.name for a in actions]
    for a in actions:
        if SKILL_PREFIX + a.name not in constants:
            raise _fail(path, a.line, f"action {a.name}: every action is a skill, declare "
                                      f"{SKILL_PREFIX}{a.name} - skill among the constants")
        if names.count(a.name) > 1:
            raise _fail(path, a.line, f"action {a.name} is defined twice")
        if not a.params or a.params[0][1] != "hand":
            raise _fail(path, a.line, f"action {a.name}: the first parameter must be the hand (?h - hand)")
    for t in TRANSPORT:
        if t not in names:
            raise _fail(path, define.line, f"the domain must define the transport skill {t}")
    return SkillDomain(text, path, name, tuple(sorted(constants)), actions)


def read_domain(path: str | Path) -> SkillDomain:
    """Read a skill domain file (`--skill-domain FILE`)."""
    return parse_domain(read_text(Path(path)), str(path))


def shipped_domain() -> SkillDomain:
    """The domain shipped with foon2pddl, named by its path in the package (`foon2pddl/data/skills/skills.pddl`,
    `shown_path`: a path a user can open, wherever the package is installed, in messages and JSON alike)."""
    ref = resources.files("foon2pddl") / "data" / "skills" / DEFAULT_DOMAIN
    return parse_domain(ref.read_text(), shown_path(str(ref)))
