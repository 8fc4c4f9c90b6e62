"""Goals: which produced node(s) a user asks for.

Syntax: `whipped cream` (any produced node with that label), `onion: chopped`,
`water: in [pot]`, `bowl: contains {lettuce, tomato}`; several states are
separated by commas outside brackets. A goal resolves, at a level, to the
produced nodes that match: the nodes whose states equal the given ones if any
exist, otherwise the nodes whose states include them. Reaching any of them
reaches the goal.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass
from pathlib import Path

from .errors import FoonInputError, FoonSyntaxError
from .levels import project_node
from .model import Foon, ObjectNode, State, make_node, make_state, normalize_label
from .parser import parse_objects, read_text

_STATE = re.compile(r"^(?P<label>[^\[\]{}]*?)\s*(?:\[(?P<rel>[^\[\]]*)\])?\s*(?:\{(?P<ing>[^{}]*)\})?$")


@dataclass(frozen=True)
class GoalSpec:
    """What the user typed: a label and optionally the states the node must be in."""

    label: str
    states: tuple[State, ...] | None = None

    def describe(self) -> str:
        if self.states is None:
            return self.label
        return f"{self.label}: " + ", ".join(s.describe() for s in self.states)


@dataclass(frozen=True)
class Goal:
    """A resolved goal: the candidate nodes (at one level), any of which satisfies it."""

    spec: GoalSpec
    candidates: tuple[ObjectNode, ...]
    level: int = 3

    def describe(self) -> str:
        return self.spec.describe()

    def satisfied_by(self, available: set[ObjectNode] | frozenset[ObjectNode]) -> ObjectNode | None:
        """The first candidate present in `available`, else None."""
        for c in self.candidates:
            if c in available:
                return c
        return None


def _split_states(text: str) -> list[str]:
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
            if depth < 0:
                raise ValueError(f"unbalanced bracket in goal states {text!r}")
        if ch == "," and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    if depth:
        raise ValueError(f"unbalanced bracket in goal states {text!r}")
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def parse_goal_spec(text: str) -> GoalSpec:
    """Parse the goal syntax; raises ValueError with what was expected."""
    label, sep, rest = text.partition(":")
    label = normalize_label(label)
    if not label:
        raise ValueError("goal has no object label (expected 'label' or 'label: state, ...')")
    if not sep:
        return GoalSpec(label)
    states = []
    for part in _split_states(rest):
        m = _STATE.match(part)
        if not m or not m.group("label").strip():
            raise ValueError(f"cannot read state {part!r} (expected 'state', 'state [object]' or 'state {{a, b}}')")
        ing = [i for i in (m.group("ing") or "").split(",") if i.strip()]
        states.append(make_state(m.group("label"), m.group("rel") or "", ing))
    return GoalSpec(label, tuple(sorted(set(states))))


def spec_of_node(node: ObjectNode) -> GoalSpec:
    """The goal that asks for exactly this node."""
    return GoalSpec(node.label, node.states)


def read_goal_file(path: str | Path) -> GoalSpec:
    """A goal file: exactly one object node written as FOON O/S lines."""
    p = Path(path)
    nodes = parse_objects(read_text(p), str(p))
    if len(nodes) != 1:
        raise FoonSyntaxError(str(p), nodes[1][1] if len(nodes) > 1 else 0,
                              f"goal file must hold exactly one object node, found {len(nodes)}")
    return spec_of_node(nodes[0][0])


def resolve_goal(spec: GoalSpec, foon: Foon, level: int | None = None) -> Goal:
    """The produced nodes of `foon` (at its level) that match `spec`.

    Raises FoonInputError naming close labels when nothing matches.
    """
    level = foon.level if level is None else level
    produced = [n for n in foon.producers]
    same_label = [n for n in produced if n.label == spec.label]
    if not same_label:
        labels = sorted({n.label for n in foon.nodes})
        close = difflib.get_close_matches(spec.label, labels, n=5, cutoff=0.6)
        hint = f"; close matches: {', '.join(close)}" if close else ""
        if spec.label in labels:
            raise FoonInputError("<goal>", 0, f"no unit produces {spec.label!r} (it only occurs as an input)")
        raise FoonInputError("<goal>", 0, f"unknown object label {spec.label!r}{hint}")
    if spec.states is None:
        return Goal(spec, tuple(sorted(same_label)), level)
    want = project_node(make_node(spec.label, spec.states), level).states
    exact = [n for n in same_label if n.states == want]
    subset = [n for n in same_label if set(want) <= set(n.states)]
    found = exact or subset
    if not found:
        known = sorted({", ".join(s.describe() for s in n.states) for n in same_label})[:8]
        raise FoonInputError(
            "<goal>", 0,
            f"no produced {spec.label!r} node is in states {spec.describe()!r}; produced states include: "
            + "; ".join(f"({k})" for k in known),
        )
    return Goal(spec, tuple(sorted(found)), level)
