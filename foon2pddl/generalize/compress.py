"""FOON-GEN: every object label replaced by its category, duplicate units removed.

Each label (node label, related object, ingredient) becomes the one category
`CategoryIndex.choose` gives it (the most specific listing it, first in file
order on ties); a label in no category stays as it is. Units that become
identical are merged (`model.foon.dedupe_units`, provenance joined). A kitchen and a
goal are abstracted the same way, so native retrieval runs unchanged on GEN.
Two objects of one category in one unit become one node or ingredient: the
compression the seed paper reports, and why `pddl/encode_lifted.py` keeps concrete
objects as typed parameters instead.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ..model.constraints import node_labels
from ..model.containment import is_auxiliary
from ..model.foon import Foon, dedupe_units, make_state
from ..model.goal import Goal, GoalSpec, spec_of_node
from ..model.kitchen import Kitchen
from .categories import CategoryIndex
from .substitute import substitute_node, substitute_unit, unit_labels


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
    """The generalized network, the label mapping used and the size before."""

    foon: Foon
    mapping: dict[str, str]
    original_units: int

    @property
    def removed_units(self) -> int:
        return self.original_units - len(self.foon.units)


def compress(foon: Foon, index: CategoryIndex) -> Compression:
    """FOON-GEN of `foon` at its level."""
    labels = set()
    for u in foon.units:
        labels |= unit_labels(u)
    mapping = category_map(sorted(labels), index)
    units = dedupe_units(substitute_unit(u, mapping) for u in foon.units)
    return Compression(Foon(units, foon.level), mapping, len(foon.units))


def abstract_kitchen(kitchen: Kitchen, index: CategoryIndex) -> Kitchen:
    """The kitchen with every object replaced by its category (nodes that coincide merge)."""
    labels = set().union(*(node_labels(n) for n in kitchen.nodes)) - {""}
    mapping = category_map(sorted(labels), index)
    return Kitchen(frozenset(substitute_node(n, mapping) for n in kitchen.nodes), kitchen.level, kitchen.source)


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
    superset, as `resolve_goal`). None when the label is no category or no node matches."""
    if not index.is_category(spec.label):
        return None
    nodes = sorted(n for label, made in foon.produced_by_label.items() if index.choose(label) == spec.label
                   for n in made if not is_auxiliary(n))
    if spec.states is not None:
        want = set(spec.states)
        images = {n: set(abstract_goal(spec_of_node(n), index).states or ()) for n in nodes}
        nodes = [n for n in nodes if images[n] == want] or [n for n in nodes if want <= images[n]]
    return Goal(spec, tuple(nodes), foon.level) if nodes else None
