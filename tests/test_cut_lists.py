"""Every list a message cuts short says how many it left out, in one format (`words.first_of`: `... (N more)`).

Issue 24's last pass found older formats: `(+2 more)`, `(and 2 more)`, `(6 in all)`, `+1 more`, and validation
problems cut at 3 with no count at all (a plan failing on 7 steps read as failing on 3)."""

from __future__ import annotations

from dataclasses import replace

import pytest
from node_words import n

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.tasktree import TaskTree
from foon2pddl.model.words import first_of

#: Five units each taking an input no kitchen holds: their tree fails validation at all five steps.
_BROKEN = tuple(FunctionalUnit((n(f"thing {i}"),), Motion("chop"), (n(f"thing {i}", "chopped"),)) for i in range(5))
_TREE = TaskTree(_BROKEN, _BROKEN[-1].outputs[0])


def test_first_of_cuts_with_a_separator_and_counts_from_a_total():
    assert first_of(["a", "b", "c"], 2, sep=", ") == "a, b, ... (1 more)"
    # a list already cut elsewhere (a defect keeps its first places and how many there are)
    assert first_of(["a", "b"], 5, sep=", ", total=7) == "a, b, ... (5 more)"
    assert first_of(["a", "b"], 5, total=2) == "a; b"


def test_the_count_note_counts_the_takers_it_leaves_out():
    from foon2pddl.pddl.count_reasons import count_reasons
    from foon2pddl.pddl.instance_counts import InstanceCounts

    empty = n("cup", "empty")
    units = tuple(FunctionalUnit((empty, n("salt")), Motion(m), (n("cup", "full"),)) for m in ("scoop", "fill"))
    counts = InstanceCounts(((empty, 2),), (), ((0, 1), (1, 1)))
    (note,) = count_reasons(Foon(units), counts, frozenset({empty, n("salt")}), shown=1)
    assert "fires scoop, ... (1 more), and no unit puts one back" in note, note


def test_an_actions_comment_counts_the_sources_it_leaves_out():
    from foon2pddl.pddl.encoding import unit_comment

    unit = replace(_BROKEN[0], sources=tuple(Source(f"r{i}.txt", i + 1) for i in range(5)))
    first, _ = unit_comment(unit, 7)
    assert first == "unit 7: chop from r0.txt:1, r1.txt:2, r2.txt:3, ... (2 more)"


def test_a_defect_counts_the_nodes_it_leaves_out():
    from foon2pddl.analysis.check_units import identity_units

    same = tuple(n(f"thing {i}") for i in range(6))
    (d,) = identity_units(Foon((FunctionalUnit(same, Motion("stir"), same),)))
    assert d.message.endswith("thing 3; ... (2 more)"), d.message


def test_check_counts_the_places_it_leaves_out():
    from foon2pddl.analysis.defects import DefectKind, defect
    from foon2pddl.cli.check_cmd import format_defects

    d = defect(DefectKind.IDENTITY_UNIT, "unit changes nothing", (Source(f"r{i}.txt", 1) for i in range(9)), [])
    line = format_defects([d], {"identity-unit": 1}).splitlines()[0]
    shown = ", ".join(str(p) for p in d.places[1:])
    assert line.endswith(f"(also at {shown}, ... ({9 - len(d.places)} more))"), line


def test_a_file_whose_blocks_were_all_skipped_counts_the_other_warnings():
    from foon2pddl.io.parser import parse_text

    block = "M\tchop\nO\tonion\t0\nS\tchopped\n"
    with pytest.raises(FoonSyntaxError) as e:
        parse_text(block + "//\n" + block + "//\n" + block)
    assert e.value.message.endswith("unit has no input objects before its motion line; skipped; ... (2 more)"), e.value.message


def test_a_plan_that_does_not_validate_counts_the_problems_left_out():
    from foon2pddl.model.tasktree import validate
    from foon2pddl.planners.decode import Decoded
    from foon2pddl.planners.result import PlanResult
    from foon2pddl.planners.solve import PlanOutcome
    from foon2pddl.status import PlanStatus

    check = validate(_TREE, frozenset())
    assert len(check.problems) == 5
    outcome = PlanOutcome(PlanResult(PlanStatus.SOLVED, ("a",)), None, Decoded(_TREE, check))
    assert outcome.message.endswith("; ... (2 more)"), outcome.message


