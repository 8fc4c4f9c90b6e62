"""`plan`'s last fallback (a task every count leaves out of holder reach, counted wide with makers by holder reach) is
kept only when it solves. The experiment's GEN network, trial 7, goals 14 and 31 (`spoon (contains {filling})` and the
apple turnover's filling): out of holder reach counted from first makers; the fallback's task gave a plan the
relational replay rejects (`0086-apple_turnover.txt:291: step 15: cookware_1 lists fillings, but the only fillings
(fillings_1) is in cookware_2` [claimed-twice]), reported as an error where the goal was reported unsolvable, out of
holder reach, before the fallback (1857aa2). Such an outcome must stay that unsolvable one, naming the units (a
rejected fallback plan, made so here: since `list_placed` puts the filling in the pan that lists it, those two cells
solve, valid and replay-clean). And where the fallback's task solves, its plan is the outcome, with a note."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from relational_checks import clean_unit_plan, compiled_counts
from test_relational_placed_back import SAUCE, macaroni

from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.worker import Batch, Job, draw_at, fingerprint, run_batch
from foon2pddl.model.foon import Foon
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.planners import solve
from foon2pddl.planners.solve import OUT_OF_REACH, UNREACHED

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


@pytest.mark.parametrize("goal", [14, 31])
def test_the_gen_fillings_the_fallback_plans_are_valid_and_replay_clean(goal: int) -> None:
    paths = (str(DATA.resolve()),)
    protocol = Protocol(10, 100, 0.9, 0, 3, similarity="cook", objects_per_item=1)  # the default experiment's
    trial = next(t for t in draw_at(paths, protocol, ()).trials if t.index == 7)
    (record,) = run_batch(Batch(trial, "gen", "fd-relational", (goal,), ()), Job(paths, fingerprint(paths), protocol, 60.0))
    assert str(record.status) == "solved", record.reason  # `plan` says solved only when the relational replay holds
    assert record.validated, record.reason


def test_a_fallback_plan_the_replay_rejects_leaves_the_out_of_reach_outcome(monkeypatch):
    # the macaroni's shape below, its fallback's plan rejected as the replay rejected GEN trial 7 goal 14's: the
    # outcome is the one naming the units out of holder reach, not an error
    units, kitchen = macaroni()
    placed: set[int] = set()
    compiling, deciding = solve.compile_goal, solve.outcome_of

    def compiled(*args, **options):
        out = compiling(*args, **options)
        if options.get("placed"):
            placed.add(id(out))
        return out

    def rejected(result, task, *args):
        out = deciding(result, task, *args)
        return replace(out, decoded=None, decode_error="rejected by the replay") if id(task) in placed else out

    monkeypatch.setattr(solve, "compile_goal", compiled)
    monkeypatch.setattr(solve, "outcome_of", rejected)
    outcome = solve.plan(Foon(units), Kitchen(kitchen), Goal(GoalSpec(SAUCE.label), (SAUCE,)), "relational",
                         time_limit=60)
    assert placed  # the fallback was planned
    assert outcome.status == "unsolvable" and outcome.result.planner == UNREACHED, outcome.message


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
