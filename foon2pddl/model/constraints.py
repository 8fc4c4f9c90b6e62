"""Constraints on what a task tree may contain: a robot's abilities and a cook's diet.

- `without-motion M`: no unit whose motion label is M (the robot cannot do it);
- `without X`: no unit any of whose nodes *mentions* X (an object or ingredient that
  must not appear anywhere in the tree);
- `must-use X`: some unit of the tree uses X (one of its input nodes mentions X);
- motion success rates (or costs, cost = -ln(rate)): how likely each motion succeeds;
- a robot's skills: `without-skill S` (a skill it lacks; the CLI turns it into the
  `without-motion` bans of the motions that map to S) and per-skill costs (`skills`).

A node mentions X when X's words occur, as consecutive whole words, in the node's
label, in a related object (`in [bowl]`) or in an item of an ingredient list: `peanut`
matches `peanut`, `peanut butter` and `bowl (contains {peanut, salt})`, never `peanuts`
or `eggplant` for `egg`. Everything made from X is excluded with it: a unit taking X
is removed, so only ways of making a node that avoid X remain.

Constraints from several profiles combine by union (`combine`); a motion given two
different rates is an error. Each ban and requirement is one `Constraint`, the unit
the minimal blocking set (`analysis.blocking`) is made of.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from enum import StrEnum
from functools import lru_cache

from .foon import FunctionalUnit, ObjectNode, normalize_label


class Kind(StrEnum):
    """What a constraint says; the value is also its flag and file key."""

    WITHOUT_MOTION = "without-motion"
    WITHOUT = "without"
    MUST_USE = "must-use"


@dataclass(frozen=True, order=True)
class Constraint:
    """One ban or requirement: its kind and the (normalized) motion or object label."""

    kind: Kind
    value: str
    source: str = field(default="", compare=False)
    skill: str = field(default="", compare=False)  # the lacking robot skill this motion ban stands for

    def describe(self) -> str:
        """`without-motion pour` as the user spelled it: `without-skill pour` for a ban a lacking skill made."""
        return f"without-skill {self.skill}" if self.skill else f"{self.kind.value} {self.value}"

    def detail(self) -> str:
        """`describe()`, naming the banned motion when a skill's ban is another motion (`without-skill pour
        (motion fill)`), for lines that list each ban."""
        return self.describe() + (f" (motion {self.value})" if self.skill and self.skill != self.value else "")


def describe_all(constraints: Iterable[Constraint]) -> tuple[str, ...]:
    """Each constraint's `describe()` once, in order: a skill's several motion bans read as one option."""
    return tuple(dict.fromkeys(c.describe() for c in constraints))


@dataclass(frozen=True)
class Constraints:
    """A set of constraints (sorted, duplicate-free) and motion success rates (sorted pairs)."""

    items: tuple[Constraint, ...] = ()
    rates: tuple[tuple[str, float], ...] = ()
    sources: tuple[str, ...] = ()
    without_skills: tuple[str, ...] = ()  # robot skills the robot lacks (sorted)
    skill_costs: tuple[tuple[str, int], ...] = ()  # per-skill costs of a robot profile (sorted)

    def __bool__(self) -> bool:
        return bool(self.items or self.rates)

    def of(self, kind: Kind) -> tuple[str, ...]:
        """The values of the constraints of one kind, sorted."""
        return tuple(c.value for c in self.items if c.kind is kind)

    @property
    def bans(self) -> tuple[Constraint, ...]:
        """The constraints that remove units (motion and object bans)."""
        return tuple(c for c in self.items if c.kind is not Kind.MUST_USE)

    @property
    def must_use(self) -> tuple[str, ...]:
        return self.of(Kind.MUST_USE)

    def without(self, drop: Iterable[Constraint]) -> Constraints:
        """These constraints with `drop` relaxed (rates kept)."""
        gone = set(drop)
        return replace(self, items=tuple(c for c in self.items if c not in gone))


def make_constraints(items: Iterable[Constraint] = (), rates: Iterable[tuple[str, float]] = (),
                     sources: Iterable[str] = (), without_skills: Iterable[str] = (),
                     skill_costs: Iterable[tuple[str, int]] = ()) -> Constraints:
    """Normalize labels, drop empty and duplicate items, sort; ValueError for a rate outside (0, 1],
    a motion given two rates, a negative skill cost or a skill given two costs."""
    found: dict[tuple[Kind, str], Constraint] = {}
    for c in items:
        value = normalize_label(c.value)
        if value.endswith("*") and c.kind is Kind.WITHOUT_MOTION:
            value = value.removesuffix("*").strip()
        if value:
            found.setdefault((c.kind, value), replace(c, value=value))
    table: dict[str, float] = {}
    for motion, rate in rates:
        motion = normalize_label(motion).removesuffix("*").strip()
        if not 0.0 < rate <= 1.0:
            raise ValueError(f"rate of {motion!r} must be in (0, 1], not {rate:g}")
        if table.get(motion, rate) != rate:
            raise ValueError(f"motion {motion!r} is given two rates, {table[motion]:g} and {rate:g}")
        table[motion] = rate
    costs: dict[str, int] = {}
    for skill, cost in skill_costs:
        skill = normalize_label(skill)
        if cost < 0:
            raise ValueError(f"cost of skill {skill!r} must be >= 0, not {cost}")
        if costs.get(skill, cost) != cost:
            raise ValueError(f"skill {skill!r} is given two costs, {costs[skill]} and {cost}")
        costs[skill] = cost
    lacks = tuple(sorted({normalize_label(s) for s in without_skills} - {""}))
    return Constraints(tuple(sorted(found.values())), tuple(sorted(table.items())), tuple(dict.fromkeys(sources)),
                       lacks, tuple(sorted(costs.items())))


def combine(*profiles: Constraints) -> Constraints:
    """The union of several constraint sets (a robot profile and a diet profile)."""
    return make_constraints((c for p in profiles for c in p.items), (r for p in profiles for r in p.rates),
                            (s for p in profiles for s in p.sources), (s for p in profiles for s in p.without_skills),
                            (c for p in profiles for c in p.skill_costs))


@lru_cache(maxsize=1 << 14)
def _words(label: str) -> tuple[str, ...]:
    return tuple(label.split(" "))


def label_mentions(label: str, obj: str) -> bool:
    """Whether the words of `obj` occur consecutively in `label` (both normalized)."""
    if label == obj:
        return True
    if obj not in label:  # fast rejection: most labels do not even contain the text
        return False
    have, want = _words(label), _words(obj)
    n = len(want)
    return any(have[i:i + n] == want for i in range(len(have) - n + 1))


@lru_cache(maxsize=1 << 16)
def node_labels(node: ObjectNode) -> frozenset[str]:
    """Every object label a node mentions: its own, related objects, ingredient items."""
    out = {node.label}
    for s in node.states:
        if s.related:
            out.add(s.related)
        out.update(s.ingredients)
    return frozenset(out)


def mentions(node: ObjectNode, obj: str) -> bool:
    """Whether `node` mentions the object `obj` (see the module doc)."""
    return any(label_mentions(label, obj) for label in node_labels(node))


def unit_mentions(unit: FunctionalUnit, obj: str) -> bool:
    """Whether any input or output node of `unit` mentions `obj`."""
    return any(mentions(n, obj) for n in (*unit.inputs, *unit.outputs))


def unit_uses(unit: FunctionalUnit, obj: str) -> bool:
    """Whether an input node of `unit` mentions `obj` (the unit uses it)."""
    return any(mentions(n, obj) for n in unit.inputs)


def violations(units: Iterable[FunctionalUnit], constraints: Constraints) -> list[str]:
    """What in a tree's units breaks `constraints` (empty when nothing does), unit by unit."""
    units = tuple(units)
    problems = []
    for u in units:
        for c in constraints.items:
            if c.kind is Kind.WITHOUT_MOTION and label_mentions(u.motion.label, c.value):
                problems.append(f"{u.describe()}: motion {c.value!r} is banned")
            elif c.kind is Kind.WITHOUT and unit_mentions(u, c.value):
                problems.append(f"{u.describe()}: mentions banned {c.value!r}")
    problems += [f"no unit uses {x!r}" for x in constraints.must_use if not any(unit_uses(u, x) for u in units)]
    return problems
