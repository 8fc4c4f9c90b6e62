"""The grid of an experiment run: its cells (point of the sweep, trial, network, solver, goal), their keys, and
the batches an engine runs.

The cells not already in the results file are grouped into batches of at most `CHUNK` goals of one (point,
trial, network, solver), so that what a solver prepares once (a fixpoint, an FD translation) serves the goals of
the batch, and a lost task loses little; costliest solvers and largest networks first, after a probe of the first
`PROBE` goals of each (solver, network) (`plan_batches`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from .config import Config
from .networks import NETWORKS
from .params import Point
from .protocol import Trial
from .records import Key, params_key
from .solvers import SOLVERS, get_solver
from .worker import Batch, draw_at

__all__ = ["CHUNK", "PROBE", "Cell", "cell_keys", "cell_labels", "cells", "plan_batches", "trials_at"]

#: Most goals in one task (a lost task loses at most this many cells). 50 rather than 25: half the
#: tasks and result messages, ~1 s less on the default protocol's native solvers (21.2 vs 22.2 s, median
#: of 3); the costliest batches start first, so the tail stays short.
CHUNK = 50
#: Goals of the probe of each (solver, network) that runs before the rest (`plan_batches`).
PROBE = 2


def trials_at(config: Config, point: Point) -> tuple[Trial, ...]:
    """The trials at one point of the sweep (`worker.draw_at`: drawn once per process)."""
    return draw_at(config.paths, config.protocol, point).trials


Cell = tuple[Point, Trial, str, str, int]


def cells(config: Config) -> list[Cell]:
    """Every cell of the run as (point, trial, network, solver, goal), solvers only on their networks."""
    out = []
    for point in config.points:
        trials = trials_at(config, point)
        for solver in config.solvers:
            spec = get_solver(solver)
            for network in config.networks:
                if spec.applies_to(network):
                    out.extend((point, t, network, solver, g) for t in trials for g in config.goals_for(solver, t))
    return out


def _params_keys(config: Config) -> dict[Point, tuple]:
    return {p: params_key(dict(p)) for p in config.points}


def cell_keys(config: Config, grid: Sequence[Cell] | None = None) -> set[Key]:
    """Every cell key of the run (of `grid`, the run's `cells`, when the caller has them)."""
    return set(cell_labels(config, grid))


def cell_labels(config: Config, grid: Sequence[Cell] | None = None) -> dict[Key, str]:
    """Every cell key of the run -> the label of its goal as drawn now (`grid`: the run's `cells`)."""
    params = _params_keys(config)
    return {(t.index, g, n, s, params[p]): t.goals[g - 1].describe()
            for p, t, n, s, g in (cells(config) if grid is None else grid)}


def plan_batches(config: Config, done: set[Key], grid: Sequence[Cell] | None = None) -> list[Batch]:
    """Batches of at most CHUNK pending goals (all of them for solvers whose preparation is costly, such as a
    Fast Downward translation), costliest solvers and largest networks first, after a probe of the first PROBE
    goals of every (solver, network) in that order; `grid`: the run's `cells`."""
    pending: dict[tuple, list[int]] = {}
    trial_of: dict[tuple, Trial] = {}
    params = _params_keys(config)
    for point, trial, network, solver, goal in (cells(config) if grid is None else grid):
        if (trial.index, goal, network, solver, params[point]) in done:
            continue
        group = (point, trial.index, network, solver)
        pending.setdefault(group, []).append(goal)
        trial_of[group] = trial
    batches = []
    for group, goals in pending.items():
        size = len(goals) if SOLVERS[group[3]].whole_batches else CHUNK
        batches.extend(Batch(trial_of[group], group[2], group[3], tuple(goals[i:i + size]), group[0])
                       for i in range(0, len(goals), size))

    def order(b: Batch) -> tuple:
        n = NETWORKS[b.network].schedule  # batches on larger networks start first (better load balance)
        return (-SOLVERS[b.solver].cost, n, config.points.index(b.point), b.trial.index, b.goals[0])

    probes, rest, probed = [], [], set()  # the first PROBE goals of every (solver, network) first: its time
    for b in sorted(batches, key=order):  # per cell is known early (`Progress.left`); the rest keeps the order
        if (b.solver, b.network) in probed:
            rest.append(b)
            continue
        probed.add((b.solver, b.network))
        split = len(b.goals) > PROBE and not SOLVERS[b.solver].whole_batches  # (split, one prepares twice)
        probes.append(replace(b, goals=b.goals[:PROBE]) if split else b)
        if split:
            rest.append(replace(b, goals=b.goals[PROBE:]))
    return probes + rest
