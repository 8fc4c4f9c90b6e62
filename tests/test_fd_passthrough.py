"""Fast Downward the way its users drive it: --alias, --search with --evaluator, --plan-file (sas_plan)."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.planners import fd
from foon2pddl.planners.result import parse_plan_text


def run(*args: str):
    return CliRunner().invoke(main, list(args))


def test_alias_table_is_the_drivers_including_computed_aliases():
    names = fd.alias_names()
    assert {"lama-first", "seq-opt-lmcut", "seq-sat-lama-2011", "lama"} <= set(names)
    lama = fd.search_config(alias="seq-sat-lama-2011").options
    assert "--if-unit-cost" in lama and any("lazy_greedy" in x for x in lama)
    assert fd.search_config().options == fd.search_options(False)
    assert fd.search_config(optimal=True).label == "seq-opt-lmcut"


@pytest.mark.parametrize(("args", "message"), [
    (("--alias", "lama-frist"), "did you mean 'lama-first'?"),
    (("--evaluator", "h=ff()"), "give --search too"),
    (("--alias", "lama-first", "--search", "astar(blind())"), "not both"),
    # --optimal is not always seq-opt-lmcut: the default relational encoding's conditional effects get astar(hmax())
    (("--optimal", "--alias", "lama-first"), "--optimal chooses an optimal search itself (seq-opt-lmcut, or "
                                             "astar(hmax()) on a task with conditional effects such as the "
                                             "relational encoding's)"),
    (("--planner", "pyperplan", "--alias", "lama-first"), "Fast Downward options"),
])
def test_bad_driver_options_fail_before_planning(args, message):
    r = run("plan", "--goal", "guacamole", *args)
    assert r.exit_code == 2 and message in r.stderr and "phases:" not in r.stderr


@pytest.mark.parametrize(("args", "option"), [
    (("--evaluator", "h=ff()"), "--evaluator"),
    (("--alias", "lama-first", "--search", "astar(blind())"), "--alias"),
    (("--optimal", "--search", "astar(blind())"), "--search"),
    (("--planner-cmd", "pyperplan", "--search", "astar(blind())"), "--planner-cmd"),
])
def test_a_misused_driver_option_is_named_as_given(args, option):
    """README: a bad command-line value gets "a usage error naming the option". `--evaluator` without `--search`
    said `Invalid value for '--search'` and `--planner-cmd pyperplan --search ...` `Invalid value for '--planner'`:
    options the user had not given (stop 50's newcomer pass)."""
    r = run("plan", "--goal", "guacamole", *args)
    assert r.exit_code == 2 and f"Invalid value for '{option}'" in r.stderr


@pytest.mark.parametrize(("args", "name", "steps"), [
    (("--alias", "seq-opt-lmcut"), "fd (seq-opt-lmcut)", 20),
    (("--alias", "seq-sat-lama-2011", "--time-limit", "15"), "fd (seq-sat-lama-2011)", None),  # anytime
    (("--search", "astar(blind())"), "fd (custom)", 20),
    (("--evaluator", "h=ff()", "--search", "lazy_greedy([h], preferred=[h])"), "fd (custom)", None),
])
def test_driver_configurations_solve(args, name, steps):
    r = run("plan", "--goal", "guacamole", "--encoding", "tree", "--format", "json", *args)  # 20 units: FOON's tree
    assert r.exit_code == 0, r.stderr
    data = json.loads(r.stdout)
    assert data["status"] == "solved" and data["planner"] == name
    assert data["validation"]["ok"]
    if steps is not None:  # optimal configurations: the fewest steps
        assert len(data["plan"]) == steps


def test_plan_file_is_fd_sas_plan_format(tmp_path):
    out = tmp_path / "plans" / "sas_plan"
    r = run("plan", "--goal", "guacamole", "--format", "json", "--plan-file", str(out))
    assert r.exit_code == 0, r.stderr
    plan = json.loads(r.stdout)["plan"]
    text = out.read_text()
    lines = text.splitlines()
    assert lines[-1] == f"; cost = {len(plan)} (unit cost)"
    assert all(line.startswith("(") and line.endswith(")") for line in lines[:-1])
    assert list(parse_plan_text(text)) == plan


def test_plan_file_checked_first_and_not_written_without_a_plan(tmp_path):
    bad = run("plan", "--goal", "guacamole", "--plan-file", "/proc/nope/sas_plan")
    assert bad.exit_code == 2 and "cannot write" in bad.stderr and "phases:" not in bad.stderr
    out = tmp_path / "sas_plan"
    r = run("plan", "--goal", "lemonade", "--plan-file", str(out))
    assert r.exit_code == 1 and not out.exists()
