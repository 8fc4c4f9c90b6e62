"""0012's readings: an object a list drops that a later unit still takes there, and what a silent node hushed."""

from __future__ import annotations

from pathlib import Path

from node_words import contains, n
from relational_checks import clean_dish_plan, clean_unit_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.list_drops import kept_in_place
from foon2pddl.pddl.relational_plan import plan_unit
from foon2pddl.pddl.relational_touched import dustings

DATA = Path(__file__).parent / "data" / "foon-subgraphs"


def on(holder: str):
    return make_state("on", holder)


def _grill(order=(0, 1, 2)):
    """0012's grill: the spatula of cheese put on it, the spray (its list then names only the bread), the heat
    that takes the spatula on the grill and the grill listing it, each a line later in one recipe file."""
    grill_on = n("grill", "on")
    spatula = n("grill spatula", contains("cheese"), on("grill"))
    with_spatula = n("grill", "on", contains("grill spatula"))
    units = (FunctionalUnit((grill_on, n("grill spatula", contains("cheese"))), Motion("pick-and-place"),
                            (with_spatula, spatula)),
             FunctionalUnit((with_spatula, n("bread", "sliced")), Motion("spray"),
                            (n("grill", "on", contains("bread")), n("bread", on("grill")))),
             FunctionalUnit((with_spatula, spatula, n("cheese", on("grill spatula"))), Motion("heat"),
                            (spatula, n("cheese", "melted", on("grill spatula")))))
    return tuple(FunctionalUnit(u.inputs, u.motion, u.outputs, (Source("r.txt", 10 * (1 + order[k])),))
                 for k, u in enumerate(units))


def _plans(units):
    return {u: plan_unit(x, Kitchen(frozenset()), frozenset(), frozenset()) for u, x in enumerate(units)}


def test_a_list_drops_an_object_a_later_unit_still_takes_there_with_the_container_listing_it():
    units = _grill()
    plans = _plans(units)
    assert [f.label for f in plans[1].flows if f.into is None] == ["grill spatula"]  # holders rule 5: consumed
    kept, gaps = kept_in_place(Foon(units), range(3), plans)
    assert not kept[1].flows
    assert [(c, x, u) for c, x, _, u in gaps] == [("grill", "grill spatula", units[1])]
    assert "heat at r.txt:30 takes on [grill]: read as still in it" in gaps[0][2]
    # the heat earlier in the recipe than the spray is no evidence: the spatula may have gone by then
    early = _grill(order=(0, 2, 1))
    assert kept_in_place(Foon(early), range(3), _plans(early)) == (_plans(early), [])
    # nor a heat that takes the grill without listing the spatula
    bare = (*units[:2], FunctionalUnit((n("grill", "on"), *units[2].inputs[1:]), units[2].motion, units[2].outputs,
                                       units[2].sources))
    assert kept_in_place(Foon(bare), range(3), _plans(bare)) == (_plans(bare), [])


def test_what_a_node_lists_on_a_role_a_later_unit_leaves_silent_went_into_what_is_put_there_next():
    # 0012: the spray leaves `bread (contains {olive oil})` and `olive oil (on [bread])`; the flip leaves the bread
    # `toasted`, silent about what is on it; the scoop then puts the cheese on and the bread lists only cheese
    oil = n("olive oil", on("bread"))
    spray = FunctionalUnit((n("bread", "sliced"), n("olive oil", "liquid")), Motion("spray"),
                           (n("bread", contains("olive oil")), oil))
    flip = FunctionalUnit((n("bread", contains("olive oil")),), Motion("flip"), (n("bread", "toasted"),))
    plans = _plans((spray, flip))
    assert dustings([plans[0]]) == frozenset()
    assert dustings(plans.values()) == {oil}


def test_grilled_cheese_sandwich_is_solved_and_replay_clean():
    outcome = clean_dish_plan(DATA / "0012-grilled-grilled_cheese_sandwich.txt")
    assert any("grill leaves grill spatula out of its list, which heat at" in note for note in outcome.compiled.notes)


