"""The `relational` encoding: holder evidence per unit, the task's holder facts, plans replayed with holders."""

from __future__ import annotations

import json

import pddl.parser.domain
import pddl.parser.problem
from click.testing import CliRunner
from conftest import SUBGRAPHS
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from foon2pddl.cli import main
from foon2pddl.io.files import load
from foon2pddl.model.aliases import unit_aliases
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.model.physical import Relation
from foon2pddl.model.places import listed, place_of
from foon2pddl.pddl.compile import ENCODINGS, compile_goal, compile_task
from foon2pddl.pddl.holder_flows import unit_flows
from foon2pddl.pddl.holder_gaps import list_gaps
from foon2pddl.pddl.holder_words import mismatches, task_aliases
from foon2pddl.pddl.holders import Fate, relational_roles
from foon2pddl.pddl.relational_plan import without
from foon2pddl.pddl.relational_replay import relational_trace
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Atom
from foon2pddl.planners.decode import simulate_plan
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

WHIPPED = SUBGRAPHS / "0001-whipped_cream.txt"


# Heavy cream poured from a carton into a cup: FOON lists the cream only as an input (read-only).
CARTON, CREAM = n("carton", contains("heavy cream")), n("heavy cream", inside("carton"))
CUP, FULL_CUP = n("cup", "empty"), n("cup", contains("heavy cream"))
POUR = FunctionalUnit((CARTON, CREAM, CUP), Motion("pour"), (FULL_CUP,))


def test_places_and_lists_read_foon_states():
    assert place_of(CREAM) == (Relation.IN, "carton") and place_of(CUP) is None
    assert place_of(n("stove", "on")) is None  # a bare `on` is switched on, not a place
    assert listed(FULL_CUP) == {"heavy cream"} and listed(CUP) == frozenset()
    assert without(CARTON, {"heavy cream"}) == n("carton", "empty")


def test_an_ingredient_listed_only_as_input_splits_a_portion_into_the_receiving_container():
    carton, cream, cup = relational_roles(POUR)
    # FOON leaves the carton out of the outputs: it still lists the cream, so a portion goes into the cup
    assert cream.fate is Fate.SPLITS and cream.after == n("heavy cream", inside("cup")) and not cream.changes
    assert cream.source.role == 0 and cream.target.role == 2  # the carton and the cup of this unit
    assert carton.after is None and carton.fate is Fate.STAYS
    assert cup.after == FULL_CUP and cup.source is None and cup.target is None
    # with the carton emptied in the outputs, the cream itself moves
    moved = FunctionalUnit(POUR.inputs, POUR.motion, (FULL_CUP, n("carton", "empty")))
    assert relational_roles(moved)[1].fate is Fate.MOVES and relational_roles(moved)[1].changes


def test_two_bowls_the_ingredient_list_names_the_holder():
    a, b = n("bowl", contains("salt")), n("bowl", contains("sugar"))
    sugar = n("sugar", inside("bowl"))
    stir = FunctionalUnit((a, b, sugar), Motion("stir"), (a, b, n("sugar", inside("bowl"), make_state("stirred"))))
    roles = relational_roles(stir)
    assert roles[2].fate is Fate.STAYS and roles[2].source == roles[2].target  # stirred where it is
    assert roles[2].source.role == 1  # the bowl listing sugar, not the first bowl


def test_a_list_names_an_object_by_its_head_noun():
    # the bowl lists `salad` where the unit makes `carrot salad` in it; `oil` is in a `pan`, the unit's
    # pan is a `cooking pan`: read as those objects (rule 0), reported, and read so by the replay
    bowl, made = n("salad bowl", contains("salad")), n("carrot salad", inside("salad bowl"))
    mix = FunctionalUnit((n("salad bowl", "empty"),), Motion("mix"), (bowl, made))
    assert unit_aliases(mix) == (("salad", "carrot salad"),)
    assert mismatches(mix) == ("salad bowl lists salad, read as carrot salad",)
    assert list_gaps(mix) == ()  # read as the salad it is in the list
    pan = n("cooking pan", make_state("on", "stove"))
    fry = FunctionalUnit((pan, n("oil", inside("bottle"))), Motion("pour"), (pan, n("oil", inside("pan"))))
    assert unit_aliases(fry) == (("pan", "cooking pan"),)
    oil = next(r for r in relational_roles(fry) if r.role.label == "oil")
    assert oil.target is not None and oil.target.holder == "cooking pan" and oil.target.role == 0
    # two roles it could be the head of: no reading
    two = FunctionalUnit((n("salad bowl", "empty"),), Motion("mix"),
                         (bowl, made, n("potato salad", inside("salad bowl"))))
    assert unit_aliases(two) == ()
    # a task in which `salad` is itself an object's label reads no alias
    assert task_aliases([mix], ["salad bowl", "carrot salad"]) == (("salad", "carrot salad"),)
    assert task_aliases([mix], ["salad bowl", "carrot salad", "salad"]) == ()


def test_a_place_no_label_matches_is_the_one_role_listing_what_is_there():
    # watermelon lemonade: poured `in [cup]`, while the unit's only receiver is the drinking glass that lists it
    glass, pitcher = n("drinking glass", contains("water ice")), n("pitcher", contains("lemonade"))
    pour = FunctionalUnit((glass, pitcher, n("lemonade", inside("pitcher"))), Motion("pour"),
                          (n("drinking glass", contains("water ice", "lemonade")), n("lemonade", inside("cup"))))
    assert unit_aliases(pour) == (("cup", "drinking glass"),)
    assert mismatches(pour) == ("lemonade is in [cup], read as drinking glass",)
    # french toast: `bread (in [pan])` in the skillet that lists it, the toast made `in [pan]` too
    skillet = n("skillet", contains("bread"))
    flip = FunctionalUnit((n("bread", inside("pan")), skillet), Motion("flip"), (n("french toast", inside("pan")),))
    assert unit_aliases(flip) == (("pan", "skillet"),)
    # no reading: the place is named only before the unit (the bulgur's bowl the pot already lists), a name
    # an ingredient list uses too, or two roles list what is there
    stir = FunctionalUnit((n("pot", contains("bulgur")), n("bulgur", inside("bowl"))), Motion("stir"),
                          (n("pot", contains("kofta mix")),))
    assert unit_aliases(stir) == ()
    listed_too = FunctionalUnit(flip.inputs, flip.motion, (n("french toast", inside("pan"), contains("pan")),))
    assert unit_aliases(listed_too) == ()
    two = FunctionalUnit((n("bread", inside("pan")), skillet, n("wok", contains("bread"))), Motion("flip"),
                         flip.outputs)
    assert unit_aliases(two) == ()


