"""The category index (FOON-GEN) and compression."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from conftest import SHARED, SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.errors import FoonInputError
from foon2pddl.generalize.categories import coverage, parse_index, shipped_index
from foon2pddl.generalize.compress import abstract_goal, abstract_kitchen, abstract_node, compress
from foon2pddl.io.files import load
from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state
from foon2pddl.model.goal import resolve_goal
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.retrieval import retrieve


def index_text(cats):
    return json.dumps({"categories": {n: {"parent": p, "description": "", "members": m} for n, p, m in cats}})


def test_shipped_index_size_and_shape():
    ix = shipped_index()
    assert len(ix) >= 50
    assert any(c.parent for c in ix.categories)  # refinements exist
    multi = [m for c in ix.categories for m in c.members if len(ix.of(m)) > 1]
    assert multi  # objects in several categories
    for c in ix.categories:  # every member's chosen category lists it
        for m in c.members:
            assert m in ix.get(ix.choose(m)).members


def test_lemon_and_lime_share_sour_citrus():
    ix = shipped_index()
    assert ix.of("lemon") == ix.of("lime") == ("lemons and limes",)
    assert ix.choose("lemon") == ix.choose("lime") == "lemons and limes" != ix.choose("orange") == "oranges"
    assert ix.ancestors("lemons and limes") == ix.ancestors("oranges") == ("citrus fruits", "fruits")
    assert {"lemon", "orange"} <= ix.members_of("citrus fruits")


def test_coverage_of_the_shared_subgraphs_and_the_example(example):
    ix = shipped_index()
    foon, _ = load([SUBGRAPHS])
    cov = coverage((n.label for n in foon.nodes), ix)
    assert len(cov.labels) > 400 and cov.percent >= 90.0
    for path in sorted(SUBGRAPHS.glob("*.txt")) + sorted((SHARED / "foon_to_pddl-examples").glob("*.txt")):
        one, _ = load([path])  # each recipe on its own, and the public converter's examples
        assert coverage((n.label for n in one.nodes), ix).percent >= 95.0, path.name
    assert ix.choose("hand") == "hands"  # the cook's hand, not a cutting tool
    kitchen = read_kitchen(example_path("example_kitchen.txt"))
    labels = {n.label for n in example.foon.nodes} | {n.label for n in kitchen.nodes}
    labels |= {x for n in kitchen.nodes for s in n.states for x in (s.related, *s.ingredients) if x}
    assert coverage(labels, ix).missing == ()


def test_choose_takes_the_deepest_then_the_first():
    ix = parse_index(index_text([("food", None, ["apple", "salt"]), ("fruit", "food", ["apple"]),
                                 ("seasoning", None, ["salt"]), ("mineral", None, ["salt"])]), "x.json")
    assert ix.choose("apple") == "fruit"  # deeper than food
    assert ix.choose("salt") == "food"  # all at depth 0: first in file order
    assert ix.choose("water") is None
    assert ix.members_of("food") == {"apple", "salt"}


@pytest.mark.parametrize("cats, message", [
    ([("a", "b", ["x"])], "unknown parent"),
    ([("a", "b", ["x"]), ("b", "a", ["y"])], "cycle"),
    ([("salt", None, ["salt"])], "object labels"),
])
def test_bad_index_is_reported_with_its_file(cats, message):
    with pytest.raises(FoonInputError, match=message) as err:
        parse_index(index_text(cats), "cats.json")
    assert err.value.path == "cats.json"


def test_compress_merges_units_of_one_category():
    ix = shipped_index()
    units = tuple(FunctionalUnit((make_node(f, [make_state("whole")]), make_node("knife")), Motion("cut"),
                                 (make_node(f, [make_state("halved")]),), (Source(f"{f}.foon", 1),))
                  for f in ("lemon", "lime", "orange"))
    c = compress(Foon(units), ix)
    assert len(c.foon.units) == 2 and c.removed_units == 1  # lemon and lime merge; orange is sweet citrus
    u, o = c.foon.units
    assert {n.label for n in u.inputs} == {"lemons and limes", "cutting tools"}
    assert [s.path for s in u.sources] == ["lemon.foon", "lime.foon"]  # provenance joined
    assert {n.label for n in o.inputs} == {"oranges", "cutting tools"}


def test_compress_reads_a_place_word_as_the_unit_reads_it():
    # the apple turnover's pour (0086:195): `butter (melted, in [pan])` where the unit's pan is the `cooking pan`
    # (rule 0, the head noun). `pan` has no category of its own: generalized, it is the cooking pan's,
    # `cookware`, not a `pan` no object of the GEN unit is; the reading is reported at the unit's file:line
    pan = make_node("cooking pan", [make_state("contains", "", ["butter"]), make_state("on", "stove")])
    butter = make_node("butter", [make_state("melted"), make_state("in", "pan")])
    apple = make_node("apple", [make_state("chopped"), make_state("in", "bowl")])
    out = (make_node("cooking pan", [make_state("contains", "", ["apple", "butter"]), make_state("on", "stove")]),
           make_node("apple", [make_state("chopped"), make_state("in", "cooking pan")]))
    pour = FunctionalUnit((pan, butter, apple), Motion("pour"), out, (Source("turnover.foon", 195),))
    ix = shipped_index()
    c = compress(Foon((pour,)), ix)
    (u,) = c.foon.units
    assert make_node("dairy", [make_state("melted"), make_state("in", "cookware")]) in u.inputs
    assert c.readings == ("turnover.foon:195: pan read as cooking pan, so cookware",)
    # the node is one thing wherever it is: a kitchen holding it (and a goal asking for it) reads it so too
    assert abstract_node(butter, c.mapping, c.names) in abstract_kitchen(Kitchen(frozenset({butter})), ix,
                                                                         c.names).nodes
    assert abstract_node(butter, c.mapping, c.names) == make_node("dairy", [make_state("melted"),
                                                                            make_state("in", "cookware")])
    # a place word the unit does not read (no role's label ends in it) stays as it is, and nothing is reported
    lid = FunctionalUnit((make_node("pot"), make_node("pot lid")), Motion("cover"),
                         (make_node("pot", [make_state("covered")]), make_node("pot lid", [make_state("on", "pan")])),
                         (Source("rice.foon", 131),))
    c = compress(Foon((lid,)), shipped_index())
    assert make_node("lids and covers", [make_state("on", "pan")]) in c.foon.units[0].outputs
    assert c.readings == ()


def test_abstract_kitchen_and_goal():
    ix = shipped_index()
    k = Kitchen(frozenset({make_node("lime", [make_state("in", "bowl")]), make_node("xyzzy")}))
    ak = abstract_kitchen(k, ix)
    assert make_node("lemons and limes", [make_state("in", "bowls")]) in ak and make_node("xyzzy") in ak
    spec = abstract_goal(parse_goal_spec("lemonade: contains {lemon juice, sugar}, in [pitcher]"), ix)
    assert spec.label == "beverages"
    assert {s.describe() for s in spec.states} == {"contains {juices, sugars}", "in [pitchers and jugs]"}


def test_gen_retrieval_solves_the_example_goal_reg_cannot(example):
    ix = shipped_index()
    for path in sorted(SUBGRAPHS.glob("*.txt")) + sorted((SHARED / "foon_to_pddl-examples").glob("*.txt")):
        one, _ = load([path])  # each recipe on its own, and the public converter's examples
        assert coverage((n.label for n in one.nodes), ix).percent >= 95.0, path.name
    assert ix.choose("hand") == "hands"  # the cook's hand, not a cutting tool
    kitchen = read_kitchen(example_path("example_kitchen.txt"))
    goal = resolve_goal(parse_goal_spec("lemonade"), example.foon)
    assert retrieve(example.foon, kitchen, goal).tree is None
    gen = compress(example.foon, ix).foon
    result = retrieve(gen, abstract_kitchen(kitchen, ix), resolve_goal(abstract_goal(goal.spec, ix), gen))
    assert result.tree is not None


def test_categories_check_cli(tmp_path):
    runner = CliRunner()
    ok = runner.invoke(main, ["categories", "--check"])
    assert ok.exit_code == 0 and "100.0 %" in ok.stderr
    foon = tmp_path / "r.foon"
    foon.write_text("O\tlemon\t0\nS\twhole\nM\tpick\nO\tflux capacitor\t0\nS\ton\n//\n")
    bad = runner.invoke(main, ["categories", "--check", str(foon)])
    assert bad.exit_code == 1 and bad.stdout == "flux capacitor\n" and "50.0 %" in bad.stderr
    listing = runner.invoke(main, ["categories"])
    assert listing.exit_code == 0 and "  citrus fruits (" in listing.stdout
