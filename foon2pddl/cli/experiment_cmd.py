"""`foon2pddl experiment`: the seed paper's REG/EXP/GEN comparison, native retrieval against planners."""

from __future__ import annotations

import shlex
import sys
from contextlib import nullcontext
from pathlib import Path

import click

from ..errors import FoonInputError, did_you_mean
from ..experiment.params import PARAMS, parse_sweep
from ..experiment.protocol import DEFAULT_GOALS, DEFAULT_KITCHEN_FRACTION, DEFAULT_SEED, DEFAULT_TRIALS, Protocol
from ..experiment.provenance import code_version, describe
from ..experiment.setting import DEFAULT_TIME_LIMIT
from ..experiment.solvers import DEFAULT_SOLVERS, SOLVERS
from ..generalize.modes import DEFAULT_MODE, SIMILARITY_MODES
from ..model.words import count
from . import main
from .options import level_option, paths_argument

#: Exit statuses of `experiment` (documented in its --help and in docs/experiment.md).
EXIT_DISAGREEMENT = 3  # the run finished, but solvers disagree or a returned tree does not validate
EXIT_INCOMPLETE = 4  # cells were lost with their workers; running the same command again redoes them


def _bad(option: str, message: str) -> click.BadParameter:
    """A bad value of `option`: `Invalid value for '--option': ...`, the form every command's options use."""
    return click.BadParameter(message, param_hint=f"'{option}'")


def _names(text: str, known, what: str) -> tuple[str, ...]:
    names = tuple(dict.fromkeys(x.strip().lower() for x in text.split(",") if x.strip()))
    unknown = [n for n in names if n not in known]
    if unknown or not names:
        hint = did_you_mean(unknown[0], known) if unknown else ""
        raise _bad(f"--{what}", f"unknown {', '.join(map(repr, unknown)) or 'empty list'}{hint} "
                                f"(choose from {', '.join(known)})")
    return names


def _sweeps(items) -> tuple[tuple[str, tuple], ...]:
    out: dict[str, tuple] = {}
    for item in items:
        try:
            name, values = parse_sweep(item)
        except ValueError as exc:
            raise _bad("--sweep", str(exc)) from None
        if name in out:
            raise _bad("--sweep", f"{name} given twice")
        out[name] = values
    return tuple(out.items())


def _goal_limits(items, solvers) -> tuple[tuple[str, int], ...]:
    out = {}
    for item in items:
        name, sep, n = item.partition("=")
        name = name.strip().lower()
        if not sep or not n.strip().isdigit() or int(n) < 1 or name not in solvers:
            raise _bad("--goal-limit", f"{item!r}: expected SOLVER=N with N >= 1 and "
                                       f"SOLVER one of the chosen solvers ({', '.join(solvers)})")
        out[name] = int(n)
    return tuple(sorted(out.items()))


def command_line(paths, protocol: Protocol, networks, solvers, jobs: int, time_limit: float, out_dir: Path,
                 report: Path, limits: tuple[tuple[str, int], ...] = (), sweeps: tuple = ()) -> str:
    """The command that reproduces a run (written into the report)."""
    parts = ["foon2pddl", "experiment", *(str(p) for p in paths), "--trials", str(protocol.trials),
             "--goals", str(protocol.goals), "--kitchen-fraction", f"{protocol.kitchen_fraction:g}",
             "--seed", str(protocol.seed), "--level", str(protocol.level), "--similarity", protocol.similarity,
             *(("--objects-per-item", str(protocol.objects_per_item)) if protocol.objects_per_item != 1 else ()),
             "--networks", ",".join(networks),
             "--solvers", ",".join(solvers), "--time-limit", f"{time_limit:g}", "--jobs", str(jobs),
             *(x for s, n in limits for x in ("--goal-limit", f"{s}={n}")),
             *(x for name, values in sweeps for x in ("--sweep", f"{name}=" + ",".join(f"{v:g}" if isinstance(v, float) else str(v)
                                                                   for v in values))),
             "-o", str(out_dir), "--report", str(report)]
    return shlex.join(parts)


@main.command("experiment")
@paths_argument
@click.option("--trials", type=click.IntRange(1), default=DEFAULT_TRIALS, show_default=True,
              help="Trials (each: a random kitchen and random goals).")
@click.option("--goals", type=click.IntRange(1), default=DEFAULT_GOALS, show_default=True, help="Goals per trial.")
@click.option("--kitchen-fraction", "fraction", type=click.FloatRange(0, 1, min_open=True),
              default=DEFAULT_KITCHEN_FRACTION, show_default=True,
              help="Fraction of the default kitchen a trial's kitchen keeps.")