def test_contradicting_output_nodes_are_gaps():
    # FOON makes `salad` and `carrot salad` in the bowl, whose node lists only `salad`
    bowl = n("salad bowl", contains("salad"))
    unit = FunctionalUnit((n("salad bowl", "empty"),), Motion("mix"),
                          (bowl, n("salad", inside("salad bowl")), n("carrot salad", inside("salad bowl"))),
                          (Source("salad.txt", 3),))
    assert list_gaps(unit) == (("salad bowl", "carrot salad",
                                "carrot salad is in [salad bowl], whose node after the unit does not list it"),)
    compiled = compile_goal(Foon((unit,)), Kitchen(frozenset({n("salad bowl", "empty")})),
                            Goal(GoalSpec("carrot salad"), (unit.outputs[2],)), "relational")
    assert "label mismatch: salad.txt:3: carrot salad is in [salad bowl], whose node after the unit does not list it" \
        in compiled.notes


def test_label_mismatches_are_reported_per_unit():
    oil = n("green olive oil", inside("bottle"))
    unit = FunctionalUnit((n("bowl", "empty"), oil), Motion("pour"), (n("bowl", contains("olive oil")),))
    assert mismatches(unit) == ("bowl lists olive oil, read as green olive oil",)
    assert next(r for r in relational_roles(unit) if r.role.label == "green olive oil").target.role == 0
    unit = FunctionalUnit(unit.inputs, unit.motion, unit.outputs, (Source("salad.txt", 7),))
    kitchen = Kitchen(frozenset({n("bowl", "empty"), oil, n("bottle", contains("green olive oil"))}))
    compiled = compile_goal(Foon((unit,)), kitchen, Goal(GoalSpec("bowl"), unit.outputs), "relational")
    assert compiled.notes == ("label mismatch: salad.txt:7: bowl lists olive oil, read as green olive oil",)
    assert "; label mismatch: salad.txt:7: bowl lists olive oil" in render(compiled.task)[0]
    # a name no role is the head of stays a mismatch, and a gap the replay does not check
    vinegar = FunctionalUnit((n("bowl", "empty"), oil), Motion("pour"), (n("bowl", contains("vinegar")),),
                             (Source("salad.txt", 9),))
    assert mismatches(vinegar) == ("bowl lists vinegar, which no object of the unit is",)
    assert list_gaps(vinegar) == (("bowl", "vinegar", "bowl lists vinegar, which no object of the unit is"),)


POUR_FOON = Foon((POUR,))
POUR_KITCHEN = Kitchen(frozenset({CARTON, CREAM, CUP}))
POUR_GOAL = Goal(GoalSpec("cup"), (FULL_CUP,))


def test_the_task_moves_the_holder_fact_and_requires_the_real_source():
    task = compile_task(POUR_FOON, POUR_KITCHEN, POUR_GOAL, "relational")
    assert Atom("in", ("carton_1", "heavy_cream_1")) in task.initial_facts  # holder first, as the converter writes it
    # a carton FOON leaves unchanged keeps its cream: a portion (a not-yet-made object) goes into the cup
    good = ["pour_u0 cup_1 heavy_cream_2", "reach-goal-1"]
    assert simulate_plan(task, good).ok
    trace = relational_trace(task, good)
    assert trace.contents("cup_1") == ("heavy_cream_2",) and trace.contents("carton_1") == ("heavy_cream_1",)
    assert replay(trace).ok
    # poured on from the cup by a unit that names no cup: the cream leaves whatever holds it (a quantified
    # conditional delete, no parameter per cup), and the cup that held it is emptied
    fill = FunctionalUnit(POUR.inputs, POUR.motion, (FULL_CUP, n("heavy cream", inside("cup")), n("carton", "empty")))
    on = FunctionalUnit((n("heavy cream", inside("cup")), n("bowl", "empty")), Motion("pour"),
                        (n("bowl", contains("heavy cream")),))
    task = compile_task(Foon((fill, on)), Kitchen(POUR_KITCHEN.nodes | {n("bowl", "empty")}),
                        Goal(GoalSpec("bowl"), on.outputs), "relational")
    assert task.requirements == (":strips", ":typing", ":conditional-effects")
    pour = next(a for a in task.actions if a.name == "pour_u1")
    assert [(c.var, c.type, c.delete) for c in pour.conditional][0] == (
        "?from_0", "physical-object", (Atom("in", ("?from_0", "?heavy_cream")),))
    good = ["pour_u0 carton_1 heavy_cream_1 cup_1", "pour_u1 heavy_cream_1 bowl_1", "reach-goal-1"]
    assert simulate_plan(task, good).ok
    trace = relational_trace(task, good)
    assert trace.holder_of("heavy_cream_1") == "bowl_1" and trace.contents("cup_1") == ()
    assert trace.final["cup_1"].node == n("cup", "empty") and trace.final["carton_1"].node == n("carton", "empty")
    assert replay(trace).ok
    # the second pour before the first: the cream is not in a cup yet
    assert not simulate_plan(task, [good[1], good[0], good[2]]).ok


def test_a_plan_that_beats_an_egg_in_another_bowl_fails_the_task_semantics():
    bowl, egg = n("bowl", contains("egg")), n("egg", inside("bowl"), make_state("whole"))
    beaten_bowl, beaten = n("bowl", contains("egg"), make_state("shaken")), n("egg", inside("bowl"), make_state("beaten"))
    foon = Foon((FunctionalUnit((bowl, egg), Motion("beat"), (beaten_bowl, beaten)),))
    kitchen = Kitchen(frozenset({bowl, egg}), 3, "k", ((bowl, 2), (egg, 2)))
    task = compile_task(foon, kitchen, Goal(GoalSpec("egg"), (beaten,)), "relational")
    assert {a.args for a in task.init if a.predicate == "in"} == {("bowl_1", "egg_1"), ("bowl_2", "egg_2")}
    (beat,) = [a for a in task.actions if a.unit is not None]
    assert Atom("in", ("?bowl", "?egg")) in beat.pre
    assert simulate_plan(task, [f"{beat.name} bowl_2 egg_2", "reach-goal-1"]).ok
    assert not simulate_plan(task, [f"{beat.name} bowl_1 egg_2", "reach-goal-1"]).ok


