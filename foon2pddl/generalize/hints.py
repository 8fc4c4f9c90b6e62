"""Would FOON-EXP or FOON-GEN make a goal the regular network cannot? A cheap check for hints.

Only run after REG answered "unreachable", and only where building the network
is cheap. GEN up to `GEN_MAX_UNITS` (compress, index, fixpoint: 0.15 s for both
checks on the 101-unit example, 0.9 s for GEN on the 1,845-unit universal FOON,
medians of 5). EXP only when the network is small (`EXP_MAX_UNITS`; EXP of the
universal FOON takes ~3 s even cached). The answer never depends on what the disk
cache holds: when EXP's similarity matrix is not cached yet it is computed (WordNet
opens: a few seconds, once) and `notify` is told first, so the wait is not silent.
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
from .expand import vocabulary
from .network import network_view
from .similarity import matrix_is_cached

#: Largest networks (units) on which EXP / GEN are built just for a hint.
EXP_MAX_UNITS = 600
GEN_MAX_UNITS = 2500


def networks_that_reach(net: Network, kitchen: Kitchen, spec: GoalSpec, level: int,
                        notify: Callable[[str], None] | None = None,
                        confirm: Mapping[str, Callable[[], bool]] | None = None) -> list[str]:
    """Which of `exp`, `gen` make the goal `spec` from `kitchen` (only the networks cheap to build).

    `notify(message)` is called before a slow step (building EXP's similarity matrix);
    `confirm[kind]()`, when given, must also hold (called only once the fixpoint reaches the goal).
    """
    confirm = confirm or {}
    found = []
    for kind in ("exp", "gen"):
        if len(net.foon.units) > (EXP_MAX_UNITS if kind == "exp" else GEN_MAX_UNITS):
            continue
        try:  # a hint is optional: nothing here (a missing WordNet or extra included) may become an error
            if kind == "exp" and notify is not None and not matrix_is_cached(vocabulary(net.foon, kitchen)):
                notify("checking whether FOON-EXP can make it: computing its WordNet similarity matrix "
                       "(once, then cached)")
            view = network_view(net, kind, level, kitchen)
            goal = view.resolve(spec)
        except (FoonError, OSError):
            continue  # no WordNet, the goal has no counterpart there, or the category index is unreadable
        reach = reachable(view.foon, view.kitchen.nodes, goal.candidates)
        if any(reach.can_make(c) for c in goal.candidates) and (kind not in confirm or confirm[kind]()):
            found.append(kind)
    return found

