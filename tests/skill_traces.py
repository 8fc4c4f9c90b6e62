"""Hand-built physical traces for the skill tests (what the relational encoding gives: objects, holders,
states per step), so the expected skills follow from the trace alone."""

from __future__ import annotations

from foon2pddl.model.foon import FunctionalUnit, Motion, Source, make_node, make_state
from foon2pddl.model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, Relation, TraceStep
from foon2pddl.skills.domain import shipped_domain
from foon2pddl.skills.micro import Naming, micro_problem

IN, ON = Relation.IN, Relation.ON


def node(label, *states):
    return make_node(label, [make_state(s) for s in states])


def unit(motion, line):
    return FunctionalUnit((), Motion(motion), (), (Source("r.txt", line),))


def trace(objects, initial, steps):
    """objects: {id: label}; initial: [ObjectState]; steps: [(motion, [ObjectState changes], [bound ids])]."""
    out = [TraceStep(k, unit(m, 10 * (k + 1)), tuple(Binding(b, None, None) for b in bound), tuple(changes),
                     f"r.txt:{10 * (k + 1)}") for k, (m, changes, bound) in enumerate(steps)]
    return PhysicalTrace(tuple(PhysicalObject(i, lab) for i, lab in objects.items()), tuple(initial), tuple(out))


ONION_WHOLE, ONION_CHOPPED = node("onion", "whole"), node("onion", "chopped")
KNIFE, BOARD, BOWL, CUP, SPOON = node("knife"), node("cutting board"), node("bowl"), node("cup"), node("spoon")
WATER = node("water", "liquid")


def kitchen_trace(*steps):
    objects = {"onion_1": "onion", "knife_1": "knife", "board_1": "cutting board", "bowl_1": "bowl",
               "cup_1": "cup", "water_1": "water", "spoon_1": "spoon", "salad_1": "salad"}
    initial = [ObjectState("onion_1", ONION_WHOLE, "board_1", ON), ObjectState("knife_1", KNIFE),
               ObjectState("board_1", BOARD), ObjectState("bowl_1", BOWL), ObjectState("cup_1", CUP),
               ObjectState("water_1", WATER, "cup_1", IN), ObjectState("spoon_1", SPOON), ObjectState("salad_1")]
    return trace(objects, initial, steps)


CHOP = ("chop", [ObjectState("onion_1", ONION_CHOPPED, "board_1", ON)], ["onion_1", "knife_1", "board_1"])
POUR = ("pour", [ObjectState("water_1", WATER, "bowl_1", IN)], ["water_1", "cup_1", "bowl_1"])
MOVE = ("pick-and-place", [ObjectState("onion_1", ONION_CHOPPED, "bowl_1", IN)], ["onion_1", "bowl_1"])
MIX = ("mix", [ObjectState("onion_1", ONION_CHOPPED, consumed=True), ObjectState("water_1", WATER, consumed=True),
               ObjectState("salad_1", node("salad", "mixed"), "bowl_1", IN)],
       ["onion_1", "water_1", "bowl_1", "spoon_1", "salad_1"])


def skills(plan):
    return [(c.skill, c.objects) for c in plan.calls]


def targets(t, skill):
    problem = micro_problem(t, 0, skill, Naming(t, shipped_domain(), 1), shipped_domain())
    return sorted(a.args[1] for a in problem.init if a.predicate == "target")