def test_renders_pddl_the_pddl_package_and_up_read():
    from unified_planning.io import PDDLReader

    task = compile_task(POUR_FOON, POUR_KITCHEN, POUR_GOAL, "relational")
    domain_text, problem_text = render(task)
    assert {a.name for a in pddl.parser.domain.DomainParser()(domain_text).actions} == {a.name for a in task.actions}
    pddl.parser.problem.ProblemParser()(problem_text)
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "d.pddl").write_text(domain_text)
        (Path(tmp) / "p.pddl").write_text(problem_text)
        problem = PDDLReader().parse_problem(str(Path(tmp) / "d.pddl"), str(Path(tmp) / "p.pddl"))
    assert len(problem.actions) == len(task.actions)
    assert render(compile_task(POUR_FOON, POUR_KITCHEN, POUR_GOAL, "relational")) == (domain_text, problem_text)


def _whipped():
    foon, _ = load([WHIPPED])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    return foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon)


def test_whipped_cream_plan_has_real_holders_and_passes_the_relational_replay():
    foon, kitchen, goal = _whipped()
    outcome = plan(foon, kitchen, goal, "relational")
    assert outcome.status == "solved", outcome.message
    trace = outcome.trace
    assert replay(trace).ok and outcome.decoded.trace_check.ok and outcome.validation.ok
    assert trace.contents("bowl_1") == ("whipped_cream_1",) and trace.contents("mixing_bowl_1") == ()
    assert trace.final["mixing_bowl_1"].node.describe() == "mixing bowl (empty)"  # scraped out (FOON omits it)
    # FOON leaves the carton and the spoon out of the pours' outputs: they keep what they held, and a
    # portion (a new object of the label) is what moves
    assert trace.final["heavy_cream_2"].consumed and trace.final["refined_sugar_2"].consumed
    assert trace.contents("carton_1") == ("heavy_cream_1",) and not trace.final["heavy_cream_1"].consumed
    first = trace.after(0)
    assert first["heavy_cream_2"].holder == "measuring_cup_1" and first["heavy_cream_1"].holder == "carton_1"
    text = outcome.compiled.view.text(outcome.task, trace)
    assert "pour heavy_cream_2 (a portion of heavy_cream_1) from carton_1 into measuring_cup_1" in text
    assert "mix in mixing_bowl_1: heavy_cream_2, refined_sugar_2 -> whipped_cream_1 with mixer_1" in text
    assert ENCODINGS["relational"].holders and not ENCODINGS["instances"].holders


def test_plan_cli_json_gives_every_objects_holder_and_consumed_flag():
    result = CliRunner().invoke(main, ["plan", "--goal", "whipped cream", "--encoding", "relational",
                                       "--format", "json", str(WHIPPED)])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["validation"]["relational"]["ok"]
    steps = data["relational"]["steps"]
    assert steps[0]["source"].endswith("0001-whipped_cream.txt:27")
    cream = next(o for o in steps[0]["objects"] if o["id"] == "heavy_cream_2")
    assert cream == {"id": "heavy_cream_2", "label": "heavy cream", "state": "heavy cream (in [measuring cup])",
                     "holder": "measuring_cup_1", "relation": "in", "consumed": False}
    assert all({"holder", "consumed", "state"} <= set(o) for s in steps for o in s["objects"])
    text = CliRunner().invoke(main, ["plan", "--goal", "whipped cream", "--encoding", "relational", str(WHIPPED)])
    assert "objects, step by step (relational encoding):" in text.stdout and "valid" in text.stderr


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(1, 3), st.integers(1, 3))
def test_every_state_of_a_trace_has_one_holder_per_object(cartons, cups):
    kitchen = Kitchen(POUR_KITCHEN.nodes, 3, "k", ((CARTON, cartons), (CUP, cups), (CREAM, cartons)))
    task = compile_goal(POUR_FOON, kitchen, POUR_GOAL, "relational").task
    holders = {}
    for a in task.initial_facts:
        if a.predicate in ("in", "on"):
            assert a.args[1] not in holders
            holders[a.args[1]] = a.args[0]
    # every cream starts in a carton that lists it, each in its own carton
    assert sorted(holders.values()) == sorted(x.name for x in task.instances if x.label == "carton")


def test_the_kitchen_is_completed_with_the_holders_and_contents_it_names():
    pot, noodle = n("pot", contains("water"), make_state("on", "stove")), n("noodle", inside("pouch"))
    cooked = n("pot", contains("noodle", "water"), make_state("on", "stove"))
    boil = FunctionalUnit((pot, noodle), Motion("add"), (cooked,))
    task = compile_task(Foon((boil,)), Kitchen(frozenset({pot, noodle})), Goal(GoalSpec("pot"), (cooked,)),
                        "relational")
    held = {(a.predicate, *a.args) for a in task.initial_facts if a.predicate in ("in", "on")}
    # a pouch, a stove and the water FOON only names
    assert held == {("in", "pouch_1", "noodle_1"), ("in", "pot_1", "water_1"), ("on", "stove_1", "pot_1")}
    assert {x.label for x in task.instances} == {"pot", "noodle", "pouch", "stove", "water"}
    outcome = plan(Foon((boil,)), Kitchen(frozenset({pot, noodle})), Goal(GoalSpec("pot"), (cooked,)), "relational")
    assert outcome.status == "solved" and replay(outcome.trace).ok
    # the pouch FOON does not show emptied keeps its noodles: a portion goes into the pot
    assert outcome.trace.contents("pot_1") == ("noodle_2", "water_1")
    assert outcome.trace.contents("pouch_1") == ("noodle_1",) and outcome.trace.holder_of("pot_1") == "stove_1"


def test_every_kitchen_container_listing_an_item_holds_one():
    # two bowls of water and a single `water (in [bowl])` node: a second water, one in each bowl
    water, bowl = n("water", inside("bowl")), n("bowl", contains("water"))
    other = n("bowl", contains("water"), make_state("chilled"))
    both = n("pot", contains("water"))
    pour = FunctionalUnit((bowl, other, water, n("pot", "empty")), Motion("pour"), (both, n("water", inside("pot"))))
    kitchen = Kitchen(frozenset({water, bowl, other, n("pot", "empty")}))
    task = compile_task(Foon((pour,)), kitchen, Goal(GoalSpec("pot"), (both,)), "relational")
    held = sorted(a.args for a in task.initial_facts if a.predicate == "in")
    assert [h for h, _ in held] == ["bowl_1", "bowl_2"] and len({x for _, x in held}) == 2


