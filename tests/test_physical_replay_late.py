"""The replay's checks that read no FOON list, so they hold for the pairs a trace reports (`PhysicalTrace.gaps`).

FOON's own nodes can contradict each other about a container and a content label (the mix's only bowl lists the
eggs, the milk says `in [bowl]`); the encoding then binds the milk's holder late, and the replay checks no list
for that pair. Stop 60 found plans at `--level 2` (every `contains` bare, so every pair unchecked) that were
physically wrong and passed: 0050 mixed the milk in bowl_1 while it stayed in bowl_2; 0007's mix consumed the sour
cream and the sugar in bowl_1 while they sat in bowl_2 and bowl_4. What an object is consumed into is made where
it is, what a step works on in place is in the holder the step uses, and what it pours leaves the holder the step
pours from, whatever the lists say.
"""

from __future__ import annotations

from dataclasses import replace

from physical_world import World, contents, node

from foon2pddl.model.physical import Binding, ObjectState
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.replay_findings import DisagreementKind as K

MILK, EGG = node("milk", ("in", "bowl")), node("egg", "beaten", ("in", "bowl"))


def _kitchen(gaps: tuple[tuple[str, str], ...]) -> World:
    """The egg beaten in bowl_1, whose list names only the egg; the milk in bowl_2, whose list names it."""
    w = World({"bowl_1": "bowl", "bowl_2": "bowl", "egg_1": "egg", "milk_1": "milk", "fork_1": "fork",
               "pan_1": "pan", "egg_mixture_1": "egg mixture"},
              {"bowl_1": ObjectState("bowl_1", contents("bowl", ["egg"])),
               "bowl_2": ObjectState("bowl_2", contents("bowl", ["milk"])),
               "egg_1": ObjectState("egg_1", EGG, "bowl_1", "in"),
               "milk_1": ObjectState("milk_1", MILK, "bowl_2", "in"),
               "fork_1": ObjectState("fork_1", node("fork", "clean")),
               "pan_1": ObjectState("pan_1", contents("pan", []))})
    w.gaps = gaps
    return w


def _trace(w: World):
    return replace(w.trace(), gaps=w.gaps)


def _chosen(w: World, *holders: str) -> None:
    """The last step binds `holders` as holders it chose, not as nodes of its unit (one bowl node each less)."""
    step = w.steps[-1]
    inputs, outputs = list(step.unit.inputs), list(step.unit.outputs)
    for h in holders:
        inputs.remove(w.now[h].node)
        outputs.remove(w.now[h].node)
    w.steps[-1] = replace(step, unit=replace(step.unit, inputs=tuple(inputs), outputs=tuple(outputs)))


def _mix_in_bowl_1(w: World, *chosen: str) -> None:
    """The mix: egg and milk consumed, the egg mixture made in bowl_1 (`chosen`: holders the step chose)."""
    w.step("mix", [ObjectState("egg_1", EGG, "bowl_1", "in", consumed=True),
                   ObjectState("milk_1", w.now["milk_1"].node, w.now["milk_1"].holder, "in", consumed=True),
                   ObjectState("egg_mixture_1", node("egg mixture", ("in", "bowl")), "bowl_1", "in"),
                   ObjectState("bowl_1", contents("bowl", ["egg mixture"]))], uses=("fork_1", *chosen), line=54)
    _chosen(w, *chosen)


def test_0050s_mix_of_milk_left_in_another_bowl_is_rejected():
    """0050 at level 2 (stop 60): the mix consumes milk_1 in bowl_2, which the step binds as the holder it chose,
    and makes the egg mixture in bowl_1. The pairs are reported, so no list is checked: it passed before."""
    w = _kitchen((("bowl", "milk"), ("bowl", "egg mixture")))
    _mix_in_bowl_1(w, "bowl_2")
    report = replay(_trace(w))
    assert [(d.kind, d.step, d.objects) for d in report.disagreements] == [
        (K.CONSUMED_ELSEWHERE, 0, ("milk_1", "bowl_2", "bowl_1"))]
    assert "milk_1 is consumed in bowl_2, but the step makes egg_mixture_1 in bowl_1" in str(report.disagreements[0])


