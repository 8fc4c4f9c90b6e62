"""One vocabulary: status enums and their one mapping, the error hierarchy, and how the CLI reports errors."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.errors import FoonError, FoonInputError, FoonSyntaxError, MissingDependencyError, UsageError
from foon2pddl.planners.result import STATUSES, PlanResult
from foon2pddl.retrieval import retrieve
from foon2pddl.retrieval.result import Retrieval
from foon2pddl.status import CellStatus, PlanStatus, RetrievalStatus, cell_status


def run(*args: str):
    return CliRunner().invoke(main, list(args))


# ------------------------------------------------------------------ statuses


def test_statuses_are_their_old_strings():
    assert STATUSES == ("solved", "unsolvable", "gave up", "timeout", "error")
    assert PlanResult("solved").status is PlanStatus.SOLVED
    assert json.dumps({"s": PlanStatus.TIMEOUT, "r": RetrievalStatus.BUDGET_EXHAUSTED}) == \
        '{"s": "timeout", "r": "budget exhausted"}'
    assert f"{RetrievalStatus.UNREACHABLE}: x" == "unreachable: x"


def test_every_plan_and_retrieval_status_maps_to_a_cell_status():
    for status in (*PlanStatus, *RetrievalStatus):
        assert cell_status(status) in CellStatus
    # every cell status but a lost worker's and a rejected plan's (a planner's `error` whose plan the physical
    # replay rejects: experiment.outcomes.plan_outcome reads it off the outcome) comes from a solver's status
    assert {cell_status(s) for s in (*PlanStatus, *RetrievalStatus)} == set(CellStatus) - {"lost", "rejected"}
    # a proof of unsolvability and a search that gave up stay apart
    assert cell_status(PlanStatus.UNSOLVABLE) is not cell_status(PlanStatus.GAVE_UP)
    assert cell_status(RetrievalStatus.UNREACHABLE) is CellStatus.UNSOLVABLE
    assert cell_status(RetrievalStatus.FOUND) is cell_status(PlanStatus.SOLVED) is CellStatus.SOLVED
    assert cell_status("timeout") is CellStatus.TIMEOUT  # plain strings (records read back) map too


def test_retrieval_status_and_reason(example):
    from foon2pddl.io.inputs import load_goal, load_kitchen

    kitchen = load_kitchen(None, example, 3)
    found = retrieve(example.foon, kitchen, load_goal("guacamole", None, example.foon), "complete")
    assert found.status is RetrievalStatus.FOUND and found.reason is None
    missing = retrieve(example.foon, kitchen, load_goal("lemonade", None, example.foon), "complete")
    assert missing.status is RetrievalStatus.UNREACHABLE and missing.reason == "unreachable"
    with pytest.raises(ValueError):
        Retrieval(None, "found", "complete")
    with pytest.raises(ValueError):
        Retrieval(None, "node limit", "complete")


# ------------------------------------------------------------------ errors


def test_error_hierarchy():
    usage = UsageError("bad value")
    assert isinstance(usage, ValueError) and isinstance(usage, FoonError)
    assert usage.location() is None and str(usage) == "bad value"
    file_error = FoonSyntaxError("k.txt", 3, "expected a node", "O1 x")
    assert file_error.location() == "k.txt:3" and str(file_error) == "k.txt:3: expected a node\n    'O1 x'"
    assert FoonInputError("dir", 0, "no files").location() == "dir"  # the file as a whole: no line
    missing = MissingDependencyError("Graphviz 'dot' is not installed", "apt-get install graphviz")
    assert missing.hint == "apt-get install graphviz" and "apt-get install graphviz" in missing.message
    assert missing.location() is None
    from foon2pddl.errors import PlanDecodeError
    from foon2pddl.pddl.instance_replay import InstancePlanError

    assert issubclass(PlanDecodeError, FoonError) and issubclass(InstancePlanError, FoonError)
    assert str(PlanDecodeError("plan step 1 (x) names no action of the task")).startswith("plan step 1")


def test_unsolvable_under_constraints_is_an_outcome(example):
    """Constraints that leave no way to the goal give an `unsolvable` outcome, not an exception."""
    from foon2pddl.io.inputs import load_goal, load_kitchen
    from foon2pddl.model.constraints import Constraint, Kind, make_constraints
    from foon2pddl.planners.solve import EXCLUDED, plan

    goal = load_goal("guacamole", None, example.foon)
    kitchen = load_kitchen(None, example, 3)
    bans = make_constraints([Constraint(Kind.WITHOUT, c.label) for c in goal.candidates])
    outcome = plan(example.foon, kitchen, goal, constraints=bans)
    assert outcome.status is PlanStatus.UNSOLVABLE and outcome.result.planner == EXCLUDED
    assert outcome.tree is None and "left by the constraints" in outcome.message


def test_batch_rows_use_the_status_vocabulary(example):
    from foon2pddl.io.goal_lists import GoalEntry
    from foon2pddl.io.inputs import load_kitchen
    from foon2pddl.model.goal import GoalSpec, resolve_goal
    from foon2pddl.retrieval.batch import solve_goals
    from foon2pddl.status import BatchStatus

    kitchen = load_kitchen(None, example, 3)
    entries = [GoalEntry(GoalSpec(x), "goals.txt", n) for n, x in enumerate(("guacamole", "lemonade", "unicorn"), 1)]
    rows = solve_goals(example.foon, kitchen.nodes, entries, lambda spec: resolve_goal(spec, example.foon))
    assert [r.status for r in rows] == [BatchStatus.SOLVED, BatchStatus.UNREACHABLE, BatchStatus.UNMATCHED]
    assert all(type(r.status) is BatchStatus for r in rows)


def test_library_raises_usage_errors_without_flag_names(example):
    from foon2pddl.io.inputs import load_goal, load_kitchen
    from foon2pddl.pddl.compile import compile_task

    goal = load_goal("guacamole", None, example.foon)
    kitchen = load_kitchen(None, example, 3)
    with pytest.raises(UsageError) as err:
        compile_task(example.foon, kitchen, goal, "nope")
    assert "--" not in err.value.message
    with pytest.raises(UsageError) as err:
        compile_task(example.foon, kitchen, goal, costs="success-rate")
    assert "--" not in err.value.message
    with pytest.raises(UsageError):
        retrieve(example.foon, kitchen, goal, "nope")


@pytest.mark.parametrize("args", [
    ("retrieve", "--goal", "guacamole", "--method", "weighted"),
    ("retrieve",),
    ("retrieve", "--goal", "xyzzy"),
    ("plan", "--goal", "guacamole", "--costs", "success-rate"),
    ("compile", "--goal", "lemonade", "--network", "gen", "--encoding", "state"),
    ("similarity", "onion"),
])
def test_option_errors_print_in_click_usage_style(args):
    result = run(*args)
    assert result.exit_code == 2
    assert "Traceback" not in result.output
    assert ": error" not in result.stderr and "<" not in result.stderr.split("Error:")[-1][:1]
    assert result.stderr.startswith("Usage: ") and "\nError: " in result.stderr, result.stderr


def test_file_errors_still_name_path_and_line(tmp_path):
    bad = tmp_path / "k.txt"
    bad.write_text("O1\tonion\t0\nS\n")
    result = run("retrieve", "--goal", "guacamole", "--kitchen", str(bad))
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{bad}:2: error: "), result.stderr
    result = run("stats", str(tmp_path / "missing"))
    assert result.exit_code == 2 and result.stderr.startswith(f"{tmp_path / 'missing'}: error: ")


@pytest.mark.parametrize(("module", "call", "extra"), [
    ("nltk", lambda: __import__("foon2pddl.generalize.wordnet", fromlist=["reader"]).reader.__wrapped__(), "gen"),
    ("tqdm", lambda: __import__("foon2pddl.experiment.progress", fromlist=["Progress"]).Progress(10, mode="bar"),
     "experiment"),
])
def test_missing_extras_name_their_install_command(monkeypatch, module, call, extra):
    import sys

    for name in [m for m in sys.modules if m == module or m.startswith(module + ".")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, module, None)  # `import module` now raises ImportError
    with pytest.raises(MissingDependencyError) as err:
        call()
    assert f"pip install 'foon2pddl[{extra}]'" in err.value.message and err.value.location() is None