def test_what_sits_where_a_mixture_is_made_with_no_output_node_is_absorbed():
    # FOON's mix lists the meat mix as the bowl's only output object: the garlic and the beef in the bowl
    # became part of it (the bowl's list still names them: they stand for the mixture's ingredients)
    bowl = n("bowl", contains("garlic", "ground beef"))
    garlic, beef = n("garlic", inside("bowl")), n("ground beef", inside("bowl"))
    mix = FunctionalUnit((bowl, garlic, beef), Motion("mix"), (n("meat mix", inside("bowl")),))
    outcome = plan(Foon((mix,)), Kitchen(frozenset({bowl, garlic, beef})),
                   Goal(GoalSpec("meat mix"), (mix.outputs[0],)), "relational")
    assert outcome.status == "solved"
    final = outcome.trace.final
    assert final["garlic_1"].consumed and final["ground_beef_1"].consumed and not final["meat_mix_1"].consumed
    assert replay(outcome.trace).ok


def test_a_kitchen_list_names_an_object_by_its_head_noun():
    starts = [n("bowl", contains("rice")), n("white rice", inside("bowl"))]
    assert task_aliases([], ["bowl", "white rice"], starts) == (("rice", "white rice"),)
    assert task_aliases([], ["bowl", "white rice", "brown rice"], starts) == ()  # two it could be


def test_ingredients_listed_by_the_product_a_unit_makes_are_consumed_not_placed_in_it():
    # custard (contains {egg, milk}) is made in the bowl: the egg is part of it, not an object inside it
    bowl = n("bowl", contains("egg", "milk"))
    egg, milk = n("egg", inside("bowl")), n("milk", inside("bowl"))
    custard = n("custard", contains("egg", "milk"), inside("bowl"))
    mix = FunctionalUnit((bowl, egg, milk), Motion("mix"), (n("bowl", contains("custard")), custard))
    fates = {r.role.label: r.fate for r in relational_roles(mix)}
    assert fates == {"bowl": Fate.STAYS, "egg": Fate.CONSUMED, "milk": Fate.CONSUMED, "custard": Fate.NEW}
    outcome = plan(Foon((mix,)), Kitchen(frozenset({bowl, egg, milk})), Goal(GoalSpec("custard"), (custard,)),
                   "relational")
    assert outcome.status == "solved" and replay(outcome.trace).ok
    assert outcome.trace.contents("bowl_1") == ("custard_1",) and outcome.trace.final["egg_1"].consumed
    # a kitchen bowl that still lists what went into the product keeps its object: only some went in
    seeds, seed = n("bowl", contains("sesame seed")), n("sesame seed", inside("bowl"))
    salad = n("salad", contains("custard", "sesame seed"), inside("bowl"))
    sprinkle = FunctionalUnit((n("bowl", contains("custard")), custard, seeds, seed), Motion("sprinkle"),
                              (n("bowl", contains("salad")), salad))
    kitchen = Kitchen(frozenset({bowl, egg, milk, seeds, seed}))
    outcome = plan(Foon((mix, sprinkle)), kitchen, Goal(GoalSpec("salad"), (salad,)), "relational")
    assert outcome.status == "solved" and replay(outcome.trace).ok, outcome.message
    holder = outcome.trace.holder_of("sesame_seed_1")
    assert holder is not None and outcome.trace.contents(holder) == ("sesame_seed_1",)
    assert outcome.trace.final["custard_1"].consumed


def test_every_example_dish_has_a_relational_plan_that_passes_the_replay():
    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.pddl.examples import GOALS, LEVEL

    net = load_network([])
    foon, kitchen = net.at(LEVEL), load_kitchen(None, net, LEVEL)
    for text in GOALS:
        outcome = plan(foon, kitchen, load_goal(text, None, foon), "relational")
        assert outcome.status == "solved", (text, outcome.message)
        assert replay(outcome.trace).ok and outcome.validation.ok, text


def test_the_task_says_why_it_has_several_objects_of_a_label():
    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.pddl.count_reasons import count_reasons
    from foon2pddl.pddl.instance_counts import derive_counts

    net = load_network([])
    foon, kitchen = net.at(3), load_kitchen(None, net, 3)
    compiled = compile_goal(foon, kitchen, load_goal("guacamole", None, foon), "relational")
    boards = sum(x.label == "cutting board" for x in compiled.task.instances)
    assert boards > 1
    (line,) = [n for n in compiled.notes if n.startswith(f"objects: {boards} x cutting board (empty): FOON's plan, unfolded, ")]
    assert "pick-and-place at 07-guacamole.foon:52" in line and "takes one out of that state" in line
    assert "; " + line in render(compiled.task)[1]  # in the problem file's header too
    # one line per kitchen state holding several objects; a stated count is said to be one
    units = tuple(range(len(foon.units)))
    goal = load_goal("guacamole", None, foon)
    counts = derive_counts(foon, units, kitchen.nodes, goal.candidates, overrides={"bowl": 3})
    reasons = count_reasons(foon, counts, kitchen.nodes, instances={"bowl": 3})
    many = [(n, k) for n, k in counts.at_node if k > 1]
    assert len(reasons) == len(many)
    assert any(r.startswith("3 x bowl (empty): 3 given by `bowl=3` (the instances stated per label), where FOON's "
                            "unfolded plan takes") for r in reasons)


def test_an_object_the_kitchen_completion_starts_in_a_made_state_does_not_let_a_plan_skip_the_unit():
    # found in review: the bowl of macaroni the kitchen completion adds may start `(cooked, in [pot])`, a node a
    # unit makes; the plan's FOON tree is checked from the kitchen as given, so a plan that only scoops the
    # invented cooked macaroni is not valid
    bag, pot = n("bag", contains("macaroni")), n("pot", contains("water"))
    raw_bag, raw_pot = n("macaroni", make_state("raw"), inside("bag")), n("macaroni", make_state("raw"), inside("pot"))
    cooked = n("macaroni", make_state("cooked"), inside("pot"))
    pour = FunctionalUnit((bag, raw_bag, pot), Motion("pour"), (n("pot", contains("macaroni", "water")), raw_pot))
    boil = FunctionalUnit((n("pot", contains("macaroni")), raw_pot), Motion("boil"), (cooked,))
    served = n("macaroni", make_state("cooked"), inside("bowl"))
    scoop = FunctionalUnit((cooked, n("bowl", "empty")), Motion("scoop"), (n("bowl", contains("macaroni")), served))
    kitchen = Kitchen(frozenset({bag, raw_bag, pot, n("pot", contains("macaroni")), n("bowl", "empty")}))
    outcome = plan(Foon((pour, boil, scoop)), kitchen, Goal(GoalSpec("macaroni"), (served,)), "relational")
    if outcome.status == "solved":
        assert "boil" in [u.motion.label for u in outcome.tree.units]
    else:
        assert "input not available" in outcome.message


