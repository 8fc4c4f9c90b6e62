"""Report plots (PNG bytes) through matplotlib's Agg canvas directly: no pyplot, no global backend."""

from __future__ import annotations

import io
import statistics

from .tables import PAPER_SUCCESSES, ReportData, goals_asked, net_name, solve_time, successes, sweep_rows


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

def plot_sweep(data: ReportData, param: str) -> bytes:
    """Successes per trial and time per goal (log) against one swept parameter, one line per network and solver."""
    rows = sweep_rows(data, param)
    fig = _figure(10.0, 4.2)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    numeric = all(isinstance(r.value, int | float) for r in rows)
    values = next((v for n, v in data.sweeps if n == param), ())
    pos = {v: (v if numeric else i) for i, v in enumerate(values)}
    for s in data.solvers:
        for n in data.networks:
            mine = [r for r in rows if r.solver == s and r.network == n]
            if not mine:
                continue
            xs = [pos[r.value] for r in mine]
            label = f"{net_name(n)} {s}"
            left.plot(xs, [r.successes for r in mine], marker="o", label=label)
            right.plot(xs, [max(r.ms_per_goal, 1e-3) for r in mine], marker="o", label=label)
    for ax in (left, right):
        ax.set_xlabel(param)
        if not numeric:
            ax.set_xticks(range(len(values)), [str(v) for v in values])
    left.set_ylabel("goals solved per trial (mean)")
    right.set_ylabel("solve time per goal (ms, mean, log)")
    right.set_yscale("log")
    left.set_title(f"Successes against {param}")
    right.set_title(f"Time against {param}")
    left.legend(fontsize=6, ncols=2)
    fig.tight_layout()
    return _png(fig)


PLOTS = {"successes.png": plot_successes, "times.png": plot_times}


def sweep_plot_name(param: str) -> str:
    return f"sweep-{param}.png"
