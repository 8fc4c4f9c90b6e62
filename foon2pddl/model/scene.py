"""Scene kitchens: physical objects with ids, as a robot's perception gives them, and where each one is.

A scene (docs/scene.md, `io.scene_file`) lists objects: an `id`, a FOON `label`, `states`, and the id of
the object it is `in` or `on`. As a kitchen it is its objects' nodes, each counted (`Kitchen.counts`:
how many objects are in that node), plus the objects themselves (`Kitchen.scene`), which the `relational`
encoding takes as its `:init`; other encodings read only the nodes and counts.

An object's FOON node (`place_scene`, read against the network) is its label and states, plus:

* its place `in [C]` / `on [C]` (C the holder's label) when some node of the network places an object of
  its label in or on a C (`heavy cream (in [carton])`); a holder FOON never names for the label (the fridge
  the onion is in, the counter under the bowl) is where the object is, not part of its FOON state;
* for a holder of objects whose node names it (a carton of cream, a board with the avocado on it),
  `contains {their labels}`, unless its states already say what it holds; `empty` then is a contradiction
  (`SceneProblem`).

O(objects + network nodes).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from .foon import ObjectNode, make_node, make_state
from .physical import Relation
from .places import CONTENT_STATES, place_state

__all__ = ["SceneObject", "SceneProblem", "place_scene", "placed_labels"]


@dataclass(frozen=True, order=True)
class SceneObject:
    """One object of a scene: its `id`, FOON `label`, FOON `node` (label and states), the id of its `holder`
    and how it rests there (`relation`; both None: it stands free), and the `line` of the file it is on."""

    id: str
    label: str
    node: ObjectNode
    holder: str | None = None
    relation: Relation | None = None
    line: int = 0

    def __post_init__(self) -> None:
        if (self.holder is None) != (self.relation is None):
            raise ValueError(f"{self.id}: a holder needs a relation and a relation a holder")
        if self.holder == self.id:
            raise ValueError(f"{self.id} cannot hold itself")


class SceneProblem(ValueError):
    """A scene that contradicts itself once read against a network; `obj` is the object it is about."""

    def __init__(self, obj: SceneObject, message: str) -> None:
        super().__init__(message)
        self.obj = obj


def placed_labels(nodes: Iterable[ObjectNode]) -> frozenset[tuple[str, Relation, str]]:
    """(object label, relation, holder label) for every place a node names (`heavy cream (in [carton])`)."""
    return frozenset((n.label, *p) for n in nodes for s in n.states if (p := place_state(s)) is not None)


def place_scene(objects: Iterable[SceneObject], network_nodes: Iterable[ObjectNode]) -> tuple[SceneObject, ...]:
    """The scene's objects with their FOON nodes completed against the network (module doc), in id order.

    Raises SceneProblem for a holder whose states say `empty` while an object whose node names it is in it.
    """
    objs = sorted(objects)
    by_id = {o.id: o for o in objs}
    known = placed_labels(network_nodes)
    placed: dict[str, SceneObject] = {}
    held: dict[str, list[str]] = {}
    for o in objs:
        if o.holder is None:
            placed[o.id] = o
            continue
        holder = by_id[o.holder]
        if (o.label, o.relation, holder.label) in known:
            node = make_node(o.label, (*o.node.states, make_state(o.relation.value, holder.label)))
            placed[o.id] = replace(o, node=node)
            held.setdefault(o.holder, []).append(o.label)
        else:
            placed[o.id] = o
    for hid, items in held.items():
        h = placed[hid]
        said = [s for s in h.node.states if s.label in CONTENT_STATES]
        if any(s.label == "empty" for s in said):
            what = ", ".join(sorted(x.id for x in objs if x.holder == hid and x.label in items))
            raise SceneProblem(h, f"{hid} is `empty`, but {what} is in or on it")
        if not said:
            placed[hid] = replace(h, node=make_node(h.label, (*h.node.states, make_state("contains", "", items))))
    return tuple(placed[o.id] for o in objs)
