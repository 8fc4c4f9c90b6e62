"""Benchmarks (`make bench`). Each module `bench/<area>.py` defines `run(ctx) -> None`
and reports medians through `ctx.report`; speed goals live here, never in tests."""
