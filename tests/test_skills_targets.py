"""Where a step's skill works and what the robot carries: targets, tools, portions, transport (hand-built traces,
`skill_traces`)."""

from __future__ import annotations

import pytest
from skill_traces import (
    BOARD,
    BOWL,
    CHOP,
    IN,
    MIX,
    MOVE,
    ON,
    ONION_CHOPPED,
    POUR,
    SPOON,
    kitchen_trace,
    node,
    skills,
    targets,
    trace,
)

from foon2pddl.model.foon import make_node, make_state
from foon2pddl.model.physical import ObjectState
from foon2pddl.skills.decompose import StepStatus, decompose, uncarried
from foon2pddl.skills.domain import shipped_domain
from foon2pddl.skills.micro import Naming, micro_problem
from foon2pddl.skills.recipe import object_names, skill_sentence
from foon2pddl.skills.report import call_text
from foon2pddl.skills.table import parse_table, shipped_table

LIME_HALVED, LIME_SQUEEZED, JUICER = node("lime", "halved"), node("lime", "squeezed"), node("juicer")


def juicer_trace(lime_changes=True):
    objects = {"lime_1": "lime", "juicer_1": "juicer", "board_1": "cutting board", "juice_1": "lime juice"}
    initial = [ObjectState("lime_1", LIME_HALVED, "board_1", ON), ObjectState("juicer_1", JUICER),
               ObjectState("board_1", BOARD), ObjectState("juice_1")]
    lime = LIME_SQUEEZED if lime_changes else LIME_HALVED
    return trace(objects, initial, [("squeeze", [ObjectState("lime_1", lime, "board_1", ON),
                                                 ObjectState("juice_1", node("lime juice", "liquid"), "juicer_1", IN)],
                                     ["lime_1", "juicer_1", "juice_1"])])


def test_a_hand_or_tool_skill_works_on_what_the_step_changes_not_where_its_product_appears():
    assert targets(juicer_trace(), "squeeze") == ["lime_1"]  # not the juicer the juice appears in
    plan = decompose(juicer_trace(), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("squeeze", ("lime_1",))]
    assert targets(juicer_trace(lime_changes=False), "squeeze") == ["juicer_1"]  # nothing changes: the product's site
    assert targets(kitchen_trace(CHOP), "chop") == ["onion_1"]
    assert targets(kitchen_trace(POUR), "pour") == ["bowl_1"]  # a transfer: where the poured water goes


def test_a_grind_with_no_tool_holds_the_mill_over_the_bowl():
    # FOON (ACT-0061 matzo brei): bowl, grinder (contains {salt}), salt (in [grinder]) -grind->
    # salt (granulated, in [bowl]); the grinder is no tool (it holds the salt): the hand holds it over the bowl
    objects = {"grinder_1": "grinder", "salt_1": "salt", "bowl_1": "bowl"}
    initial = [ObjectState("grinder_1", node("grinder")), ObjectState("salt_1", node("salt"), "grinder_1", IN),
               ObjectState("bowl_1", BOWL)]
    t = trace(objects, initial, [("grind", [ObjectState("salt_1", node("salt", "granulated"), "bowl_1", IN)],
                                  ["bowl_1", "grinder_1", "salt_1"])])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("grinder_1", "workspace")), ("grind", ("grinder_1", "bowl_1")),
                            ("place", ("grinder_1", "workspace"))]
    mash = decompose(t, parse_table('{"motions": {"grind": "mash"}}', "t.json"), shipped_domain())
    assert mash.steps[0].status is StepStatus.FAILED  # the old mapping: a mash with no masher cannot move the salt


def test_a_scoop_into_a_spoon_holds_the_spoon_and_dips_it_into_the_source():
    # FOON (0080 virgin mojito): container (contains {sugar}), sugar (in [container]), spoon -scoop->
    # spoon (contains {sugar}), sugar (in [spoon]); the spoon holds the sugar after: where it goes, not a tool
    objects = {"container_1": "container", "sugar_1": "sugar", "spoon_1": "spoon"}
    sugar = node("refined sugar", "granulated")
    initial = [ObjectState("container_1", node("container")), ObjectState("sugar_1", sugar, "container_1", IN),
               ObjectState("spoon_1", SPOON)]
    t = trace(objects, initial, [("scoop", [ObjectState("sugar_1", sugar, "spoon_1", IN)],
                                  ["container_1", "sugar_1", "spoon_1"])])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("spoon_1", "workspace")), ("scoop-up", ("container_1", "spoon_1")),
                            ("place", ("spoon_1", "workspace"))]
    params = tuple(v for v, _ in shipped_domain().by_name["scoop-up"].params)
    assert call_text(plan.calls[1], params) == "scoop-up from container_1 into spoon_1"
    assert skill_sentence(plan.calls[1], params, object_names(t)) == "scoop up from the container into the spoon"


