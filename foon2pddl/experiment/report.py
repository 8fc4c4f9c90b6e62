"""Reports of an experiment: CSV, Markdown tables beside the seed paper's, PNG plots.

Pure functions from records to text and bytes; `write_report` is the I/O edge
(every file written atomically). Tables:

- successes per trial and network (the paper's Table 2), counted with the
  reference solver (native complete: exactly the goals some task tree reaches),
  then per solver;
- average time per trial and per goal (the paper's Table 3): a trial's time is
  the sum of its goals' solve times plus the batch's shared setup (fixpoint,
  FD translation) once; validation is not counted;
- agreement of native complete with FD on the `tree` encoding, cell by cell
  (they must have the same solvable set; any difference is flagged), and of
  every solver with native complete;
- quality: units of greedy and complete trees against the optimal ones;
- statuses and validation per solver.
Plots use matplotlib's Agg canvas directly (no pyplot, no global backend).
"""

from __future__ import annotations

import csv
import io
import math
import statistics
from collections import defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from .records import STATUSES, Record

#: The seed paper's results (Paulius et al.; Tables 2 and 3), 10 trials x 100 goals, Intel i7-6500U.
PAPER_SUCCESSES = {"reg": (15, 53), "exp": (14, 62), "gen": (66, 87)}
PAPER_TIME_MS = {"reg": 2120.0, "exp": 15217.0, "gen": 1167.5}
PAPER_CPU = "Intel i7-6500U"

REFERENCE = "native-complete"
#: Solvers whose trees are made of concrete (REG) units whatever network they run on.
CONCRETE_TREES = frozenset({"fd-lifted-gen"})
FD_TREE = "fd-tree"
NETWORK_NAMES = {"reg": "REG", "exp": "EXP", "gen": "GEN"}
UNTIMED_PHASES = frozenset({"validate"})


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


def net_name(network: str) -> str:
    return NETWORK_NAMES.get(network, network)


def solve_time(record: Record) -> float:
    """Seconds the solver spent on this goal (validation excluded)."""
    return sum(v for k, v in record.times.items() if k not in UNTIMED_PHASES)


# -- CSV -----------------------------------------------------------------------------------------

def to_csv(records: Iterable[Record]) -> str:
    """One row per cell, sorted by key; times in milliseconds, one column per phase."""
    records = sorted(records, key=lambda r: r.key)
    phases = sorted({p for r in records for p in r.times})
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["trial", "goal", "network", "solver", "goal_label", "status", "solved", "validated", "foon_valid",
                "units", "plan_length", "proven_optimal", "time_ms", "setup_ms", *(f"{p}_ms" for p in phases), "reason"])

    def opt(v):
        return "" if v is None else v

    for r in records:
        w.writerow([r.trial, r.goal, r.network, r.solver, r.goal_label, r.status, r.solved, opt(r.validated),
                    opt(r.foon_valid), opt(r.units), opt(r.plan_length), opt(r.proven_optimal), f"{solve_time(r) * 1000:.3f}",
                    f"{r.setup * 1000:.3f}", *(f"{r.times[p] * 1000:.3f}" if p in r.times else "" for p in phases),
                    r.reason])
    return buf.getvalue()


# -- Markdown helpers ----------------------------------------------------------------------------

def md_table(header: Sequence[str], rows: Iterable[Sequence[object]], align: str = "") -> str:
    """A Markdown table; `align` gives l/r per column (default: first left, others right)."""
    header = [str(h) for h in header]
    align = align or "l" + "r" * (len(header) - 1)
    sep = ["---:" if a == "r" else ":---" for a in align]
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join(sep) + " |"]
    for row in rows:
        lines.append("| " + " | ".join(_cell(x) for x in row) + " |")
    return "\n".join(lines) + "\n"


def _cell(x: object) -> str:
    if x is None:
        return "-"
    if isinstance(x, float):
        return f"{x:,.1f}" if abs(x) >= 10 or x == 0 else f"{x:.2f}"
    if isinstance(x, int):
        return f"{x:,}"
    return str(x).replace("|", "\\|").replace("\n", " ")


def _span(values: Sequence[int]) -> str:
    return f"{min(values)}-{max(values)}" if values else "-"


# -- successes (Table 2) -------------------------------------------------------------------------

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


