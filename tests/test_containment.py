"""`--containment infer`: the containment rule in native retrieval, the validator, PDDL and the CLI."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.io.parser import parse_text
from foon2pddl.model.containment import (
    Containment,
    inferred_nodes,
    is_inference,
    rule_holds,
    with_containment,
)
from foon2pddl.model.foon import make_node, make_state
from foon2pddl.model.goal import GoalSpec, resolve_goal
from foon2pddl.model.levels import project, project_node
from foon2pddl.model.tasktree import TaskTree, validate
from foon2pddl.retrieval import retrieve

# The search inputs' convention: the kitchen says the cornmeal is in the bowl, the unit also needs the bowl's side.
FOON = """//
O1\tbowl\t0
S1\tcontains\t{cornmeal, milk}
S2\tin\t[mixer]
O2\tcornmeal\t1
S3\tground
S4\tin\t[bowl]
O3\tmilk\t1
S4\tin\t[bowl]
O4\tspoon\t1
M1\tstir\tAssumed\tAssumed
O5\tbatter\t1
S4\tin\t[bowl]
//
O6\tjar\t0
S5\tcontains\t{salt}
M2\tshake\tAssumed\tAssumed
O7\tsalt\t1
S6\tsprinkled
//
"""

CORNMEAL = make_node("cornmeal", [make_state("ground"), make_state("in", "bowl")])
MILK = make_node("milk", [make_state("in", "bowl")])
BOWL_IN_MIXER = make_node("bowl", [make_state("in", "mixer")])
SPOON = make_node("spoon")
KITCHEN = frozenset({CORNMEAL, MILK, BOWL_IN_MIXER, SPOON, make_node("salt", [make_state("in", "jar")])})


@pytest.fixture(scope="module")
def foon():
    return parse_text(FOON, "c.foon").foon


def goal(foon, label):
    return resolve_goal(GoalSpec(label), foon)


def test_strict_cannot_infer_make_it_and_the_tree_lists_the_inference(foon):
    assert retrieve(foon, KITCHEN, goal(foon, "batter")).tree is None
    aug = with_containment(foon, KITCHEN, Containment.INFER)
    result = retrieve(aug, KITCHEN, goal(aug, "batter"))
    tree = result.tree
    assert tree is not None and [u.motion.label for u in tree.units if not is_inference(u)] == ["stir"]
    bowl = make_node("bowl", [make_state("contains", "", ["cornmeal", "milk"]), make_state("in", "mixer")])
    assert inferred_nodes(tree.units) == (bowl,)
    infer = validate(tree, KITCHEN, "infer")
    assert infer.ok and infer.inferred == (bowl,)
    strict = validate(tree, KITCHEN, "strict")
    assert not strict.ok and "needs infer" in strict.problems[0]


def test_validator_infers_a_missing_container_input_without_an_inference_step(foon):
    stir = foon.units[0]
    tree = TaskTree((stir,), stir.outputs[0])
    assert not validate(tree, KITCHEN).ok
    check = validate(tree, KITCHEN, Containment.INFER)
    assert check.ok and len(check.inferred) == 1


def test_other_container_states_must_be_witnessed(foon):
    without_base = KITCHEN - {BOWL_IN_MIXER}
    aug = with_containment(foon, without_base, "infer")
    assert retrieve(aug, without_base, goal(aug, "batter")).tree is None
    assert not rule_holds(foon.units[0].inputs[0], without_base, 3)


def test_every_content_must_be_in_the_container(foon):
    only_cornmeal = KITCHEN - {MILK}
    assert not rule_holds(foon.units[0].inputs[0], only_cornmeal, 3)
    aug = with_containment(foon, only_cornmeal, "infer")
    assert retrieve(aug, only_cornmeal, goal(aug, "batter")).tree is None


def test_single_content_without_other_states(foon):
    aug = with_containment(foon, KITCHEN, "infer")
    tree = retrieve(aug, KITCHEN, goal(aug, "salt")).tree
    assert tree is not None and validate(tree, KITCHEN, "infer").ok


def test_level_2_needs_one_content_of_any_label(foon):
    two = project(foon, 2)
    kitchen2 = frozenset(project_node(n, 2) for n in KITCHEN - {MILK})  # the milk is not needed at level 2
    aug = with_containment(two, kitchen2 | {project_node(MILK, 2)}, "infer")
    tree = retrieve(aug, kitchen2 | {project_node(MILK, 2)}, goal(aug, "batter")).tree
    assert tree is not None and validate(tree, kitchen2 | {project_node(MILK, 2)}, "infer").ok
    bowl2 = make_node("bowl", [make_state("contains"), make_state("in", "mixer")])
    assert rule_holds(bowl2, {project_node(CORNMEAL, 2), project_node(BOWL_IN_MIXER, 2)}, 2)
    assert not rule_holds(bowl2, {project_node(BOWL_IN_MIXER, 2)}, 2)


def test_level_1_infers_nothing(foon):
    one = project(foon, 1)
    assert with_containment(one, KITCHEN, "infer") is one


def test_strict_is_the_network_itself(foon):
    assert with_containment(foon, KITCHEN, "strict") is foon


def test_cli_retrieve_and_plan_under_infer(tmp_path):
    net = tmp_path / "c.foon"
    net.write_text(FOON)
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("cornmeal: ground, in [bowl]\nmilk: in [bowl]\nbowl: in [mixer]\nspoon\n")
    strict = CliRunner().invoke(main, ["retrieve", str(net), "--kitchen", str(kitchen), "--goal", "batter"])
    assert strict.exit_code == 1
    infer = CliRunner().invoke(main, ["retrieve", str(net), "--kitchen", str(kitchen), "--goal", "batter",
                                      "--containment", "infer"])
    assert infer.exit_code == 0, infer.output
    assert "1 unit, 1 inferred by containment: bowl (contains {cornmeal, milk}, in [mixer])" in infer.stderr
    planned = CliRunner().invoke(main, ["plan", str(net), "--kitchen", str(kitchen), "--goal", "batter",
                                        "--containment", "infer", "--encoding", "tree"])  # FOON's semantics
    assert planned.exit_code == 0, planned.output
    assert "valid" in planned.stderr