def test_a_dip_holds_the_object_dipped_and_dips_it_into_the_dips_container():
    # FOON (05 french toast): bowl (contains {custard}), custard (in [bowl]), bread (sliced) -dip->
    # bread (sliced, soaked {custard}); the holders' reading puts the custard it soaks up in the bread
    objects = {"bowl_1": "bowl", "custard_1": "custard", "bread_1": "bread"}
    custard = node("custard", "liquid")
    initial = [ObjectState("bowl_1", node("bowl")), ObjectState("custard_1", custard, "bowl_1", IN),
               ObjectState("bread_1", node("bread", "sliced"))]
    t = trace(objects, initial, [("dip", [ObjectState("bread_1", node("bread", "sliced", "soaked")),
                                          ObjectState("custard_1", custard, "bread_1", IN)],
                                  ["bowl_1", "custard_1", "bread_1"])])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("bread_1", "workspace")), ("dip", ("bowl_1", "bread_1")),
                            ("place", ("bread_1", "workspace"))]  # the custard is never taken out of its bowl
    params = tuple(v for v, _ in shipped_domain().by_name["dip"].params)
    assert skill_sentence(plan.calls[1], params, object_names(t)) == "dip the bread into the bowl"


def test_a_dip_with_nothing_in_its_source_to_take_is_carried_out_by_transport():
    # FOON (0032 cheeseburger): bowl (contains {ground beef}), onion (chopped, on [cutting board]) -dip->
    # bowl (contains {ground beef, onion}): the onion is put into the bowl, the bowl is not dipped into the board
    objects = {"bowl_1": "bowl", "onion_1": "onion", "board_1": "cutting board"}
    initial = [ObjectState("bowl_1", node("bowl")), ObjectState("onion_1", ONION_CHOPPED, "board_1", ON),
               ObjectState("board_1", node("cutting board", "contains {onion}"))]
    t = trace(objects, initial, [("dip", [ObjectState("onion_1", ONION_CHOPPED, "bowl_1", IN)],
                                  ["bowl_1", "onion_1", "board_1"])])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert plan.steps[0].skill == "put-in"
    assert skills(plan) == [("pick", ("onion_1", "board_1")), ("put-in", ("onion_1", "bowl_1"))]


def test_a_scrape_with_no_tool_tips_the_board_over_the_bowl():
    # FOON (0033 miso soup): tofu (diced, on [cutting board]), bowl (empty) -scrape-> tofu (diced, in [bowl])
    objects = {"tofu_1": "tofu", "board_1": "cutting board", "bowl_1": "bowl"}
    tofu = node("tofu", "diced")
    initial = [ObjectState("tofu_1", tofu, "board_1", ON), ObjectState("board_1", BOARD), ObjectState("bowl_1", BOWL)]
    t = trace(objects, initial, [("scrape", [ObjectState("tofu_1", tofu, "bowl_1", IN)], ["tofu_1", "bowl_1"])])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("board_1", "workspace")), ("scrape-by-hand", ("board_1", "bowl_1")),
                            ("place", ("board_1", "workspace"))]


