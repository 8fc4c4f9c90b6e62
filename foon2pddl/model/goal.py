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
from dataclasses import dataclass

from ..errors import UsageError
from .containment import is_auxiliary
from .foon import Foon, ObjectNode, State, make_node
from .levels import project_node


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






def level_loss(spec: GoalSpec, level: int) -> str:
    """What reading `spec` at `level` drops, in words ("" when nothing): level 1 keeps only the
    object label, level 2 drops ingredient lists. Used to warn instead of silently answering
    a different question."""
    if spec.states is None or level >= 3:
        return ""
    kept = project_node(make_node(spec.label, spec.states), level)
    full = make_node(spec.label, spec.states)
    if kept == full:
        return ""
    what = "a goal's states" if level == 1 else "ingredients ({...})"
    read = spec_of_node(kept) if kept.states else GoalSpec(kept.label)
    return f"level {level} ignores {what}: {spec.describe()!r} is read as {read.describe()!r}"


def label_hints(label: str, foon: Foon, limit: int = 5) -> list[str]:
    """Produced labels close to `label`: difflib's close matches, then labels containing it as a word.

    Only produced labels are goals, so only they are offered.
    """
    produced = sorted({n.label for n in foon.producers})
    close = difflib.get_close_matches(label, produced, n=limit, cutoff=0.6)
    words = set(label.split())
    close += [x for x in produced if x not in close and words and words <= set(x.split())]
    return close[:limit]


def spec_of_node(node: ObjectNode) -> GoalSpec:
    """The goal that asks for exactly this node."""
    return GoalSpec(node.label, node.states)




def resolve_goal(spec: GoalSpec, foon: Foon, level: int | None = None) -> Goal:
    """The produced nodes of `foon` (at its level) that match `spec`.

    Raises UsageError naming close labels when nothing matches.
    """
    level = foon.level if level is None else level
    same_label = [n for n in foon.produced_by_label.get(spec.label, ()) if not is_auxiliary(n)]
    if not same_label:
        close = label_hints(spec.label, foon)
        hint = f"; close matches: {', '.join(close)}" if close else ""
        hint += "; `foon2pddl goals` lists every goal"
        if any(n.label == spec.label for n in foon.nodes):
            raise UsageError(f"no unit produces {spec.label!r} (it only occurs as an input){hint}")
        raise UsageError(f"unknown object label {spec.label!r}{hint}")
    if spec.states is None:
        return Goal(spec, tuple(sorted(same_label)), level)
    want = project_node(make_node(spec.label, spec.states), level).states
    found = [n for n in same_label if n.states == want]
    if not found:
        wanted = set(want)
        found = [n for n in same_label if wanted <= set(n.states)]
    if not found:
        known = sorted({", ".join(s.describe() for s in n.states) for n in same_label})[:8]
        raise UsageError(
            f"no produced {spec.label!r} node is in states {spec.describe()!r}; produced states include: "
            + "; ".join(f"({k})" for k in known),
        )
    return Goal(spec, tuple(sorted(found)), level)
