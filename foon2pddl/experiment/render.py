"""Rendering report tables: Markdown and CSV text from the rows `tables.py` computes."""

from __future__ import annotations

import csv
import io
import statistics
from collections.abc import Iterable, Sequence

from .networks import DEFAULT_NETWORK
from .records import STATUSES, CellStatus, Record
from .solvers import SOLVERS, Role
from .tables import (
    FD_TREE,
    PAPER_CPU,
    PAPER_SUCCESSES,
    PAPER_TIME_MS,
    REFERENCE,
    ReportData,
    agreement,
    goals_asked,
    net_name,
    optimality_rows,
    optimum_checks,
    quality_rows,
    reference_solver,
    solve_time,
    status_rows,
    successes,
    sweep_rows,
    trial_times,
)


def to_csv(records: Iterable[Record]) -> str:
    """One row per cell, sorted by key; times in milliseconds, one column per phase.

    Columns added since the first version come last, and only when some record has them:
    `bound` and `gap` (anytime optimal solvers), the physical schedule's `executable`, `executable_reason`
    and `extra_objects` (trees scheduled over the kitchen's objects), then one column per swept parameter.
    """
    records = sorted(records, key=lambda r: (*r.key[:4], repr(r.key[4])))
    phases = sorted({p for r in records for p in r.times})
    anytime = any(r.bound is not None or r.gap is not None for r in records)
    params = list(dict.fromkeys(p for r in records for p in r.params))
    physical = any(r.executable is not None for r in records)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["trial", "goal", "network", "solver", "goal_label", "status", "solved", "validated", "foon_valid",
                "units", "plan_length", "proven_optimal", "time_ms", "setup_ms", *(f"{p}_ms" for p in phases), "reason",
                *(("bound", "gap") if anytime else ()),
                *(("executable", "executable_reason", "extra_objects") if physical else ()), *params])

    def opt(v):
        return "" if v is None else v

    for r in records:
        w.writerow([r.trial, r.goal, r.network, r.solver, r.goal_label, r.status, r.solved, opt(r.validated),
                    opt(r.foon_valid), opt(r.units), opt(r.plan_length), opt(r.proven_optimal), f"{solve_time(r) * 1000:.3f}",
                    f"{r.setup * 1000:.3f}", *(f"{r.times[p] * 1000:.3f}" if p in r.times else "" for p in phases),
                    r.reason, *((opt(r.bound), opt(r.gap)) if anytime else ()),
                    *((opt(r.executable), opt(r.executable_reason), opt(r.extra_objects)) if physical else ()),
                    *(opt(r.params.get(p)) for p in params)])
    return buf.getvalue()


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


def lifted_md(data: ReportData) -> str:
    """The lifted GEN planner (concrete trees) against exact REG and GEN retrieval on the same goals."""
    solver = next(iter(data.role(Role.CONCRETE)), None)
    lifted = (SOLVERS[solver].networks or (DEFAULT_NETWORK,))[0] if solver else DEFAULT_NETWORK
    cells = data.cells(lifted, solver) if solver else []
    if not cells or REFERENCE not in data.solvers:
        return ""
    index = data.by_key()
    reg = [index.get((r.trial, r.goal, DEFAULT_NETWORK, REFERENCE)) for r in cells]
    gen = [index.get((r.trial, r.goal, lifted, REFERENCE)) for r in cells]
    rows = [["goals asked", len(cells)], [f"{solver} solves", sum(r.solved for r in cells)]]
    for name, refs in ((net_name(DEFAULT_NETWORK), reg), (net_name(lifted), gen)):
        if all(x is not None for x in refs):
            rows.append([f"{name} {REFERENCE} solves", sum(x.solved for x in refs)])
            rows.append([f"solved by {solver}, not by {name} {REFERENCE}",
                         sum(r.solved and not x.solved for r, x in zip(cells, refs, strict=True))])
            rows.append([f"solved by {name} {REFERENCE}, not by {solver}",
                         sum(x.solved and not r.solved for r, x in zip(cells, refs, strict=True))])
    return md_table(["", "goals"], rows)