def test_an_object_in_a_holder_of_its_own_label_compiles_at_every_level():
    # found by hypothesis (test_goal_in_kitchen): `bowl (in [bowl])` in the kitchen, at level 2 (no lists):
    # the holder added for it cannot list it, and the bowl then stands free instead of failing an assertion
    inner = n("bowl", inside("bowl"))
    unit = FunctionalUnit((inner, n("spoon")), Motion("stir"), (n("bowl", inside("bowl"), make_state("stirred")),))
    for level in (1, 2, 3):
        task = compile_goal(Foon((unit,)), Kitchen(frozenset({inner, n("spoon")})),
                            Goal(GoalSpec("bowl"), unit.outputs), "relational", level).task
        assert "bowl" in {x.label for x in task.instances}


def test_an_object_its_only_holder_does_not_list_is_bound_late_and_reported():
    # pancake batter: the bowl lists egg white and egg yolk, the mix takes `egg white and yolk (in [bowl])`,
    # which no unit put into that bowl: FOON's words disagree, so the planner may take it from its own bowl
    bowl = n("bowl", contains("egg white", "egg yolk", "flour"))
    eggs, flour = n("egg white and yolk", inside("bowl")), n("flour", inside("bowl"))
    white, yolk = n("egg white", inside("bowl")), n("egg yolk", inside("bowl"))
    batter = n("pancake batter", inside("bowl"), make_state("raw"))
    mix = FunctionalUnit((bowl, eggs, flour, white, yolk), Motion("mix"),
                         (n("bowl", contains("pancake batter")), batter))
    roles = relational_roles(mix)
    assert roles[1].source.role is None and roles[2].source.role == 0  # flour is listed: its bowl is bound
    assert ("bowl", "egg white and yolk") in {(c, x) for c, x, _ in list_gaps(mix)}
    outcome = clean_unit_plan([mix], [bowl, eggs, flour, white, yolk], batter)
    assert outcome.trace.final["egg_white_and_yolk_1"].consumed
    assert any("egg white and yolk is in [bowl], whose node before the unit does not list it" in x
               for x in outcome.compiled.notes)


def test_a_container_left_out_of_the_outputs_is_poured_out_whole():
    # tuna sandwich: the bowl of tuna is poured into the bowl of mayonnaise; FOON gives one bowl as output
    mayo_bowl, tuna_bowl = n("bowl", contains("mayonnaise")), n("bowl", contains("tuna"))
    mayo, tuna = n("mayonnaise", inside("bowl")), n("tuna", inside("bowl"))
    pour = FunctionalUnit((mayo_bowl, mayo, tuna_bowl), Motion("pour"), (n("bowl", contains("mayonnaise", "tuna")),))
    spread = n("tuna spread", inside("bowl"))
    mix = FunctionalUnit((n("bowl", contains("mayonnaise", "tuna")), mayo, tuna), Motion("mix"),
                         (n("bowl", contains("tuna spread")), spread))
    outcome = clean_unit_plan([pour, mix], [mayo_bowl, tuna_bowl, mayo, tuna], spread)
    final = outcome.trace.final
    assert final["tuna_1"].consumed and final["mayonnaise_1"].consumed
    empty = [b for b in ("bowl_1", "bowl_2") if final[b].node.describe() == "bowl (empty)"]
    assert len(empty) == 1 and outcome.trace.contents(empty[0]) == ()


def test_a_tool_leaving_an_unnamed_holder_for_no_place_moves_whole():
    # orange juice: the squeezer on the surface ends `dirty`, a node with no place: it is the same squeezer
    squeezer = n("squeezer", contains("orange juice"), make_state("on", "surface"))
    juice, glass = n("orange juice", inside("squeezer")), n("drinking glass", "empty")
    served = n("orange juice", inside("drinking glass"))
    pour = FunctionalUnit((squeezer, juice, glass), Motion("pour"),
                          (n("squeezer", "dirty"), n("drinking glass", contains("orange juice")), served))
    squeeze = FunctionalUnit((n("squeezer", "clean", make_state("on", "surface")), n("orange", "halved")),
                             Motion("squeeze"), (squeezer, juice, n("orange", "squeezed")))
    surface = n("surface", contains("cutting board"))  # a node that says what a surface holds
    outcome = clean_unit_plan([squeeze, pour], [squeeze.inputs[0], squeeze.inputs[1], surface, glass], served)
    ids = [o.id for o in outcome.trace.objects if o.label == "squeezer"]
    assert ids == ["squeezer_1"] and outcome.trace.final["squeezer_1"].node == n("squeezer", "dirty")


def test_all_that_leaves_a_pan_at_once_empties_it_of_all():
    # beef enchiladas: the beef and the onion in the pan (which the unit does not name) become the filling
    pan = n("cooking pan", contains("ground beef", "onion"))
    beef, onion = n("ground beef", "cooked", inside("pan")), n("onion", "chopped", inside("pan"))
    fill = n("meat mix", contains("ground beef", "onion"), make_state("on", "tortilla"))
    put = FunctionalUnit((n("cooking pan", "empty"), n("ground beef", "raw")), Motion("pick-and-place"),
                         (n("cooking pan", contains("ground beef")), n("ground beef", inside("pan"))))
    fry = FunctionalUnit((n("cooking pan", contains("ground beef")), n("ground beef", inside("pan")),
                          n("onion", "chopped")), Motion("fry"), (pan, beef, onion))
    place_ = FunctionalUnit((n("tortilla", "plain"), beef, onion), Motion("pick-and-place"),
                            (n("tortilla", contains("meat mix")), fill))
    start = [*put.inputs, fry.inputs[2], place_.inputs[0]]
    outcome = clean_unit_plan([put, fry, place_], start, fill)
    assert outcome.trace.final["cooking_pan_1"].node.describe() == "cooking pan (empty)"


