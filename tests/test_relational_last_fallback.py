"""`plan`'s last fallback (a task every count leaves out of holder reach, counted wide with makers by holder reach) is
kept only when it solves. The experiment's GEN network, trial 7, goals 14 and 31 (`spoon (contains {filling})` and the
apple turnover's filling): out of holder reach counted from first makers; the fallback's task gave a plan the
relational replay rejects (`0086-apple_turnover.txt:291: step 15: cookware_1 lists fillings, but the only fillings
(fillings_1) is in cookware_2` [claimed-twice]), reported as an error where the goal was reported unsolvable, out of
holder reach, before the fallback (1857aa2). The outcome must stay that unsolvable one, naming the units. And where
the fallback's task solves, its plan is the outcome, with a note."""

from __future__ import annotations

from pathlib import Path

import pytest
from relational_checks import clean_unit_plan, compiled_counts
from test_relational_placed_back import SAUCE, macaroni

from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.worker import Batch, Job, draw_at, fingerprint, run_batch
from foon2pddl.planners.solve import OUT_OF_REACH

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


@pytest.mark.parametrize("goal", [14, 31])
def test_a_fallback_plan_the_replay_rejects_leaves_the_out_of_reach_outcome(goal: int) -> None:
    paths = (str(DATA.resolve()),)
    protocol = Protocol(10, 100, 0.9, 0, 3, similarity="cook", objects_per_item=1)  # the default experiment's
    trial = next(t for t in draw_at(paths, protocol, ()).trials if t.index == 7)
    (record,) = run_batch(Batch(trial, "gen", "fd-relational", (goal,), ()), Job(paths, fingerprint(paths), protocol, 60.0))
    assert str(record.status) == "unsolvable", record.reason
    assert record.reason.startswith("no reachable state applies what the goal needs"), record.reason


def test_a_fallback_plan_that_solves_is_the_outcome(monkeypatch):
    # the southern macaroni's shape (test_relational_placed_back): counted from first makers (16 objects, small and
    # wide alike, so not counted small) the muffin's blend beats the egg in another bowl than the stir's, out of holder
    # reach; counted wide with makers by holder reach, the omelette's mix beats it in the stir's bowl: 12 objects
    units, kitchen = macaroni()
    counts = compiled_counts(monkeypatch)
    outcome = clean_unit_plan(units, kitchen, SAUCE, time_limit=60)
    assert counts == ["small", "wide own", "wide placed"]  # FOON's own plan unfolded, out of holder reach too
    assert outcome.decoded.notes[-1] == f"objects: {OUT_OF_REACH}, 12", outcome.decoded.notes
    assert len(outcome.task.instances) == 12
    assert [(s.unit.motion.label, s.unit.sources[0].line) for s in outcome.trace.steps] == [
        ("crack", 246), ("mix", 11), ("pour", 46), ("sprinkle", 58), ("stir", 97)]
