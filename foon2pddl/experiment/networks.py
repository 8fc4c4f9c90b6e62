"""The three networks an experiment compares, each with how it sees a trial's kitchen and goals.

Built on `generalize.network.network_view` (the `--network reg|exp|gen` view of
the CLI): REG is the network as read; EXP is FOON-EXP and sees kitchen and goal
unchanged; GEN is FOON-GEN and sees them abstracted through the category index.
Trial kitchens are subsets of the default kitchen, whose labels the network
already has, so one view (built with the default kitchen) serves every trial:
only the kitchen mapping is applied per trial. Every view keeps the concrete
REG network beside it (the lifted GEN planner plans over it with category types).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..io.inputs import Network
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, resolve_goal, spec_of_node
from ..model.kitchen import Kitchen, default_kitchen

NETWORKS = ("reg", "exp", "gen")


@dataclass(frozen=True, eq=False)
class NetworkView:
    """A network to search, with the maps from concrete trial inputs to its nodes."""

    name: str
    foon: Foon  # at the protocol's level
    concrete: Foon  # REG at the protocol's level
    view: Any  # generalize.network.NetworkView
    index: Any = None  # GEN: the CategoryIndex

    def kitchen(self, kitchen: Kitchen) -> Kitchen:
        """The trial's (concrete) kitchen as this network sees it."""
        if self.index is None:
            return kitchen
        from ..generalize.compress import abstract_kitchen

        return abstract_kitchen(kitchen, self.index)

    def goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node`, as this network sees it (FoonInputError if it has no match)."""
        return resolve_goal(self.view.map_goal(spec_of_node(node)), self.foon)

    def concrete_goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node` on the concrete network."""
        return Goal(spec_of_node(node), (node,), self.concrete.level)


def build_view(name: str, net: Network, level: int, threshold: float | None = None) -> NetworkView:
    """The view `name` (reg, exp or gen) of `net` at `level` (EXP with similarity `threshold`)."""
    from ..generalize.expand import DEFAULT_THRESHOLD
    from ..generalize.network import network_view

    if name not in NETWORKS:
        raise ValueError(f"unknown network {name!r} (expected one of {', '.join(NETWORKS)})")
    reg = net.at(level)
    index = None
    if name == "gen":
        from ..generalize.categories import load_index

        index = load_index()
    view = network_view(net, name, level, default_kitchen(reg), index=index,
                        threshold=DEFAULT_THRESHOLD if threshold is None else threshold)
    return NetworkView(name, view.foon, reg, view, index)
