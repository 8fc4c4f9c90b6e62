"""Start-up benchmarks: what a CLI call costs before any work, with lazy against eager command loading.

Figures (medians over `ctx.repeat` interleaved runs of a fresh interpreter each):
- wall and CPU time of `python -c pass`, `foon2pddl --version` and `foon2pddl stats FILE`
  on one shared subgraph (floor: both commands <= 0.4 s wall);
- the same two commands with every command module imported first (what start-up cost when
  the CLI registered all commands eagerly), and the ratio eager / lazy;
- the import time `-X importtime` reports for each (sum of the modules' own times), and how
  many modules each imports.
The package's bytecode is written first, as installing a wheel or `make install` does: where
PYTHONDONTWRITEBYTECODE is set and nothing compiled the package, every call compiles each module
from source (stats FILE: 0.154 s CPU instead of 0.131 s, medians of 11 interleaved runs).
"""

from __future__ import annotations

import compileall
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from .harness import Context

AREA = "startup"
FLOOR = 0.4

#: Runs the CLI like `python -m foon2pddl`, after importing the command modules `EAGER` names.
_RUN = """
import importlib, sys
from foon2pddl import cli
for name in sorted(set(cli.COMMANDS.values())) if sys.argv[1] == "eager" else ():
    importlib.import_module("foon2pddl.cli." + name)
sys.argv = ["foon2pddl", *sys.argv[2:]]
from foon2pddl.__main__ import run
run()
"""


def _env() -> dict[str, str]:
    root = str(Path(__file__).resolve().parent.parent)
    return dict(os.environ, PYTHONPATH=root)


def _once(argv: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds (user + system) of one child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, env=_env(), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _import_time(argv: list[str]) -> tuple[float, int]:
    """Seconds of import `-X importtime` reports (each module's own time, summed) and the module count."""
    proc = subprocess.run([argv[0], "-X", "importtime", *argv[1:]], env=_env(), capture_output=True, text=True,
                          check=True)
    own = [int(line.split("|")[0].split(":")[1]) for line in proc.stderr.splitlines()
           if line.startswith("import time:") and "self [us]" not in line]
    return sum(own) / 1e6, len(own)


def run(ctx: Context) -> None:
    sample = sorted((ctx.shared / "foon-subgraphs").glob("*.txt"))[0]
    py = sys.executable
    package = Path(__file__).resolve().parent.parent / "foon2pddl"
    compileall.compile_dir(package, quiet=1)  # what an installed package has
    cases = {
        "python -c pass": [py, "-c", "pass"],
        "--version": [py, "-c", _RUN, "lazy", "--version"],
        "--version (eager)": [py, "-c", _RUN, "eager", "--version"],
        "stats FILE": [py, "-c", _RUN, "lazy", "stats", str(sample)],
        "stats FILE (eager)": [py, "-c", _RUN, "eager", "stats", str(sample)],
    }
    repeat = 3 if ctx.quick else max(5, ctx.repeat)
    for argv in cases.values():
        _once(argv)  # warm the file cache
    walls: dict[str, list[float]] = {k: [] for k in cases}
    cpus: dict[str, list[float]] = {k: [] for k in cases}
    for _ in range(repeat):  # interleaved: a burst of load on the host hits every case alike
        for name, argv in cases.items():
            wall, cpu = _once(argv)
            walls[name].append(wall)
            cpus[name].append(cpu)
    wall = {k: statistics.median(v) for k, v in walls.items()}
    cpu = {k: statistics.median(v) for k, v in cpus.items()}
    for name in cases:
        floor = f"; floor <= {FLOOR} s" if name in ("--version", "stats FILE") else ""
        ctx.report(AREA, f"{name} wall", wall[name], "s", f"median of {repeat}{floor}")
        ctx.report(AREA, f"{name} CPU", cpu[name], "s", f"median of {repeat}, user + system")
    for name in ("--version", "stats FILE"):
        ctx.report(AREA, f"{name}: eager / lazy", wall[f"{name} (eager)"] / wall[name], "x",
                   f"wall; CPU {cpu[f'{name} (eager)'] / cpu[name]:.3g}x")
        for variant in (name, f"{name} (eager)"):
            seconds, modules = _import_time(cases[variant])
            ctx.report(AREA, f"{variant} -X importtime", seconds, "s", f"{modules} modules")
        if wall[name] > FLOOR:
            print(f"[{AREA}] note: {name} above the {FLOOR} s floor on this host "
                  f"(python -c pass: {wall['python -c pass']:.3g} s)", flush=True)