@click.option("--networks", default="reg,exp,gen", show_default=True, help="Networks to compare (reg, exp, gen).")
@click.option("--solvers", default=",".join(DEFAULT_SOLVERS), show_default=True,
              help=f"Solvers to compare, from: {', '.join(SOLVERS)}.")
@click.option("--seed", type=int, default=DEFAULT_SEED, show_default=True, help="Master seed.")
@level_option
@click.option("--similarity", type=click.Choice(list(SIMILARITY_MODES)), default=DEFAULT_MODE, show_default=True,
              help="FOON-EXP's similarity mode (docs/generalization.md); recorded in the protocol.")
@click.option("--objects-per-item", "per_item", type=click.IntRange(1), default=1, show_default=True,
              help="Physical objects per kitchen item when returned trees are scheduled (docs/experiment.md); "
                   "recorded in the protocol.")
@click.option("--jobs", "-j", type=click.IntRange(1), default=1, show_default=True,
              help="Workers: 1 runs the cells in this process; N > 1 starts a local Dask cluster of N workers.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run the cells on an existing Dask cluster (e.g. tcp://10.0.0.5:8786) instead of locally.")
@click.option("--time-limit", type=click.FloatRange(0, min_open=True), default=DEFAULT_TIME_LIMIT,
              show_default=True, help="Seconds per planner run.")
@click.option("-o", "--output-dir", "out_dir", type=click.Path(path_type=Path, file_okay=False),
              default=Path("experiment"), show_default=True,
              help="Directory for results.jsonl, results.csv, protocol.json and the plots.")
@click.option("--report", "report", type=click.Path(path_type=Path, dir_okay=False), default=None,
              help="Markdown report to write [default: DIR/report.md].")
@click.option("--sweep", "sweeps", multiple=True, metavar="NAME=V1,V2,...",
              help=f"Run the grid at every value (repeatable: every combination); NAME one of {', '.join(PARAMS)}.")
@click.option("--sensitivity", default="none", hidden=True, help="Replaced by --sweep kitchen-fraction=...; ignored.")
@click.option("--goal-limit", "goal_limits", multiple=True, metavar="SOLVER=N",
              help="Ask SOLVER only the first N goals of each trial (for slow solvers; repeatable).")
@click.option("--fresh", is_flag=True, help="Discard results already in DIR instead of resuming.")
@click.option("--progress/--no-progress", default=True, show_default=True,
              help="Progress on stderr: a bar on a terminal, otherwise a line every second (cells done, rate, ETA).")
