"""Utensils (`--utensils FILE`): reusable objects, available in base state when the kitchen holds them."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.kitchen_files import parse_utensils
from foon2pddl.io.parser import parse_text
from foon2pddl.model.foon import make_node, make_state
from foon2pddl.model.kitchen import Kitchen, with_utensils

FOON = """//
O1\tknife\t1
S1\tclean
O2\tonion\t0
S2\twhole
M1\tchop\tAssumed\tAssumed
O2\tonion\t0
S3\tchopped
O1\tknife\t1
S4\tdirty
//
"""


def test_parse_utensils_normalizes_and_skips_comments():
    assert parse_utensils("# tools\nCutting  Board\n\nknife\n") == frozenset({"cutting board", "knife"})
    with pytest.raises(FoonSyntaxError) as exc:
        parse_utensils("knife\nbad\tline\n", "u.txt")
    assert exc.value.line == 2


def test_a_utensil_in_any_state_provides_its_base_state_nodes():
    foon = parse_text(FOON, "u.foon").foon
    dirty = make_node("knife", [make_state("dirty")])
    kitchen = Kitchen(frozenset({dirty, make_node("onion", [make_state("whole")])}))
    assert with_utensils(kitchen, foon, {"knife"}).nodes == kitchen.nodes | {make_node("knife", [make_state("clean")])}
    assert with_utensils(kitchen, foon, {"spoon"}) is kitchen


def test_cli_utensils_make_a_goal_reachable(tmp_path):
    net, kit, ut = tmp_path / "u.foon", tmp_path / "k.txt", tmp_path / "utensils.txt"
    net.write_text(FOON)
    kit.write_text("knife: dirty\nonion: whole\n")
    ut.write_text("knife\n")
    args = ["retrieve", str(net), "--kitchen", str(kit), "--goal", "onion: chopped"]
    assert CliRunner().invoke(main, args).exit_code == 1
    r = CliRunner().invoke(main, args + ["--utensils", str(ut)])
    assert r.exit_code == 0, r.output
    c = CliRunner().invoke(main, ["compile", *args[1:], "--utensils", str(ut), "-o", str(tmp_path / "p")])
    assert c.exit_code == 0 and "knife" in (tmp_path / "p" / "problem.pddl").read_text()
