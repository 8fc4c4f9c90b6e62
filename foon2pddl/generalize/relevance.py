"""Which units of the concrete network can matter for a lifted FOON-GEN goal, and the atoms' argument order.

`relevant` walks back from a goal over the lifted network's reachable ground instances
(`grounding.ground`; on an image network, `image_relevant`, when they are too many to
find). Those depend on the network, kitchen and generalization policy only, so
`shared_grounding` keeps the last few: every goal of an experiment trial shares one
(rebuilding them per goal would dominate the lifted encoding's time).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from ..analysis.reachability import UNREACHED, reachable, walk_back
from ..model.constraints import node_labels
from ..model.foon import Foon, ObjectNode
from .categories import CategoryIndex
from .grounding import Grounded, unit_params
from .substitute import substitute_node, substitute_unit, unit_labels


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



def relevant(foon: Foon, kitchen: frozenset[ObjectNode], candidates: Iterable[ObjectNode],
             generalize: Callable[[str], bool], index: CategoryIndex, grounded: Grounded | None) -> list[int]:
    """Indexes of the units that can matter for making a candidate from the kitchen, sorted.

    Relevance over the lifted task's reachable ground instances `grounded` (`grounding.ground`, built
    once per network, kitchen and policy and shared by every goal: `shared_grounding`), as
    `pddl.prune.prune_task` prunes a ground task: backwards from the candidates over the instances that
    make a node (an output that is not among their inputs: what a step keeps is no help in a delete-free
    plan), their inputs needed in turn, not past kitchen nodes (`reachability.walk_back`). A unit is kept
    when one of its instances is. Sound: every step of a plan is a reachable instance, and a plan keeps
    a valid sub-plan made of relevant ones. O(instances + their nodes) per goal. When there were too
    many instances to find (`grounded` is None), `image_relevant` decides.
    """
    candidates = tuple(candidates)
    if grounded is None:
        return image_relevant(foon, kitchen, candidates, generalize, index)
    ids = [grounded.node_id[c] for c in candidates if c in grounded.node_id]
    instances = walk_back(grounded.makers, grounded.inputs, ids, bytearray(grounded.kitchen))
    return sorted({grounded.units[i] for i in instances})


def image_relevant(foon: Foon, kitchen: frozenset[ObjectNode], candidates: tuple[ObjectNode, ...],
                   generalize: Callable[[str], bool], index: CategoryIndex) -> list[int]:
    """The units `relevant` keeps judged on an image of the network, for policies whose instances are too many.

    Each object whose category is, or refines, a parameter's category is replaced by the outermost such
    category. A parameter binds objects of its category or of one refining it, all with the parameter's
    own image, so every ground instance has its unit's image, and a unit whose image does not fire from
    the kitchen's image, or makes no image needed for a candidate's, is in no plan. Needed images are not
    cut at the kitchen's (a needed node may share its image with a kitchen node without being one).
    Weaker than the ground relevance; O(network) per goal.
    """
    params = {cat for u in foon.units for cat in unit_params(u, generalize, index).values()}

    def image(label: str) -> str:
        cat = index.choose(label)
        return label if cat is None else next((c for c in (*reversed(index.ancestors(cat)), cat) if c in params),
                                              label)

    labels = set().union(*map(unit_labels, foon.units), *map(node_labels, (*kitchen, *candidates)))
    mapping = {x: y for x in labels if (y := image(x)) != x}
    reach = reachable(Foon(tuple(substitute_unit(u, mapping) for u in foon.units), foon.level),
                      frozenset(substitute_node(n, mapping) for n in kitchen))
    ix = reach.index
    makers: list[list[int]] = [[] for _ in ix.nodes]
    for u, unit in enumerate(foon.units):
        if reach.unit_round[u] != UNREACHED:
            for n in ix.ids({substitute_node(n, mapping) for n in unit.outputs if n not in unit.inputs}):
                makers[n].append(u)
    targets = ix.ids(substitute_node(c, mapping) for c in candidates)
    return sorted(walk_back(makers, ix.inputs, targets, bytearray(len(ix.nodes))))


#: Ground instances of the last few (network, level, kitchen, policy, index): every goal of a trial shares one.
_GROUNDED: dict[tuple, tuple[Foon, CategoryIndex, Grounded | None]] = {}


_GROUNDED_KEPT = 4


def shared_grounding(foon: Foon, level: int, kitchen: frozenset[ObjectNode], policy: str, index: CategoryIndex,
                     build: Callable[[], Grounded | None]) -> Grounded | None:
    """`build()`, or the instances built last time for the same network object, level, kitchen, policy and index."""
    key = (id(foon), level, kitchen, policy, id(index))
    hit = _GROUNDED.get(key)
    if hit is not None and hit[0] is foon and hit[1] is index:
        return hit[2]
    grounded = build()
    if len(_GROUNDED) >= _GROUNDED_KEPT:
        _GROUNDED.pop(next(iter(_GROUNDED)))
    _GROUNDED[key] = (foon, index, grounded)
    return grounded
