"""The Python API for many goals: `retrieve_goals` and `plan_goals` answer many goals on one loaded network (as
several `--goal` do), `run_experiment` runs the experiment's grid (`foon2pddl experiment`)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import UsageError
from ..generalize.network import DEFAULT_NETWORK, get_network, network_view
from ..io.inputs import Network
from ..io.rates import Rates
from ..model.foon import Foon
from ..model.goal import GoalSpec
from ..model.kitchen import Kitchen
from ..planners.solve import PlanOutcome
from ..retrieval.batch import GoalRow
from ..status import BatchStatus, PlanStatus
from .inputs import goal_spec, network_of, resolve_goal
from .solve import plan


def retrieve_goals(network: Network | Foon, kitchen: Kitchen, goals: Iterable[str | GoalSpec],
                   method: str = "complete", *, level: int = 3, rates: Rates | None = None,
                   network_kind: str = DEFAULT_NETWORK, **limits: int) -> list[GoalRow]:
    """Many goals on one loaded network (one fixpoint shared), as `retrieve` with several `--goal`: one row each
    (`status`: `status.BatchStatus`; a goal naming no produced node is `unmatched`, not an error).

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> [str(r.status) for r in retrieve_goals(net, load_kitchen(net), ["guacamole", "lemonade", "unicorn"])]
    ['solved', 'unreachable', 'unmatched']
    """
    from ..io.goal_lists import GoalEntry
    from ..model.goal import resolve_goal as resolve
    from ..retrieval.batch import solve_goals

    view = network_view(network_of(network), get_network(network_kind).name, level, kitchen.project(level))
    entries = [GoalEntry(goal_spec(g), "<goal>", n) for n, g in enumerate(goals, 1)]
    return solve_goals(view.foon, view.kitchen.nodes, entries, lambda spec: resolve(view.map_goal(spec), view.foon),
                       method=method, rates=rates, **limits)


@dataclass(frozen=True)
class GoalPlan:
    """One goal of `plan_goals`: its outcome, or None with the reason it names no produced node."""

    goal: str
    outcome: PlanOutcome | None
    reason: str = ""

    @property
    def status(self) -> PlanStatus | BatchStatus:
        """The outcome's status, or `unmatched` for a goal naming no produced node (as `retrieve_goals` rows say)."""
        return self.outcome.status if self.outcome is not None else BatchStatus.UNMATCHED


def plan_goals(network: Network | Foon, kitchen: Kitchen, goals: Iterable[str | GoalSpec], encoding: str = "tree",
               **options) -> list[GoalPlan]:
    """`plan` for each goal, in order (`options` as `plan`'s); a goal that names no produced node is reported.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> [(p.goal, str(p.status), p.reason[:20]) for p in plan_goals(net, load_kitchen(net), ["guacamole", "unicorn"])]
    [('guacamole', 'solved', ''), ('unicorn', 'unmatched', 'unknown object label')]
    """
    rows = []
    for g in goals:
        spec = goal_spec(g)
        try:
            rows.append(GoalPlan(spec.describe(), plan(network, kitchen, spec, encoding, **options)))
        except UsageError as exc:
            try:  # a goal that names no produced node is a row; any other usage error is the caller's
                resolve_goal(network, spec, options.get("level", 3))
            except UsageError:
                rows.append(GoalPlan(spec.describe(), None, exc.message))
                continue
            raise
    return rows


def run_experiment(out_dir: str | Path, *paths: str | Path, networks: Iterable[str] | None = None,
                   solvers: Iterable[str] | None = None, trials: int | None = None, goals: int | None = None,
                   jobs: int = 1, time_limit: float | None = None, progress: bool = False, **protocol):
    """The experiment of `foon2pddl experiment` (cells appended to OUT_DIR/results.jsonl; a rerun resumes):
    `protocol` takes `kitchen_fraction`, `seed`, `level`, `threshold`, `similarity`. Returns the run's
    summary (`experiment.runner.RunSummary`: records, cells ran and reused, seconds)."""
    from ..experiment import runner
    from ..experiment.config import Config
    from ..experiment.protocol import Protocol
    from ..experiment.setting import DEFAULT_TIME_LIMIT
    from ..experiment.solvers import DEFAULT_SOLVERS, get_solver
    from ..generalize.network import NETWORKS

    counts = {k: v for k, v in (("trials", trials), ("goals", goals)) if v is not None}
    nets = tuple(get_network(n).name for n in (networks if networks is not None else NETWORKS))
    chosen = tuple(get_solver(s).name for s in (solvers if solvers is not None else DEFAULT_SOLVERS))
    config = Config(tuple(str(p) for p in paths), Protocol(**counts, **protocol), nets, chosen, Path(out_dir),
                    jobs, DEFAULT_TIME_LIMIT if time_limit is None else time_limit)
    return runner.run(config, progress=progress)
