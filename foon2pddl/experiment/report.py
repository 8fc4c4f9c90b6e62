"""Reports of an experiment: CSV, a Markdown report beside the seed paper's tables, PNG plots.

`tables.py` computes (row dataclasses), `render.py` formats Markdown and CSV,
`plots.py` draws; this module puts them into the template
(`templates/experiment.md.j2`) and writes every file atomically (`write_report`,
the I/O edge). With sweeps, the main tables are those of the first point of the
sweep, and each swept parameter gets its own table and plot over all points.
"""

from __future__ import annotations

import math
import statistics
from pathlib import Path

from .plots import PLOTS, plot_sweep, sweep_plot_name
from .render import (
    _cell,
    _paper_span,
    _span,
    agreement_matrix,
    agreement_md,
    errors_md,
    failures_md,
    gen_md,
    lifted_md,
    optimality_md,
    physical_planners_md,
    quality_md,
    short_labels_md,
    short_md,
    statuses_md,
    sweep_md,
    table2,
    table2_by_solver,
    table2_physical,
    table3,
    table3_per_goal,
    to_csv,
    verdicts_md,
)
from .solvers import Role
from .tables import (
    PAPER_CPU,
    PAPER_SUCCESSES,
    PAPER_TIME_MS,
    REFERENCE,
    Agreement,
    ReportData,
    agreement,
    invalid_trees,
    net_name,
    reference_solver,
    successes,
    trial_times,
)

__all__ = ["Agreement", "ReportData", "agreement", "agreement_md", "context", "invalid_trees", "render_markdown",
           "report_files", "to_csv", "trial_times", "write_report"]


def context(data: ReportData, plot_links: dict[str, str]) -> dict:
    """Everything the Markdown template shows."""
    ref = reference_solver(data)
    succ = successes(data)
    times = trial_times(data)
    ag = agreement(data)
    paper = next(iter(data.role(Role.PAPER)), None)
    timed = paper or ref
    summary = {}
    for n in data.networks:
        counts = list(succ.get((n, ref), {}).values())
        greedy = list(succ.get((n, paper), {}).values())
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
    greedy = data.cells_of(paper) if paper else []
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
        "optimality": optimality_md(data),
        "sweeps": [{"name": name, "shown": ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in values),
                    "table": sweep_md(data, name), "plot": plot_links.get(sweep_plot_name(name), "")}
                   for name, values in data.sweeps],
        "paper_solver": paper,
        "plots": plot_links,
        "paper_cpu": PAPER_CPU,
        **physical_context(data, summary),
    }


def physical_context(data: ReportData, summary: dict) -> dict:
    """The physical-execution sections (`physical.py`); `summary` gains each network's executable mean."""
    from .physical import gen_rows, physical_planners, physical_successes, planner_means, scheduled, short_labels

    ref = reference_solver(data)
    per = physical_successes(data, ref) if ref else {}
    for n, trials in per.items():
        if n in summary:
            done = [b for _, b in trials.values()]
            solved = sum(a for a, _ in trials.values())
            summary[n]["executable_mean"] = statistics.fmean(done) if done else math.nan
            summary[n]["executable_share"] = 100.0 * sum(done) / solved if solved else math.nan
    gen = gen_rows(data)
    return {
        "physical": scheduled(data),
        "per_item": data.meta.get("objects_per_item", 1),
        "verdicts": verdicts_md(data),
        "table2_physical": table2_physical(data),
        "short": short_md(data),
        "short_labels": short_labels_md(data),
        "failures": failures_md(data),
        "concrete_table": gen_md(data),
        "gen_means": None if gen is None else {
            f: statistics.fmean(getattr(g, f) for g in gen[2]) for f in ("category", "concrete", "concrete_executable")},
        "physical_planners": physical_planners_md(data),
        "replays": [{"solver": p.solver, "name": net_name(p.network), "plans": p.plans, "holders": p.holders,
                     "failures": p.replay_failures, "no_plan": sum(k for _, k in p.no_plan),
                     "statuses": ", ".join(f"{status} {k}" for status, k in p.no_plan)}
                    for p in physical_planners(data)],
        "planner_means": ", ".join(f"`{s}` {net_name(n)} {_cell(m)}" for s, n, m in planner_means(data)),
        "top_short": list(dict.fromkeys(f"`{label}`" for _, label, _, _ in short_labels(data, ref or REFERENCE, 6)))[:3],
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

    every = data.all_records if data.all_records is not None else data.records
    files: dict[Path, str | bytes] = {out_dir / "results.csv": to_csv(every)}
    links = {}
    plots = {**PLOTS, **{sweep_plot_name(p): (lambda d, p=p: plot_sweep(d, p)) for p, _ in data.sweeps}}
    for name, plot in plots.items():
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