def table2(data: ReportData) -> str:
    """Successes per trial and network with the reference solver, with the paper's ranges."""
    ref = reference_solver(data)
    succ = successes(data)
    nets = [n for n in data.networks if (n, ref) in succ]
    rows = []
    for t in data.trials:
        rows.append([t["trial"], t["kitchen_nodes"], *(succ[(n, ref)][t["trial"]] for n in nets)])
    per_net = {n: list(succ[(n, ref)].values()) for n in nets}
    rows.append(["min-max", "", *(_span(per_net[n]) for n in nets)])
    rows.append(["mean", "", *(statistics.fmean(per_net[n]) for n in nets)])
    rows.append(["paper (min-max)", "", *(_paper_span(n) for n in nets)])
    goals = len(data.trials[0]["goals"]) if data.trials else 0
    return md_table(["trial", "kitchen nodes", *(f"{net_name(n)} (of {goals})" for n in nets)], rows)


def _paper_span(network: str) -> str:
    lo_hi = PAPER_SUCCESSES.get(network)
    return f"{lo_hi[0]}-{lo_hi[1]} of 100" if lo_hi else "-"


def goals_asked(data: ReportData, solver: str) -> int:
    """Goals per trial `solver` was asked (fewer than the protocol's with a goal limit)."""
    per_trial: dict[tuple[int, str], set[int]] = defaultdict(set)
    for r in data.records:
        if r.solver == solver:
            per_trial[(r.trial, r.network)].add(r.goal)
    return max((len(v) for v in per_trial.values()), default=0)


def table2_by_solver(data: ReportData) -> str:
    """Mean (min-max) successes per trial for every solver and network."""
    succ = successes(data)
    rows = []
    for s in data.solvers:
        row: list[object] = [s, goals_asked(data, s)]
        for n in data.networks:
            counts = list(succ[(n, s)].values()) if (n, s) in succ else []
            row.append(f"{statistics.fmean(counts):.1f} ({_span(counts)})" if counts else "-")
        rows.append(row)
    return md_table(["solver", "goals/trial", *(net_name(n) for n in data.networks)], rows)


# -- time (Table 3) ------------------------------------------------------------------------------

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


def table3(data: ReportData) -> str:
    """Average time per trial (ms) for every solver and network, with the paper's row."""
    times = trial_times(data)
    rows = []
    for s in data.solvers:
        rows.append([s, goals_asked(data, s), *(statistics.fmean(times[(n, s)].values()) * 1000
                                                if (n, s) in times else None for n in data.networks)])
    rows.append([f"paper (greedy, {PAPER_CPU})", 100, *(PAPER_TIME_MS.get(n) for n in data.networks)])
    return md_table(["solver", "goals/trial", *(f"{net_name(n)} ms/trial" for n in data.networks)], rows)


def table3_per_goal(data: ReportData) -> str:
    """Mean and median solve time per goal (ms), and the mean setup per trial (ms)."""
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = data.cells(n, s)
            if not cells:
                continue
            ts = [solve_time(r) * 1000 for r in cells]
            setups: dict[int, float] = {}
            for r in cells:
                setups[r.trial] = max(setups.get(r.trial, 0.0), r.setup * 1000)
            rows.append([s, net_name(n), statistics.fmean(ts), statistics.median(ts), max(ts),
                         statistics.fmean(setups.values())])
    return md_table(["solver", "network", "mean ms/goal", "median ms/goal", "max ms/goal", "setup ms/trial"], rows,
                    "llrrrr")


# -- agreement -----------------------------------------------------------------------------------

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


def agreement_md(data: ReportData) -> str:
    """The agreement section: a loud verdict, the per-trial table, the differing cells."""
    ag = agreement(data)
    if ag is None:
        return f"_Not computed: run both `{REFERENCE}` and `{FD_TREE}`._\n"
    if ag.disagreements:
        head = (f"**DISAGREEMENT: {len(ag.disagreements)} of {ag.compared} cells differ between "
                f"{REFERENCE} and {FD_TREE}.** They must have the same solvable set; see the cells below.\n")
    else:
        head = f"**Agreement on all {ag.compared} cells**: {REFERENCE} and {FD_TREE} solve exactly the same goals.\n"
    text = head + "\n" + md_table(["network", "cells", "both solve", "neither", f"{REFERENCE} only",
                                   f"{FD_TREE} only"], ag.rows)
    if ag.disagreements:
        rows = [(net_name(a.network), a.trial, a.goal, a.goal_label, a.status, b.status, b.reason or a.reason)
                for a, b in ag.disagreements[:30]]
        text += "\n" + md_table(["network", "trial", "goal", "goal node", REFERENCE, FD_TREE, "reason"], rows,
                                 "lrrllll")
    return text


