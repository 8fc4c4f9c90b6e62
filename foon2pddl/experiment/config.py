"""What defines an experiment run (`Config`): inputs, protocol, sweeps, the networks and solvers compared, where
results go (`RESULTS` in its output directory), how its cells run."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .engine import NO_WORKER_LIMIT
from .params import PARAMS, Point, points
from .protocol import Protocol, Trial
from .setting import DEFAULT_TIME_LIMIT
from .worker import fingerprint

__all__ = ["RESULTS", "Config"]

RESULTS = "results.jsonl"


@dataclass(frozen=True)
class Config:
    """Everything that defines a run: inputs, protocol, sweeps, what to compare, where results go, how to run."""

    paths: tuple[str, ...]
    protocol: Protocol
    networks: tuple[str, ...]
    solvers: tuple[str, ...]
    out_dir: Path
    jobs: int = 1
    time_limit: float = DEFAULT_TIME_LIMIT
    goal_limits: tuple[tuple[str, int], ...] = ()  # (solver, n): that solver gets the first n goals of a trial
    sweeps: tuple[tuple[str, tuple], ...] = ()  # (parameter, values): the grid is run at every combination
    scheduler: str | None = None  # a Dask scheduler's address: run there instead of locally
    no_worker_limit: float = NO_WORKER_LIMIT  # seconds without a live Dask worker before pending cells are lost

    @property
    def results_path(self) -> Path:
        return self.out_dir / RESULTS

    @property
    def points(self) -> tuple[Point, ...]:
        return points(self.sweeps)

    def goals_for(self, solver: str, trial: Trial) -> range:
        """1-based indexes of the goals of `trial` that `solver` is asked (goal samples are prefix-stable)."""
        limit = dict(self.goal_limits).get(solver, len(trial.goals))
        return range(1, min(limit, len(trial.goals)) + 1)

    def identity(self) -> dict:
        """What results in this directory depend on: the protocol (swept parameters aside) and the inputs."""
        swept = [name for name, _ in self.sweeps]
        base = self.protocol.identity()
        for name in swept:
            base.pop(PARAMS[name].field or "", None)
        if swept:
            base["swept"] = sorted(swept)
        return {**base, "inputs": fingerprint(self.paths)}