def test_0007s_mix_of_ingredients_in_three_other_bowls_is_rejected():
    """0007's step 10 at level 2: the dressing is made in bowl_1 from the mayonnaise there and the sour cream,
    the sugar and the salt in bowl_2, bowl_4 and bowl_7, each bound by the step."""
    food = {"mayonnaise": "bowl_1", "sour cream": "bowl_2", "sugar": "bowl_4", "salt": "bowl_7"}
    ids = {f: f.replace(" ", "_") + "_1" for f in food}
    w = World({**{b: "bowl" for b in food.values()}, **{ids[f]: f for f in food}, "dressing_1": "salad dressing",
               "spoon_1": "spoon"},
              {**{b: ObjectState(b, node("bowl", ("contains", []))) for b in food.values()},
               **{ids[f]: ObjectState(ids[f], node(f, ("in", "bowl")), b, "in") for f, b in food.items()},
               "spoon_1": ObjectState("spoon_1", node("spoon"))})
    w.step("mix", [*(ObjectState(ids[f], node(f, ("in", "bowl")), b, "in", consumed=True) for f, b in food.items()),
                   ObjectState("dressing_1", node("salad dressing", ("in", "bowl")), "bowl_1", "in")],
           uses=("spoon_1", "bowl_1", "bowl_2", "bowl_4", "bowl_7"), line=166)
    _chosen(w, "bowl_2", "bowl_4", "bowl_7")
    report = replay(w.trace())
    assert sorted(d.objects[:2] for d in report.disagreements if d.kind is K.CONSUMED_ELSEWHERE) == [
        ("salt_1", "bowl_7"), ("sour_cream_1", "bowl_2"), ("sugar_1", "bowl_4")]


def test_the_mix_after_the_milk_is_poured_in_passes():
    """The right late-bound plan: the unit names only the bowl it pours into; the milk leaves bowl_2, where it
    is, and the mix consumes it in bowl_1, where the mixture is made."""
    w = _kitchen((("bowl", "milk"), ("bowl", "egg mixture")))
    w.step("pour", [ObjectState("milk_1", MILK, "bowl_1", "in"), ObjectState("bowl_2", contents("bowl", [])),
                    ObjectState("bowl_1", contents("bowl", ["egg", "milk"]))], line=44)
    _mix_in_bowl_1(w)
    report = replay(_trace(w))
    assert report.ok, [str(d) for d in report.disagreements]


def _pour_from_bowl_2(changes: list[ObjectState], uses: tuple[str, ...], line: int):
    """The milk poured from bowl_2 into the pan, bowl_2 bound as a holder the effect left as it was (it still
    lists the milk: the pair (bowl, milk) is reported, so no bowl's list is checked); bowl_1 lists milk too."""
    w = World({"bowl_1": "bowl", "bowl_2": "bowl", "milk_1": "milk", "pan_1": "pan"},
              {"bowl_1": ObjectState("bowl_1", contents("bowl", ["milk"])),
               "bowl_2": ObjectState("bowl_2", contents("bowl", ["milk"])),
               "milk_1": ObjectState("milk_1", MILK, "bowl_2", "in"),
               "pan_1": ObjectState("pan_1", contents("pan", []))})
    w.step("pour", [ObjectState("milk_1", node("milk", ("in", "pan")), "pan_1", "in"),
                    ObjectState("pan_1", contents("pan", ["milk"])), *changes], uses=uses, line=line)
    step = w.steps[-1]
    if "bowl_2" not in step.objects:
        w.steps[-1] = replace(step, bindings=(*step.bindings, Binding("bowl_2", w.now["bowl_2"].node, None, role=False)))
    return replay(replace(w.trace(), gaps=(("bowl", "milk"),)))


def test_a_pour_from_another_bowl_than_the_one_the_step_empties_is_rejected():
    """The unit empties bowl_1, its bowl (`bowl (contains {milk})` -> `bowl (empty)`), into the pan, while the milk
    leaves bowl_2: it passed before; right when the step empties bowl_2, or names no bowl (FOON leaves it out)."""
    report = _pour_from_bowl_2([ObjectState("bowl_1", contents("bowl", []))], (), 60)
    assert [(d.kind, d.objects) for d in report.disagreements] == [(K.WRONG_SOURCE, ("milk_1", "bowl_2", "bowl_1"))]
    assert "pour: the step uses bowl_1, but milk_1 is in bowl_2" in str(report.disagreements[0])
    assert _pour_from_bowl_2([ObjectState("bowl_2", contents("bowl", []))], (), 60).ok
    assert _pour_from_bowl_2([], (), 60).ok


def test_a_bowl_the_step_names_but_leaves_as_it_is_is_no_source():
    """ACT-0003-blueberry_muffin.txt:220: the unit names a bowl of batter it leaves as it is, and the blueberry is
    poured from the bowl it is in (FOON's list of that bowl names no blueberry): right. So is the tomato slid
    from its own board onto the sandwich on the board the unit names (0061-club_sandwich.txt:232)."""
    assert _pour_from_bowl_2([], ("bowl_1",), 220).ok


