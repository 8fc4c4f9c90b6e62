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
from collections.abc import Iterable
from dataclasses import dataclass, replace

from ..errors import UsageError
from .containment import is_auxiliary
from .foon import Foon, ObjectNode, State, make_node
from .levels import project_node
from .words import count, first_of


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
    preferred: str = ""  # why a bare label kept these nodes: "dish", "final product", "any" (all of several) or ""
    others: tuple[ObjectNode, ...] = ()  # the label's other produced nodes, left out by that preference

    def describe(self) -> str:
        return self.spec.describe()

    def choice_note(self, limit: int = 5, asked: str = "", network: str = "") -> str:
        """Which nodes a bare label was read as, and the others it could name ("" when nothing was left out);
        `asked`: the label the user typed, named first when `network` (FOON-GEN) reads it as another one."""
        if not self.preferred:
            return ""
        label = self.spec.label
        name = f"{asked!r} (FOON-{network.upper()}: {label!r})" if asked and asked != label else repr(label)
        if self.preferred == "any":
            shown = first_of([f"`{c.describe()}`" for c in self.candidates], limit)
            return (f"goal {name} names no recipe's dish and no final product (a unit uses each {label!r} node): "
                    f"any of its {count(len(self.candidates), 'node')} will do, the method chooses which "
                    f"(give the states to ask for one): {shown}")
        many = len(self.candidates) > 1
        what = ("the recipes' dishes" if many else "the recipe's dish") if self.preferred == "dish" else \
            ("the final products (no unit uses them)" if many else "the final product (no unit uses it)")
        chosen = "; ".join(f"`{c.describe()}`" for c in self.candidates)
        more = first_of([f"`{o.describe()}`" for o in self.others], limit)
        return (f"goal {name} read as {what}: {chosen}; other {label!r} nodes "
                f"(give the states to ask for one): {more}")

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


def state_hints(wanted: Iterable[State], nodes: Iterable[ObjectNode]) -> str:
    """For each wanted state that none of `nodes` (one label's produced nodes) has, its close matches among
    theirs (`'choped'` -> `chopped`, `in [bowel]` -> `in [bowl]`): `state 'choped' is on no produced 'onion' node
    (close: chopped); `, "" when every wanted state occurs. difflib over the states as written; O(states^2) at worst."""
    nodes = list(nodes)
    known = sorted({s.describe() for n in nodes for s in n.states})
    label = nodes[0].label if nodes else ""
    out = ""
    for text in sorted({s.describe() for s in wanted} - set(known)):
        close = difflib.get_close_matches(text, known, n=3, cutoff=0.6)
        out += f"state {text!r} is on no produced {label!r} node" + (f" (close: {', '.join(close)})" if close else "") + "; "
    return out


def spec_of_node(node: ObjectNode) -> GoalSpec:
    """The goal that asks for exactly this node."""
    return GoalSpec(node.label, node.states)




def prefer_dishes(goal: Goal, foon: Foon) -> Goal:
    """A bare label means the dish: keep the candidates that are a recipe's dish, else those no unit
    consumes (final products), else all (marked "any" when there are several, for the note); the ones left out
    are kept in `others` for the note.

    A cook asking for `salmon` means the finished salmon, not the first state some recipe
    passes through (the earliest-made node, which `complete` retrieval would pick). O(candidates).
    """
    for kind, keep in (("dish", [c for c in goal.candidates if c in foon.dishes]),
                       ("final product", [c for c in goal.candidates if c not in foon.consumers])):
        if keep and len(keep) < len(goal.candidates):
            others = tuple(c for c in goal.candidates if c not in keep)
            return Goal(goal.spec, tuple(keep), goal.level, kind, others)
        if keep:
            return goal
    return replace(goal, preferred="any") if len(goal.candidates) > 1 else goal


def resolve_goal(spec: GoalSpec, foon: Foon, level: int | None = None, *, listing: str = "foon2pddl goals") -> Goal:
    """The produced nodes of `foon` (at its level) that match `spec`.

    Raises UsageError naming close labels when nothing matches, and `listing`, the command that lists this
    network's goals (another network kind's view names its `--network`).
    """
    level = foon.level if level is None else level
    same_label = [n for n in foon.produced_by_label.get(spec.label, ()) if not is_auxiliary(n)]
    if not same_label:
        close = label_hints(spec.label, foon)
        hint = f"; close matches: {', '.join(close)}" if close else ""
        hint += f"; `{listing}` lists every goal"
        if any(n.label == spec.label for n in foon.nodes):
            raise UsageError(f"no unit produces {spec.label!r} (it only occurs as an input){hint}")
        raise UsageError(f"unknown object label {spec.label!r}{hint}")
    if spec.states is None:
        return prefer_dishes(Goal(spec, tuple(sorted(same_label)), level), foon)
    want = project_node(make_node(spec.label, spec.states), level).states
    found = [n for n in same_label if n.states == want]
    if not found:
        wanted = set(want)
        found = [n for n in same_label if wanted <= set(n.states)]
    if not found:
        known = sorted({", ".join(s.describe() for s in n.states) for n in same_label})
        raise UsageError(
            f"no produced {spec.label!r} node is in states {spec.describe()!r}; {state_hints(want, same_label)}"
            "produced states include: " + first_of(known, 8, lambda k: f"({k})"),
        )
    return Goal(spec, tuple(sorted(found)), level)