def agreement_matrix(data: ReportData) -> str:
    """For every solver and network: cells whose solved/unsolved differs from native complete's."""
    if REFERENCE not in data.solvers:
        return ""
    index = data.by_key()
    rows = []
    for s in data.solvers:
        if s == REFERENCE:
            continue
        row: list[object] = [s]
        for n in data.networks:
            cells = data.cells(n, s)
            if not cells:
                row.append("-")
                continue
            more = fewer = 0
            for r in cells:
                ref = index.get((r.trial, r.goal, n, REFERENCE))
                if ref is not None and ref.solved != r.solved:
                    more += r.solved
                    fewer += ref.solved
            row.append(f"+{more} / -{fewer}" if more or fewer else "same")
        rows.append(row)
    return md_table(["solver", *(net_name(n) for n in data.networks)], rows)


def lifted_md(data: ReportData, solver: str = "fd-lifted-gen") -> str:
    """The lifted GEN planner (concrete trees) against exact REG and GEN retrieval on the same goals."""
    cells = data.cells("gen", solver)
    if not cells or REFERENCE not in data.solvers:
        return ""
    index = data.by_key()
    reg = [index.get((r.trial, r.goal, "reg", REFERENCE)) for r in cells]
    gen = [index.get((r.trial, r.goal, "gen", REFERENCE)) for r in cells]
    rows = [["goals asked", len(cells)], [f"{solver} solves", sum(r.solved for r in cells)]]
    for name, refs in (("REG", reg), ("GEN", gen)):
        if all(x is not None for x in refs):
            rows.append([f"{name} {REFERENCE} solves", sum(x.solved for x in refs)])
            rows.append([f"solved by {solver}, not by {name} {REFERENCE}",
                         sum(r.solved and not x.solved for r, x in zip(cells, refs, strict=True))])
            rows.append([f"solved by {name} {REFERENCE}, not by {solver}",
                         sum(x.solved and not r.solved for r, x in zip(cells, refs, strict=True))])
    return md_table(["", "goals"], rows)


# -- quality -------------------------------------------------------------------------------------

def quality_md(data: ReportData) -> str:
    """Tree sizes of each solver against the optimum, on the goals both solved."""
    index = data.by_key()
    optimum = [s for s in ("native-optimal", "fd-tree-opt") if s in data.solvers]
    if not optimum:
        return "_Not computed: run `native-optimal` or `fd-tree-opt`._\n"
    rows, notes = [], []
    for n in data.networks:
        for s in data.solvers:
            cells = [r for r in data.cells(n, s) if r.solved and r.units is not None]
            if not cells:
                continue
            # trees of concrete units (lifted GEN) are compared with REG's optimum, the others with their network's
            base = "reg" if s in CONCRETE_TREES else n
            pairs = []
            for r in cells:
                best = [o.units for o in (index.get((r.trial, r.goal, base, x)) for x in optimum)
                        if o is not None and o.solved and o.units is not None]
                if best:
                    pairs.append((r.units, min(best)))
            if not pairs:
                continue
            excess = [u - b for u, b in pairs]
            rows.append([net_name(n), s, len(pairs), statistics.fmean(u for u, _ in pairs),
                         statistics.fmean(b for _, b in pairs), sum(e > 0 for e in excess), max(excess),
                         sum(e < 0 for e in excess)])
        both = [(a, index.get((a.trial, a.goal, n, "fd-tree-opt"))) for a in data.cells(n, "native-optimal")]
        both = [(a, b) for a, b in both if b is not None and a.solved and b.solved and a.proven_optimal]
        if both:
            mismatch = sum(a.units != b.units for a, b in both)
            notes.append(f"{net_name(n)}: native-optimal (proven) and fd-tree-opt find optima of the same size "
                         f"on {len(both) - mismatch} of {len(both)} goals"
                         + (f" -- **{mismatch} MISMATCHES**" if mismatch else ""))
        solved = [r for r in data.cells(n, "native-optimal") if r.solved]
        unproven = sum(r.proven_optimal is False for r in solved)
        if unproven:
            notes.append(f"{net_name(n)}: native-optimal hit its node limit on {unproven} of {len(solved)} "
                         "solved goals (best tree found, not proven optimal)")
    if not rows:
        return "_No solver returned trees._\n"
    text = md_table(["network", "solver", "goals", "mean units", "mean optimum", "larger than optimum",
                     "max excess units", "smaller than optimum"], rows, "ll" + "r" * 6)
    if notes:
        text += "\n" + "".join(f"- {x}\n" for x in notes)
    return text


