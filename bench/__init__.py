"""Benchmarks (`make bench`). Each module `bench/<area>.py` defines `run(ctx) -> None`
and reports medians through `ctx.report`; speed goals live here, never in tests."""

import sys

if sys.argv[:1] == ["-m"]:  # run as `python -m bench[.NAME]` (argv[0] is "-m" while the module is located)
    from foon2pddl.io.interrupts import exit_on_signals

    exit_on_signals()  # as `foon2pddl` does: Ctrl-C while the modules load exits 130 quietly (then harness.run_main)