def quality_md(data: ReportData) -> str:
    """Tree sizes of each solver against the optimum, on the goals both solved, with notes."""
    optimum = data.role(Role.OPTIMUM)
    if not optimum:
        return "_Not computed: run an optimal solver (" + ", ".join(f"`{s}`" for s in _registered(Role.OPTIMUM)) + ")._\n"
    rows = [[net_name(q.network), q.solver, q.goals, q.mean_units, q.mean_optimum, q.larger, q.max_excess, q.smaller]
            for q in quality_rows(data)]
    if not rows:
        return "_No solver returned trees._\n"
    notes = [f"{net_name(c.network)}: {c.native} (proven) and {c.planner} find optima of the same size "
             f"on {c.compared - c.mismatches} of {c.compared} goals"
             + (f" -- **{c.mismatches} MISMATCHES**" if c.mismatches else "") for c in optimum_checks(data)]
    text = md_table(["network", "solver", "goals", "mean units", "mean optimum", "larger than optimum",
                     "max excess units", "smaller than optimum"], rows, "ll" + "r" * 6)
    if notes:
        text += "\n" + "".join(f"- {x}\n" for x in notes)
    return text


def _registered(role: Role) -> tuple[str, ...]:
    from .solvers import with_role

    return with_role(role)


def optimality_md(data: ReportData) -> str:
    """How often optimality was proven, per solver and network (empty when no solver says)."""
    rows = [[o.solver, net_name(o.network), o.trees, o.proven, f"{100.0 * o.proven / o.trees:.1f} %",
             None if o.median_gap is None else f"{100.0 * o.median_gap:.1f} %", o.median_bound]
            for o in optimality_rows(data)]
    if not rows:
        return ""
    return md_table(["solver", "network", "trees", "proven optimal", "share proven", "median gap of the rest",
                     "median bound of the rest"], rows, "llrrrrr")


#: Statuses given a column only when some cell has them (a lost worker; a plan the physical replay rejects).
_SHOWN_IF_ANY = frozenset({CellStatus.LOST, CellStatus.REJECTED})


def statuses_md(data: ReportData) -> str:
    """Cells per status for every solver and network, with the trees returned and validated."""
    rows = status_rows(data)
    shown = [s for s in STATUSES if s not in _SHOWN_IF_ANY or any(r.counts.get(s) for r in rows)]
    return md_table(["solver", "network", *shown, "trees returned", "validated", "pass FOON simulation"],
                    [[r.solver, net_name(r.network), *(r.counts.get(s, 0) for s in shown), r.trees, r.validated,
                      r.foon_valid] for r in rows], "ll" + "r" * (len(shown) + 3))


def sweep_md(data: ReportData, param: str) -> str:
    """Mean successes per trial and mean ms per goal of every solver and network, at each value of `param`."""
    rows = sweep_rows(data, param)
    values = next((v for n, v in data.sweeps if n == param), ())
    by = {(r.solver, r.network, r.value): r for r in rows}
    table = []
    for s in data.solvers:
        for n in data.networks:
            if any((s, n, v) in by for v in values):
                table.append([s, net_name(n), *(f"{by[(s, n, v)].successes:.1f} / {by[(s, n, v)].ms_per_goal:.2f} ms"
                                                 if (s, n, v) in by else "-" for v in values)])
    return md_table(["solver", "network", *(f"{param}={v:g}" if isinstance(v, float) else f"{param}={v}"
                                             for v in values)], table, "ll" + "r" * len(values))


def errors_md(data: ReportData, limit: int = 15) -> str:
    """The first cells that ended in an error, with their reasons."""
    errs = [r for r in data.records if r.status == "error"]
    if not errs:
        return ""
    rows = [(r.solver, net_name(r.network), r.trial, r.goal, r.goal_label, r.reason[:160]) for r in errs[:limit]]
    return md_table(["solver", "network", "trial", "goal", "goal node", "reason"], rows, "llrrll")


# -- physical execution (`physical.py`) ----------------------------------------------------------

def verdicts_md(data: ReportData) -> str:
    """Schedule verdicts of every solver's trees, per network."""
    from .physical import VERDICTS, verdict_rows

    rows = [[v.solver, net_name(v.network), v.trees, *(v.counts.get(x, 0) for x in VERDICTS),
             f"{100.0 * v.share:.1f} %"] for v in verdict_rows(data)]
    return md_table(["solver", "network", "trees", *VERDICTS, "share executable"], rows,
                    "ll" + "r" * (len(VERDICTS) + 2)) if rows else ""