def experiment(paths, trials, goals, fraction, networks, solvers, seed, level, similarity, per_item, jobs, scheduler,
               time_limit, out_dir,
               report, sweeps, sensitivity, goal_limits, fresh, progress) -> None:
    """Run the REG/EXP/GEN experiment and write results (JSONL, CSV), a Markdown report and plots.

    Each cell (trial, goal, network, solver, swept values) is appended to DIR/results.jsonl as it
    finishes; running the same command again skips the cells already done, so an interrupted run
    resumes (damaged lines are reported and their cells recomputed). Exit status: 0 done; 2 bad
    input or options; 3 native complete retrieval and Fast Downward (tree encoding) disagree on some
    cell, or a returned tree does not validate; 4 cells were lost with their workers (run the same
    command again to redo them); 130 interrupted.
    """
    from ..experiment import collector, runner
    from ..experiment.config import Config
    from ..experiment.networks import NETWORKS
    from ..experiment.report import ReportData, agreement, invalid_trees, write_report
    from ..model.bulk import full_gc_paused
    from .progress import BEAT, slow_step

    step = slow_step if progress else runner.silent_step  # --no-progress: no line at all

    nets = _names(networks, NETWORKS, "networks")
    chosen = _names(solvers, tuple(SOLVERS), "solvers")
    limits = _goal_limits(goal_limits, chosen)
    swept = _sweeps(sweeps)
    if sensitivity.strip().lower() not in ("", "none", "off"):
        click.echo("warning: --sensitivity is replaced by --sweep kitchen-fraction=V1,V2,...; ignored", err=True)
    protocol = Protocol(trials, goals, fraction, seed, level, similarity=similarity, objects_per_item=per_item)
    report = report or out_dir / "report.md"
    config = Config(tuple(str(p) for p in paths), protocol, nets, chosen, out_dir, jobs, time_limit, limits,
                    swept, scheduler)
    try:
        summary = runner.run(config, progress=progress, fresh=fresh, step=step, every=BEAT)
    except runner.OtherResults as exc:
        raise FoonInputError(exc.path, exc.line, exc.message + "; use another -o directory, or --fresh to discard "
                                                               "them") from None
    for warning in summary.warnings:
        click.echo(warning, err=True)
    # the run froze its networks and records while its cells ran and unfroze them when it returned: frozen again
    # through the report, whose full collections walked them (1.2-2.5 s at load 20, the ticking line held up)
    with collector.building() as settle:
        building = runner.unbuilt(config)  # every cell reused, or run in workers: seconds for EXP and GEN
        with step(f"building the networks ({', '.join(NETWORKS[n].label for n in building)}) for the report") \
                if building else nullcontext():
            views = runner.views(config)
        settle()  # the run's objects, frozen: the report's collections need not walk them
        # what the report is made of is gathered under its step too: its network sizes (the node tables of FOON-EXP
        # and FOON-GEN) took 0.6 s at load 25 outside every step, after the results were read back (stop 54's pass)
        with step(f"writing the report and plots ({report})"):
            meta = {
                "command": command_line(paths, protocol, nets, chosen, jobs, time_limit, out_dir, report, limits, swept),
                "goal_limits": dict(limits),
                "inputs": ", ".join(f"`{p}`" for p in paths) or "the embedded example network",
                "files": len(runner.input_files(config.paths)),
                "fingerprint": runner.fingerprint(config.paths),
                "trials": trials, "goals": goals, "level": level, "seed": seed, "kitchen_fraction": f"{fraction:g}",
                "similarity": similarity, "objects_per_item": per_item,
                "default_kitchen": summary.default_kitchen, "goal_pool": summary.goal_pool,
                "network_sizes": [{"name": NETWORKS[v.name].label, "units": len(v.foon.units), "nodes": len(v.foon.nodes),
                                   "what": NETWORKS[v.name].summary.replace("{similarity}", similarity)} for v in views],
                "solver_descriptions": [{"name": s, "description": SOLVERS[s].description + (
                    f" (first {dict(limits)[s]} goals of each trial)" if s in dict(limits) else "")} for s in chosen],
                "time_limit": f"{time_limit:g}", "jobs": jobs, "scheduler": scheduler, "wall": f"{summary.seconds:.1f} s",
                "ran": summary.ran, "skipped": summary.skipped, "machine": machine(),
                "history": [dict(h, code=describe(h)) for h in summary.history], "code": describe(code_version()),
            }
            first = dict(config.points[0])
            data = ReportData(tuple(r for r in summary.records if r.params == first), nets, chosen,
                              tuple(t.summary() for t in summary.trials), meta, swept, summary.records)
            try:
                with full_gc_paused():  # 6-9 s, load 15
                    written = write_report(data, out_dir, report)  # matplotlib and the plots; no full collection holds a beat
            except OSError as exc:
                raise FoonInputError(str(report), 0, f"cannot write the report: {exc.strerror or exc}") from None
    solved = sum(r.solved for r in summary.records)
    took = f"in {summary.seconds:.1f} s"
    if summary.ran:  # the bar's elapsed time counts the cells only: say where the rest went
        took += (f" ({summary.cell_seconds:.1f} s running the cells, the rest reading the network, drawing the "
                 f"trials and building the networks)")
    click.echo(f"{count(summary.ran, 'cell')} run, {summary.skipped} reused, {solved} solved, {took}; "
               f"wrote {config.results_path}, " + ", ".join(str(p) for p in written))
    ag = agreement(data)
    bad = invalid_trees(data)
    if (ag is not None and ag.disagreements) or bad:
        if ag is not None and ag.disagreements:
            click.echo(f"DISAGREEMENT: native-complete and fd-tree differ on {count(len(ag.disagreements), 'cell')} "
                       f"(see {report})", err=True)
        if bad:
            click.echo(f"INVALID: {count(len(bad), 'returned tree')} {'does' if len(bad) == 1 else 'do'} not validate (see {report})", err=True)
        sys.exit(EXIT_DISAGREEMENT)
    if summary.lost:
        click.echo(f"INCOMPLETE: {count(summary.lost, 'cell')} {'was' if summary.lost == 1 else 'were'} lost with their workers; run the same command again "
                   "to redo them", err=True)
        sys.exit(EXIT_INCOMPLETE)


def machine() -> str:
    """CPU model and count, and the Python version (times in the report depend on them)."""
    import os
    import platform

    model = platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            model = next((line.split(":", 1)[1].strip() for line in fh if line.startswith("model name")), model)
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} CPUs, Python {platform.python_version()}"

