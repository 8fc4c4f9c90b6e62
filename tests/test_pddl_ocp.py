"""The `ocp` encoding: the public foon_to_pddl converter's object-centred format, checked against the
converter's own output for its pour_water example (tests/data/foon_to_pddl-examples), and its rules."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from conftest import SHARED

import foon2pddl as fp
from foon2pddl.cli import main
from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
from foon2pddl.pddl.encode_ocp import node_facts, unit_effects
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


def test_ocp_writes_the_converters_pour_water_domain_and_problem(tmp_path, converter_kitchen):
    result = CliRunner().invoke(main, ["compile", str(POUR), "--encoding", "ocp", "--no-prune", "--kitchen",
                                       str(converter_kitchen), "--goal", BOWL, "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    ours = structure((tmp_path / "out" / "domain.pddl").read_text(), (tmp_path / "out" / "problem.pddl").read_text())
    reference = structure((EXAMPLES / "FOON-pour_water_domain.pddl").read_text(),
                          (EXAMPLES / "FOON-pour_water_problem.pddl").read_text())
    assert sorted(ours["actions"]) == sorted(reference["actions"]) == ["fill_0", "pour_water_1"]
    for name, (pre, add, delete) in reference["actions"].items():
        assert ours["actions"][name] == (pre, add, delete), name
    assert ours["init"] == reference["init"] and ours["goal"] == reference["goal"]
    assert ("in", "cup", "air") in ours["init"] and ("under", "water", "cup") in ours["actions"]["fill_0"][1]


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


def test_the_converters_bloody_mary_example_is_planned():
    net = fp.load_network(EXAMPLES / "FOON-0076-bloody_mary.txt")
    outcome = fp.plan(net, fp.load_kitchen(net, "default"), "bloody mary", "ocp", time_limit=120)
    assert outcome.status == PlanStatus.SOLVED and len(outcome.tree) == 9


# --- the rules, one unit each ----------------------------------------------------------------------------


def _n(label, *states, flag=0):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states], motion_flag=flag)


def test_a_node_without_a_place_is_on_the_table_and_a_surface_holds_air_on_it():
    assert node_facts(_n("knife")) == (("under", "knife", "table"), ("on", "table", "knife"))
    assert ("on", "plate", "air") in node_facts(_n("plate", "empty"))
    assert ("in", "bowl", "air") in node_facts(_n("bowl", "empty"))
    assert set(node_facts(_n("salt", ("in", "bowl")))) == {("in", "bowl", "salt"), ("under", "salt", "bowl")}
    assert node_facts(_n("lid", ("under", "pot"))) == (("under", "pot", "lid"),)


def test_mixed_is_said_of_the_holder_and_physical_states_replace_each_other():
    assert ("is-mixed", "bowl") in node_facts(_n("batter", "mixed", ("in", "bowl")))
    whole, chopped = _n("onion", "whole", ("on", "cutting board")), _n("onion", "chopped", ("on", "cutting board"))
    pre, add, delete = unit_effects(FunctionalUnit((whole, _n("knife", flag=1)), Motion("chop"), (chopped,)))
    assert ("is-whole", "onion") in pre and ("is-chopped", "onion") in add and delete == (("is-whole", "onion"),)


def test_contents_are_replaced_only_where_an_output_container_lists_them():
    bowl_a = _n("bowl", ("contains", "", ["flour"]))
    bowl_ab = _n("bowl", ("contains", "", ["flour", "sugar"]))
    sugar = _n("sugar", ("in", "bowl"), flag=1)
    _, add, delete = unit_effects(FunctionalUnit((bowl_a, _n("sugar", ("in", "bag"), flag=1)), Motion("pour"),
                                                 (bowl_ab, sugar)))
    assert ("in", "bowl", "sugar") in add and not [d for d in delete if d[1] == "bowl"]  # flour stays in
    assert ("in", "bag", "sugar") not in delete  # no output says what the bag holds
    batter = _n("batter", "mixed", ("in", "bowl"))
    _, add, delete = unit_effects(FunctionalUnit((bowl_ab, _n("whisk")), Motion("mix"),
                                                 (_n("bowl", ("contains", "", ["batter"])), batter)))
    assert set(delete) >= {("in", "bowl", "flour"), ("in", "bowl", "sugar")} and ("is-mixed", "bowl") in add


def test_an_object_put_somewhere_leaves_the_table_and_a_scooped_one_is_not_put_on_it():
    _, _, delete = unit_effects(FunctionalUnit((_n("onion"), _n("bowl", "empty")), Motion("pick-and-place"),
                                               (_n("onion", ("in", "bowl")), _n("bowl", ("contains", "", ["onion"])))))
    assert set(delete) == {("on", "table", "onion"), ("under", "onion", "table"), ("in", "bowl", "air")}
    inputs, outputs = (_n("sauce", ("in", "pot")), _n("spoon", flag=1)), (_n("sauce", "liquid"),)
    assert ("on", "table", "sauce") in unit_effects(FunctionalUnit(inputs, Motion("pour"), outputs))[1]
    assert ("on", "table", "sauce") not in unit_effects(FunctionalUnit(inputs, Motion("scoop"), outputs))[1]


def test_operator_names_follow_the_converters_focal_object():
    from foon2pddl.pddl.encode_ocp import action_name

    pour = FunctionalUnit((_n("cup", ("contains", "", ["water"])), _n("water", ("in", "cup"), flag=1)), Motion("pour"),
                          (_n("water", ("in", "bowl")),))
    assert action_name(pour) == "pour water"
    assert action_name(FunctionalUnit((_n("bowl", ("contains", "", ["a"])),), Motion("mix"), ())) == "mix ingredients"
    assert action_name(FunctionalUnit((_n("cup", flag=1),), Motion("fill"), ())) == "fill"
