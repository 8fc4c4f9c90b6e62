"""How the kitchen fraction drives the results: exact solvable counts per fraction, network and trial.

For each fraction, the protocol's trials are redrawn with the same seeds (so a
smaller kitchen is a subset of a larger one) and the reachability fixpoint
counts, per network, the goals some task tree reaches: what every complete
solver (native complete, FD on the `tree` encoding) must find. One fixpoint per
(fraction, trial, network); no search.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from ..analysis.reachability import reachable
from .networks import NetworkView
from .protocol import Protocol, make_trials

DEFAULT_FRACTIONS = (0.5, 0.6, 0.7, 0.8, 0.9, 1.0)


@dataclass(frozen=True)
class SensitivityRow:
    """Solvable goals per trial for one (fraction, network)."""

    fraction: float
    network: str
    solvable: tuple[int, ...]  # per trial, in trial order
    goals: int  # goals per trial


def sensitivity(views: Sequence[NetworkView], protocol: Protocol,
                fractions: Sequence[float] = DEFAULT_FRACTIONS) -> tuple[SensitivityRow, ...]:
    """Rows for every fraction (ascending) and view (in the given order)."""
    reg = next((v.concrete for v in views), None)
    if reg is None:
        return ()
    rows = []
    for fraction in sorted(set(fractions)):
        trials = make_trials(reg, replace(protocol, kitchen_fraction=fraction))
        for view in views:
            counts = []
            for trial in trials:
                nodes = view.kitchen(trial.kitchen).project(view.foon.level).nodes
                reach = reachable(view.foon, nodes)
                counts.append(sum(any(reach.can_make(c) for c in view.goal(g).candidates) for g in trial.goals))
            rows.append(SensitivityRow(fraction, view.name, tuple(counts), len(trials[0].goals)))
    return tuple(rows)
