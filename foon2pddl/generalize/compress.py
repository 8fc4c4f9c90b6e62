"""FOON-GEN: every object label replaced by its category, duplicate units removed.

Each label (node label, related object, ingredient) becomes the one category
`CategoryIndex.choose` gives it (the most specific listing it, first in file
order on ties); a label in no category stays as it is. Units that become
identical are merged (`model.dedupe.dedupe_units`, provenance joined). A kitchen and a
goal are abstracted the same way, so native retrieval runs unchanged on GEN.
Two objects of one category in one unit become one node or ingredient: the
compression the seed paper reports, and why `pddl/encode_lifted.py` keeps concrete
objects as typed parameters instead. A name a node uses for an object of its unit under
another word (`butter (in [pan])` beside the `cooking pan`) takes that object's category
when it has none of its own (`readings.py`); kitchen and goal nodes are read the same.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from ..model.constraints import node_labels
from ..model.containment import is_auxiliary
from ..model.dedupe import dedupe_units
from ..model.foon import Foon, ObjectNode, make_state
from ..model.goal import Goal, GoalSpec, prefer_dishes, spec_of_node
from ..model.kitchen import Kitchen
from .categories import CategoryIndex
from .readings import node_readings
from .substitute import node_mapping, substitute_node, substitute_unit, unit_labels


def category_map(labels: Iterable[str], index: CategoryIndex) -> dict[str, str]:
    """Label -> chosen category, for the labels that have one."""
    out = {}
    for label in labels:
        cat = index.choose(label)
        if cat is not None:
            out[label] = cat
    return out


@dataclass(frozen=True)
class Compression:
    """The generalized network, the label mapping used, the size before, and the names nodes use read as
    their unit's object (`names`: node -> {name: category}; `readings`: `FILE:LINE: pan read as cooking pan,
    so cookware`, sorted)."""

    foon: Foon
    mapping: dict[str, str]
    original_units: int
    names: dict[ObjectNode, dict[str, str]]
    readings: tuple[str, ...] = ()

    @property
    def removed_units(self) -> int:
        return self.original_units - len(self.foon.units)


def compress(foon: Foon, index: CategoryIndex) -> Compression:
    """FOON-GEN of `foon` at its level."""
    labels = set()
    for u in foon.units:
        labels |= unit_labels(u)
    mapping = category_map(sorted(labels), index)
    names, readings = node_readings(foon.units, mapping)
    units = dedupe_units(substitute_unit(u, mapping, per_node=names) for u in foon.units)
    return Compression(Foon(units, foon.level), mapping, len(foon.units), names, readings)


def abstract_kitchen(kitchen: Kitchen, index: CategoryIndex,
                     names: Mapping[ObjectNode, Mapping[str, str]] | None = None) -> Kitchen:
    """The kitchen with every object replaced by its category (nodes that coincide merge); a node of the
    network also with the names its units read (`names`, `Compression.names`)."""
    labels = set().union(*(node_labels(n) for n in kitchen.nodes)) - {""}
    mapping = category_map(sorted(labels), index)
    return Kitchen(frozenset(abstract_node(n, mapping, names) for n in kitchen.nodes), kitchen.level,
                   kitchen.source)


def abstract_node(node: ObjectNode, mapping: Mapping[str, str],
                  names: Mapping[ObjectNode, Mapping[str, str]] | None = None) -> ObjectNode:
    """`node` with its labels replaced by `mapping` (label -> category) and its own `names`, as FOON-GEN
    reads it in its units."""
    return substitute_node(node, node_mapping(node, mapping, names))


def abstract_goal(spec: GoalSpec, index: CategoryIndex) -> GoalSpec:
    """The goal with its object and the objects its states mention replaced by categories."""
    def gen(label: str) -> str:
        return index.choose(label) or label

    if spec.states is None:
        return GoalSpec(gen(spec.label))
    states = {make_state(s.label, gen(s.related) if s.related else "", (gen(i) for i in s.ingredients))
              for s in spec.states}
    return GoalSpec(gen(spec.label), tuple(sorted(states)))


def category_goal(spec: GoalSpec, foon: Foon, index: CategoryIndex) -> Goal | None:
    """A goal naming a category (`beverages`, as `goals --network gen` lists FOON-GEN's goals) read on
    the concrete network: the produced nodes whose label generalizes to it (`CategoryIndex.choose`)
    and whose category image is in the given states (equal states if any node has them, else a
    superset, as `resolve_goal`); a bare category means its dishes (`prefer_dishes`, as a bare label does).
    None when the label is no category or no node matches."""
    if not index.is_category(spec.label):
        return None
    nodes = sorted(n for label, made in foon.produced_by_label.items() if index.choose(label) == spec.label
                   for n in made if not is_auxiliary(n))
    if not nodes:
        return None
    if spec.states is None:
        return prefer_dishes(Goal(spec, tuple(nodes), foon.level), foon)
    want = set(spec.states)
    images = {n: set(abstract_goal(spec_of_node(n), index).states or ()) for n in nodes}
    nodes = [n for n in nodes if images[n] == want] or [n for n in nodes if want <= images[n]]
    return Goal(spec, tuple(nodes), foon.level) if nodes else None
