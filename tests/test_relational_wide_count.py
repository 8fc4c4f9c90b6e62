"""`plan` falls back last on FOON's own plan unfolded when the wide task, counted with a needed node made by another
of its makers, has no valid plan (issue 21): the experiment's REG network, trial 6, solved the goals below at eaf15d7
with the 14 and 11 objects FOON's plan unfolded counts, and since 7728308 (the plans with a needed node made by
another of its makers, `count_plans._other_makers`, counted in every count) found them `unsolvable`: the wide count
had taken the plan whose water comes from the pesto linguine's pour (`0075-pesto_linguine.txt:25`), 9 and 6
objects, as few as the small count, so nothing was left to fall back on ("translator: no relaxed solution")."""

from __future__ import annotations

from pathlib import Path

from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.worker import Batch, Job, draw_at, fingerprint, run_batch

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def test_a_small_count_with_no_valid_plan_falls_back_on_foon_s_own_plan_unfolded() -> None:
    paths = (str(DATA.resolve()),)
    protocol = Protocol(10, 100, 0.9, 0, 3, similarity="cook", objects_per_item=1)  # the default experiment's
    trial = next(t for t in draw_at(paths, protocol, ()).trials if t.index == 6)
    assert [trial.goals[g - 1].describe() for g in (42, 75)] == ["macaroni (in [pot], raw)", "bowl (contains {egg})"]
    records = run_batch(Batch(trial, "reg", "fd-relational", (42, 75), ()), Job(paths, fingerprint(paths), protocol, 60.0))
    assert [(str(r.status), r.validated) for r in records] == [("solved", True)] * 2, [r.reason for r in records]
