"""The three networks an experiment compares, each with how it sees a kitchen and a goal.

REG is the network as read; EXP is FOON-EXP (`generalize.expand`, threshold
0.89) and sees the same kitchen and goal; GEN is FOON-GEN (`generalize.compress`)
and sees them abstracted through the shipped category index. Every view is at
the protocol's hierarchy level and keeps the concrete REG network beside it
(the lifted GEN planner plans over the concrete network with category types).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..goals import Goal, spec_of_node
from ..kitchen import Kitchen
from ..model import Foon, ObjectNode

NETWORKS = ("reg", "exp", "gen")


@dataclass(frozen=True, eq=False)
class NetworkView:
    """A network to search, with the maps from concrete trial inputs to its nodes."""

    name: str
    foon: Foon
    concrete: Foon
    index: Any = None  # GEN: the CategoryIndex
    mapping: dict[str, str] | None = None  # GEN: label -> category

    def kitchen(self, kitchen: Kitchen) -> Kitchen:
        """The trial's (concrete) kitchen as this network sees it."""
        if self.index is None:
            return kitchen
        from ..generalize.compress import abstract_kitchen

        return abstract_kitchen(kitchen, self.index)

    def goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node`, as this network sees it."""
        if self.index is None:
            return Goal(spec_of_node(node), (node,), self.foon.level)
        from ..generalize.compress import abstract_goal
        from ..generalize.substitute import substitute_node

        spec = abstract_goal(spec_of_node(node), self.index)
        mapping = {label: cat for label in _labels(node) if (cat := self.index.choose(label)) is not None}
        return Goal(spec, (substitute_node(node, mapping),), self.foon.level)

    def concrete_goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node` on the concrete network."""
        return Goal(spec_of_node(node), (node,), self.concrete.level)


def _labels(node: ObjectNode) -> set[str]:
    return {node.label} | {x for s in node.states for x in (s.related, *s.ingredients) if x}


def build_view(name: str, reg: Foon) -> NetworkView:
    """The view `name` (reg, exp or gen) of the REG network `reg` (already at the protocol's level)."""
    if name == "reg":
        return NetworkView("reg", reg, reg)
    if name == "exp":
        from ..generalize.expand import expand

        return NetworkView("exp", expand(reg).foon, reg)
    if name == "gen":
        from ..generalize.categories import shipped_index
        from ..generalize.compress import compress

        index = shipped_index()
        compression = compress(reg, index)
        return NetworkView("gen", compression.foon, reg, index, compression.mapping)
    raise ValueError(f"unknown network {name!r} (expected one of {', '.join(NETWORKS)})")