def test_everything_of_a_label_in_the_mixing_bowl_goes_into_the_mixture():
    # coleslaw dressing: two sugars in the bowl (FOON's counts), the mix lists the dressing alone after it
    bowl = n("bowl", contains("sugar", "vinegar"))
    sugar, vinegar = n("sugar", inside("bowl")), n("vinegar", inside("bowl"))
    dressing = n("salad dressing", inside("bowl"))
    mix = FunctionalUnit((bowl, sugar, vinegar), Motion("mix"), (n("bowl", contains("salad dressing")), dressing))
    stir = FunctionalUnit((bowl, sugar), Motion("stir"), (bowl, sugar))
    outcome = plan(Foon((stir, mix)), Kitchen(frozenset({bowl, sugar, vinegar}), counts=((sugar, 2),)),
                   Goal(GoalSpec("salad dressing"), (dressing,)), "relational")
    assert outcome.status == "solved", outcome.message
    assert replay(outcome.trace).ok
    assert all(s.consumed for i, s in outcome.trace.final.items() if i.startswith("sugar_"))


def test_what_a_kitchen_holder_holds_starts_as_the_unit_that_uses_the_pair_takes_it():
    # roux: the kitchen's `stove (off, with [skillet])` holds a skillet no kitchen node describes; the heat
    # unit takes that stove with `skillet (empty, on [stove])`, so the skillet starts empty, not with butter
    on_stove = make_state("on", "stove")
    stove = n("stove", "off", make_state("with", "skillet"))
    ready, ready_with = n("stove", "off (ready)"), n("stove", "off (ready)", make_state("with", "skillet"))
    empty, hot = n("skillet", "empty", on_stove), n("skillet", "hot", "empty", on_stove)
    place_ = FunctionalUnit((ready, n("skillet", "empty")), Motion("pick-and-place"), (ready_with, empty))
    heat = FunctionalUnit((stove, empty), Motion("heat"), (hot,))
    bowl, butter = n("bowl", contains("butter")), n("butter", "cube", inside("bowl"))
    in_skillet = n("butter", "cube", inside("skillet"))
    pour = FunctionalUnit((bowl, butter, hot), Motion("pour"),
                          (n("skillet", "hot", contains("butter"), on_stove), in_skillet))
    outcome = clean_unit_plan([place_, heat, pour], [ready, n("skillet", "empty"), stove, bowl, butter], in_skillet)
    first = next(iter(outcome.trace.states()))
    held = [i for i, s in first.items() if s.holder is not None and s.node.label == "skillet"]
    assert [first[i].node for i in held] == [empty]


def test_a_holder_the_kitchen_implies_starts_in_a_node_of_the_network_that_lists_what_it_holds():
    # potato croquette: the kitchen's `pot (heated, on [stove])` sits on a stove no kitchen node names; the
    # cook takes `stove (on, with [pot])`, the network's node of a stove holding a pot, so the stove is that
    on_stove = make_state("on", "stove")
    heated, bottle, oil = n("pot", "heated", on_stove), n("bottle", contains("oil")), n("oil", inside("bottle"))
    oiled, oil_in = n("pot", contains("oil"), on_stove), n("oil", inside("pot"))
    pour = FunctionalUnit((heated, bottle, oil), Motion("pour"), (oiled, oil_in, n("bottle", "empty")))
    hot = n("oil", "hot", inside("pot"))
    with_pot = n("stove", "on", make_state("with", "pot"))
    cook = FunctionalUnit((with_pot, oiled, oil_in), Motion("heat"), (hot,))
    water_pot, water = n("pot", contains("water")), n("water", inside("pot"))
    boil = FunctionalUnit((n("stove", "on"), water_pot), Motion("pick-and-place"),
                          (with_pot, n("pot", contains("water"), on_stove)))
    outcome = clean_unit_plan([boil, pour, cook], [heated, bottle, oil, n("stove", "on"), water_pot, water], hot)
    first = outcome.trace.after(-1)
    stove = first[next(o.id for o in outcome.trace.objects if o.label == "pot" and first[o.id].node == heated)].holder
    assert first[stove].node == with_pot
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "heat"]  # no need to place the water


def test_an_object_that_leaves_an_unnamed_holder_for_no_place_empties_it():
    # crayfish wrap: the squeeze takes the sliced lemon off a board it does not name; the squeezed lemon is
    # nowhere, so the board (which the kitchen lists it on) no longer lists it
    board, lemon = n("cutting board", contains("lemon")), n("lemon", "sliced", make_state("on", "cutting board"))
    glass, juice = n("glass", "empty"), n("lemon juice", inside("glass"))
    squeeze = FunctionalUnit((lemon, glass), Motion("squeeze"),
                             (n("glass", contains("lemon juice")), juice, n("lemon", "squeezed")))
    outcome = clean_unit_plan([squeeze], [board, lemon, glass], juice)
    assert outcome.trace.final["cutting_board_1"].node == n("cutting board", "empty")


def test_a_second_object_of_a_label_in_one_holder_is_bound_late():
    # turkey sandwich: the stacking unit takes two breads `on [cutting board]` under a board that lists
    # `{bread}` once; each bread was put on an empty board, so the second comes from its own board
    on_board = make_state("on", "cutting board")
    board, bread = n("cutting board", "empty"), n("bread", "plain")
    plain, buttered = n("bread", "plain", on_board), n("bread", make_state("buttered", "", ["butter"]), on_board)
    topped = n("bread", contains("butter", "turkey"), on_board)
    put = FunctionalUnit((board, bread), Motion("pick-and-place"), (n("cutting board", contains("bread")), plain))
    spread = FunctionalUnit((plain, n("butter", "soft")), Motion("spread"), (buttered,))
    top = FunctionalUnit((buttered, n("turkey", "sliced")), Motion("pick-and-place"), (topped,))
    sandwich = n("sandwich", contains("bread", "butter", "turkey"), on_board)
    stack = FunctionalUnit((n("cutting board", contains("bread")), topped, buttered), Motion("pick-and-place"),
                           (n("cutting board", contains("sandwich")), sandwich))
    roles = relational_roles(stack)
    assert roles[1].source.role == 0 and roles[2].source.role is None
    outcome = clean_unit_plan([put, spread, top, stack], [board, bread, n("butter", "soft"), n("turkey", "sliced")], sandwich)
    assert sum(s.unit is put for s in outcome.trace.steps) == 2


