"""Run the benchmarks: `python -m bench [--shared DIR] [--only AREA ...] [--repeat N] [--quick]`."""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path

from .harness import Context, run_main, shared_data, what_it_measures

#: Benchmark modules in the order they run (each has `run(ctx)`).
AREAS = ["startup", "foundation", "scaling", "pddl_compile", "planning", "retrieval", "batch", "constraints",
         "generalize", "similarity", "similarity_holdout", "category_extend", "exp_gains", "experiment", "reliability", "physical_replay", "translation", "skills", "silence"]


def main() -> None:
    ap = argparse.ArgumentParser(prog="python -m bench", description=__doc__)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"), help="shared data directory")
    ap.add_argument("--only", nargs="*", choices=AREAS, help="run only these areas")
    ap.add_argument("--repeat", type=int, default=5, help="runs per measurement (median reported)")
    ap.add_argument("--quick", action="store_true", help="smaller samples, for a smoke run")
    ap.add_argument("--save", type=Path, default=Path("bench/results/latest.json"), help="where to write figures")
    args = ap.parse_args()
    shared_data(args.shared)
    ctx = Context(args.shared, args.repeat, args.quick)
    for area in args.only or AREAS:
        run_area(area, ctx)
    ctx.save(args.save)


def run_area(area: str, ctx: Context) -> None:
    """Run one area, first saying on stderr which and what it measures (its module's first line): an area
    prints its figures once measured, minutes later for some, and no command waits silently."""
    module = importlib.import_module(f"bench.{area}")
    print(f"bench {area}: {what_it_measures(module)} (its figures follow as each is measured) ...", file=sys.stderr,
          flush=True)
    module.run(ctx)


if __name__ == "__main__":
    run_main(main)
