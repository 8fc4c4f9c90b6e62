"""Report tables of an experiment, computed from its records: plain numbers and row dataclasses.

No formatting here (`render.py` turns rows into Markdown and CSV, `plots.py` into PNG).
Which solver plays which part (the reference that counts successes, the planner that
must agree with it, the optimal solvers, the seed paper's method, solvers returning
concrete trees) comes from the solvers registry (`solvers.Role`), not from names.

- successes per trial and network (the paper's Table 2), counted with the reference;
- time per trial: a trial's goals' solve times plus the batch's shared setup
  (fixpoint, FD translation) once; validation is not counted (the paper's Table 3);
- agreement of the reference with the agreement planner, cell by cell;
- quality: tree sizes against the optimum; how often optimality was proven;
- one table per swept parameter: successes and time at each value.
"""

from __future__ import annotations

import statistics
from collections import defaultdict
from dataclasses import dataclass, field

from .networks import DEFAULT_NETWORK, NETWORKS
from .records import Record
from .solvers import Role, with_role

#: The seed paper's success range (percent of goals) and greedy time per trial, per network (`NetworkKind.paper`).
PAPER_SUCCESSES = {k.name: k.paper.successes for k in NETWORKS.values() if k.paper is not None}
PAPER_TIME_MS = {k.name: k.paper.time_ms for k in NETWORKS.values() if k.paper is not None}
PAPER_CPU = "Intel i7-6500U"
UNTIMED_PHASES = frozenset({"validate", "schedule"})  # checks of a tree, not finding it
#: The solver Table 2 counts with and the planner that must agree with it.
REFERENCE = with_role(Role.REFERENCE)[0]
FD_TREE = with_role(Role.AGREEMENT)[0]



@dataclass(frozen=True)
class ReportData:
    """What a report is made of: the run's records and a description of the run."""

    records: tuple[Record, ...]
    networks: tuple[str, ...]
    solvers: tuple[str, ...]
    trials: tuple[dict, ...]  # Trial.summary() of each trial
    meta: dict = field(default_factory=dict)  # protocol, inputs, jobs, wall time, cells ran/skipped
    sweeps: tuple[tuple[str, tuple], ...] = ()  # swept parameters and their values
    all_records: tuple[Record, ...] | None = None  # every point of the sweep (`records`: the first point's)

    def cells(self, network: str, solver: str) -> list[Record]:
        return [r for r in self.records if r.network == network and r.solver == solver]

    def cells_of(self, solver: str) -> list[Record]:
        return [r for r in self.records if r.solver == solver]

    def by_key(self) -> dict[tuple, Record]:
        """Records by (trial, goal, network, solver): unique within one point of a sweep."""
        return {r.key[:4]: r for r in self.records}

    def role(self, role: Role) -> tuple[str, ...]:
        """The run's solvers with `role`, in the run's order."""
        return tuple(s for s in self.solvers if s in with_role(role))


def net_name(network: str) -> str:
    """A network's label in reports (`NetworkKind.label`: REG, EXP, GEN)."""
    return NETWORKS[network].label if network in NETWORKS else network


def solve_time(record: Record) -> float:
    """Seconds the solver spent on this goal (validation excluded)."""
    return sum(v for k, v in record.times.items() if k not in UNTIMED_PHASES)


def successes(data: ReportData) -> dict[tuple[str, str], dict[int, int]]:
    """(network, solver) -> trial -> goals solved (tree found and validated)."""
    out: dict[tuple[str, str], dict[int, int]] = defaultdict(lambda: defaultdict(int))
    trials = [t["trial"] for t in data.trials]
    for r in data.records:
        counts = out[(r.network, r.solver)]
        counts[r.trial] += r.solved
    return {k: {t: v.get(t, 0) for t in trials} for k, v in out.items()}


def reference_solver(data: ReportData) -> str | None:
    """The solver Table 2 counts with: native complete when run, else the first solver run."""
    if REFERENCE in data.solvers:
        return REFERENCE
    return data.solvers[0] if data.solvers else None


