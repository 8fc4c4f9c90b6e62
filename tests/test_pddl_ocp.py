"""The `ocp` encoding: the public foon_to_pddl converter's object-centred format, checked against the
converter's own output for its pour_water example (tests/data/foon_to_pddl-examples), and its rules."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SHARED

import foon2pddl as fp
from foon2pddl.cli import main
from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
from foon2pddl.pddl.encode_ocp import goal_facts_of, node_facts, unit_effects
from foon2pddl.skills.sexpr import SList, parse
from foon2pddl.status import PlanStatus

EXAMPLES = SHARED / "foon_to_pddl-examples"
POUR = EXAMPLES / "FOON-pour_water.txt"
BOWL = "bowl: contains {water}, on [table]"

#: The kitchen of the converter's problem file: the inputs no earlier unit makes, the empty cup among them
#: (the network's default kitchen lacks it: the pour makes `cup (empty, on [table])` again).
CONVERTER_KITCHEN = """\
O\tbottle\t1
S\tcontains\t{water}
S\ton\t[table]
//
O\tcup\t0
S\tempty
S\ton\t[table]
//
O\twater\t1
S\tliquid
S\tin\t[bottle]
//
O\tbowl\t0
S\tempty
S\ton\t[table]
//
"""


def _norm(symbol: str) -> str:
    """A name modulo sanitization: the converter writes `_` where foon2pddl keeps `-`."""
    return symbol.lower().replace("-", "_")


def _atom(x: SList) -> tuple[str, ...]:
    return tuple(_norm(s) for s in x.items)


def _conjuncts(x: SList) -> list[SList]:
    return list(x.items[1:]) if x.head == "and" else [x]


def _section(top: SList, key: str):
    return next(x for x in top.items if isinstance(x, SList) and x.head == key)


def structure(domain: str, problem: str) -> dict:
    """Actions (name -> precondition, adds, deletes as atom sets), init and goal, read from PDDL text."""
    (dom,), (prob,) = parse(domain), parse(problem)
    actions = {}
    for a in (x for x in dom.items if isinstance(x, SList) and x.head == ":action"):
        fields = dict(zip(a.items[2::2], a.items[3::2], strict=True))
        effect = _conjuncts(fields[":effect"])
        actions[_norm(a.items[1])] = (
            frozenset(_atom(p) for p in _conjuncts(fields[":precondition"])),
            frozenset(_atom(e) for e in effect if e.head != "not"),
            frozenset(_atom(e.items[1]) for e in effect if e.head == "not"))
    return {"actions": actions,
            "init": frozenset(_atom(x) for x in _section(prob, ":init").items[1:]),
            "goal": frozenset(_atom(x) for x in _conjuncts(_section(prob, ":goal").items[1]))}


@pytest.fixture
def converter_kitchen(tmp_path):
    path = tmp_path / "pour_water_kitchen.txt"
    path.write_text(CONVERTER_KITCHEN)
    return path


def _compile(tmp_path, kitchen: Path, goal: str, name: str, *extra: str) -> tuple[str, str]:
    out = tmp_path / name
    result = CliRunner().invoke(main, ["compile", str(POUR), "--encoding", "ocp", "--no-prune", "--kitchen",
                                       str(kitchen), "--goal", goal, "-o", str(out), *extra])
    assert result.exit_code == 0, result.output
    return (out / "domain.pddl").read_text(), (out / "problem.pddl").read_text()


def test_ocp_writes_the_converters_pour_water_domain_and_problem(tmp_path, converter_kitchen):
    """The same actions (preconditions, adds, deletes), :init and :goal as the converter's own output. The
    converter's goal is every final product of the file (the bowl of water, and the water in the bowl);
    the bowl's `contains {water}` gives foon2pddl the water's fact, and the water alone gives a part."""
    reference = structure((EXAMPLES / "FOON-pour_water_domain.pddl").read_text(),
                          (EXAMPLES / "FOON-pour_water_problem.pddl").read_text())
    bowl = structure(*_compile(tmp_path, converter_kitchen, BOWL, "bowl"))
    water = structure(*_compile(tmp_path, converter_kitchen, "water: in [bowl], liquid", "water"))
    assert sorted(bowl["actions"]) == sorted(reference["actions"]) == ["fill_0", "pour_water_1"]
    for name, (pre, add, delete) in reference["actions"].items():
        assert bowl["actions"][name] == (pre, add, delete), name
    assert bowl["actions"] == water["actions"] and bowl["init"] == water["init"] == reference["init"]
    assert bowl["goal"] == reference["goal"] and water["goal"] == {("in", "bowl", "water")}
    assert ("in", "cup", "air") in bowl["init"] and ("under", "water", "cup") in bowl["actions"]["fill_0"][1]


def test_ocp_output_is_byte_identical_across_runs_and_hash_seeds(tmp_path, converter_kitchen):
    outs = []
    for seed in ("1", "2"):
        out = tmp_path / seed
        env = {**os.environ, "PYTHONHASHSEED": seed}
        subprocess.run([sys.executable, "-m", "foon2pddl", "compile", str(EXAMPLES / "FOON-0076-bloody_mary.txt"),
                        "--goal", "bloody mary", "--encoding", "ocp", "-o", str(out)],
                       check=True, env=env, capture_output=True)
        outs.append(((out / "domain.pddl").read_bytes(), (out / "problem.pddl").read_bytes()))
    assert outs[0] == outs[1] and b"(is-mixed drinking_glass)" in outs[0][0]


def test_fast_downward_plans_the_converters_example_fill_then_pour(converter_kitchen):
    net = fp.load_network(POUR)
    kitchen = fp.load_kitchen(net, converter_kitchen)
    outcome = fp.plan(net, kitchen, BOWL, "ocp", time_limit=120)
    assert outcome.status == PlanStatus.SOLVED
    assert outcome.result.plan == ("fill_0", "pour_water_1")


def test_the_converters_example_makes_no_goal_from_the_default_kitchen():
    net = fp.load_network(POUR)
    goals = ["bowl: contains {water}, on [table]", "cup: contains {water}, on [table]", "cup: empty, on [table]",
             "water: in [bowl], liquid", "water: in [cup], liquid"]
    default = fp.load_kitchen(net, "default")
    assert [fp.plan(net, default, g, "ocp", time_limit=120).status for g in goals] == [PlanStatus.UNSOLVABLE] * 5


def test_the_converters_kitchen_makes_all_five_goals(converter_kitchen):
    net = fp.load_network(POUR)
    kitchen = fp.load_kitchen(net, converter_kitchen)
    lengths = {g: len(fp.plan(net, kitchen, g, "ocp", time_limit=120).result.plan)
               for g in ("bowl: contains {water}, on [table]", "cup: contains {water}, on [table]",
                         "cup: empty, on [table]", "water: in [bowl], liquid", "water: in [cup], liquid")}
    assert lengths == {"bowl: contains {water}, on [table]": 2, "cup: contains {water}, on [table]": 1,
                       "cup: empty, on [table]": 0, "water: in [bowl], liquid": 2, "water: in [cup], liquid": 1}


def test_the_converters_bloody_mary_example_is_planned_as_the_converter_reads_it():
    """The goal node says `in [drinking glass]` and `mixed`, and its `contains {...}` is written by no
    action (the items are `in [drinking glass]`, not in the bloody mary): so the celery's insert is not
    needed, and the mix comes last, after the seven pours and sprinkles its inputs need."""
    net = fp.load_network(EXAMPLES / "FOON-0076-bloody_mary.txt")
    outcome = fp.plan(net, fp.load_kitchen(net, "default"), "bloody mary", "ocp", time_limit=120)
    assert outcome.status == PlanStatus.SOLVED
    plan = outcome.result.plan
    assert len(plan) == 8 and plan[-1].startswith("mix_ingredients_") and not [a for a in plan if "insert" in a]


# --- the rules, one unit each ----------------------------------------------------------------------------


def _n(label, *states, flag=0):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states], motion_flag=flag)


def test_a_node_without_a_place_is_on_the_table_and_contents_are_said_by_their_own_nodes():
    assert node_facts(_n("knife")) == (("under", "knife", "table"), ("on", "table", "knife"))
    assert ("on", "plate", "air") in node_facts(_n("plate", "empty"))
    assert ("in", "bowl", "air") in node_facts(_n("bowl", "empty"))
    assert set(node_facts(_n("salt", ("in", "bowl")))) == {("in", "bowl", "salt"), ("under", "salt", "bowl")}
    assert node_facts(_n("lid", ("under", "pot"))) == (("under", "pot", "lid"),)
    assert node_facts(_n("bowl", ("contains", "", ["salt"]), ("on", "table"))) == (
        ("on", "table", "bowl"), ("under", "bowl", "table"))  # `contains` writes nothing
    assert node_facts(_n("salt", ("in", "bowl")), goal=True) == (("in", "bowl", "salt"),)  # goals: no `under`


def test_mixed_is_said_of_the_holder_and_physical_states_replace_each_other():
    assert ("is-mixed", "bowl") in node_facts(_n("batter", "mixed", ("in", "bowl")))
    assert ("is-mixed", "batter") in node_facts(_n("batter", "mixed"))
    whole, chopped = _n("onion", "whole", ("on", "cutting board")), _n("onion", "chopped", ("on", "cutting board"))
    pre, add, delete = unit_effects(FunctionalUnit((whole, _n("knife", flag=1)), Motion("chop"), (chopped,)))
    assert ("is-whole", "onion") in pre and ("is-chopped", "onion") in add and delete == (("is-whole", "onion"),)
    assert ("under", "knife", "table") in add  # no output speaks of the knife: kept


def test_air_in_and_out_is_the_only_change_of_place_deleted():
    """Filling deletes the container's air and emptying its contents; the poured item stays `under` its old
    holder and an object put into a bowl stays on the table, as the converter writes it."""
    onion, bowl = _n("onion"), _n("bowl", "empty")
    _, add, delete = unit_effects(FunctionalUnit((onion, bowl), Motion("pick-and-place"),
                                                 (_n("onion", ("in", "bowl")), _n("bowl", ("contains", "", ["onion"])))))
    assert delete == (("in", "bowl", "air"),) and ("in", "bowl", "onion") in add
    assert not {("under", "onion", "table"), ("on", "table", "onion")} & set(add)  # neither kept nor deleted
    cup = _n("cup", ("contains", "", ["water"]), ("on", "table"))
    water = _n("water", ("in", "cup"), flag=1)
    _, add, delete = unit_effects(FunctionalUnit((cup, water, bowl), Motion("pour"),
                                                 (_n("water", ("in", "bowl")), _n("cup", "empty", ("on", "table")))))
    assert set(delete) == {("in", "cup", "water"), ("in", "bowl", "air")}
    assert {("in", "cup", "air"), ("in", "bowl", "water"), ("under", "water", "bowl")} <= set(add)
    assert ("under", "water", "cup") not in delete and not set(add) & set(delete)


def test_a_scooped_object_is_not_put_on_the_table():
    inputs, outputs = (_n("sauce", ("in", "pot")), _n("spoon", flag=1)), (_n("sauce", "liquid"),)
    assert ("on", "table", "sauce") in unit_effects(FunctionalUnit(inputs, Motion("pour"), outputs))[1]
    assert ("on", "table", "sauce") not in unit_effects(FunctionalUnit(inputs, Motion("scoop"), outputs))[1]


def test_a_goal_container_asks_for_the_listed_items_its_network_writes():
    bowl = _n("bowl", ("contains", "", ["salt", "water"]))
    assert goal_facts_of(bowl, {("in", "bowl", "salt")}) == (
        ("under", "bowl", "table"), ("on", "table", "bowl"), ("in", "bowl", "salt"))


def test_operator_names_follow_the_converters_focal_object():
    from foon2pddl.pddl.encode_ocp import action_name

    pour = FunctionalUnit((_n("cup", ("contains", "", ["water"])), _n("water", ("in", "cup"), flag=1)), Motion("pour"),
                          (_n("water", ("in", "bowl")),))
    assert action_name(pour) == "pour water"
    assert action_name(FunctionalUnit((_n("bowl", ("contains", "", ["a"])),), Motion("mix"), ())) == "mix ingredients"
    assert action_name(FunctionalUnit((_n("cup", flag=1),), Motion("fill"), ())) == "fill"


def test_a_kitchen_container_writes_what_it_holds_so_a_goal_it_holds_holds_at_start():
    # found by test_goal_in_kitchen's hypothesis search in a fresh clone: the goal `bowl (contains {salt, water})`
    # requires `(in bowl water)` (a unit reads `water (in [bowl])`), which the kitchen's own bowl did not write
    from foon2pddl.model.foon import Foon
    from foon2pddl.model.goal import Goal, GoalSpec
    from foon2pddl.model.kitchen import Kitchen
    from foon2pddl.pddl.compile import compile_goal
    from foon2pddl.pddl.task import Atom

    bowl = make_node("bowl", [make_state("contains", "", ["salt", "water"])])
    fill = FunctionalUnit((make_node("water", [make_state("in", "bowl")]),), Motion("pour"), (bowl,))
    task = compile_goal(Foon((fill,)), Kitchen(frozenset({bowl})), Goal(GoalSpec("bowl"), (bowl,)), "ocp").task
    assert Atom("in", ("bowl", "water")) in task.init
    assert set(task.goal) <= set(task.init)
    assert Atom("in", ("bowl", "salt")) not in task.init  # salt is no object of the task: nothing writes it
