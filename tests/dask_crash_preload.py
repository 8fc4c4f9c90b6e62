"""Dask worker preload for tests/test_experiment_dask.py: a solver that kills its worker once.

`crash-once` answers like `native-complete`, except that the first worker to reach goal 3 of
trial 1 creates the marker file named by FOON2PDDL_CRASH_MARKER and dies at once (`os._exit`,
as if killed), so the scheduler loses that task. Later runs find the marker and answer normally.
"""

from __future__ import annotations

import os
from pathlib import Path

from foon2pddl.experiment.setting import Prepared
from foon2pddl.experiment.solvers import SOLVERS, Solver


class _CrashOnce(Prepared):
    def __init__(self, setting) -> None:
        self.inner = SOLVERS["native-complete"].prepare(setting)
        self.setup = self.inner.setup

    def solve(self, node):
        marker = Path(os.environ["FOON2PDDL_CRASH_MARKER"])
        if node.describe() == os.environ.get("FOON2PDDL_CRASH_GOAL") and not marker.exists():
            marker.write_text("crashed\n")
            os._exit(1)
        return self.inner.solve(node)


CRASH_ONCE = Solver("crash-once", "native-complete that kills its worker once (tests)", _CrashOnce)
SOLVERS.setdefault("crash-once", CRASH_ONCE)
