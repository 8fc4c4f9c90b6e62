"""Which units of the concrete network can matter for a lifted FOON-GEN goal: the image network.

`relevant` judges on an image of the network in which every object of a top-level
category that some parameter belongs to is replaced by that category (see its
doc). The image network and its reachability from the kitchen's image depend on
the network, kitchen and generalization policy only, so `coarse_network` builds
them once and `shared_coarse` keeps the last few: every goal of an experiment
trial shares one (the lifted encoding spent ~90 % of its time rebuilding it).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from ..analysis.reachability import UNREACHED, reachable
from ..model.constraints import node_labels
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from .categories import CategoryIndex
from .substitute import substitute_node, substitute_unit, unit_labels


def input_labels(unit: FunctionalUnit) -> frozenset[str]:
    """Labels mentioned by the unit's input nodes (labels, related objects, ingredients)."""
    return unit_labels(FunctionalUnit(unit.inputs, unit.motion, ()))


class Ordering:
    """The argument order of node atoms: (top-level category, label) of each object."""

    def __init__(self, index: CategoryIndex) -> None:
        self.index = index
        self._root: dict[str, str] = {}

    def root(self, label: str) -> str:
        found = self._root.get(label)
        if found is None:
            cat = self.index.choose(label)
            found = "" if cat is None else ((self.index.ancestors(cat) or (cat,))[-1])
            self._root[label] = found
        return found

    def key(self, label: str) -> tuple[str, str]:
        return (self.root(label), label)



@dataclass(frozen=True)
class Coarse:
    """The image network of `relevant` for one network, kitchen and policy: what every goal shares."""

    roots: frozenset[str]
    reach: object  # analysis.reachability result on the image network
    producers: dict[int, list[int]]  # image node id -> units with it among their outputs

    def image(self, label: str, ordering: Ordering) -> str:
        root = ordering.root(label)
        return root if root in self.roots else label


def coarse_network(foon: Foon, kitchen: frozenset[ObjectNode], generalize: Callable[[str], bool],
                   index: CategoryIndex, ordering: Ordering) -> Coarse:
    """The image network and its reachability from the kitchen's image (see `relevant`); O(network)."""
    roots = frozenset(ordering.root(x) for u in foon.units for x in input_labels(u)
                      if index.choose(x) is not None and generalize(x))
    coarse = Coarse(roots, None, {})
    labels = {x for u in foon.units for x in unit_labels(u)} | {x for n in kitchen for x in node_labels(n)}
    mapping = {x: coarse.image(x, ordering) for x in labels}
    images = [substitute_unit(u, mapping) for u in foon.units]
    reach = reachable(Foon(tuple(images), foon.level), frozenset(substitute_node(n, mapping) for n in kitchen))
    producers: dict[int, list[int]] = {}  # image node -> units making a concrete node of that image: an image
    for u, unit in enumerate(foon.units):  # unit that outputs one of its inputs may still make a new concrete node
        made = {substitute_node(n, mapping) for n in unit.outputs if n not in unit.inputs}
        for n in sorted(reach.index.ids(made)):
            producers.setdefault(n, []).append(u)
    return Coarse(roots, reach, producers)


def relevant(foon: Foon, kitchen: frozenset[ObjectNode], candidates: Iterable[ObjectNode],
             generalize: Callable[[str], bool], index: CategoryIndex, ordering: Ordering,
             coarse: Coarse | None = None) -> list[int]:
    """Indexes of the units that can matter for making a candidate from the kitchen.

    Judged on an image of the network: every object of a top-level category that some
    parameter belongs to is replaced by that category. A grounded action binds a
    parameter to an object of a subtype of its type, hence of the same top-level
    category, so its nodes have the image of its unit's nodes, and the image network
    over-approximates the lifted task: a unit whose image does not fire from the
    kitchen's image, or outputs no image needed for a candidate's image, is never
    part of a plan. A unit counts as a maker of the images of the concrete nodes it
    makes (outputs that are not among its inputs): an image unit may output one of its
    own inputs and still make a new concrete node, but an object the unit keeps (the
    same node in and out, a knife) stays the same node under every binding, since a
    binding substitutes inputs and outputs alike, so the unit is never the first to
    add its atom and is not kept for it (in a delete-free plan, what a step adds
    that its precondition already holds is no help). The image
    network (`coarse`) depends on the goal only through the candidates' images, so
    it is built once per network, kitchen and policy and shared by every goal.
    """
    candidates = tuple(candidates)
    coarse = coarse or coarse_network(foon, kitchen, generalize, index, ordering)
    ix = coarse.reach.index
    mapping = {x: coarse.image(x, ordering) for n in candidates for x in node_labels(n)}
    needed = set(ix.ids(substitute_node(c, mapping) for c in candidates))
    stack = list(needed)
    keep: set[int] = set()
    while stack:
        n = stack.pop()
        for u in coarse.producers.get(n, ()):
            if coarse.reach.unit_round[u] != UNREACHED and u not in keep:
                keep.add(u)
                for i in ix.inputs[u]:
                    if i not in needed:
                        needed.add(i)
                        stack.append(i)
    return sorted(keep)


#: Image networks of the last few (network, level, kitchen, policy, index): every goal of a trial shares one.
_COARSE: dict[tuple, tuple[Foon, CategoryIndex, Coarse]] = {}


_COARSE_KEPT = 4


def shared_coarse(foon: Foon, level: int, kitchen: frozenset[ObjectNode], policy: str, index: CategoryIndex,
                   build: Callable[[], Coarse]) -> Coarse:
    key = (id(foon), level, kitchen, policy, id(index))
    hit = _COARSE.get(key)
    if hit is not None and hit[0] is foon and hit[1] is index:
        return hit[2]
    coarse = build()
    if len(_COARSE) >= _COARSE_KEPT:
        _COARSE.pop(next(iter(_COARSE)))
    _COARSE[key] = (foon, index, coarse)
    return coarse