# -- statuses and validation ---------------------------------------------------------------------

def statuses_md(data: ReportData) -> str:
    """Cells per status for every solver and network, with the trees returned and validated."""
    rows = []
    for s in data.solvers:
        for n in data.networks:
            cells = data.cells(n, s)
            if not cells:
                continue
            count = {st: 0 for st in STATUSES}
            for r in cells:
                count[r.status] += 1
            trees = sum(r.units is not None for r in cells)
            valid = sum(r.validated is True for r in cells)
            foon = sum(r.foon_valid is True for r in cells)
            rows.append([s, net_name(n), *(count[st] for st in STATUSES), trees, valid, foon])
    return md_table(["solver", "network", *STATUSES, "trees returned", "validated", "pass FOON simulation"], rows,
                    "ll" + "r" * (len(STATUSES) + 3))


def invalid_trees(data: ReportData) -> list[Record]:
    """Cells that returned a tree or plan that does not validate."""
    return [r for r in data.records if r.units is not None and r.validated is not True]


def errors_md(data: ReportData, limit: int = 15) -> str:
    """The first cells that ended in an error, with their reasons."""
    errs = [r for r in data.records if r.status == "error"]
    if not errs:
        return ""
    rows = [(r.solver, net_name(r.network), r.trial, r.goal, r.goal_label, r.reason[:160]) for r in errs[:limit]]
    return md_table(["solver", "network", "trial", "goal", "goal node", "reason"], rows, "llrrll")


# -- plots ---------------------------------------------------------------------------------------

def _figure(width: float, height: float):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), dpi=100)
    FigureCanvasAgg(fig)
    return fig


def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", metadata={"Software": None})
    return buf.getvalue()


def plot_successes(data: ReportData) -> bytes:
    """Grouped bars: mean % of goals solved per trial by network and solver (min-max whiskers), paper ranges shaded."""
    succ = successes(data)
    goals = len(data.trials[0]["goals"]) if data.trials else 1
    asked = {s: goals_asked(data, s) or 1 for s in data.solvers}
    fig = _figure(8.5, 4.5)
    ax = fig.add_subplot(1, 1, 1)
    nets, solvers = list(data.networks), list(data.solvers)
    width = 0.8 / max(1, len(solvers))
    for i, n in enumerate(nets):
        if n in PAPER_SUCCESSES:
            a, b = PAPER_SUCCESSES[n]
            ax.fill_between([i - 0.45, i + 0.45], a, b, color="grey", alpha=0.2, lw=0,
                            label="paper (min-max)" if i == 0 else None)
    for j, s in enumerate(solvers):
        xs, means, lo, hi = [], [], [], []
        for i, n in enumerate(nets):
            counts = [100.0 * c / asked[s] for c in succ.get((n, s), {}).values()]
            if not counts:
                continue
            m = statistics.fmean(counts)
            xs.append(i - 0.4 + width * (j + 0.5))
            means.append(m)
            lo.append(m - min(counts))
            hi.append(max(counts) - m)
        if xs:
            label = s if asked[s] == goals else f"{s} (first {asked[s]} goals)"
            ax.bar(xs, means, width, yerr=[lo, hi], capsize=2, label=label)
    ax.set_xticks(range(len(nets)), [net_name(n) for n in nets])
    ax.set_ylim(0, 100)
    ax.set_ylabel("% of a trial's goals solved")
    ax.set_title("Successes per trial (mean, min-max over trials)")
    ax.legend(fontsize=7, ncols=2, loc="upper left")
    fig.tight_layout()
    return _png(fig)


