"""Kitchens: the object nodes available before any unit runs.

Three file formats are read (FOON-style O/S lines, the JSON convention of public
FOON search projects, and one goal-syntax node per line), and a network's
default kitchen is derived by the rule documented in `default_kitchen`.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from itertools import chain

from .bulk import bulk
from .foon import Foon, ObjectNode
from .levels import project_node
from .memo import per_network
from .node_table import NodeTable, first_objects
from .scene import SceneObject
from .words import count

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
    #: a scene kitchen's objects with ids (`model.scene`; their nodes and counts are `nodes` and `counts`)
    scene: tuple[SceneObject, ...] = ()
    #: the line of its file that first lists each node (a file's kitchen; a scene's are its objects'): for messages
    lines: tuple[tuple[ObjectNode, int], ...] = field(default=(), compare=False, repr=False)
    #: the nodes among `counts` whose count restoring units set (`pddl.restore.with_restore`), not the kitchen's own:
    #: for the notes that say who gave a count
    restored: frozenset[ObjectNode] = field(default=frozenset(), compare=False, repr=False)

    def __contains__(self, node: object) -> bool:
        return node in self.nodes

    def __repr__(self) -> str:
        """Counts and a few nodes: the dataclass repr of a kitchen lists hundreds of nodes."""
        shown = sorted(n.describe() for n in self.nodes)
        head = ", ".join(shown[:3]) + (", ..." if len(shown) > 3 else "")
        source = f" from {self.source}" if self.source else ""
        counted = f", {len(self.counts)} counted" if self.counts else ""
        return f"<Kitchen level {self.level}: {count(len(self.nodes), 'node')}{counted}{source} ({head})>"

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
        restored = frozenset(project_node(n, level) for n in self.restored)  # who gave a count (`with_restore`)
        if self.scene:
            return replace(scene_kitchen([replace(o, node=project_node(o.node, level)) for o in self.scene],
                                         self.source, level), restored=restored)
        lines = first_lines((project_node(n, level), line) for n, line in self.lines)  # merged nodes: the first
        return Kitchen(frozenset(project_node(n, level) for n in self.nodes), level, self.source,
                       tuple(sorted(counts.items())), lines=tuple(sorted(lines.items())), restored=restored)

    def line_numbers(self) -> dict[ObjectNode, int]:
        """Node -> the line of the kitchen's file that first lists it (nodes not read from a file line: absent)."""
        return first_lines(((o.node, o.line) for o in self.scene) if self.scene else self.lines)

    def stated_counts(self) -> dict[ObjectNode, int]:
        """Node -> instance count for the nodes whose count the kitchen states."""
        return dict(self.counts)

    def holder_nodes(self) -> frozenset[ObjectNode]:
        """The nodes of a scene's objects that hold something (the fridge, the counter); empty for other kitchens."""
        held = {o.holder for o in self.scene}
        return frozenset(o.node for o in self.scene if o.id in held)

    def sorted_nodes(self) -> list[ObjectNode]:
        """Nodes in a stable order (for writing and display)."""
        return sorted(self.nodes)


def first_lines(pairs: Iterable[tuple[ObjectNode, int]]) -> dict[ObjectNode, int]:
    """Node -> the smallest of its lines among (node, line) `pairs`: the first line of a file that lists it (nodes a
    level merges, or a scene's objects of one node). O(pairs)."""
    lines: dict[ObjectNode, int] = {}
    for node, line in pairs:
        lines[node] = min(line, lines.get(node, line))
    return lines


def scene_kitchen(objects: Iterable[SceneObject], source: str = "", level: int = 3) -> Kitchen:
    """The kitchen of a scene's objects: their nodes, each counted by how many objects are in it."""
    objs = tuple(sorted(objects))
    counts: dict[ObjectNode, int] = {}
    for o in objs:
        counts[o.node] = counts.get(o.node, 0) + 1
    return Kitchen(frozenset(counts), level, source, tuple(sorted(counts.items())), objs)


@bulk
def starting_nodes(foon: Foon) -> frozenset[ObjectNode]:
    """Input nodes that no unit creates (a unit that passes a node through unchanged does not create it)."""
    table = foon.table
    return frozenset(map(_input_objects(foon).__getitem__, _input_ids(table) - _created_ids(table)))


def _input_objects(foon: Foon) -> dict[int, ObjectNode]:
    """Node number -> the first object a unit lists for it as input (the one a set of input nodes keeps)."""
    return first_objects(foon.units, foon.table.inputs, "inputs")


def _input_ids(table: NodeTable) -> set[int]:
    return set(chain.from_iterable(table.inputs))


def _created_ids(table: NodeTable) -> set[int]:
    """Numbers of the nodes some unit outputs without having it among its inputs."""
    return {o for ins, outs in zip(table.inputs, table.outputs, strict=True) for o in outs if o not in ins}


def default_kitchen(foon: Foon, base_states: Iterable[str] = BASE_STATES) -> Kitchen:
    """Starting nodes plus every input node whose states are all base states (built once per network
    for the default base states)."""
    if base_states is BASE_STATES:
        return _default_kitchen(foon)
    return _kitchen_of(foon, frozenset(base_states))


@per_network
def _default_kitchen(foon: Foon) -> Kitchen:
    return _kitchen_of(foon, BASE_STATES)


@bulk
def _kitchen_of(foon: Foon, base: frozenset[str]) -> Kitchen:
    table = foon.table
    nodes = _input_objects(foon)
    inputs = _input_ids(table)  # each distinct node checked once
    extra = {i for i in inputs if nodes[i].states and is_base_node(nodes[i], base)}
    ids = (inputs - _created_ids(table)) | extra
    return Kitchen(frozenset(map(nodes.__getitem__, ids)), foon.level, "default kitchen")