def test_work_in_place_in_another_bowl_than_the_step_changes_is_rejected():
    """The mash changes bowl_1 (the unit's bowl) while the milk it works on sits in bowl_2: wrong with the pair
    reported too; right when the step changes bowl_2, or no bowl at all."""
    def whisk(*changed: str):
        w = _kitchen((("bowl", "milk"),))
        w.step("whisk", [ObjectState("milk_1", node("milk", "whisked", ("in", "bowl")), "bowl_2", "in"),
                         *(ObjectState(c, node("bowl", ("contains", [w.label(x) for x in w.now if w.now[x].holder == c]),
                                               "stirred")) for c in changed)], uses=("fork_1",))
        return replay(_trace(w))

    assert [(d.kind, d.objects) for d in whisk("bowl_1").disagreements] == [
        (K.HOLDER_NOT_BOUND, ("milk_1", "bowl_2", "bowl_1"))]
    assert whisk("bowl_2").ok and whisk().ok


def test_a_product_made_where_nothing_was_held_still_passes():
    """What stood free is consumed into a product anywhere (the rice wrapped into the onigiri on the plate)."""
    w = World({"rice_1": "rice", "plate_1": "plate", "onigiri_1": "onigiri"},
              {"rice_1": ObjectState("rice_1", node("rice", "cooked")),
               "plate_1": ObjectState("plate_1", contents("plate", []))})
    w.step("wrap", [ObjectState("rice_1", node("rice", "cooked"), consumed=True),
                    ObjectState("onigiri_1", node("onigiri", ("on", "plate")), "plate_1", "on"),
                    ObjectState("plate_1", contents("plate", ["onigiri"]))])
    assert replay(w.trace()).ok


def test_what_the_step_brings_to_its_product_passes():
    """0049-turkey_sandwich.txt:92: the slice on board_2 is lifted onto the other on board_1, making the sandwich
    there; ACT-0085-greek_salad_dressing.txt:72: the pour and stir takes the pepper from the measuring cup its
    unit names into the bowl where it makes the dressing."""
    w = World({"board_1": "cutting board", "board_2": "cutting board", "bread_1": "bread", "bread_2": "bread",
               "sandwich_1": "sandwich"},
              {"board_1": ObjectState("board_1", contents("cutting board", ["bread"])),
               "board_2": ObjectState("board_2", contents("cutting board", ["bread"])),
               **{b: ObjectState(b, node("bread", ("on", "cutting board")), h, "on")
                  for b, h in (("bread_1", "board_1"), ("bread_2", "board_2"))}})
    w.step("pick-and-place", [ObjectState("bread_1", node("bread", ("on", "cutting board")), "board_1", "on", consumed=True),
                              ObjectState("bread_2", node("bread", ("on", "cutting board")), "board_2", "on", consumed=True),
                              ObjectState("sandwich_1", node("sandwich", ("on", "cutting board")), "board_1", "on"),
                              ObjectState("board_1", contents("cutting board", ["sandwich"])),
                              ObjectState("board_2", contents("cutting board", []))])
    assert replay(w.trace()).ok

    def dressing(cup: str) -> set[K]:
        w = World({"cup_1": cup, "bowl_1": "bowl", "pepper_1": "pepper", "oil_1": "olive oil", "dressing_1": "dressing"},
                  {"cup_1": ObjectState("cup_1", contents(cup, ["pepper"])),
                   "bowl_1": ObjectState("bowl_1", contents("bowl", ["olive oil"])),
                   "pepper_1": ObjectState("pepper_1", node("pepper", ("in", cup)), "cup_1", "in"),
                   "oil_1": ObjectState("oil_1", node("olive oil", ("in", "bowl")), "bowl_1", "in")})
        w.step("pour and stir", [ObjectState("pepper_1", node("pepper", ("in", cup)), "cup_1", "in", consumed=True),
                                 ObjectState("oil_1", node("olive oil", ("in", "bowl")), "bowl_1", "in", consumed=True),
                                 ObjectState("dressing_1", node("dressing", ("in", "bowl")), "bowl_1", "in"),
                                 ObjectState("cup_1", contents(cup, [])),
                                 ObjectState("bowl_1", contents("bowl", ["dressing"]))])
        return set(replay(w.trace()).kinds())

    assert dressing("measuring cup") == set()
    assert dressing("bowl") == set()  # a unit over two bowls pours one into the other (0050's unit had one)