def test_the_milk_a_kitchen_bowl_lists_is_the_kitchens_milk_in_that_bowl():
    # chocolate sandwich: the kitchen has `bowl (contains {milk})` and `milk (in [carton])`; the milk the
    # completion puts in that bowl is `milk (in [bowl])`, the kitchen's milk in another place, so a plan that
    # mixes it without pouring milk first is a valid FOON tree from that kitchen
    carton, milk = n("carton", contains("milk")), n("milk", inside("carton"))
    bowl, in_bowl = n("bowl", contains("milk")), n("milk", inside("bowl"))
    pour = FunctionalUnit((carton, milk, n("bowl", "empty")), Motion("pour"), (bowl, in_bowl))
    mixed = n("egg mixture", inside("bowl"))
    mix = FunctionalUnit((bowl, in_bowl, n("egg", "beaten")), Motion("mix"), (n("bowl", contains("egg mixture")), mixed))
    outcome = clean_unit_plan([pour, mix], [carton, milk, bowl, n("bowl", "empty"), n("egg", "beaten")], mixed)
    assert [s.unit for s in outcome.trace.steps] == [mix]
    assert in_bowl in outcome.compiled.placed


def test_what_a_list_names_by_another_word_follows_the_list():
    # greek salad dressing: the grind lists `pepper` in the cup for the black pepper; the stir that makes the
    # dressing in the cup takes what the cup lists, so the black pepper goes into the dressing too
    cup, oil = n("cup", contains("oil")), n("oil", inside("cup"))
    grinder, pepper = n("grinder", contains("black pepper")), n("black pepper", "ground", inside("grinder"))
    peppered = n("cup", contains("oil", "pepper"))
    grind = FunctionalUnit((cup, grinder, pepper), Motion("grind"), (peppered, n("black pepper", "ground", inside("cup"))))
    dressing = n("dressing", inside("cup"))
    stir = FunctionalUnit((peppered, oil, n("whisk")), Motion("stir"), (n("cup", contains("dressing")), dressing))
    outcome = clean_unit_plan([grind, stir], [cup, oil, grinder, pepper, n("whisk")], dressing)
    assert [o for o, s in outcome.trace.final.items() if o.startswith("black_pepper") and s.consumed]


def test_what_a_container_drops_goes_even_when_the_unit_takes_that_label_from_elsewhere():
    # mushroom soup: the mix takes `flour (in [bowl])` while the measuring cup lists the flour that was poured
    # into it; the cup's new node lists only the stock, so its flour is in the stock too
    cup = n("measuring cup", contains("broth", "flour"))
    broth, cup_flour = n("broth", inside("measuring cup")), n("flour", inside("measuring cup"))
    bowl, bowl_flour = n("bowl", contains("flour")), n("flour", inside("bowl"))
    pour = FunctionalUnit((n("measuring cup", contains("broth")), broth, bowl, bowl_flour), Motion("pour"),
                          (cup, cup_flour))
    stock = n("soup stock", inside("measuring cup"))
    mix = FunctionalUnit((cup, bowl_flour, broth, n("whisk")), Motion("mix"),
                         (n("measuring cup", contains("soup stock")), stock))
    assert any(f.label == "flour" for f in unit_flows(mix))
    outcome = clean_unit_plan([pour, mix], [n("measuring cup", contains("broth")), broth, bowl, bowl_flour, n("whisk")], stock)
    assert all(s.consumed or s.holder != "measuring_cup_1" for o, s in outcome.trace.final.items()
               if o.startswith("flour"))


def test_what_a_glass_drops_goes_into_the_drink_beside_an_object_of_its_label_from_no_place():
    # bloody mary: a lemon was rolled into the glass; the squeeze of another lemon (no place) makes the drink,
    # whose glass lists only the drink: the lemon in the glass is in the drink too
    glass, rolled = n("glass", contains("lemon")), n("lemon", "halved", inside("glass"))
    roll = FunctionalUnit((n("glass", "empty"), n("lemon", "halved")), Motion("roll"), (glass, rolled))
    drink = n("drink", contains("lemon", "lemon juice"), inside("glass"))
    squeeze = FunctionalUnit((glass, n("lemon", "halved")), Motion("squeeze"), (n("glass", contains("drink")), drink))
    outcome = clean_unit_plan([roll, squeeze], [n("glass", "empty"), n("lemon", "halved")], drink)
    assert all(s.consumed for o, s in outcome.trace.final.items() if o.startswith("lemon"))


def test_an_ingredient_listed_only_as_input_goes_into_the_container_that_newly_lists_it():
    # chocolate cake: `bowl (contains {cocoa powder})`, `bowl (contains {flour, sugar})` and `cocoa powder (in
    # [bowl])` in, only `bowl (contains {cocoa powder, flour, sugar})` out: the cocoa goes into the flour's bowl, although its
    # implied node `cocoa powder (in [bowl])` is the one it had
    cocoa_bowl, cocoa = n("bowl", contains("cocoa powder")), n("cocoa powder", inside("bowl"))
    flour_bowl, both = n("bowl", contains("flour", "sugar")), n("bowl", contains("cocoa powder", "flour", "sugar"))
    pour = FunctionalUnit((cocoa_bowl, flour_bowl, cocoa), Motion("pour"), (both,))
    assert relational_roles(pour)[2].target.role == 1
    mix = n("cake mix", inside("bowl"))
    stir = FunctionalUnit((both, cocoa, n("whisk")), Motion("stir"), (n("bowl", contains("cake mix")), mix))
    start = [cocoa_bowl, flour_bowl, cocoa, n("flour", inside("bowl")), n("sugar", inside("bowl")), n("whisk")]
    outcome = clean_unit_plan([pour, stir], start, mix)
    assert outcome.trace.final["cake_mix_1"].holder == outcome.trace.steps[0].bindings[1].object


def test_a_place_a_unit_names_by_another_objects_label_is_read_as_that_units_holder():
    # protein shake: the pour leaves `strawberry (in [cup])` in the blender cup, in a task with a cup too;
    # the blend that empties the blender cup's list into the shake consumes that strawberry
    cup, yogurt = n("cup", contains("yogurt")), n("yogurt", inside("cup"))
    blender_cup, with_yogurt = n("blender cup", "empty"), n("blender cup", contains("yogurt"))
    pour_yogurt = FunctionalUnit((cup, yogurt, blender_cup), Motion("pour"),
                                 (with_yogurt, n("yogurt", inside("blender cup"))))
    bowl, berry = n("bowl", contains("strawberry")), n("strawberry", inside("bowl"))
    both = n("blender cup", contains("strawberry", "yogurt"))
    pour_berry = FunctionalUnit((with_yogurt, bowl, berry), Motion("pour"), (both, n("strawberry", inside("cup"))))
    shake = n("shake", contains("strawberry", "yogurt"), inside("blender cup"))
    blend = FunctionalUnit((both,), Motion("blend"), (n("blender cup", contains("shake")), shake))
    outcome = clean_unit_plan([pour_yogurt, pour_berry, blend], [cup, yogurt, blender_cup, bowl, berry], shake)
    final = outcome.trace.final
    berries = [o.id for o in outcome.trace.objects if o.label == "strawberry"]
    assert [b for b in berries if final[b].consumed] and not [b for b in berries if final[b].holder == "blender_cup_1"]


