"""Helpers shared by the benchmark modules: medians over repeated runs, a universal FOON's dishes."""

from __future__ import annotations

import json
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NoReturn

from foon2pddl.analysis.reachability import reachable
from foon2pddl.io.interrupts import interrupt_exit, sigterm_raises
from foon2pddl.model.foon import Foon, ObjectNode


def shared_data(path: Path) -> Path:
    """`--shared`'s FOON data directory, or exit 2 saying where that data is (the docs' `../shared/data` is the
    project's layout, beside the checkout; a clone has a copy in tests/data)."""
    if not (path / "foon-subgraphs").is_dir():
        print(f"{path}: no FOON data here (no foon-subgraphs/): the project's layout has it beside the checkout, "
              "../shared/data; a clone has a copy: --shared tests/data", file=sys.stderr)
        raise SystemExit(2)
    _say_what_runs()
    return path


def run_main(main: Callable[[], int | None]) -> NoReturn:
    """Run a bench module's `main` (`python -m bench...`) and exit with its status. Ctrl-C (SIGINT) or SIGTERM
    stops it as it stops a `foon2pddl` command: the `finally` blocks clean up (planner processes, temporary
    files), then one line, `interrupted` or `terminated`, and status 130 or 143; no traceback."""
    with sigterm_raises():
        try:
            status = main()
        except (KeyboardInterrupt, RuntimeError) as exc:
            ended = interrupt_exit(exc)
            if ended is None:
                raise
            print(ended[0], file=sys.stderr, flush=True)
            raise SystemExit(ended[1]) from None
    raise SystemExit(status)


def what_it_measures(module) -> str:
    """A bench module's first docstring paragraph on one line: what it measures, said before it measures."""
    return first_paragraph(module.__doc__)


def first_paragraph(doc: str | None) -> str:
    """A docstring's first paragraph on one line."""
    return " ".join((doc or "").strip().split("\n\n", 1)[0].split())


def _say_what_runs() -> None:
    """Say on stderr what the benchmark run as `python -m bench.NAME` measures (its module's first paragraph),
    once its arguments are read: most print their first figure or row only after a whole measurement, seconds
    to minutes in, and no documented command waits silently. `python -m bench` says it per area instead."""
    main = sys.modules.get("__main__")
    name = getattr(getattr(main, "__spec__", None), "name", None) or ""
    if name.startswith("bench.") and name != "bench.__main__":
        print(f"python -m {name}: {what_it_measures(main)} ...", file=sys.stderr, flush=True)


def timeit(fn: Callable[[], Any], repeat: int = 5, warmup: int = 1) -> tuple[float, list[float], Any]:
    """Median wall time of `fn` in seconds over `repeat` runs (after `warmup`), all times, last result."""
    result = None
    for _ in range(warmup):
        result = fn()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), times, result


def reachable_dishes(foon: Foon, kitchen_nodes) -> list[ObjectNode]:
    """The nodes some recipe marks as its dish (`Foon.dishes`: whichever recipe was merged first) that a unit
    makes and the kitchen can make, sorted: a universal FOON's goals, the same in any merge order (the first
    node listed need not carry the mark: merged in reverse, three of the shared dishes lost it)."""
    reach = reachable(foon, kitchen_nodes)
    return sorted(n for n in foon.dishes if n in foon.producers and reach.can_make(n))


@dataclass
class Context:
    """What a benchmark module gets: shared data path, repeat count and a report sink."""

    shared: Path
    repeat: int = 5
    quick: bool = False
    rows: list[dict[str, Any]] = field(default_factory=list)

    def report(self, area: str, name: str, value: float, unit: str, note: str = "") -> None:
        """Record and print one figure."""
        self.rows.append({"area": area, "name": name, "value": value, "unit": unit, "note": note})
        shown = f"{value:.4g}" if isinstance(value, float) else str(value)
        print(f"[{area}] {name}: {shown} {unit}" + (f"  ({note})" if note else ""), flush=True)

    def save(self, path: Path) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(self.rows, indent=2) + "\n")
