"""Relational readings that only the universal FOON (many recipes in one network) puts to the test: a name one
recipe uses for its own label must not be read as another recipe's longer label; and the bench of the universal floor."""

from __future__ import annotations

from conftest import SHARED
from node_words import contains, inside, n
from relational_checks import clean_unit_plan

from bench.pddl_relational import universal_rows
from foon2pddl.model.foon import FunctionalUnit, Motion
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.relational_plan import plan_unit
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

# 0077 (bread toast, line 70): milk poured out of a cup the unit does not name, and a later unit (line 113) still
# takes `milk (in [cup])`. Alone, the cup keeps its milk (a portion is poured). In the universal FOON a protein
# shake fills a *blender* cup with milk; `cup` was read as the head of `blender cup`, so the toast's cup was
# taken for a container units fill and emptied, while the second milk the later unit takes was still in it.
CUP, MILK = n("cup", contains("milk")), n("milk", inside("cup"))
BREAD = n("bread", "toasted")
SOAK = FunctionalUnit((BREAD, MILK), Motion("pour"), (n("bread", contains("milk"), "toasted"),))
KITCHEN = {CUP, MILK, BREAD}


def test_a_cup_is_not_read_as_a_blender_cup_when_the_task_has_cups():
    slot = plan_unit(SOAK, frozenset(KITCHEN), frozenset(), frozenset({("blender cup", "milk")}),
                     frozenset({"cup", "blender cup", "bread", "milk"})).slots[1]
    assert (str(slot.fate), slot.late_empties) == ("splits", False)  # the cup keeps its milk: a portion
    # with no `cup` label in the task, `cup` still reads as the blender cup the units fill (as before)
    slot = plan_unit(SOAK, frozenset(KITCHEN), frozenset(), frozenset({("blender cup", "milk")}),
                     frozenset({"blender cup", "bread", "milk"})).slots[1]
    assert (str(slot.fate), slot.late_empties) == ("moves", True)


def test_the_universal_bread_toast_is_clean(universal):
    foon, _ = universal
    dish = next(x for x in sorted(foon.nodes) if x.dish is not None and x.describe().startswith("bread toast"))
    outcome = plan(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational", time_limit=60)
    assert outcome.status == "solved", outcome.message
    assert replay(outcome.trace).ok


def test_the_bench_plans_the_universal_foons_reachable_dishes_in_order():
    # `python -m bench.pddl_relational --universal`: issue 21's universal floor, one row per goal and encoding
    rows = list(universal_rows(SHARED, 60.0, limit=1, encodings=("relational",)))
    assert [(r.file, r.encoding, r.status, r.kinds) for r in rows] == [
        ("barbecued ribs (cooked, on [baking tray])", "relational", "solved", ())]


def test_what_was_kneaded_into_an_object_leaves_the_unnamed_holder_with_it():
    # kofta (ACT-0054, lines 91-162; only the universal FOON makes its kofta mix, from ACT-0053): salt, paprika and
    # scallion are sprinkled onto the baking tray, kneaded into the kofta mix there, and the shape takes the mix
    # off a tray it does not name. The tray was emptied of the kofta mix only, so it still listed the paprika
    # that is in the mix (claimed twice). It is emptied of what the task's units put into the mix too.
    tray = n("baking tray", contains("dough"))
    dough = n("dough", inside("baking tray"))
    salted = n("baking tray", contains("dough", "salt"))
    salt_on = n("salt", "granulated", inside("baking tray"))
    sprinkle = FunctionalUnit((tray, n("bowl", contains("salt")), n("salt", "granulated", inside("bowl"))),
                              Motion("sprinkle"), (salted, salt_on))
    kneaded = n("dough", contains("salt"), inside("baking tray"), "kneaded")
    knead = FunctionalUnit((salted, dough, salt_on), Motion("knead"), (kneaded,))
    shaped = n("dough", contains("salt"), "shaped")
    shape = FunctionalUnit((kneaded,), Motion("shape"), (shaped,))
    outcome = clean_unit_plan((sprinkle, knead, shape), {tray, dough, *sprinkle.inputs[1:]}, shaped)
    assert outcome.trace.final["baking_tray_1"].node == n("baking tray", "empty")