def goals_asked(data: ReportData, solver: str) -> int:
    """Goals per trial `solver` was asked (fewer than the protocol's with a goal limit)."""
    per_trial: dict[tuple[int, str], set[int]] = defaultdict(set)
    for r in data.records:
        if r.solver == solver:
            per_trial[(r.trial, r.network)].add(r.goal)
    return max((len(v) for v in per_trial.values()), default=0)


def trial_times(data: ReportData) -> dict[tuple[str, str], dict[int, float]]:
    """(network, solver) -> trial -> seconds: the goals' solve times plus the batch setup once."""
    total: dict[tuple[str, str], dict[int, float]] = defaultdict(lambda: defaultdict(float))
    setup: dict[tuple[str, str, int], float] = {}
    for r in data.records:
        total[(r.network, r.solver)][r.trial] += solve_time(r)
        k = (r.network, r.solver, r.trial)
        setup[k] = max(setup.get(k, 0.0), r.setup)
    for (n, s, t), v in setup.items():
        total[(n, s)][t] += v
    return {k: dict(v) for k, v in total.items()}



@dataclass(frozen=True)
class Agreement:
    """Native complete against FD `tree`, over the cells both ran."""

    rows: tuple[tuple, ...]  # (network, cells, both, neither, a only, b only)
    disagreements: tuple[tuple[Record, Record], ...]  # (native, fd) pairs that differ
    compared: int


def agreement(data: ReportData, a: str = REFERENCE, b: str = FD_TREE) -> Agreement | None:
    """Cell-by-cell comparison of solvers `a` and `b`; None when either was not run."""
    if a not in data.solvers or b not in data.solvers:
        return None
    index = data.by_key()
    rows, diffs, compared = [], [], 0
    for n in data.networks:
        counts = [0, 0, 0, 0]
        for t in data.trials:
            for g in range(1, len(t["goals"]) + 1):
                ra, rb = index.get((t["trial"], g, n, a)), index.get((t["trial"], g, n, b))
                if ra is None or rb is None:
                    continue
                compared += 1
                if ra.solved == rb.solved:
                    counts[0 if ra.solved else 1] += 1
                else:
                    counts[2 if ra.solved else 3] += 1
                    diffs.append((ra, rb))
        if sum(counts):
            rows.append((net_name(n), sum(counts), *counts))
    return Agreement(tuple(rows), tuple(diffs), compared)


def invalid_trees(data: ReportData) -> list[Record]:
    """Cells that returned a tree or plan that does not validate."""
    return [r for r in data.records if r.units is not None and r.validated is not True]

# -- quality and optimality ----------------------------------------------------------------------

@dataclass(frozen=True)
class QualityRow:
    """Tree sizes of one solver on one network against the optimum, on the goals both solved."""

    network: str
    solver: str
    goals: int
    mean_units: float
    mean_optimum: float
    larger: int  # trees larger than the optimum
    max_excess: int
    smaller: int  # smaller: the optimum was not proven, or a concrete tree beat every REG tree


def quality_rows(data: ReportData) -> list[QualityRow]:
    """One row per (network, solver) with solved trees that an optimal solver also solved."""
    index = data.by_key()
    optimum = data.role(Role.OPTIMUM)
    concrete = set(data.role(Role.CONCRETE))
    rows = []
    for n in data.networks:
        for s in data.solvers:
            # trees of concrete units (lifted GEN) are compared with REG's optimum, the others with their network's
            base = DEFAULT_NETWORK if s in concrete else n
            pairs = []
            for r in data.cells(n, s):
                if not r.solved or r.units is None:
                    continue
                best = [o.units for o in (index.get((r.trial, r.goal, base, x)) for x in optimum)
                        if o is not None and o.solved and o.units is not None]
                if best:
                    pairs.append((r.units, min(best)))
            if pairs:
                excess = [u - b for u, b in pairs]
                rows.append(QualityRow(n, s, len(pairs), statistics.fmean(u for u, _ in pairs),
                                       statistics.fmean(b for _, b in pairs), sum(e > 0 for e in excess),
                                       max(excess), sum(e < 0 for e in excess)))
    return rows


