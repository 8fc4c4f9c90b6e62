"""`foon2pddl compile`: writes both files atomically, reports bad input with exit status 2 and no output."""

from __future__ import annotations

import re

import click
import pddl.parser.domain
from click.testing import CliRunner
from conftest import SEARCH_INPUTS, SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.cli.options import costs_option, encoding_option
from foon2pddl.pddl.compile import ENCODINGS
from foon2pddl.pddl.costs import COST_MODES

RECIPE = str(SUBGRAPHS / "0076-bloody_mary.txt")


def _run(*args):
    return CliRunner().invoke(main, ["compile", *args])


def test_compile_writes_domain_and_problem_and_says_where(tmp_path):
    result = _run(RECIPE, "--goal", "bloody mary", "-o", str(tmp_path / "out"))
    assert result.exit_code == 0, result.output
    domain = (tmp_path / "out" / "domain.pddl").read_text()
    problem = (tmp_path / "out" / "problem.pddl").read_text()
    assert str(tmp_path / "out" / "domain.pddl") in result.output
    assert pddl.parser.domain.DomainParser()(domain).actions
    assert re.search(r"\(:domain foon-tree-[0-9a-f]{8}\)", problem) and "bloody_mary" in problem
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")]  # no temporary left


def test_options_reach_the_encoder(tmp_path):
    result = _run(RECIPE, "--goal", "bloody mary", "--encoding", "state", "--level", "2", "--no-prune",
                  "--costs", "success-rate", "--rates", str(SEARCH_INPUTS / "motion.txt"), "-o", str(tmp_path))
    assert result.exit_code == 0, result.output
    domain = (tmp_path / "domain.pddl").read_text()
    assert "(define (domain foon-state-" in domain and "level 2: all " in domain
    assert "(increase (total-cost) " in domain and "rates: motion.txt" in domain


def test_bad_goal_exits_2_and_leaves_existing_files_alone(tmp_path):
    (tmp_path / "domain.pddl").write_text("old domain")
    result = _run(RECIPE, "--goal", "bloody marx", "-o", str(tmp_path))
    assert result.exit_code == 2
    assert "unknown object label 'bloody marx'" in result.output and "bloody mary" in result.output
    assert "Traceback" not in result.output
    assert (tmp_path / "domain.pddl").read_text() == "old domain"
    assert not (tmp_path / "problem.pddl").exists()


def test_missing_rates_and_missing_goal_exit_2(tmp_path):
    result = _run(RECIPE, "--goal", "bloody mary", "--costs", "success-rate", "-o", str(tmp_path))
    assert result.exit_code == 2 and "--rates" in result.output
    result = _run(RECIPE, "-o", str(tmp_path))
    assert result.exit_code == 2 and "--goal" in result.output
    result = _run(RECIPE, "--goal", "bloody mary", "--kitchen", str(tmp_path / "nope.txt"), "-o", str(tmp_path))
    assert result.exit_code == 2 and "nope.txt" in result.output
    assert not list(tmp_path.iterdir())


def test_unwritable_output_exits_2(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = _run(RECIPE, "--goal", "bloody mary", "-o", str(blocker / "sub"))
    assert result.exit_code == 2 and "Traceback" not in result.output


def test_cli_choices_are_the_encoders_and_cost_modes():
    @click.command()
    @encoding_option
    @costs_option
    def probe(encoding, costs):  # pragma: no cover - only inspected
        pass

    choices = {p.name: tuple(p.type.choices) for p in probe.params}
    assert choices == {"encoding": tuple(ENCODINGS), "costs": COST_MODES}


def _bare_kitchen(tmp_path):
    path = tmp_path / "bare.json"
    path.write_text('[{"label": "knife", "states": [], "ingredients": [], "container": null}]\n')
    return path


def test_unreachable_goal_exits_1_with_retrieves_reason_and_writes_nothing(tmp_path):
    kitchen = _bare_kitchen(tmp_path)
    for encoding in ("tree", "instances", "state", "foon-compat"):
        out = tmp_path / encoding
        result = _run(RECIPE, "--goal", "bloody mary", "--kitchen", str(kitchen), "--encoding", encoding,
                      "-o", str(out))
        assert result.exit_code == 1, (encoding, result.output)
        assert "cannot compile: 'bloody mary' is unreachable: " in result.output
        assert "nodes no unit makes" in result.output and "tomato juice" in result.output
        assert not out.exists() or not list(out.iterdir())
    retrieved = CliRunner().invoke(main, ["retrieve", RECIPE, "--goal", "bloody mary", "--kitchen", str(kitchen)])
    reason = retrieved.output.split(": unreachable: ")[1].splitlines()[0]
    assert reason in result.output


def test_unreachable_goal_in_a_batch_is_an_unreachable_row_without_files(tmp_path):
    import json

    kitchen = _bare_kitchen(tmp_path)
    result = _run(RECIPE, "--goal", "bloody mary", "--goal", "unicorn stew", "--kitchen", str(kitchen),
                  "--format", "jsonl", "-o", str(tmp_path / "out"))
    assert result.exit_code == 1, result.output
    rows = [json.loads(line) for line in result.stdout.splitlines()]
    assert [r["status"] for r in rows] == ["unreachable", "unmatched"]
    assert "nodes no unit makes" in rows[0]["reason"]
    assert not (tmp_path / "out" / "bloody_mary").exists()


def test_gen_header_names_the_kitchen_file_and_counts_in_the_singular(tmp_path):
    result = _run("--network", "gen", "--encoding", "gen-lifted", "--goal", "guacamole", "-o", str(tmp_path))
    assert result.exit_code == 0, result.output
    lines = (tmp_path / "domain.pddl").read_text().splitlines()
    assert "; goal: guacamole (1 candidate node)" in lines
    kitchen = next(line for line in lines if line.startswith("; kitchen: "))
    assert kitchen.startswith("; kitchen: example_kitchen.txt (") and "/" not in kitchen


def test_gen_header_counts_the_units_pruning_kept_as_the_other_encodings_do(tmp_path):
    first = {}
    for prune in ("--prune", "--no-prune"):
        out = tmp_path / prune
        result = _run("--network", "gen", "--goal", "guacamole", prune, "-o", str(out))
        assert result.exit_code == 0, result.output
        first[prune] = (out / "domain.pddl").read_text().splitlines()[0]
    kept = re.fullmatch(r"; foon2pddl, lifted FOON-GEN \(categories as types\), level 3: \d+ lifted units "
                        r"from (\d+) of 101 units after relevance pruning", first["--prune"])
    assert kept and int(kept.group(1)) < 101, first["--prune"]
    assert re.fullmatch(r"; foon2pddl, .*: \d+ lifted units from all 101 units", first["--no-prune"]), first


def test_domain_name_identifies_the_domain_and_the_problem_names_it(tmp_path):
    names = {}
    for goal in ("guacamole", "whipped cream", "guacamole"):
        out = tmp_path / goal
        assert _run("--goal", goal, "--prune", "-o", str(out)).exit_code == 0
        domain, problem = (out / "domain.pddl").read_text(), (out / "problem.pddl").read_text()
        name = re.search(r"\(define \(domain (foon-tree-[0-9a-f]{8})\)", domain).group(1)
        assert f"(:domain {name})" in problem
        names.setdefault(goal, set()).add(name)
    assert len(names["guacamole"]) == 1 and names["guacamole"] != names["whipped cream"]
