"""Atoms of the lifted FOON-GEN encoding: a node is one atom whose predicate is its *shape*.

A node's shape is its states with the objects they mention replaced by argument
positions; the atom's arguments are the node's object, then the objects its
states mention, ordered by (top-level category, label) (`generalize.relevance.Ordering`). An atom
determines its node (`node_of`); `representations` lists every atom that
reconstructs a node under the shapes some action needs (objects of one
top-level category in any order, as a grounded action may order them differently).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from ..generalize.relevance import Ordering
from ..model.constraints import node_labels
from ..model.foon import ObjectNode, make_node, make_state

__all__ = ["MAX_REPRESENTATIONS", "Family", "Shape", "family_label", "node_atom_labels", "node_of", "representations", "shape_label",
           "shape_with"]

#: Most atoms written for one kitchen node or goal candidate (orderings of same-category objects).
MAX_REPRESENTATIONS = 24

# A node shape: arity, then per state (label, related position or -1, ingredient positions).
Shape = tuple[int, tuple[tuple[str, int, tuple[int, ...]], ...]]

#: A predicate of node atoms: a shape and the objects at its fixed positions ((position, label), sorted).
Family = tuple[Shape, tuple[tuple[int, str], ...]]


def shape_with(node: ObjectNode, order: list[str]) -> Shape:
    """The shape of `node` when its mentioned labels take positions 1.. in `order`."""
    pos = {node.label: 0, **{label: i for i, label in enumerate(order, start=1)}}
    states = tuple(sorted((s.label, pos[s.related] if s.related else -1, tuple(sorted(pos[i] for i in s.ingredients)))
                          for s in node.states))
    return (len(order) + 1, states)


def node_atom_labels(node: ObjectNode, ordering: Ordering) -> tuple[Shape, tuple[str, ...]]:
    """The canonical (shape, argument labels) of `node`."""
    order = sorted(node_labels(node) - {node.label}, key=ordering.key)
    return shape_with(node, order), (node.label, *order)


def representations(node: ObjectNode, ordering: Ordering, shapes: set[Shape]) -> list[tuple[Shape, tuple[str, ...]]]:
    """Every (shape in `shapes`, argument labels) that reconstructs `node`, same-category objects in any order."""
    order = sorted(node_labels(node) - {node.label}, key=ordering.key)
    groups = [list(g) for _, g in itertools.groupby(order, key=ordering.root)]
    out: list[tuple[Shape, tuple[str, ...]]] = []
    for combo in itertools.islice(_orderings(groups), MAX_REPRESENTATIONS):
        labels = [x for part in combo for x in part]
        shape = shape_with(node, labels)
        if shape in shapes:
            out.append((shape, (node.label, *labels)))
    return out


def _orderings(groups: list[list[str]]) -> Iterator[tuple[tuple[str, ...], ...]]:
    """One permutation per group, in `itertools.product`'s order (the last group varies fastest), lazily:
    `product` first reads every input to its end, and the permutations of a group of 12 same-category labels
    are 479 million tuples (a worker of the test suite grew to 24 GB on one such node)."""
    if not groups:
        yield ()
        return
    for first in itertools.permutations(groups[0]):
        for rest in _orderings(groups[1:]):
            yield (first, *rest)


def node_of(shape: Shape, labels: tuple[str, ...]) -> ObjectNode:
    """The node an atom of `shape` with argument `labels` stands for."""
    states = [make_state(s, labels[r] if r >= 0 else "", (labels[i] for i in ings)) for s, r, ings in shape[1]]
    return make_node(labels[0], states)


def shape_label(shape: Shape) -> str:
    """Readable text naming a shape (`contains {1} in [2]`), the base of its predicate name."""
    parts = []
    for s, r, ings in shape[1]:
        text = s + (f" [{r}]" if r >= 0 else "") + (" {" + " ".join(map(str, ings)) + "}" if ings else "")
        parts.append(text)
    return "node " + (", ".join(parts) if parts else "plain") + f" /{shape[0]}"


def family_label(shape: Shape, fixed: tuple[tuple[int, str], ...]) -> str:
    """Readable text naming a predicate: the node with its fixed objects, `x<k>` at argument positions
    (`x0 contains {salt x2} in [bowl]`), the base of its predicate name."""
    at = dict(fixed)

    def name(i: int) -> str:
        return at.get(i, f"x{i}")

    parts = [s + (f" [{name(r)}]" if r >= 0 else "") + (" {" + " ".join(map(name, ings)) + "}" if ings else "")
             for s, r, ings in shape[1]]
    return f"{name(0)} " + (", ".join(parts) if parts else "plain")
