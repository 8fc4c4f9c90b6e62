"""Report rows for success as physical execution: the trees scheduled over the trial kitchen's objects.

Every tree a solver returns is scheduled in its order over the kitchen's physical
objects (`planners.executable.schedule`, at `--objects-per-item` objects per kitchen
node; a physical planner's plan is replayed object by object instead); its verdict is
in the record (`Record.executable`, with the label and step that failed). From those:

- verdicts per (solver, network): trees, executable, short, used-up, missing;
- successes per trial under physical execution (the second Table 2), beside the counts;
- goals the kitchen runs short for: how many more objects would do, and where more do not help;
- the labels that run short most often;
- GEN concrete (trees of kitchen objects: the lifted planner) against category-level success, per trial.

No formatting here (`render_physical` in `render.py`). O(records) each.
"""

from __future__ import annotations

import statistics
from collections import Counter, defaultdict
from dataclasses import dataclass

from ..planners.executable import Verdict
from .networks import DEFAULT_NETWORK
from .records import Record
from .solvers import SOLVERS, Role
from .tables import REFERENCE, ReportData

#: Verdicts in report order.
VERDICTS = tuple(str(v) for v in Verdict)


def executable(record: Record) -> bool:
    """Solved, and its tree (or plan) carried out object by object with the trial's kitchen."""
    return record.solved and record.executable == Verdict.EXECUTABLE


def scheduled(data: ReportData) -> bool:
    """Whether the run's records carry schedule verdicts (results of earlier versions have none)."""
    return any(r.executable is not None for r in data.records)


@dataclass(frozen=True)
class VerdictRow:
    """Schedule verdicts of one solver's trees on one network."""

    solver: str
    network: str
    trees: int  # solved cells (validated trees)
    counts: dict[str, int]  # verdict -> trees

    @property
    def share(self) -> float:
        return self.counts.get(str(Verdict.EXECUTABLE), 0) / self.trees if self.trees else 0.0


def verdict_rows(data: ReportData) -> list[VerdictRow]:
    """One row per (solver, network) with solved cells that carry a verdict, in the run's order."""
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = [r for r in data.cells(n, s) if r.solved and r.executable is not None]
            if cells:
                rows.append(VerdictRow(s, n, len(cells), dict(Counter(r.executable for r in cells))))
    return rows


def physical_successes(data: ReportData, solver: str = REFERENCE) -> dict[str, dict[int, tuple[int, int]]]:
    """network -> trial -> (goals solved, of which executable) by `solver`."""
    out: dict[str, dict[int, tuple[int, int]]] = {}
    for n in data.networks:
        cells = data.cells(n, solver)
        if not cells:
            continue
        per = {t["trial"]: [0, 0] for t in data.trials}
        for r in cells:
            if r.trial in per:
                per[r.trial][0] += r.solved
                per[r.trial][1] += executable(r)
        out[n] = {t: (a, b) for t, (a, b) in per.items()}
    return out


@dataclass(frozen=True)
class ShortRow:
    """Trees of one solver on one network that the kitchen cannot carry out, by what would fix them."""

    solver: str
    network: str
    short: int  # the kitchen runs out of some label
    more_suffice: int  # of those, more objects of the kitchen's labels would do
    mean_extra: float | None  # objects needed beyond the kitchen's, mean over `more_suffice`
    max_extra: int | None
    used_up: int  # a unit must fire again (more objects do not help)


def short_rows(data: ReportData) -> list[ShortRow]:
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = [r for r in data.cells(n, s) if r.solved and r.executable is not None]
            short = [r for r in cells if r.executable == Verdict.SHORT]
            used = sum(r.executable == Verdict.USED_UP for r in cells)
            if not short and not used:
                continue
            extra = [r.extra_objects for r in short if r.extra_objects is not None]
            rows.append(ShortRow(s, n, len(short), len(extra), statistics.fmean(extra) if extra else None,
                                 max(extra) if extra else None, used))
    return rows


def short_labels(data: ReportData, solver: str = REFERENCE, limit: int = 10) -> list[tuple[str, str, int, int]]:
    """(network, label, trees it stops, median step) of the labels that stop `solver`'s trees most often.

    The label and step come from the verdict's reason (`schedule`'s message: "step K (motion) needs one
    more LABEL in ..." or "... needs 'NODE' again ..."); ties broken by network order, then label.
    """
    stops: dict[tuple[str, str], list[int]] = defaultdict(list)
    for r in data.records:
        if r.solver != solver or not r.solved or r.executable in (None, Verdict.EXECUTABLE):
            continue
        step, label = failure_of(r.executable_reason or "")
        stops[(r.network, label)].append(step)
    order = {n: i for i, n in enumerate(data.networks)}
    ranked = sorted(stops.items(), key=lambda kv: (-len(kv[1]), order.get(kv[0][0], 0), kv[0][1]))
    return [(n, label, len(steps), int(statistics.median(steps))) for (n, label), steps in ranked[:limit]]


def failure_of(reason: str) -> tuple[int, str]:
    """(step, label) named by a schedule verdict's message; (0, reason) when it names neither."""
    head, _, rest = reason.partition(" (")
    step = int(head.split()[1]) if head.startswith("step ") and head.split()[1].isdigit() else 0
    if " one more " in rest:
        return step, rest.split(" one more ", 1)[1].split(" in '", 1)[0]
    if " moved the " in rest:
        return step, rest.split(" moved the ", 1)[1].split(" on ", 1)[0]
    if " needs '" in rest:
        return step, rest.split(" needs '", 1)[1].split("'", 1)[0]
    return step, reason


