"""Scene kitchens: objects with ids as a robot's perception gives them become the relational task's `:init`."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pddl.parser.domain
import pddl.parser.problem
import pytest
from click.testing import CliRunner
from conftest import ROOT
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.cli import main
from foon2pddl.errors import FoonError
from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
from foon2pddl.io.scene_file import KEYS, OBJECT_KEYS
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.render import render
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

SCENES = ROOT / "tests" / "data" / "scene"
WHIPPED_SCENE = SCENES / "whipped_cream_scene.json"
DRESSED = SCENES / "dressed_lettuce.foon"
WHIPPED_GOAL = "whipped cream: whipped, in [bowl]"
DRESSED_GOAL = "bowl: contains {dressing, lettuce}"


def _ids(path: Path) -> set[str]:
    return {o["id"] for o in json.loads(path.read_text())["objects"]}


def _plan(paths, scene: Path, goal: str, encoding: str = "relational"):
    net = load_network(paths)
    foon = net.at(3)
    kitchen = load_kitchen(scene, net, 3)
    return plan(foon, kitchen, load_goal(goal, None, foon), encoding), kitchen


def test_a_scene_of_the_example_kitchen_plans_whipped_cream_with_only_its_ids():
    outcome, kitchen = _plan([], WHIPPED_SCENE, WHIPPED_GOAL)
    assert outcome.status == "solved", outcome.message
    trace = outcome.trace
    assert replay(trace).ok and outcome.decoded.trace_check.ok and outcome.validation.ok
    ids = _ids(WHIPPED_SCENE)
    first = next(iter(trace.states()))
    existing = {x for x, s in first.items() if s.exists}
    assert existing == ids  # the task's objects at the start are exactly the scene's
    made = {o.id for o in trace.objects} - ids
    assert made and all(not first[x].exists for x in made)  # the rest are what the plan makes
    init = set(outcome.task.initial_facts)
    holders = {(a.predicate, *a.args) for a in init if a.predicate in ("in", "on")}
    assert ("in", "fridge_1", "sugar_1") in holders and ("on", "counter_1", "bowl_1") in holders
    assert ("in", "carton_1", "cream_1") in holders and ("on", "board_1", "knife_1") in holders
    assert len(holders) == sum(1 for o in json.loads(WHIPPED_SCENE.read_text())["objects"] if "in" in o or "on" in o)
    # the sugar leaves the fridge, the cream stays in its carton (a portion is poured), the dish is in bowl_1
    assert trace.final["sugar_1"].holder != "fridge_1" and trace.final["cream_1"].holder == "carton_1"
    assert trace.contents("bowl_1") == ("whipped_cream_1",)
    named = {a for s in outcome.result.plan for a in s.split()[1:]}
    assert named <= ids | made
    assert kitchen.stated_counts()  # counts come from the scene


def test_plan_cli_names_the_scene_ids_in_text_and_json():
    args = ["plan", "--kitchen", str(WHIPPED_SCENE), "--encoding", "relational", "--goal", WHIPPED_GOAL]
    text = CliRunner().invoke(main, args)
    assert text.exit_code == 0, text.output
    # FOON's pour names no source for the sugar: the fridge is where it is kept, not what it is poured from
    assert "take sugar_1 out of fridge_1, pour it into mixing_bowl_1" in text.stdout
    assert "pour heavy_cream_2 (a portion of cream_1) from carton_1 into mixing_bowl_1" in text.stdout
    assert "scoop whipped_cream_1 from mixing_bowl_1 into bowl_1 with spatula_1" in text.stdout
    assert "matches no node" not in text.stderr  # the fridge and the counter are places, not stray items
    data = json.loads(CliRunner().invoke(main, [*args, "--format", "json"]).stdout)
    initial = {o["id"]: o for o in data["relational"]["initial"]}
    assert initial["sugar_1"]["holder"] == "fridge_1" and initial["knife_1"] == {
        "id": "knife_1", "label": "knife", "state": "knife", "holder": "board_1", "relation": "on", "consumed": False}


def test_ids_that_are_no_pddl_names_are_sanitized_in_pddl_and_shown_as_given(tmp_path):
    objects = json.loads(WHIPPED_SCENE.read_text())["objects"]
    rename = {"bowl_1": "Bowl #1", "fridge_1": "(define fridge)", "sugar_1": "sucre \u00e9 1"}
    for o in objects:
        for key in ("id", "in", "on"):
            if o.get(key) in rename:
                o[key] = rename[o[key]]
    path = _scene(tmp_path, objects)
    result = CliRunner().invoke(main, ["plan", "--kitchen", str(path), "--encoding", "relational", "--goal",
                                       WHIPPED_GOAL, "--format", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["validation"]["relational"]["ok"]
    texts = [s["text"] for s in data["relational"]["steps"]]
    assert "take sucre \u00e9 1 out of (define fridge), pour it into mixing_bowl_1" in texts
    assert "scoop whipped_cream_1 from mixing_bowl_1 into Bowl #1 with spatula_1" in texts
    assert {o["id"] for o in data["relational"]["initial"]} >= set(rename.values())
    assert any(a.split()[1:] and "bowl_1" in a for a in data["plan"])  # the raw plan: PDDL names
    assert not any(x in " ".join(data["plan"]) for x in rename.values())


@pytest.mark.parametrize("encoding", ["tree", "instances", "relational", "state", "foon-compat", "ocp"])
def test_every_encoding_accepts_a_scene(encoding, tmp_path):
    result = CliRunner().invoke(main, ["compile", "--kitchen", str(WHIPPED_SCENE), "--encoding", encoding,
                                       "--goal", WHIPPED_GOAL, "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert list(tmp_path.glob("*.pddl"))


def test_counts_come_from_the_scene(tmp_path):
    objects = json.loads(WHIPPED_SCENE.read_text())["objects"]
    objects += [{"id": f"bowl_{k}", "label": "bowl", "states": ["empty"], "on": "counter_1"} for k in (2, 3)]
    net = load_network([])
    foon = net.at(3)
    kitchen = load_kitchen(_scene(tmp_path, objects), net, 3)
    goal = load_goal(WHIPPED_GOAL, None, foon)
    instances = compile_goal(foon, kitchen, goal, "instances").task.instances
    assert sum(x.label == "bowl" for x in instances) == 3  # the scene's three empty bowls, not the derived one
    relational = compile_goal(foon, kitchen, goal, "relational").task.instances
    made = {x.name for x in relational if x.start is None}
    assert {x.name for x in relational} - made == {o["id"] for o in objects}


def test_two_bowls_at_once_plan_and_one_bowl_names_the_step_that_needs_the_second():
    outcome, _ = _plan([DRESSED], SCENES / "dressing_two_bowls.json", DRESSED_GOAL)
    assert outcome.status == "solved" and replay(outcome.trace).ok
    used = {x for s in outcome.trace.steps for b in s.bindings for x in [b.object]}
    assert {"bowl_1", "bowl_2"} <= used
    result = CliRunner().invoke(main, ["plan", str(DRESSED), "--kitchen", str(SCENES / "dressing_one_bowl.json"),
                                       "--encoding", "relational", "--goal", DRESSED_GOAL])
    assert result.exit_code == 1
    assert ("the scene has too few objects: step 4 (pick-and-place) needs one more bowl in 'bowl (empty)': "
            "the kitchen has 1 there") in result.stderr


def _scene(tmp_path, objects, **extra) -> Path:
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"objects": objects, **extra}, indent=1))
    return path


BOWL = {"id": "bowl_1", "label": "bowl", "states": ["empty"]}


@pytest.mark.parametrize(("objects", "index", "message"), [
    ([BOWL, {"id": "cream_1", "label": "heavy cream", "in": "carton_9"}], 1, "'carton_9', which is no id of the scene"),
    ([BOWL, {"id": "bowl_1", "label": "bowl"}], 1, "duplicate id 'bowl_1' (first on line 3)"),
    ([BOWL, {"id": "egg_1", "label": "egg", "in": "bowl_1", "on": "bowl_1"}], 1, "is in two holders"),
    ([BOWL, {"id": "egg_1", "label": "egg", "states": ["in [bowl]"]}], 1, "say where an object is with"),
    ([BOWL, {"id": "egg_1", "label": "egg", "states": ["whole [bowl"]}], 1, "cannot read state"),
    ([BOWL, {"id": "egg_1", "label": "egg", "states": ["whole\u0007"]}], 1, "control character in state"),
    ([BOWL, {"id": "egg_1", "label": "egg", "states": "whole"}], 1, "'states' must be a list of strings"),
    ([BOWL, {"id": "egg_1", "label": "egg", "colour": "white"}], 1,
     "object 2: unknown key 'colour' (expected one of id, label, states, in, on)"),
    ([BOWL, {"id": "", "label": "egg"}], 1, "'id' must be a non-empty string"),
    ([BOWL, {"id": "egg_1", "label": "egg", "in": "egg_1"}], 1, "cannot hold itself"),
    ([{**BOWL, "in": "pot_1"}, {"id": "pot_1", "label": "pot", "in": "bowl_1"}], 0, "cycle"),
    # read against the network: the example places whipped cream in a bowl, and this bowl says it is empty
    ([BOWL, {"id": "cream_1", "label": "whipped cream", "in": "bowl_1"}], 0, "bowl_1 is `empty`, but cream_1 is in"),
])
def test_a_bad_scene_is_a_located_error_never_a_traceback(tmp_path, objects, index, message):
    path = _scene(tmp_path, objects)
    line = 3 + sum(len(json.dumps(o, indent=1).splitlines()) for o in objects[:index])
    result = CliRunner().invoke(main, ["plan", "--kitchen", str(path), "--encoding", "relational",
                                       "--goal", WHIPPED_GOAL])
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert f"{path}:{line}: " in result.stderr and message in result.stderr, result.stderr
    with pytest.raises(FoonError):
        load_kitchen(path, load_network([]), 3)


def test_a_scene_document_is_checked_as_a_whole(tmp_path):
    for data, message in [({"objects": []}, "non-empty list"), ({"objects": [BOWL], "robot": 1},
                                                                 "unknown key 'robot' (expected one of objects, $schema, "
                                                                 "description, name)"),
                          ({"things": []}, "or a scene")]:
        path = tmp_path / "s.json"
        path.write_text(json.dumps(data))
        result = CliRunner().invoke(main, ["compile", "--kitchen", str(path), "--goal", WHIPPED_GOAL])
        assert result.exit_code == 2 and message in result.stderr and "Traceback" not in result.output


def test_the_schema_declares_exactly_the_keys_the_reader_accepts():
    schema = json.loads((ROOT / "foon2pddl" / "data" / "scene.schema.json").read_text())
    assert set(schema["properties"]) == set(KEYS) and schema["additionalProperties"] is False
    item = schema["properties"]["objects"]["items"]
    assert set(item["properties"]) == set(OBJECT_KEYS) and item["additionalProperties"] is False
    assert set(item["required"]) == {"id", "label"}
    assert "docs/scene.md" in (ROOT / "README.md").read_text()


def test_the_scene_survives_projection_to_a_lower_level():
    net = load_network([])
    kitchen = load_kitchen(WHIPPED_SCENE, net, 1)
    assert {o.id for o in kitchen.scene} == _ids(WHIPPED_SCENE)
    assert all(not o.node.states for o in kitchen.scene)  # level 1: labels only
    assert sum(k for _, k in kitchen.counts) == len(kitchen.scene)


_HOSTILE = st.lists(st.sampled_from([*"ab(); \"'?-_:é漢", "(define", ") (:init", "bowl_1"]), min_size=1,
                    max_size=8).map("".join)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(ids=st.lists(_HOSTILE.filter(str.strip), min_size=3, max_size=3, unique=True),
       label=_HOSTILE.filter(lambda s: s.strip() and not set(s) & set("[]{},:")))
def test_ids_and_labels_that_would_break_pddl_compile_to_pddl_that_parses(tmp_path, ids, label):
    objects = json.loads(WHIPPED_SCENE.read_text())["objects"]
    rename = dict(zip(["bowl_1", "fridge_1", "sugar_1"], ids, strict=True))
    for o in objects:
        for key in ("id", "in", "on"):
            if o.get(key) in rename:
                o[key] = rename[o[key]]
    objects.append({"id": ids[0] + " extra", "label": label, "states": [label], "on": ids[1]})
    path = _scene(tmp_path, objects)
    net = load_network([])
    foon = net.at(3)
    task = compile_goal(foon, load_kitchen(path, net, 3), load_goal(WHIPPED_GOAL, None, foon), "relational").task
    domain, problem = render(task)
    pddl.parser.domain.DomainParser()(domain)
    parsed = pddl.parser.problem.ProblemParser()(problem)
    names = {str(o.name) for o in parsed.objects}
    # the objects no action can touch are set aside from the problem (`pddl.untouched`), the others declared
    assert len(names) == len(task.objects) and {x.name for x in task.instances} == names | {x for x, _ in task.aside}
    assert {task.labels[x.name] for x in task.instances if x.start is not None} >= set(ids)  # each id, named


def test_two_bowls_of_one_label_read_as_what_moves_from_which_bowl_into_which():
    """The last step pours one bowl's contents into the other bowl: both the tree's cook's words and the object
    line say what moves, from where, into what (not a list of two bowls, not the other bowl's dressing as a
    tool). FOON's pairing makes the lettuce's bowl the one left empty (`model.pairing`), as the planner does."""
    result = CliRunner().invoke(main, ["plan", str(DRESSED), "--kitchen", str(SCENES / "dressing_two_bowls.json"),
                                       "--encoding", "relational", "--goal", DRESSED_GOAL])
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "5. pour lettuce (chopped) from the bowl (contains {lettuce}) into the bowl (contains {dressing})" in lines
    assert "5. pour lettuce_1 from bowl_1 into bowl_2" in lines


def test_the_instances_object_line_says_what_moves_from_which_bowl_into_which():
    """The `instances` encoding's object line for the same step listed the two bowls (`pour bowl_2, bowl_1 with
    dressing_1, lettuce_1`) where the cook's words name them: it says what moves, from which bowl into which, as
    the relational encoding's line does, and the dressing already in the receiving bowl is no tool."""
    result = CliRunner().invoke(main, ["plan", str(DRESSED), "--kitchen", str(SCENES / "dressing_two_bowls.json"),
                                       "--encoding", "instances", "--goal", DRESSED_GOAL])
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "5. pour lettuce (chopped) from the bowl (contains {lettuce}) into the bowl (contains {dressing})" in lines
    assert any(line.startswith("5. pour lettuce_1 from bowl_1 into bowl_2: ") for line in lines), result.stdout


@pytest.mark.parametrize(("relation", "taken"), [("in", "take sugar_1 out of fridge_1"), ("on", "take sugar_1 off shelf_1")])
def test_an_object_moved_from_a_holder_its_node_does_not_name_is_taken_from_it_first(relation, taken):
    """Issue 24's last pass: the account said `pour sugar_1 from fridge_1 into mixing_bowl_1`; a cook does not pour
    from a fridge. A holder the object's node does not name (storage, a shelf) is where it is kept: the account takes
    it out first; a holder its node names (`in [bag]`) is poured from."""
    from node_words import contains, inside, n

    from foon2pddl.model.foon import FunctionalUnit, Motion
    from foon2pddl.model.physical import Binding, ObjectState, Relation, TraceStep
    from foon2pddl.pddl.relational_replay import step_words

    store = "fridge_1" if relation == "in" else "shelf_1"
    rel = Relation.IN if relation == "in" else Relation.ON
    sugar, bowl = n("sugar", "granulated"), n("bowl", "empty")
    after_sugar, after_bowl = n("sugar", inside("bowl")), n("bowl", contains("sugar"))
    step = TraceStep(0, FunctionalUnit((bowl, sugar), Motion("pour"), (after_bowl, after_sugar)),
                     (Binding("bowl_1", bowl, after_bowl), Binding("sugar_1", sugar, after_sugar)), ())
    before = {"bowl_1": ObjectState("bowl_1", bowl), "sugar_1": ObjectState("sugar_1", sugar, store, rel),
              store: ObjectState(store, n(store[:-2]))}
    after = {**before, "bowl_1": ObjectState("bowl_1", after_bowl),
             "sugar_1": ObjectState("sugar_1", after_sugar, "bowl_1", Relation.IN)}
    assert step_words(step, before, after) == f"{taken}, pour it into bowl_1"
    # in a bag its node names, the sugar is poured from the bag
    bagged = n("sugar", inside("bag"))
    step = TraceStep(0, FunctionalUnit((bowl, bagged), Motion("pour"), (after_bowl, after_sugar)),
                     (Binding("bowl_1", bowl, after_bowl), Binding("sugar_1", bagged, after_sugar)), ())
    before = {**before, "sugar_1": ObjectState("sugar_1", bagged, "bag_1", Relation.IN),
              "bag_1": ObjectState("bag_1", n("bag"))}
    assert step_words(step, before, {**after, "bag_1": before["bag_1"]}) == "pour sugar_1 from bag_1 into bowl_1"


def test_a_holder_the_unit_names_is_taken_from_in_the_motion():
    """The shared subgraphs' plans said `take frittata_1 out of cooking_pan_1, pick-and-place it onto plate_1`
    (0026-cheddar_frittata.txt:441) after b9bb1d1: a holder the unit lists, or one that stands for a place the moved
    object's node names (`in [pan]`), is what the cook takes from, not storage: `... from cooking_pan_1 onto ...`."""
    from node_words import contains, inside, n

    from foon2pddl.model.foon import FunctionalUnit, Motion
    from foon2pddl.model.physical import Binding, ObjectState, Relation, TraceStep
    from foon2pddl.pddl.relational_replay import step_words

    pan, plate, food = n("cooking pan", contains("frittata")), n("plate"), n("frittata", "cooked")
    pan_after, plate_after, food_after = n("cooking pan", "empty"), n("plate", contains("frittata")), n("frittata")
    step = TraceStep(0, FunctionalUnit((pan, food, plate), Motion("pick-and-place"), (pan_after, food_after,
                                                                                       plate_after)),
                     (Binding("cooking_pan_1", pan, pan_after), Binding("frittata_1", food, food_after),
                      Binding("plate_1", plate, plate_after)), ())
    before = {"cooking_pan_1": ObjectState("cooking_pan_1", pan), "plate_1": ObjectState("plate_1", plate),
              "frittata_1": ObjectState("frittata_1", food, "cooking_pan_1", Relation.IN)}
    after = {"cooking_pan_1": ObjectState("cooking_pan_1", pan_after), "plate_1": ObjectState("plate_1", plate_after),
             "frittata_1": ObjectState("frittata_1", food_after, "plate_1", Relation.ON)}
    assert step_words(step, before, after).startswith("pick-and-place frittata_1 from cooking_pan_1 onto plate_1")
    # the unit's own words, 0026-cheddar_frittata.txt:441: `frittata (..., in [pan])`, the cooking pan no role of it
    # (the relational encoding's holder for the pan the node names)
    in_pan = n("frittata", "cooked", inside("pan"))
    step = replace(step, unit=FunctionalUnit((in_pan, plate), Motion("pick-and-place"), (food_after, plate_after)),
                   bindings=(Binding("cooking_pan_1", pan, pan_after, role=False),
                             Binding("frittata_1", in_pan, food_after), Binding("plate_1", plate, plate_after)))
    before = {**before, "frittata_1": replace(before["frittata_1"], node=in_pan)}
    assert step_words(step, before, after).startswith("pick-and-place frittata_1 from cooking_pan_1 onto plate_1")