@dataclass(frozen=True)
class OptimumCheck:
    """Two optimal solvers (a native search that proves optimality, a planner) on one network."""

    network: str
    native: str
    planner: str
    compared: int  # goals both solved, the native one with proven optimality
    mismatches: int  # of those, optima of different sizes


def optimum_checks(data: ReportData) -> list[OptimumCheck]:
    from .solvers import SOLVERS

    index = data.by_key()
    optimum = data.role(Role.OPTIMUM)
    natives = [s for s in optimum if not SOLVERS[s].planner]
    planners = [s for s in optimum if SOLVERS[s].planner]
    out = []
    for n in data.networks:
        for a in natives:
            for b in planners:
                both = [(x, index.get((x.trial, x.goal, n, b))) for x in data.cells(n, a)]
                both = [(x, y) for x, y in both if y is not None and x.solved and y.solved and x.proven_optimal]
                if both:
                    out.append(OptimumCheck(n, a, b, len(both), sum(x.units != y.units for x, y in both)))
    return out


@dataclass(frozen=True)
class OptimalityRow:
    """How often a solver that reports optimality proved it, on one network."""

    solver: str
    network: str
    trees: int  # cells with a validated tree
    proven: int  # of those, proven optimal
    median_gap: float | None  # median gap ((units - bound) / units) of the unproven ones that report a bound
    median_bound: float | None


def optimality_rows(data: ReportData) -> list[OptimalityRow]:
    """Rows for every (solver, network) whose cells say whether their tree is proven optimal."""
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = [r for r in data.cells(n, s) if r.solved and r.proven_optimal is not None]
            if not cells:
                continue
            unproven = [r for r in cells if not r.proven_optimal]
            gaps = [r.gap for r in unproven if r.gap is not None]
            bounds = [r.bound for r in unproven if r.bound is not None]
            rows.append(OptimalityRow(s, n, len(cells), len(cells) - len(unproven),
                                      statistics.median(gaps) if gaps else None,
                                      statistics.median(bounds) if bounds else None))
    return rows


# -- statuses ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class StatusRow:
    """Cells per status of one solver on one network, with the trees returned and validated."""

    solver: str
    network: str
    counts: dict[str, int]
    trees: int
    validated: int
    foon_valid: int


def status_rows(data: ReportData) -> list[StatusRow]:
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = data.cells(n, s)
            if cells:
                counts: dict[str, int] = defaultdict(int)
                for r in cells:
                    counts[str(r.status)] += 1
                rows.append(StatusRow(s, n, dict(counts), sum(r.units is not None for r in cells),
                                      sum(r.validated is True for r in cells), sum(r.foon_valid is True for r in cells)))
    return rows


# -- sweeps --------------------------------------------------------------------------------------

@dataclass(frozen=True)
class SweepRow:
    """One (solver, network) at one value of a swept parameter, over every point with that value."""

    param: str
    value: object
    solver: str
    network: str
    successes: float  # mean goals solved per (trial, point)
    goals: int  # goals asked per trial
    ms_per_goal: float  # mean solve time per goal
    cells: int = field(default=0)


def sweep_rows(data: ReportData, param: str) -> list[SweepRow]:
    """Successes and time against one swept parameter (means over trials and the other parameters' values)."""
    records = data.all_records if data.all_records is not None else data.records
    values = next((v for n, v in data.sweeps if n == param), ())
    rows = []
    for s in data.solvers:
        for n in data.networks:
            for value in values:
                cells = [r for r in records if r.solver == s and r.network == n and r.params.get(param) == value]
                if not cells:
                    continue
                per_trial: dict[tuple, int] = defaultdict(int)
                goals: dict[tuple, int] = defaultdict(int)
                for r in cells:
                    group = (r.trial, tuple(sorted(r.params.items())))
                    per_trial[group] += r.solved
                    goals[group] += 1
                rows.append(SweepRow(param, value, s, n, statistics.fmean(per_trial.values()), max(goals.values()),
                                     statistics.fmean(solve_time(r) for r in cells) * 1000, len(cells)))
    return rows
