"""`planners.copies`: objects of one kitchen node a plan uses one after another where one would do."""

from __future__ import annotations

from dataclasses import replace

from node_words import n

from foon2pddl.model.foon import FunctionalUnit, Motion
from foon2pddl.model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, TraceStep
from foon2pddl.planners.copies import at_once, busy, copies

CLEAN, DIRTY = n("knife", "clean"), n("knife", "dirty")
ONION, CUT = n("onion", "whole"), n("onion", "chopped")
FLOUR_BOWL, SUGAR_BOWL = n("bowl", "flour"), n("bowl", "sugar")
CUTS = FunctionalUnit((CLEAN, ONION), Motion("slice"), (DIRTY, CUT))


def _trace(steps: list[list[tuple[str, bool]]], consumed: frozenset[str] = frozenset()) -> PhysicalTrace:
    """Objects knife_1..3 (clean), onion_1..3, bowl_1 (flour), bowl_2 (sugar); per step the objects bound
    (as a role or not); `consumed`: objects a step consumes."""
    start = {"knife_1": CLEAN, "knife_2": CLEAN, "knife_3": CLEAN, "onion_1": ONION, "onion_2": ONION,
             "onion_3": ONION, "bowl_1": FLOUR_BOWL, "bowl_2": SUGAR_BOWL}
    out = [TraceStep(k, CUTS, tuple(Binding(x, start[x], None, role) for x, role in bound),
                     tuple(ObjectState(x, start[x], consumed=True) for x, _ in bound if x in consumed))
           for k, bound in enumerate(steps)]
    return PhysicalTrace(tuple(PhysicalObject(x, node.label) for x, node in start.items()),
                         tuple(ObjectState(x, node) for x, node in start.items()), tuple(out))


def test_objects_of_one_kitchen_node_used_one_after_another_are_copies():
    trace = _trace([[("knife_1", True)], [("knife_2", True)], [("knife_1", True), ("knife_3", True)]])
    assert at_once(trace)[CLEAN] == 2  # knife_1 is in use from step 0 to step 2, knife_3 at step 2
    assert copies(trace) == {"knife": 1}


def test_consumed_objects_other_kitchen_nodes_and_bindings_that_are_no_role_are_no_copies():
    trace = _trace([[("onion_1", True), ("bowl_1", True)], [("onion_2", True), ("bowl_2", True)],
                    [("knife_1", True)], [("knife_2", False)]], consumed=frozenset({"onion_1", "onion_2"}))
    assert copies(trace) == {}


def test_busy_holds_an_object_to_the_end_when_it_is_consumed_or_left_where_it_cannot_be_turned_back():
    trace = _trace([[("knife_1", True)], [("knife_2", True)], [("knife_3", True)]])
    assert busy(trace, lambda node, start: True) == {CLEAN: 1}  # one after another, each turned back
    consumed = _trace([[("knife_1", True)], [("knife_2", True)]], consumed=frozenset({"knife_1"}))
    assert busy(consumed, lambda node, start: True) == {CLEAN: 2}  # knife_1 is gone: knife_2 is a second one
    assert busy(trace, lambda node, start: False) == {CLEAN: 1}  # no change: each stays clean, free again
    dirtied = PhysicalTrace(trace.objects, trace.initial, tuple(
        replace(s, changes=(ObjectState(s.bindings[0].object, DIRTY),)) for s in trace.steps))
    assert busy(dirtied, lambda node, start: (node, start) == (DIRTY, CLEAN)) == {CLEAN: 1}  # washed in between
    assert busy(dirtied, lambda node, start: False) == {CLEAN: 3}  # left dirty with no wash: three knives
