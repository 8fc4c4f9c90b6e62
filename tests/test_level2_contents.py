"""What a node says about its contents when its `contains` has no list (issue 21 item 3, issue 24: notes true).

FOON's level 2 keeps a state's label and related object and drops its ingredient list, so `bowl (contains {onion,
salt})` is `bowl (contains)` there: it holds something and does not say what. Read as a node listing nothing, every
ingredient put into it read as unlisted, and `plan --level 2 --goal guacamole` printed 35 false `label mismatch:`
notes (`onion is in [bowl], whose node after the unit does not list it`, ...). The public data writes one such
`contains` at level 3 too: the plate `0082-homemade_cheese_pizza.txt:492` puts the cheese pizza on.
"""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.io.files import load
from foon2pddl.model.foon import make_node, make_state
from foon2pddl.model.levels import project, project_node
from foon2pddl.model.places import describes_contents, listed
from foon2pddl.pddl.holders import relational_roles

BOWL = make_node("bowl", [make_state("contains", "", ["onion", "salt"])])


def test_a_contains_without_a_list_says_nothing_of_the_contents():
    bare = project_node(BOWL, 2)
    assert bare.states == (make_state("contains"),)
    assert describes_contents(BOWL) and not describes_contents(bare)
    assert listed(bare) == frozenset()


@pytest.mark.parametrize("node", [make_node("bowl", [make_state("empty")]),
                                  make_node("baking tray", [make_state("contains", "parchment paper")]),
                                  make_node("mixer", [make_state("with", "mixing bowl")])])
def test_a_level_2_node_that_names_its_contents_still_describes_them(node):
    assert describes_contents(project_node(node, 2))


def test_a_list_left_out_beside_a_named_content_leaves_the_rest_unsaid():
    """`baking tray (contains {pizza dough}, contains [parchment paper])` at level 2 names the paper only: the
    dough on it is no unlisted content."""
    tray = make_node("baking tray", [make_state("contains", "", ["pizza dough"]), make_state("contains", "parchment paper")])
    assert not describes_contents(project_node(tray, 2))


def test_the_plate_of_the_public_data_with_an_unlisted_contains_is_silent():
    foon, _ = load([SUBGRAPHS / "0082-homemade_cheese_pizza.txt"])
    plates = [n for n in foon.nodes if n.label == "plate" and any(s.label == "contains" for s in n.states)]
    assert plates and all(not listed(n) and not describes_contents(n) for n in plates)


def _notes(*args: str) -> list[str]:
    result = CliRunner().invoke(main, ["plan", *args])
    assert result.exit_code == 0, result.output
    assert "valid" in result.stderr
    return [line for line in result.stderr.splitlines() if "label mismatch:" in line]


def test_plan_at_level_2_reports_no_list_that_level_2_does_not_have():
    notes = _notes("--level", "2", "--goal", "guacamole")
    assert not [n for n in notes if "does not list" in n or "lists nothing" in n or "nothing says" in n], notes


def test_the_plate_that_does_not_say_what_it_holds_is_no_mismatch_at_level_3():
    notes = _notes(str(SUBGRAPHS / "0082-homemade_cheese_pizza.txt"), "--goal", "cheese pizza")
    assert notes and not [n for n in notes if "cheese pizza is on [plate]" in n], notes


def test_an_object_in_a_level_2_holder_is_in_the_holder_the_unit_names():
    """`0050-scrambled_eggs_with_bacon-cheese.txt:135` at level 2: the scoop takes `bowl (contains)` and `butter (in
    [bowl], stick)`. Read as a bowl listing nothing, the bowl was no candidate to hold the butter: bound late, the plan
    scooped it out of one bowl while the unit's bowl was the egg mixture's."""
    foon, _ = load([SUBGRAPHS / "0050-scrambled_eggs_with_bacon-cheese.txt"])
    scoop = next(u for u in project(foon, 2).units if u.motion.label == "scoop and pour")
    roles = relational_roles(scoop)
    butter = next(r for r in roles if r.role.label == "butter")
    assert butter.source is not None and butter.source.role is not None
    assert roles[butter.source.role].role.label == "bowl"


def test_a_level_2_kitchen_object_starts_in_a_holder_of_the_level_2_network():
    """The kitchen's `garlic (clove, on [cutting board])` of `0023-garlic_rice.txt` at level 2 starts on FOON's
    `cutting board (contains)`, the node the chop at `:27` takes, where an added `cutting board (contains {garlic})`
    (a node of no level-2 network) left the goal out of holder reach (`plan` unsolvable)."""
    result = CliRunner().invoke(main, ["plan", str(SUBGRAPHS / "0023-garlic_rice.txt"), "--level", "2", "--kitchen",
                                       "default", "--goal", "garlic rice", "--format", "json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["status"] == "solved" and out["validation"]["ok"]
    start = {o["id"]: o for o in out["relational"]["initial"]}
    garlic = [o for o in start.values() if o["state"] == "garlic (clove, on [cutting board])"]
    assert garlic and {start[o["holder"]]["state"] for o in garlic} == {"cutting board (contains)"}