def failures(data: ReportData, solver: str = REFERENCE, limit: int = 12) -> list[Record]:
    """The first `limit` trees of `solver` that are not executable, in (network, trial, goal) order."""
    order = {n: i for i, n in enumerate(data.networks)}
    bad = [r for r in data.records if r.solver == solver and r.solved
           and r.executable not in (None, Verdict.EXECUTABLE)]
    return sorted(bad, key=lambda r: (order.get(r.network, 0), r.trial, r.goal))[:limit]


@dataclass(frozen=True)
class GenRow:
    """One trial's GEN successes: category-level (`native-complete` on GEN), concrete (the lifted planner's
    trees of kitchen objects) and concrete trees the kitchen's objects carry out."""

    trial: int
    category: int
    concrete: int
    concrete_executable: int


def gen_rows(data: ReportData) -> tuple[str, str, list[GenRow]] | None:
    """(GEN network, concrete solver, rows per trial); None without both solvers' cells."""
    solver = next(iter(data.role(Role.CONCRETE)), None)
    if solver is None or REFERENCE not in data.solvers:
        return None
    network = (SOLVERS[solver].networks or (DEFAULT_NETWORK,))[0]
    concrete = data.cells(network, solver)
    if not concrete:
        return None
    category = data.cells(network, REFERENCE)
    rows = []
    for t in data.trials:
        k = t["trial"]
        rows.append(GenRow(k, sum(r.solved for r in category if r.trial == k),
                           sum(r.solved for r in concrete if r.trial == k),
                           sum(executable(r) for r in concrete if r.trial == k)))
    return network, solver, rows


@dataclass(frozen=True)
class PhysicalPlannerRow:
    """A planner over physical objects on one network, against the reference's trees on the same goals."""

    solver: str
    network: str
    solved: int
    replayed: int  # plans the trial's objects carry out (replayed object by object, within the kitchen's counts)
    more_objects: int  # plans that use more objects of some kitchen node than the kitchen has
    mean_extra: float | None  # objects beyond the kitchen's, mean over `more_objects`
    reference_executable: int  # the reference's trees of the same goals the kitchen's objects carry out
    mean_steps: float | None  # plan steps (repeated firings, washes and restoring steps included)
    mean_repeated: float | None  # of those, unit steps firing a unit the plan fired before
    mean_units: float | None  # the reference's tree units, on the goals both solved
    plans: int = 0  # plans returned: those replayed clean (`solved`) and those that fail the replay
    replay_failures: tuple[str, ...] = ()  # why each plan that fails the replay fails (its record's reason)
    no_plan: tuple[tuple[str, int], ...] = ()  # (status, goals) of the goals the reference solves and it has no plan
    holders: bool = False  # its replay includes holders (the relational replay: `replays_holders`)


def replays_holders(solver: str) -> bool:
    """`solver`'s plans are replayed with their holders (its encoding's `holders`), not on objects alone."""
    from ..pddl.compile import ENCODINGS

    encoding = SOLVERS[solver].encoding
    return encoding is not None and ENCODINGS[encoding].holders


def physical_planners(data: ReportData) -> list[PhysicalPlannerRow]:
    """Rows for the planners over physical objects (neither the agreement planner, an optimal one nor the
    concrete one), whose records say their plans were replayed."""
    index = data.by_key()
    skip = set(data.role(Role.AGREEMENT)) | set(data.role(Role.OPTIMUM)) | set(data.role(Role.CONCRETE))
    out = []
    for s in data.solvers:
        if not SOLVERS[s].planner or s in skip:
            continue
        for n in data.networks:
            asked = data.cells(n, s)
            cells = [r for r in asked if r.solved]
            if not cells:
                continue
            ref = [index.get((r.trial, r.goal, n, REFERENCE)) for r in asked]
            both = [(r, x) for r in cells
                    if (x := index.get((r.trial, r.goal, n, REFERENCE))) is not None and x.solved
                    and r.plan_length is not None and x.units is not None]
            more = [r.extra_objects for r in cells if r.executable == Verdict.SHORT and r.extra_objects is not None]
            repeated = [r.repeated for r, _ in both if r.repeated is not None]
            failed = [r for r in asked if not r.solved and r.plan_length is not None]
            no_plan = Counter(str(r.status) for r, x in zip(asked, ref, strict=True)
                              if x is not None and x.solved and not r.solved and r.plan_length is None)
            out.append(PhysicalPlannerRow(s, n, len(cells), sum(executable(r) for r in cells), len(more),
                                          statistics.fmean(more) if more else None,
                                          sum(x is not None and executable(x) for x in ref),
                                          statistics.fmean(r.plan_length for r, _ in both) if both else None,
                                          statistics.fmean(repeated) if repeated else None,
                                          statistics.fmean(x.units for _, x in both) if both else None,
                                          len(cells) + len(failed), tuple(r.reason for r in failed),
                                          tuple(sorted(no_plan.items())), replays_holders(s)))
    return out


def planner_successes(data: ReportData) -> dict[tuple[str, str], dict[int, int]]:
    """(solver, network) -> trial -> goals whose plan the trial's objects carry out, for the rows of
    `physical_planners` (the second Table 2's columns beside the reference's trees)."""
    out = {}
    for p in physical_planners(data):
        cells = data.cells(p.network, p.solver)
        out[(p.solver, p.network)] = {t["trial"]: sum(executable(r) for r in cells if r.trial == t["trial"])
                                      for t in data.trials}
    return out


def planner_means(data: ReportData) -> list[tuple[str, str, float]]:
    """(solver, network, mean goals per trial its plans carry out with the trial's objects) for the rows of
    `physical_planners`, in their order."""
    trials = len(data.trials) or 1
    return [(p.solver, p.network, p.replayed / trials) for p in physical_planners(data)]
