"""The networks an experiment compares: `generalize.network` views built with the default kitchen.

REG is the network as read; EXP is FOON-EXP and sees kitchen and goal unchanged;
GEN is FOON-GEN and sees them abstracted through the category index. Trial
kitchens are subsets of the default kitchen, whose labels the network already
has, so one view (built with the default kitchen) serves every trial: only the
kitchen mapping is applied per trial (`NetworkView.map_kitchen`). Every view keeps
the concrete REG network beside it (the lifted GEN planner plans over it).
"""

from __future__ import annotations

from ..generalize.expand import DEFAULT_THRESHOLD
from ..generalize.modes import DEFAULT_MODE
from ..generalize.network import DEFAULT_NETWORK, NETWORKS, NetworkView, lifted_networks, network_view
from ..io.inputs import Network
from ..model.kitchen import default_kitchen

__all__ = ["DEFAULT_NETWORK", "NETWORKS", "NetworkView", "build_view", "lifted_networks"]


def build_view(name: str, net: Network, level: int, threshold: float | None = None,
               similarity: str = DEFAULT_MODE) -> NetworkView:
    """The view `name` (reg, exp or gen) of `net` at `level`, EXP with similarity `threshold` (default 0.89)
    and the `similarity` mode.

    Raises UsageError for an unknown name.
    """
    return network_view(net, name, level, default_kitchen(net.at(level)),
                        threshold=DEFAULT_THRESHOLD if threshold is None else threshold, similarity=similarity)
