"""What a holder's new node drops with an object that leaves it goes with that object: a holder emptied by a unit
never keeps an object its new node does not list.

FOON-GEN's lentil kofta (the experiment's GEN trial 8, goals 46 and 57) stirs the bulgur out of a bowl the stir
does not name (`ACT-0053-lentil_kofta-1.txt:150`): the bowl `contains {grains, water and ice}` becomes `bowls
(empty)`, because other units put water into grains (what the task's units put into an object leaves its holder's
list with it, `Slot.along`). The kitchen's water sat in the bowl beside the bulgur, and the task let it stay there:
the plan ended with `water_and_ice_1 is in bowls_1, whose node 'bowls (empty)' lists nothing`, which the relational
replay rejects. Here the smallest tasks of that shape (the holder named or not, the object consumed or moved),
searched exhaustively."""

from __future__ import annotations

from dataclasses import replace

import pytest
from node_words import contains, inside, n
from task_search import explore

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.model.places import describes_contents, listed
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.task import type_closure

BAG, RICE_BAG = n("bag", contains("rice")), n("rice", "uncooked", inside("bag"))
CUP, WATER_CUP = n("cup", contains("water")), n("water", inside("cup"))
EMPTY, FILLED = n("bowl", "empty"), n("bowl", contains("rice"))
RICE, BOTH, WATER = n("rice", "uncooked", inside("bowl")), n("bowl", contains("rice", "water")), n("water", inside("bowl"))
POT, BROTH, SPOON = n("pot", contains("broth")), n("broth", inside("pot")), n("spoon", "clean")
SOUP, PLATE = n("soup", contains("broth", "rice"), inside("pot")), n("plate", "empty")
FILL = FunctionalUnit((EMPTY, BAG, RICE_BAG), Motion("pour"), (FILLED, RICE, n("bag", "empty")), (Source("r.txt", 1),))
WET = FunctionalUnit((FILLED, CUP, WATER_CUP), Motion("pour"), (BOTH, WATER, n("cup", "empty")), (Source("r.txt", 9),))
# water put into the rice: what leaves a bowl with the rice leaves its list with it
SOAK = FunctionalUnit((FILLED, RICE, CUP, WATER_CUP), Motion("soak"),
                      (BOTH, n("rice", "uncooked", contains("water"), inside("bowl")), n("cup", "empty")),
                      (Source("r.txt", 17),))
KITCHEN = frozenset({BAG, RICE_BAG, CUP, WATER_CUP, EMPTY, POT, BROTH, SPOON, PLATE})
# the stir names the bowl (emptied, FOON leaves it out of the outputs); the kofta's names none (the pour before it
# leaves the rice `in [bowl]`, as ACT-0053:134 leaves the bulgur); a pick-and-place moves the rice off the bowl
NAMED = (FunctionalUnit((POT, BOTH, RICE, BROTH, SPOON), Motion("stir"), (n("pot", contains("soup")), SOUP),
                        (Source("r.txt", 25),)),)
UNNAMED = (FunctionalUnit((POT, BOTH, RICE), Motion("pour"), (n("pot", contains("broth", "rice")), RICE),
                          (Source("r.txt", 33),)),
           FunctionalUnit((n("pot", contains("broth", "rice")), RICE, BROTH, SPOON), Motion("stir"),
                          (n("pot", contains("soup")), SOUP), (Source("r.txt", 25),)))
MOVED = (FunctionalUnit((PLATE, RICE, n("cup", "empty")), Motion("pick-and-place"),
                        (n("plate", contains("rice")), n("rice", "uncooked", inside("plate")), n("cup", "empty")),
                        (Source("r.txt", 41),)),)


@pytest.mark.parametrize(("last", "goal"), [(NAMED, SOUP), (UNNAMED, SOUP), (MOVED, MOVED[0].outputs[1])],
                         ids=["consumed-named", "consumed-unnamed", "moved-unnamed"])
def test_no_reachable_state_has_a_bowl_holding_what_its_node_does_not_list(last, goal):
    task = compile_goal(Foon((FILL, WET, SOAK, *last)), Kitchen(KITCHEN), Goal(GoalSpec(goal.label), (goal,)),
                        "relational").task
    task = replace(task, init=task.initial_facts)  # the objects set aside too (the water no role names)
    label = {x.name: x.label for x in task.instances}
    node = dict(task.nodes)
    states, applied = explore(task, type_closure(task))
    # the case is reached: the water poured in beside the rice, and the rice taken out of that bowl
    assert any(a.predicate == "is" and node.get(a.args[1]) == BOTH for s in states for a in s)
    assert any(a.name.startswith(("stir", "pick-and-place")) for a in task.actions if a.name in applied)
    made = [s for s in states if any(a.predicate == "is" and node.get(a.args[1]) == goal for a in s)]
    assert made
    for s in states:
        for atom in s:
            if atom.predicate == "is" and label.get(atom.args[0]) == "bowl" and describes_contents(
                    here := node.get(atom.args[1])):
                bowl = atom.args[0]
                held = {label[a.args[1]] for a in s if a.predicate == "in" and a.args[0] == bowl}
                assert held <= listed(here), (bowl, here.describe(), sorted(held), sorted(map(str, s)))
