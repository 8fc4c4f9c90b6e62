"""A relational plan with none at level 1 or 2 says what the level reads otherwise (issue 24: reasons that name the
cause; issue 21: level 2's relational plans).

FOON's level 2 drops ingredient lists, from which the relational encoding reads which container holds what and
whether a pour leaves some behind; a dish level 3 plans then said only `translator: no relaxed solution`.
"""

from __future__ import annotations

from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main


def test_a_level_2_dish_without_a_plan_says_what_level_2_reads_otherwise():
    """`0004-pancake_batter.txt` plans at level 3; at level 2 the relational planner finds none, and the reason was
    only `the planner found no plan ... (see its message)` under `translator: no relaxed solution`. The measuring
    cup FOON says keeps milk after the pour at `:46` (a portion is poured) says nothing at level 2 (the milk leaves it
    whole): the reason names the level, the lists it leaves out, and the units it reads otherwise."""
    path = str(SUBGRAPHS / "0004-pancake_batter.txt")
    result = CliRunner().invoke(main, ["plan", path, "--level", "2", "--goal", "pancake batter"])
    assert result.exit_code == 1, result.output
    reason = next(line for line in result.stderr.splitlines() if line.startswith("reason: "))
    assert "relational encoding at level 2, whose nodes leave out the ingredient lists" in reason
    assert ("0004-pancake_batter.txt:46: milk leaves a portion out of the unit's measuring cup into the unit's bowl "
            "at level 3, moves whole out of the unit's measuring cup into the unit's bowl at level 2") in reason
    assert "`--level 3` reads the lists" in reason
    # level 3 reads the lists; FOON's mix at :58 takes the kitchen's egg white and yolk in another bowl than the
    # batter's (issue 21), so its plan pours it over first, a step beyond FOON naming the mix
    three = CliRunner().invoke(main, ["plan", path, "--goal", "pancake batter"])
    assert three.exit_code == 0, three.output
    (step,) = [line for line in three.stdout.splitlines() if "beyond FOON" in line]
    assert step.startswith("5. pour ") and step.endswith("0004-pancake_batter.txt:58, whose words leave it in "
                                                          "another holder)"), step


def test_each_object_is_compared_with_its_own_level_2_reading():
    """Each object is compared with its own level-2 role: the one at its position in the projected unit, of its label
    (`levels.project_unit` keeps a node per node since 494e862). Before, equal level-2 nodes were kept once, a unit
    had fewer roles at level 2, and position paired an object with another's reading: 0005's sprinkle at :149 said
    `bowl stays at level 3, moves whole out of the unit's bowl into whichever bean mix at level 2` (the salt's reading
    given to the bowl), its pick-and-place at :457 `bread is consumed ... at level 3, is made into whichever cutting
    board at level 2` (the sandwich's)."""
    from foon2pddl.io.files import load
    from foon2pddl.pddl.level_readings import lost_readings

    units = {u.sources[0].line: u for u in load([SUBGRAPHS / "0005-chipotle-bean_sandwich.txt"])[0].units}
    (sprinkle,) = lost_readings([units[149]], 2)
    # level 2 keeps the sprinkle's two bowls (`levels.project_unit`), and no list says which holds the salt
    assert sprinkle.endswith(":149: salt leaves a portion out of the unit's bowl into whichever bean mix at level 3, "
                             "moves whole out of whichever bowl into whichever bean mix at level 2"), sprinkle
    assert lost_readings([units[457]], 2) == ()  # the bread is consumed into the sandwich at both levels


def test_an_object_paired_otherwise_at_level_2_is_still_compared_at_its_position():
    """0008's pour at :255: the bowl moves whole into the double boiler at level 3 and stays at level 2 (its level-2
    role is paired with another output). Looked up by its projected (before, after) it found no role and was not
    compared; at its position in the projected unit, a role of its label, it is."""
    from foon2pddl.io.files import load
    from foon2pddl.pddl.level_readings import lost_readings

    units = {u.sources[0].line: u for u in load([SUBGRAPHS / "0008-buckeye_candy-allrecipes.txt"])[0].units}
    assert lost_readings([units[255]], 2) == (
        f"pour at {SUBGRAPHS / '0008-buckeye_candy-allrecipes.txt'}:255: bowl moves whole into the unit's double boiler "
        "at level 3, stays at level 2",)
