"""Would FOON-EXP or FOON-GEN make a goal the regular network cannot? A cheap check for hints.

Only run after REG answered "unreachable", on the kinds of `network.NETWORKS` that
have a `hint`, and only where building the network is cheap (`NetworkKind.hint_max_units`):
GEN up to 2,500 units (compress, index, fixpoint: 0.15 s for both checks on the
101-unit example, 0.9 s for GEN on the 1,845-unit universal FOON, medians of 5), EXP
up to 600 (EXP of the universal FOON takes ~3 s even cached). The answer never depends
on what the disk cache holds: when a build will be slow (EXP's similarity matrix not
cached yet: WordNet opens, a few seconds, once) `slow_hint` says what it will do,
for the caller to say when the check starts (`NetworkKind.slow_step`), so the wait is not silent.
The check is reachability (the linear fixpoint) on each network, with the kitchen
and goal mapped as `--network` maps them; a caller's `confirm` check (the CLI runs
the lifted planner for GEN) must pass too, since the category-level fixpoint also
"makes" a dish from another dish's categories.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from ..analysis.reachability import reachable
from ..errors import FoonError
from ..io.inputs import Network
from ..model.goal import GoalSpec
from ..model.kitchen import Kitchen
from .network import NETWORKS, NetworkKind, network_view


def hinted_kinds(net: Network) -> list[NetworkKind]:
    """The kinds a hint check builds for `net`: those with a `hint`, where `net` is small enough to build them
    cheaply (`NetworkKind.hint_max_units`), in `NETWORKS` order."""
    return [k for k in NETWORKS.values() if k.hint and len(net.foon.units) <= k.hint_max_units]


def slow_hint(net: Network, kitchen: Kitchen) -> str | None:
    """What the first slow build of a hint check will do (`NetworkKind.slow_step`), None when every
    hinted network is quick to build (EXP's matrix cached): the caller says it when the check starts."""
    for kind in (k for k in hinted_kinds(net) if k.slow_step is not None):
        try:
            slow = kind.slow_step(net, kitchen)
        except (FoonError, OSError):
            continue
        if slow is not None:
            return slow
    return None


def networks_that_reach(net: Network, kitchen: Kitchen, spec: GoalSpec, level: int,
                        confirm: Mapping[str, Callable[[], bool]] | None = None) -> list[str]:
    """Which hinted kinds (EXP, GEN) make the goal `spec` from `kitchen` (only the networks cheap to build).

    `confirm[kind]()`, when given, must also hold (called only once the fixpoint reaches the goal).
    """
    confirm = confirm or {}
    found = []
    for kind in hinted_kinds(net):
        try:  # a hint is optional: nothing here (a missing WordNet or extra included) may become an error
            view = network_view(net, kind.name, level, kitchen)
            goal = view.resolve(spec)
        except (FoonError, OSError):
            continue  # no WordNet, the goal has no counterpart there, or the category index is unreadable
        reach = reachable(view.foon, view.kitchen.nodes, goal.candidates)
        if reach.makes_any(goal.candidates) and (kind.name not in confirm or confirm[kind.name]()):
            found.append(kind.name)
    return found