def test_what_goes_onto_an_object_in_its_container_is_still_in_that_container():
    # carrot salad: the lemon juice poured into the salad bowl seasons the carrot there; the bowl, which FOON
    # leaves out of the mix's outputs, still lists it, and the next unit takes the bowl in that state
    cup, carrot = n("measuring cup", contains("carrot")), n("carrot", inside("measuring cup"))
    bowl, juice = n("bowl", contains("lemon juice")), n("lemon juice", inside("bowl"))
    salad_bowl = n("salad bowl", contains("carrot", "lemon juice"))
    in_bowl, juiced = n("carrot", inside("salad bowl")), n("lemon juice", inside("salad bowl"))
    pour = FunctionalUnit((cup, carrot, bowl, juice, n("salad bowl", "empty")), Motion("pour"),
                          (salad_bowl, in_bowl, juiced))
    seasoned = n("carrot", make_state("seasoned", "", ["lemon juice"]), inside("salad bowl"))
    mix = FunctionalUnit((salad_bowl, in_bowl, juiced), Motion("mix"), (seasoned,))
    jar, dressing = n("jar", contains("dressing")), n("dressing", inside("jar"))
    done = n("salad bowl", contains("carrot", "dressing", "lemon juice"))
    scoop = FunctionalUnit((salad_bowl, seasoned, jar, dressing), Motion("scoop"),
                           (done, n("dressing", inside("salad bowl"))))
    outcome = clean_unit_plan([pour, mix, scoop], [cup, carrot, bowl, juice, n("salad bowl", "empty"), jar, dressing], done)
    final = outcome.trace.final
    label = {o.id: o.label for o in outcome.trace.objects}
    on_carrot = [x for x, lab in label.items() if lab == "lemon juice" and label.get(final[x].holder) == "carrot"]
    assert len(on_carrot) == 1 and label[final[final[on_carrot[0]].holder].holder] == "salad bowl"


def test_an_object_in_the_units_one_holder_of_its_place_before_and_after_stays_there():
    # garlic rice: `white rice (in [pot])` before and after, beside the unit's one `pot (contains {rice})`
    # (`rice` is no alias: the unit makes `garlic rice` too)
    pot, rice = n("pot", contains("rice")), n("white rice", inside("pot"))
    plate, garlic = n("plate", contains("garlic")), n("garlic", make_state("on", "plate"))
    done = n("white rice", make_state("garnished", "", ["garlic"]), inside("pot"))
    pour = FunctionalUnit((pot, garlic, plate, rice), Motion("pour"),
                          (done, n("garlic rice", contains("garlic"), inside("pot"))))
    rice_role = relational_roles(pour)[3]
    assert rice_role.fate is Fate.STAYS and rice_role.source == rice_role.target and rice_role.source.role == 0
    # the chocolate sandwich put onto the plate of egg mixture came from another plate: it moves
    sandwich, egg_plate = n("sandwich", make_state("on", "plate")), n("plate", contains("egg mixture"))
    place = FunctionalUnit((egg_plate, sandwich), Motion("pick-and-place"),
                           (n("plate", contains("egg mixture", "sandwich")), n("sandwich", "soaked", make_state("on", "plate"))))
    assert relational_roles(place)[1].fate is Fate.MOVES and relational_roles(place)[1].source.role is None
    bowl, raw = n("bowl", contains("white rice")), n("white rice", inside("bowl"))
    fill = FunctionalUnit((n("pot", "empty"), bowl, raw), Motion("pour"), (pot, rice))
    outcome = clean_unit_plan([fill, pour], [n("pot", "empty"), bowl, raw, plate, garlic], done)
    final = outcome.trace.final
    garnished = [x for x, st in final.items() if st.node == done]
    assert final["pot_1"].node == pot and len(garnished) == 1 and final[garnished[0]].holder == "pot_1"


def test_a_networks_readings_kept_between_goals_give_the_task_a_fresh_network_gives():
    # the mutual lists (0017's bread and tray) and the input stitches (0036's sprouts, 0019's chicken) are read
    # once per network object and kept for its next goal: every task is the one a new, equal network gives
    paths = [p for p in sorted(SUBGRAPHS.iterdir()) if p.name[:4] in ("0017", "0019", "0036", "0079")]
    kept, _ = load(paths)
    dishes = sorted(x for x in kept.nodes if x.dish is not None)
    assert len(dishes) == 4

    def task(foon, dish):
        c = compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational")
        return repr((c.task, c.notes))

    first = [task(kept, d) for d in dishes]
    again = [task(kept, d) for d in reversed(dishes)][::-1]
    fresh = [task(load(paths)[0], d) for d in dishes]
    assert first == again == fresh
    assert any("read as" in t for t in first)


def test_a_reading_is_a_note_of_the_tasks_that_have_its_node_only():
    # 0017's garlic bread lists the tray in the bread and the bread in the tray: its task reports the reading,
    # the dalgona coffee's task over the same network does not
    foon, _ = load([p for p in sorted(SUBGRAPHS.iterdir()) if p.name[:4] in ("0017", "0079")])
    notes = {}
    for dish in sorted(x for x in foon.nodes if x.dish is not None):
        c = compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational")
        notes[dish.label] = [x for x in c.notes if "each in the other" in x]
    assert notes["garlic bread"] and all("0017-garfield_garlic_bread.txt:35" in x for x in notes["garlic bread"])
    assert notes["dalgona coffee"] == []


def test_encoding_keeps_no_network_alive():
    # the readings kept per network object (mutual lists, input stitches) die with it: a long run (an
    # experiment's workers, this test suite) would otherwise keep every network it encoded, and its indexes
    import gc
    import weakref

    for names in (("0001",), ("0017", "0036")):  # no reading at all; a mutual reading and an input stitch
        foon, _ = load([p for p in sorted(SUBGRAPHS.iterdir()) if p.name[:4] in names])
        dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
        compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational")
        alive = weakref.ref(foon)
        del foon
        gc.collect()
        assert alive() is None, names