def plot_times(data: ReportData) -> bytes:
    """Box plots of solve time per goal (ms, log scale), one panel per network, one box per solver."""
    nets = [n for n in data.networks if any(r.network == n for r in data.records)]
    fig = _figure(4.2 * max(1, len(nets)), 4.5)
    first = None
    for i, n in enumerate(nets, start=1):
        ax = fig.add_subplot(1, len(nets), i, sharey=first)
        first = first or ax
        labels, values = [], []
        for s in data.solvers:
            ts = [max(solve_time(r) * 1000, 1e-3) for r in data.cells(n, s)]
            if ts:
                labels.append(s)
                values.append(ts)
        if values:
            ax.boxplot(values, tick_labels=labels, showfliers=True, flierprops={"markersize": 2})
        ax.set_yscale("log")
        ax.set_title(net_name(n))
        ax.tick_params(axis="x", labelrotation=60, labelsize=7)
        if i == 1:
            ax.set_ylabel("solve time per goal (ms, log)")
    fig.tight_layout()
    return _png(fig)


PLOTS = {"successes.png": plot_successes, "times.png": plot_times}


# -- the report ----------------------------------------------------------------------------------

def context(data: ReportData, plot_links: dict[str, str]) -> dict:
    """Everything the Markdown template shows."""
    ref = reference_solver(data)
    succ = successes(data)
    times = trial_times(data)
    ag = agreement(data)
    timed = "native-greedy" if "native-greedy" in data.solvers else ref
    summary = {}
    for n in data.networks:
        counts = list(succ.get((n, ref), {}).values())
        greedy = list(succ.get((n, "native-greedy"), {}).values())
        t = times.get((n, timed)) or {}
        summary[n] = {
            "name": net_name(n),
            "span": _span(counts), "mean": statistics.fmean(counts) if counts else math.nan,
            "greedy_span": _span(greedy),
            "paper_span": _paper_span(n),
            "ms_per_trial": statistics.fmean(t.values()) * 1000 if t else math.nan,
            "paper_ms": PAPER_TIME_MS.get(n),
        }
    goals = len(data.trials[0]["goals"]) if data.trials else 0
    in_ranges = bool(goals) and all(
        n in PAPER_SUCCESSES and PAPER_SUCCESSES[n][0] <= 100 * summary[n]["mean"] / goals <= PAPER_SUCCESSES[n][1]
        for n in data.networks)
    index = data.by_key()
    greedy = data.cells_of("native-greedy")
    greedy_exact = bool(greedy) and all(
        (ref_rec := index.get((r.trial, r.goal, r.network, REFERENCE))) is not None and ref_rec.solved == r.solved
        for r in greedy)
    return {
        "in_paper_ranges": in_ranges,
        "greedy_exact": greedy_exact,
        "meta": data.meta,
        "networks": data.networks,
        "solvers": data.solvers,
        "reference": ref,
        "timed": timed,
        "trials": data.trials,
        "summary": summary,
        "table2": table2(data),
        "table2_by_solver": table2_by_solver(data),
        "table3": table3(data),
        "table3_per_goal": table3_per_goal(data),
        "agreement": agreement_md(data),
        "agreement_ok": ag is not None and not ag.disagreements,
        "agreement_matrix": agreement_matrix(data),
        "lifted": lifted_md(data),
        "quality": quality_md(data),
        "statuses": statuses_md(data),
        "invalid": len(invalid_trees(data)),
        "errors": errors_md(data),
        "sensitivity": "",
        "plots": plot_links,
        "paper_cpu": PAPER_CPU,
    }


def render_markdown(data: ReportData, plot_links: dict[str, str]) -> str:
    """The Markdown report (template `templates/experiment.md.j2`)."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("foon2pddl", "templates"), autoescape=False,
                             undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True,
                             keep_trailing_newline=True)
    env.filters["num"] = _cell
    return env.get_template("experiment.md.j2").render(context(data, plot_links))


def report_files(data: ReportData, out_dir: Path, report_path: Path) -> dict[Path, str | bytes]:
    """Every report file by path: results.csv and the plots in `out_dir`, the Markdown at `report_path`."""
    import os

    files: dict[Path, str | bytes] = {out_dir / "results.csv": to_csv(data.records)}
    links = {}
    for name, plot in PLOTS.items():
        path = out_dir / name
        files[path] = plot(data)
        links[name] = Path(os.path.relpath(path, report_path.parent)).as_posix()
    files[report_path] = render_markdown(data, links)
    return files


def write_report(data: ReportData, out_dir: Path, report_path: Path) -> list[Path]:
    """Write the CSV, plots and Markdown (all or none); return their paths."""
    from ..io.atomic import atomic_write_many

    files = report_files(data, out_dir, report_path)
    atomic_write_many(files)
    return sorted(files)