#: `--kitchen` values naming a kitchen built from the network instead of a file.
BASE_KITCHEN = "base"
DEFAULT_KITCHEN = "default"
#: `Kitchen.source` of a base kitchen.
BASE_SOURCE = "base kitchen"


def _placed(node: ObjectNode) -> bool:
    """Whether the node sits in or holds something: a state naming another object, or an ingredient set."""
    return any(s.related or s.ingredients for s in node.states)


def _drawn(node: ObjectNode) -> bool:
    """Whether a state says where the node was drawn from (`from [faucet]`, `from faucet`)."""
    return any(s.label == "from" or s.label.startswith("from ") for s in node.states)


def created_labels(foon: Foon, kitchen: Kitchen | None = None) -> frozenset[str]:
    """Labels some unit makes out of other objects: an output's label that none of the unit's inputs has
    as label or as ingredient (the lemon juice a squeeze outputs, a mixture; not the beans a pan of beans
    turns into) and not drawn from something (`water (from [faucet])`), less the labels `kitchen`
    (default: the default kitchen) holds loose, in no container and holding nothing: the public data
    has units that output bread or a measuring cup without listing it as an input, and a loose loaf is
    a raw ingredient. Ingredient sets of outputs are not read for the same reason (salt listed with no
    input carrying it). One pass over the units (node numbers; a unit's ingredients are read only when
    an output's label is not among its inputs' labels)."""
    kitchen = kitchen if kitchen is not None else default_kitchen(foon)
    loose = {n.label for n in kitchen.nodes if not _placed(n)}
    table = foon.table
    nodes = table.nodes
    labels = [n.label for n in nodes]
    made: set[str] = set()
    for ins, outs in zip(table.inputs, table.outputs, strict=True):
        have = {labels[i] for i in ins}
        for o in outs:
            label = labels[o]
            if label not in have and label not in made and not _drawn(nodes[o]) \
                    and not any(label in s.ingredients for i in ins for s in nodes[i].states):
                made.add(label)
    return frozenset(made - loose)


def half_made(foon: Foon, base_states: Iterable[str] = BASE_STATES,
              kitchen: Kitchen | None = None) -> frozenset[ObjectNode]:
    """The default kitchen's half-made dishes: nodes that sit in or hold something (a state naming another
    object, or an ingredient set) and that are, or hold, an object some unit of the network creates
    (`created_labels`).

    `pitcher (contains {lemon juice, water})` and `lemon juice (in [pitcher])` are half-made where a unit
    squeezes lemon juice; `milk (in [carton])` is a raw ingredient in its packaging where no unit creates
    milk. `kitchen`: the default kitchen when already built. One pass over the units, one over the kitchen;
    once per network for the default base states and kitchen.
    """
    if base_states is BASE_STATES and (kitchen is None or kitchen is _default_kitchen(foon)):
        return _default_half_made(foon)
    return _half_made(foon, kitchen if kitchen is not None else default_kitchen(foon, base_states))


@per_network
def _default_half_made(foon: Foon) -> frozenset[ObjectNode]:
    return _half_made(foon, _default_kitchen(foon))


def _half_made(foon: Foon, kitchen: Kitchen) -> frozenset[ObjectNode]:
    made = created_labels(foon, kitchen)
    return frozenset(n for n in kitchen.nodes
                     if _placed(n) and (n.label in made or any(x in made for s in n.states for x in s.ingredients)))


def base_kitchen(foon: Foon, base_states: Iterable[str] = BASE_STATES) -> Kitchen:
    """Raw ingredients and tools in their base states: the default kitchen without its half-made
    dishes (`half_made`), so retrieval on a merged network starts from scratch rather than from
    another recipe's pitcher of juice."""
    full = default_kitchen(foon, base_states)
    return Kitchen(full.nodes - half_made(foon, base_states, full), foon.level, BASE_SOURCE)


def chosen_kitchen(foon: Foon) -> Kitchen:
    """The kitchen of a run that names none: the base kitchen on a network of several recipes (its
    units mark more than one dish; a FOON recipe file marks one) whose default kitchen holds half-made
    dishes, else the default kitchen. In a merge one recipe's starting point is another's middle; a
    single recipe's starting nodes are what its author started from, so there nothing changes."""
    full = default_kitchen(foon)
    half = half_made(foon, kitchen=full) if len(foon.dishes) > 1 else frozenset()
    return Kitchen(full.nodes - half, foon.level, BASE_SOURCE) if half else full


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


def unmatched_items(nodes: Iterable[ObjectNode], foon: Foon, limit: int = 10,
                    lines: dict[ObjectNode, int] | None = None) -> tuple[list[tuple[int, str]], int]:
    """Kitchen nodes that are no node of `foon` (same level): (line, message with hints) for the first
    `limit`, in the order of their `lines` in the kitchen's file (0: no line), then of the nodes, and how
    many there are in all. Such items can never be used; most are typos.
    """
    known, at = set(foon.nodes), lines or {}
    stray = sorted((at.get(n, 0), n) for n in nodes if n not in known)
    messages = []
    for line, n in stray[:limit]:
        hints = node_hints(n, foon)
        close = f"; close: {'; '.join(f'`{h}`' for h in hints)}" if hints else ""
        messages.append((line, f"kitchen item `{_goal_syntax(n)}` matches no node of the network{close}"))
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
    return Kitchen(kitchen.nodes | extra, kitchen.level, kitchen.source, kitchen.counts, kitchen.scene)