def table2_physical(data: ReportData) -> str:
    """The paper's Table 2 again, each count beside the trees the trial's objects carry out (`solved / executable`)."""
    from .physical import physical_successes, planner_successes

    ref = reference_solver(data)
    per = physical_successes(data, ref) if ref else {}
    nets = [n for n in data.networks if n in per]
    if not nets:
        return ""
    plans = planner_successes(data)  # beside the trees, each physical planner's plans carried out
    rows = [[t["trial"], *(f"{per[n][t['trial']][1]} of {per[n][t['trial']][0]}" for n in nets),
             *(p[t["trial"]] for p in plans.values())] for t in data.trials]
    executable = [*([per[n][t["trial"]][1] for t in data.trials] for n in nets),
                  *([p[t["trial"]] for t in data.trials] for p in plans.values())]
    rows.append(["min-max", *(_span(e) for e in executable)])
    rows.append(["mean", *(f"{statistics.fmean(e):.1f}" for e in executable)])
    rows.append(["paper (min-max, not physical)", *(_paper_span(n) for n in nets), *("-" for _ in plans)])
    goals = len(data.trials[0]["goals"]) if data.trials else 0
    return md_table(["trial", *(f"{net_name(n)} executable (of {goals})" for n in nets),
                     *(f"{net_name(n)} `{s}` plans carried out" for s, n in plans)], rows)


def short_md(data: ReportData) -> str:
    """Trees the kitchen runs short for: how many more objects they need, and those more objects cannot fix."""
    from .physical import short_rows

    rows = [[r.solver, net_name(r.network), r.short, r.more_suffice, r.mean_extra, r.max_extra, r.used_up]
            for r in short_rows(data)]
    return md_table(["solver", "network", "short", "more objects suffice", "mean extra objects",
                     "max extra objects", "used-up (a unit must fire again)"], rows, "llrrrrr") if rows else ""


def short_labels_md(data: ReportData) -> str:
    """The labels that stop the reference's trees most often, with the median step they stop at."""
    from .physical import short_labels

    rows = [[net_name(n), label, count, step] for n, label, count, step in short_labels(data)]
    return md_table(["network", "label", "trees it stops", "median step"], rows, "llrr") if rows else ""


def failures_md(data: ReportData) -> str:
    """The first trees of the reference that are not executable, each with its verdict, label and step."""
    from .physical import failures

    rows = [(net_name(r.network), r.trial, r.goal, r.goal_label, r.executable, r.executable_reason or "")
            for r in failures(data)]
    return md_table(["network", "trial", "goal", "goal node", "verdict", "why (label and step)"], rows,
                    "lrrlll") if rows else ""


def gen_md(data: ReportData) -> str:
    """GEN per trial: category-level successes against concrete (object-fillable) ones, beside the paper's range."""
    from .physical import gen_rows

    found = gen_rows(data)
    if found is None:
        return ""
    network, solver, rows = found
    table = [[g.trial, g.category, g.concrete, g.concrete_executable] for g in rows]
    for name, fn in (("min-max", _span), ("mean", lambda v: f"{statistics.fmean(v):.1f}")):
        table.append([name, *(fn([getattr(g, f) for g in rows]) for f in ("category", "concrete",
                                                                            "concrete_executable"))])
    table.append(["paper (min-max)", _paper_span(network), "-", "-"])
    goals = len(data.trials[0]["goals"]) if data.trials else 0
    return md_table(["trial", f"category-level ({REFERENCE}, of {goals})", f"concrete ({solver})",
                     "concrete and executable"], table)


def physical_planners_md(data: ReportData) -> str:
    """Planners over physical objects: goals solved, plans the trial's objects carry out, plans that need more
    objects (how many), against the reference's executable trees; plan length against the reference's tree."""
    from .physical import physical_planners

    rows = [[p.solver, net_name(p.network), p.solved, p.replayed, p.more_objects, p.mean_extra,
             p.reference_executable, p.mean_steps, p.mean_repeated, p.mean_units] for p in physical_planners(data)]
    return md_table(["solver", "network", "goals solved", "carried out with the trial's objects",
                     "only with more objects", "mean extra objects", f"{REFERENCE} trees executable",
                     "mean plan steps", "of them repeated firings", f"mean {REFERENCE} tree units"], rows,
                    "llrrrrrrrr") if rows else ""