def test_an_experiment_tree_that_does_not_validate_counts_the_problems_left_out():
    from foon2pddl.experiment.outcomes import native_outcome
    from foon2pddl.retrieval.result import Retrieval

    outcome = native_outcome(Retrieval(_TREE, None, "greedy"), frozenset(), 0.0)
    assert outcome.reason.startswith("tree does not validate: ") and outcome.reason.endswith("; ... (2 more)")


def test_a_batch_tree_that_does_not_validate_counts_the_problems_left_out(monkeypatch):
    from foon2pddl.io.goal_lists import GoalEntry
    from foon2pddl.model.containment import Containment
    from foon2pddl.model.goal import Goal, GoalSpec
    from foon2pddl.retrieval import batch
    from foon2pddl.retrieval.result import Retrieval

    # the tree checked in a stricter mode than it was found in: here, a tree that fails at all five steps
    monkeypatch.setattr(batch, "retrieve", lambda *a, **k: Retrieval(_TREE, None, "greedy"))
    goal = Goal(GoalSpec("thing 4"), (_TREE.goal,))
    row = batch._one(Foon(_BROKEN), frozenset(), GoalEntry(GoalSpec("thing 4"), "g.txt", 1), lambda spec: goal,
                     Containment.STRICT, None, "greedy", None, {}, 0.0, lambda: 0.0)
    assert row.reason.endswith("; ... (2 more)"), row.reason


def test_a_goal_in_no_produced_state_counts_the_states_it_leaves_out():
    """`plan --goal "bowl: contains {xyz}"` listed the first 8 of the embedded example's produced bowl states and
    stopped, with no word of the rest."""
    from foon2pddl.api import load_network
    from foon2pddl.errors import UsageError
    from foon2pddl.io.goal_files import parse_goal_spec
    from foon2pddl.model.containment import is_auxiliary
    from foon2pddl.model.goal import resolve_goal

    foon = load_network().foon
    produced = {n.states for n in foon.produced_by_label["bowl"] if not is_auxiliary(n)}
    assert len(produced) > 8
    with pytest.raises(UsageError) as e:
        resolve_goal(parse_goal_spec("bowl: contains {xyz}"), foon)
    assert str(e.value).endswith(f"; ... ({len(produced) - 8} more)"), str(e.value)


# The cut lists 57f8b92 left in their older formats (the stop's re-read, reread57): each now says how many it left out.


def test_a_load_whose_every_file_was_skipped_counts_the_files_it_leaves_out(tmp_path):
    from foon2pddl.io.files import load

    for i in range(5):
        (tmp_path / f"notes{i}.txt").write_text("shopping list\n")
    with pytest.raises(FoonSyntaxError) as e:
        load([tmp_path])
    assert e.value.message.endswith("(no `O`, `S`, `M` or `//` line); ... (2 more)"), e.value.message


def test_an_explain_line_counts_the_avoided_units_it_leaves_out():
    from foon2pddl.retrieval.constrained import Shaping, explain_line

    line = explain_line(Shaping("without-motion chop", 5, _BROKEN))
    assert line.endswith("thing 2 (chopped); ... (2 more)"), line


def test_a_plan_step_whose_preconditions_fail_counts_those_it_leaves_out():
    from foon2pddl.pddl.task import Action, Atom, PlanningTask
    from foon2pddl.planners.decode import apply_step

    pre = tuple(Atom("have", (f"x{i}",)) for i in range(5))
    task = PlanningTask("d", "p", "tree", 3, (), (Action("go", pre, ()),), (), ())
    _, why = apply_step(task, set(), "go", 1, {})
    assert why == "plan step 1 (go): precondition false: (have x0), (have x1), (have x2), ... (2 more)", why


def test_an_experiment_plan_failing_foon_simulation_counts_the_problems_left_out():
    from foon2pddl.experiment.outcomes import plan_outcome
    from foon2pddl.model.tasktree import validate
    from foon2pddl.planners.decode import Decoded
    from foon2pddl.planners.result import PlanResult
    from foon2pddl.planners.solve import PlanOutcome
    from foon2pddl.status import PlanStatus

    # an encoding without FOON's semantics (`state`): a valid plan whose tree fails at all five steps
    outcome = PlanOutcome(PlanResult(PlanStatus.SOLVED, ("a",)), None,
                          Decoded(_TREE, validate(_TREE, frozenset()), foon_semantics=False))
    reason = plan_outcome(outcome, ("a",)).reason
    assert reason.startswith("tree fails FOON simulation: ") and reason.endswith("; ... (3 more)"), reason
