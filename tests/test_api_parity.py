"""The Python API does what the CLI does: network kinds, constraints, search configuration, batches, experiment."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

import foon2pddl as fp
from foon2pddl.cli import main
from foon2pddl.errors import FoonInputError, UsageError


@pytest.fixture(scope="module")
def net():
    return fp.load_network()


def test_the_package_namespace_is_the_api():
    package = Path(fp.__file__).parent
    modules = {p.stem for p in package.glob("*.py")} | {p.name for p in package.iterdir() if p.is_dir()}
    public = {n for n in dir(fp) if not n.startswith("_")}
    assert public <= set(fp.__all__) | modules, sorted(public - set(fp.__all__) - modules)
    assert not hasattr(fp, "Any") and not hasattr(fp, "annotations")


def test_missing_paths_are_input_errors(net, tmp_path):
    with pytest.raises(FoonInputError, match="no such file"):
        fp.load_network(tmp_path / "nope.txt")
    with pytest.raises(FoonInputError, match="no such file"):
        fp.load_kitchen(net, tmp_path / "kitchen.txt")


def test_load_network_takes_what_the_clis_paths_take(tmp_path):
    """Issue 24's last pass: `fp.load_network(["dir"])` raised a TypeError. A path, a directory, several, or a
    list of them load the same network; anything else is a UsageError naming what was given."""
    data = Path(__file__).parent / "data" / "foon-subgraphs"
    one, two = sorted(data.iterdir())[:2]
    units = len(fp.load_network(one, two).foon.units)
    assert len(fp.load_network([one, two]).foon.units) == units
    assert len(fp.load_network([str(one)], (str(two),)).foon.units) == units
    assert len(fp.load_network([data]).foon.units) == len(fp.load_network(str(data)).foon.units)
    with pytest.raises(FoonInputError, match="no such file"):
        fp.load_network([tmp_path / "nope.txt"])
    for bad in (3, [one, 3], [[one]]):
        with pytest.raises(UsageError, match="load_network: .* is not a path"):
            fp.load_network(bad)


def test_an_unknown_encoding_is_a_usage_error_naming_the_encodings(net):
    """Issue 24's tried-again pass (stop 58): `fp.plan(net, kitchen, "guacamole", "relation")` raised a bare
    `KeyError: 'relation'` (so did `compile_goal` and `plan_goals`), where every other bad argument of the API is a
    `UsageError` naming the choices, as README's error hierarchy says and `skill_plan` already did."""
    kitchen = fp.load_kitchen(net)
    calls = (lambda: fp.plan(net, kitchen, "guacamole", "relation"),
             lambda: fp.compile_goal(net, kitchen, fp.resolve_goal(net, "guacamole"), "relation"),
             lambda: fp.plan_goals(net, kitchen, ["guacamole"], "relation"),
             lambda: fp.skill_plan(net, kitchen, "guacamole", encoding="relation"))
    for call in calls:
        with pytest.raises(UsageError, match="encoding must be one of tree, .*relational.*, not 'relation'"):
            call()


def test_retrieve_under_constraints_and_kinds_matches_the_cli(net):
    kitchen = fp.load_kitchen(net)
    no_lime = fp.constraints_of(without=["lime"])
    for kind in ("reg", "exp", "gen"):
        api = fp.retrieve(net, kitchen, "guacamole", constraints=no_lime, network_kind=kind)
        r = CliRunner().invoke(main, ["retrieve", "--goal", "guacamole", "--without", "lime", "--network", kind,
                                      "--format", "json"])
        assert (r.exit_code == 0) == api.found, (kind, r.stderr)
        if api.found:
            assert json.loads(r.stdout)["units"] == len(api.tree)


def test_plan_takes_a_search_configuration(net):
    kitchen = fp.load_kitchen(net)
    out = fp.plan(net, kitchen, "guacamole", alias="seq-opt-lmcut")
    assert out.status == "solved" and out.result.planner == "fd (seq-opt-lmcut)"
    with pytest.raises(UsageError, match="unknown Fast Downward alias"):
        fp.plan(net, kitchen, "guacamole", alias="lama-frist")
    with pytest.raises(UsageError, match="configure Fast Downward"):
        fp.plan(net, kitchen, "guacamole", planner="pyperplan", search="astar(lmcut())")


def test_batches_and_the_experiment(net, tmp_path):
    kitchen = fp.load_kitchen(net)
    rows = fp.plan_goals(net, kitchen, ["guacamole", "unicorn"])
    assert rows[0].outcome.status == "solved" and rows[1].outcome is None and "unicorn" in rows[1].reason
    summary = fp.run_experiment(tmp_path, networks=["reg"], solvers=["native-complete"], trials=1, goals=3)
    assert summary.ran == 3 and (tmp_path / "results.jsonl").is_file()


def test_plan_goals_rows_have_a_status_as_retrieve_goals_rows_do(net):
    """README shows `[str(r.status) for r in fp.retrieve_goals(...)]`; the same comprehension over `plan_goals` raised
    `AttributeError: 'GoalPlan' object has no attribute 'status'` (stop 59's newcomer pass). A goal naming no produced
    node is `unmatched` in both, as in a batch `plan` run."""
    kitchen = fp.load_kitchen(net)
    goals = ["guacamole", "lemonade", "unicorn"]
    planned = [str(r.status) for r in fp.plan_goals(net, kitchen, goals)]
    retrieved = [str(r.status) for r in fp.retrieve_goals(net, kitchen, goals)]
    assert planned[0] == retrieved[0] == "solved"
    assert planned[2] == retrieved[2] == "unmatched"
    assert planned[1] != "solved"