def test_a_portion_a_transport_step_moves_is_picked_up_where_its_source_is():
    # the relational encoding's portion: some of the chopped onion on the board (onion_2, not yet an object
    # before the step) goes into the bowl while onion_1 stays on the board: the robot picks it from the board
    objects = {"onion_1": "onion", "onion_2": "onion", "board_1": "cutting board", "bowl_1": "bowl"}
    initial = [ObjectState("onion_1", ONION_CHOPPED, "board_1", ON), ObjectState("onion_2"),
               ObjectState("board_1", BOARD), ObjectState("bowl_1", BOWL)]
    step = ("pick-and-place", [ObjectState("onion_2", ONION_CHOPPED, "bowl_1", IN)], ["onion_2", "onion_1", "bowl_1"])
    plan = decompose(trace(objects, initial, [step]), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert [s.status for s in plan.steps] == [StepStatus.DECOMPOSED]
    assert [(c.skill, c.objects[0]) for c in plan.calls] == [("pick", "onion_2"), ("put-in", "onion_2")]
    assert plan.calls[0].holders[0] == "board_1"  # picked where the onion it was part of lies


def test_a_transport_step_moves_what_it_sets_down_and_never_picks_up_and_puts_back_what_stays():
    # FOON restates a pan the butter goes into (`skillet (heated, on [stove])` -> `skillet (contains {butter},
    # on [stove])`): the pan stays on the stove and no transport skill changes an object it does not set down,
    # so the robot moves the butter only (it used to pick the skillet up from the stove and put it back)
    objects = {"butter_1": "butter", "skillet_1": "skillet", "stove_1": "stove"}
    initial = [ObjectState("butter_1", node("butter", "cubed")), ObjectState("skillet_1", node("skillet", "heated"),
               "stove_1", ON), ObjectState("stove_1", node("stove", "on"))]
    step = ("pick-and-place", [ObjectState("butter_1", node("butter", "cubed"), "skillet_1", IN),
                               ObjectState("skillet_1", node("skillet"), "stove_1", ON)],
            ["butter_1", "skillet_1", "stove_1"])
    plan = decompose(trace(objects, initial, [step, CHECK_STOVE]), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert [(c.skill, c.objects[0]) for c in plan.calls if c.macro == 0] == [("pick", "butter_1"),
                                                                              ("put-in", "butter_1")]
    # a transport step that moves nothing else still sets its changed object down: that is the step
    alone = ("pick-and-place", [ObjectState("skillet_1", node("skillet"), "stove_1", ON)], ["skillet_1", "stove_1"])
    plan = decompose(trace(objects, initial, [alone]), shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert [(c.skill, c.objects[0]) for c in plan.calls] == [("pick", "skillet_1"), ("place", "skillet_1")]


#: A later step that reads the skillet's restated phase (the replay carries it on).
CHECK_STOVE = ("turn off", [ObjectState("stove_1", node("stove", "off"))], ["stove_1"])


def test_food_in_a_container_or_a_pan_on_the_stove_is_no_tool():
    # FOON (0045 pork chops): spread: cooking pan (contains {butter, vegetable oil}, on [stove]) -> cooking pan
    # (greased {...}): no spatula listed; the oil in the pan held nothing and stayed, so it was taken for a tool
    # (`take-out vegetable_oil_2, spread vegetable_oil_2 ...`); a tool stands free on the table
    objects = {"oil_1": "vegetable oil", "pan_1": "cooking pan", "stove_1": "stove"}
    initial = [ObjectState("oil_1", node("vegetable oil"), "pan_1", IN), ObjectState("pan_1", node("cooking pan"),
               "stove_1", ON), ObjectState("stove_1", node("stove", "on"))]
    step = ("spread", [ObjectState("pan_1", node("cooking pan", "greased"), "stove_1", ON)], ["oil_1", "pan_1"])
    t = trace(objects, initial, [step])
    problem = micro_problem(t, 0, "spread", Naming(t, shipped_domain(), 1), shipped_domain())
    assert not any(a.predicate == "tool" for a in problem.init)
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.steps[0].status is StepStatus.FAILED and "no tool to spread with" in plan.steps[0].reason


def test_a_hand_skill_never_carries_an_object_the_robot_picks_and_places_it():
    # FOON (0037 french toast): heat: skillet (empty), stove (on) -> skillet (heated, on [stove]): the skillet goes
    # onto the stove; a hand skill holds nothing, so the robot picks the skillet up and places it (was: `heat
    # stove_1`, the skillet moving onto the stove by itself)
    objects = {"skillet_1": "skillet", "stove_1": "stove"}
    initial = [ObjectState("skillet_1", node("skillet", "empty")), ObjectState("stove_1", node("stove", "on"))]
    step = ("heat", [ObjectState("skillet_1", node("skillet", "heated"), "stove_1", ON),
                     ObjectState("stove_1", node("stove", "on"))], ["skillet_1", "stove_1"])
    t = trace(objects, initial, [step])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert uncarried(plan, t) == []
    assert [(c.skill, c.objects[0]) for c in plan.calls if c.skill != "heat"] == [("pick", "skillet_1"),
                                                                                  ("place", "skillet_1")]

    def carried_by_heat(domain_text, problem_text):  # the former plan: the skillet reached the stove by itself
        return "solved", ("heat hand_1 skillet_1",), "", 0.0

    assert uncarried(decompose(t, shipped_table(), shipped_domain(), solver=carried_by_heat), t) == [(0, "skillet_1")]
    assert [c.skill for c in plan.calls].count("heat") == 1


def test_a_tool_skill_that_moves_a_free_standing_object_has_it_set_down_by_the_robot():
    # FOON (0013 creamy potato soup): grate: grater, bowl (empty), cheese (block) -> cheese (grated, in [bowl]):
    # the block stood on the table; the robot puts it in the bowl and grates it there (was: grating it made the
    # block appear in the bowl)
    objects = {"cheese_1": "cheese", "grater_1": "grater", "bowl_1": "bowl"}
    initial = [ObjectState("cheese_1", node("cheese", "block")), ObjectState("grater_1", node("grater", "clean")),
               ObjectState("bowl_1", node("bowl", "empty"))]
    step = ("grate", [ObjectState("cheese_1", node("cheese", "grated"), "bowl_1", IN)],
            ["grater_1", "bowl_1", "cheese_1"])
    t = trace(objects, initial, [step])
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert uncarried(plan, t) == []
    assert ("grate", ("grater_1", "cheese_1")) in skills(plan)


def test_a_portion_a_pour_moves_is_poured_from_the_holder_of_what_it_is_part_of():
    # the relational encoding's portion in a pour (0037 french toast: some of the cubed butter in the bowl goes
    # into the pan): the robot pours from the bowl the butter is in (was: `pick stove_1, pour from stove_1 over
    # pan_1`, since the portion only appeared in the pan, whatever the robot held)
    objects = {"butter_1": "butter", "butter_2": "butter", "tub_1": "bowl", "pan_1": "pan", "stove_1": "stove"}
    cubed = node("butter", "cubed")
    initial = [ObjectState("butter_1", cubed, "tub_1", IN), ObjectState("butter_2"),
               ObjectState("tub_1", BOWL), ObjectState("pan_1", node("pan")), ObjectState("stove_1", node("stove"))]
    step = ("pour", [ObjectState("butter_2", cubed, "pan_1", IN)], ["butter_1", "butter_2", "tub_1", "pan_1",
                                                                       "stove_1"])
    t = trace(objects, initial, [step])
    problem = micro_problem(t, 0, "pour", Naming(t, shipped_domain(), 1), shipped_domain())
    facts = {f"({a.predicate} {' '.join(a.args)})" for a in problem.init}
    assert {"(in tub_1 butter_2)", "(moves-in sk-pour butter_2 pan_1)"} <= facts  # it stands where its source is
    assert not any(a.predicate == "makes-in" for a in problem.init)  # not made in the pan by any pour
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("pick", ("tub_1", "workspace")), ("pour", ("tub_1", "pan_1")),
                            ("place", ("tub_1", "workspace"))]



def egg_trace(consumed):
    # FOON (0037 french toast, line 7): crack: measuring cup (empty), egg (uncracked) -> measuring cup (contains
    # {egg white and yolk}), egg white and yolk (in [measuring cup]); the relational trace keeps the egg (FOON lists
    # it as an input only, as it lists a knife), another trace may use it up
    objects = {"egg_1": "egg", "cup_1": "measuring cup", "yolk_1": "egg white and yolk"}
    egg = node("egg", "uncracked")
    initial = [ObjectState("egg_1", egg), ObjectState("cup_1", node("measuring cup", "empty")), ObjectState("yolk_1")]
    step = ("crack", [ObjectState("egg_1", egg, consumed=consumed),
                      ObjectState("cup_1", make_node("measuring cup", [make_state("contains", "", ["egg white and yolk"])])),
                      ObjectState("yolk_1", node("egg white and yolk"), "cup_1", IN)], ["cup_1", "egg_1", "yolk_1"])
    return trace(objects, initial, [step])


@pytest.mark.parametrize("consumed", [False, True])
def test_a_hand_skill_works_on_the_egg_it_cracks_not_on_the_cup_the_yolk_appears_in(consumed):
    # the french toast cracked the measuring cup (`crack measuring_cup_1`): the skill aimed where the yolk appears
    t = egg_trace(consumed)
    assert targets(t, "crack") == ["egg_1"]
    plan = decompose(t, shipped_table(), shipped_domain())
    assert plan.ok, plan.replay.problems
    assert skills(plan) == [("crack", ("egg_1",))]


def test_a_tool_skill_that_changes_nothing_works_where_its_product_appears():
    # several ingredients used up in the bowl their mixture appears in: the mix works in the bowl, with the spoon
    mixed = decompose(kitchen_trace(CHOP, MOVE, POUR, MIX), shipped_table(), shipped_domain())
    assert [c.objects for c in mixed.calls if c.skill == "mix"] == [("spoon_1", "bowl_1")]