def test_a_node_on_the_grill_another_unit_made_is_no_evidence_the_object_stayed():
    # a universal FOON written as one file has every recipe in it: the spatula on the grill that the heat takes
    # must come from the unit that made the grill the spray takes, not from another unit earlier in the file
    grill_on, cheesy = n("grill", "on"), n("grill spatula", contains("cheese"))
    spatula = n("grill spatula", contains("cheese"), on("grill"))
    with_spatula = n("grill", "on", contains("grill spatula"))
    units = (FunctionalUnit((grill_on, cheesy), Motion("pick-and-place"), (with_spatula,)),
             FunctionalUnit((cheesy, n("grill", "off")), Motion("place"), (spatula, n("grill", "off"))),
             FunctionalUnit((with_spatula, n("bread", "sliced")), Motion("spray"),
                            (n("grill", "on", contains("bread")), n("bread", on("grill")))),
             FunctionalUnit((with_spatula, spatula, n("cheese", on("grill spatula"))), Motion("heat"),
                            (spatula, n("cheese", "melted", on("grill spatula")))))
    units = tuple(FunctionalUnit(u.inputs, u.motion, u.outputs, (Source("universal.txt", 10 * (1 + k)),))
                  for k, u in enumerate(units))
    plans = _plans(units)
    assert [f.label for f in plans[2].flows if f.into is None] == ["grill spatula"]
    assert kept_in_place(Foon(units), range(4), plans) == (plans, [])


def test_only_what_the_unit_making_the_hushed_node_made_beside_it_is_dust():
    # another unit's olive oil on bread (another recipe of a universal FOON) is not what the flip hushed
    oil = n("olive oil", on("bread"))
    spray = FunctionalUnit((n("bread", "sliced"), n("olive oil", "liquid")), Motion("spray"),
                           (n("bread", contains("olive oil")),))
    drizzle = FunctionalUnit((n("bread", "toasted"), n("olive oil", "liquid")), Motion("drizzle"),
                             (n("bread", "toasted", contains("olive oil", "salt")), oil))
    flip = FunctionalUnit((n("bread", contains("olive oil")),), Motion("flip"), (n("bread", "toasted"),))
    dust = dustings(_plans((spray, drizzle, flip)).values())
    assert [x.label for x in dust] == ["olive oil"] and oil not in dust  # the spray's own oil only


def _foil():
    """0010 (lines 218-243): the foil placed on the empty tray, the bread put on the tray (its list then names only
    the bread), the wrap that takes the foil sheet on the tray, as the place left it, and no node of the tray."""
    sheet, tray = n("aluminium foil", "sheet"), n("baking tray", "empty")
    on_tray = n("aluminium foil", "sheet", on("baking tray"))
    with_foil = n("baking tray", make_state("with", "aluminium foil"))
    bread = n("bread", contains("butter"), on("cutting board"))
    placed = n("bread", contains("butter"), on("baking tray"))
    units = (FunctionalUnit((sheet, tray), Motion("place"), (on_tray, with_foil)),
             FunctionalUnit((with_foil, bread), Motion("pick-and-place"),
                            (n("cutting board", "dirty"), n("baking tray", contains("bread")), placed)),
             FunctionalUnit((placed, on_tray), Motion("wrap"),
                            (n("aluminium foil", make_state("covering", "bread"), on("baking tray")),
                             n("bread", contains("butter"), make_state("covered", "aluminium foil"),
                               on("baking tray")))))
    return tuple(FunctionalUnit(u.inputs, u.motion, u.outputs, (Source("r.txt", 10 * (1 + k)),))
                 for k, u in enumerate(units))


def test_a_list_drops_an_object_a_later_unit_takes_there_with_no_node_of_the_container():
    # cheesy garlic bread (0010): read as part of the bread, the foil left the wrap needing a second sheet on a
    # second tray; on the universal FOON the trays were used up and search timed out
    units = _foil()
    plans = _plans(units)
    assert [f.label for f in plans[1].flows if f.into is None] == ["aluminium foil"]
    kept, gaps = kept_in_place(Foon(units), range(3), plans)
    assert not kept[1].flows
    assert gaps[0][2] == ("baking tray leaves aluminium foil out of its list, which wrap at r.txt:30 takes on "
                          "[baking tray]: read as still in it")
    sheet, tray, bread = units[0].inputs[0], units[0].inputs[1], units[1].inputs[1]
    outcome = clean_unit_plan(units, {sheet, tray, bread, n("cutting board", contains("bread"))}, units[2].outputs[1])
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["place", "pick-and-place", "wrap"]
