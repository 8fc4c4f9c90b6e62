"""Kitchens: the object nodes available before any unit runs.

Three file formats are read (FOON-style O/S lines, the JSON convention of public
FOON search projects, and one goal-syntax node per line), and a network's
default kitchen is derived by the rule documented in `default_kitchen`.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from .bulk import bulk
from .foon import Foon, ObjectNode
from .levels import project_node

#: States an object is in before anyone touches it. An input node whose states
#: are all base states is in the default kitchen even if some unit also produces
#: it (a mixer goes off -> on -> off; without this rule `off` would never be available).
BASE_STATES: frozenset[str] = frozenset(
    {
        "off", "off (ready)", "empty", "clean", "whole", "raw", "uncooked", "uncook",
        "unpeeled", "uncracked", "closed", "sealed", "dry", "frozen", "ready",
        "solid", "liquid", "granulated", "powder", "fresh", "cold", "room temperature",
    }
)


@dataclass(frozen=True)
class Kitchen:
    """A set of available object nodes at one hierarchy level."""

    nodes: frozenset[ObjectNode]
    level: int = 3
    source: str = ""
    counts: tuple[tuple[ObjectNode, int], ...] = ()  # stated instance counts (`2 x bowl (empty)`), sorted

    def __contains__(self, node: object) -> bool:
        return node in self.nodes

    def __repr__(self) -> str:
        """Counts and a few nodes: the dataclass repr of a kitchen lists hundreds of nodes."""
        shown = sorted(n.describe() for n in self.nodes)
        head = ", ".join(shown[:3]) + (", ..." if len(shown) > 3 else "")
        source = f" from {self.source}" if self.source else ""
        counted = f", {len(self.counts)} counted" if self.counts else ""
        return f"<Kitchen level {self.level}: {len(self.nodes)} nodes{counted}{source} ({head})>"

    def __len__(self) -> int:
        return len(self.nodes)

    def project(self, level: int) -> Kitchen:
        """The kitchen as seen at `level`."""
        if level >= self.level:
            return self
        counts: dict[ObjectNode, int] = {}
        for n, k in self.counts:  # nodes that become one at `level` add up their counts
            p = project_node(n, level)
            counts[p] = counts.get(p, 0) + k
        return Kitchen(frozenset(project_node(n, level) for n in self.nodes), level, self.source,
                       tuple(sorted(counts.items())))

    def stated_counts(self) -> dict[ObjectNode, int]:
        """Node -> instance count for the nodes whose count the kitchen states."""
        return dict(self.counts)

    def sorted_nodes(self) -> list[ObjectNode]:
        """Nodes in a stable order (for writing and display)."""
        return sorted(self.nodes)


@bulk
def starting_nodes(foon: Foon) -> frozenset[ObjectNode]:
    """Input nodes that no unit creates (a unit that passes a node through unchanged does not create it)."""
    # `u.key[1]` is the unit's input set (hashed, cached by the merge): membership without
    # comparing the output with every input field by field
    created = {n for u in foon.units for n in u.outputs if n not in u.key[1]}
    return frozenset(n for u in foon.units for n in u.inputs if n not in created)


@bulk
def default_kitchen(foon: Foon, base_states: Iterable[str] = BASE_STATES) -> Kitchen:
    """Starting nodes plus every input node whose states are all base states."""
    base = frozenset(base_states)
    inputs = {n for u in foon.units for n in u.inputs}  # each distinct node checked once
    extra = {n for n in inputs if n.states and all(s.label in base and not s.related and not s.ingredients
                                                   for s in n.states)}
    return Kitchen(starting_nodes(foon) | frozenset(extra), foon.level, "default kitchen")


#: `--kitchen` values naming a kitchen built from the network instead of a file.
BASE_KITCHEN = "base"


def base_kitchen(foon: Foon, base_states: Iterable[str] = BASE_STATES) -> Kitchen:
    """Raw ingredients and tools in their base states: the default kitchen's nodes whose states mention
    no other object (no `in [x]`, no `contains {...}`), so no half-made dish (a pitcher of juice,
    seasoned beans in a pot) is on hand at the start and retrieval starts from scratch."""
    nodes = frozenset(n for n in default_kitchen(foon, base_states).nodes
                      if all(not s.related and not s.ingredients for s in n.states))
    return Kitchen(nodes, foon.level, "base kitchen")


def _goal_syntax(node: ObjectNode) -> str:
    """`onion: whole`: how a user writes the node in a kitchen or goal line."""
    return node.label + (": " + ", ".join(s.describe() for s in node.states) if node.states else "")


def node_hints(node: ObjectNode, foon: Foon, limit: int = 3) -> list[str]:
    """Network nodes (goal syntax) close to `node`, for a user who mistyped it.

    Candidates are the nodes whose label is the node's label, a label close to it
    (difflib), or a leading part of it (`onion whole` -> `onion`); among them the
    closest in goal syntax come first. Cost: one difflib pass over the labels, then over
    the few candidate nodes, so hints stay cheap on networks of thousands of nodes.
    """
    import difflib

    by_label: dict[str, list[ObjectNode]] = {}
    for n in foon.nodes:
        by_label.setdefault(n.label, []).append(n)
    words = node.label.split()
    labels = {node.label} if node.label in by_label else set()
    labels.update(" ".join(words[:i]) for i in range(1, len(words)) if " ".join(words[:i]) in by_label)
    labels.update(difflib.get_close_matches(node.label, list(by_label), n=3, cutoff=0.75))
    pool = {_goal_syntax(n): n for label in labels for n in by_label[label]}
    return difflib.get_close_matches(_goal_syntax(node), sorted(pool), n=limit, cutoff=0.0) if pool else []


def unmatched_items(nodes: Iterable[ObjectNode], foon: Foon, limit: int = 10) -> tuple[list[str], int]:
    """Kitchen nodes that are no node of `foon` (same level): a message with hints for the first
    `limit` (sorted), and how many there are in all. Such items can never be used; most are typos.
    """
    known = set(foon.nodes)
    stray = sorted(n for n in nodes if n not in known)
    messages = []
    for n in stray[:limit]:
        hints = node_hints(n, foon)
        close = f"; close: {'; '.join(f'`{h}`' for h in hints)}" if hints else ""
        messages.append(f"kitchen item `{_goal_syntax(n)}` matches no node of the network{close}")
    return messages, len(stray)


def is_base_node(node: ObjectNode, base_states: frozenset[str] = BASE_STATES) -> bool:
    """A node in no state, or only in plain base states (`knife`, `bowl (empty)`, `pot (clean)`)."""
    return all(s.label in base_states and not s.related and not s.ingredients for s in node.states)


def with_utensils(kitchen: Kitchen, foon: Foon, utensils: Iterable[str]) -> Kitchen:
    """The kitchen plus, for every utensil label it holds in any state, the network's base-state
    nodes of that label: a utensil is not consumed and is cleaned after use (docs/format.md)."""
    labels = frozenset(utensils) & {n.label for n in kitchen.nodes}
    if not labels:
        return kitchen
    extra = {project_node(n, kitchen.level) for n in foon.nodes if n.label in labels and is_base_node(n)}
    return Kitchen(kitchen.nodes | extra, kitchen.level, kitchen.source, kitchen.counts)
