"""Run the benchmarks: `python -m bench [--shared DIR] [--only AREA ...] [--repeat N] [--quick]`."""

from __future__ import annotations

import argparse
import ast
import importlib
import sys
from pathlib import Path

from .harness import Context, first_paragraph, run_main, shared_data, what_it_measures

#: Benchmark modules in the order they run (each has `run(ctx)`).
AREAS = ["startup", "foundation", "scaling", "pddl_compile", "planning", "retrieval", "batch", "constraints",
         "generalize", "similarity", "similarity_relabel", "similarity_holdout", "category_extend", "exp_gains", "experiment", "reliability", "physical_replay", "translation", "skills", "silence"]


def main() -> None:
    ap = argparse.ArgumentParser(prog="python -m bench", description=__doc__, epilog=areas_help(),
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"),
                    help="FOON data directory, default ../shared/data (beside the checkout; a clone has a copy: "
                         "--shared tests/data)")
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


def areas_help() -> str:
    """`--help`'s list of areas, each with what it measures (its module's first paragraph, read from the source:
    importing every area would load most of foon2pddl)."""
    here = Path(__file__).parent
    lines = ["areas, in the order they run (--only AREA ...):"]
    for area in AREAS:
        source = here / f"{area}.py"
        doc = (ast.get_docstring(ast.parse(source.read_text(encoding="utf-8"))) if source.is_file()
               else getattr(sys.modules.get(f"bench.{area}"), "__doc__", None))  # an area made in memory (tests)
        lines.append(f"  {area}: {first_paragraph(doc)}")
    return "\n".join(lines)


def run_area(area: str, ctx: Context) -> None:
    """Run one area, first saying on stderr which and what it measures (its module's first line): an area
    prints its figures once measured, minutes later for some, and no command waits silently."""
    module = importlib.import_module(f"bench.{area}")
    print(f"bench {area}: {what_it_measures(module)} (its figures follow as each is measured) ...", file=sys.stderr,
          flush=True)
    module.run(ctx)


if __name__ == "__main__":
    run_main(main)
