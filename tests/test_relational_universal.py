"""Relational readings that only the universal FOON (many recipes in one network) puts to the test: a name one
recipe uses for its own label must not be read as another recipe's longer label; and the bench of the universal floor."""

from __future__ import annotations

from conftest import SHARED
from node_words import contains, inside, n

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
