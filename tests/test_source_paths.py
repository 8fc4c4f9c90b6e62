"""Messages name a unit's source one way: a file shipped with the package (the embedded example) by its path in
the package, wherever it is installed; any other file as the user gave it.

Before one helper named them (`model.where.shown_path`), relational notes printed the embedded example's
absolute install path (`/.../site-packages/foon2pddl/data/example/09-fruit_salad.foon:199`) while `plan --skills`
printed `foon2pddl/data/example/...`.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

import foon2pddl
from foon2pddl.cli import main
from foon2pddl.model.where import shown_path

PACKAGE = Path(foon2pddl.__file__).resolve().parent


def test_a_note_on_the_embedded_example_names_the_file_by_its_path_in_the_package():
    result = CliRunner().invoke(main, ["plan", "--goal", "fruit salad"])
    assert result.exit_code == 0, result.output
    notes = [line for line in result.stderr.splitlines() if "label mismatch" in line]
    assert notes, result.stderr  # 09-fruit_salad.foon:199: the bowl lists whipped cream, put on the salad
    assert all("foon2pddl/data/example/09-fruit_salad.foon:" in line for line in notes), notes
    assert str(PACKAGE) not in result.stderr + result.stdout


def test_every_plan_line_of_the_embedded_example_is_free_of_the_install_place():
    for args in (["--goal", "guacamole", "--skills"], ["--goal", "guacamole", "--format", "json"],
                 ["--goal", "guacamole", "--encoding", "instances", "--format", "json"]):
        result = CliRunner().invoke(main, ["plan", *args])
        assert str(PACKAGE) not in result.stdout + result.stderr, args


def test_a_file_outside_the_package_is_named_as_given(tmp_path):
    given = str(SUBGRAPHS / "0001-whipped_cream.txt")
    assert shown_path(given) == given
    assert shown_path("recipes/x.txt") == "recipes/x.txt"
    assert shown_path(str(PACKAGE / "data" / "example" / "01-lemonade.foon")) == "foon2pddl/data/example/01-lemonade.foon"


@pytest.mark.parametrize("command", [["stats"], ["stats", "--json"], ["check"], ["check", "--json"]])
def test_stats_and_check_name_the_embedded_examples_files_by_their_path_in_the_package(command):
    """Issue 24's re-pass (stop 47): `stats` (units per source file) and `check` (defect places) on the embedded
    example printed its absolute install path (`/.../site-packages/foon2pddl/data/example/04-pancakes.foon:178`),
    where every note names it `foon2pddl/data/example/...`."""
    result = CliRunner().invoke(main, command)
    assert result.exit_code in (0, 1), result.output
    assert "foon2pddl/data/example/0" in result.stdout
    assert str(PACKAGE) not in result.stdout + result.stderr
