"""Containers a unit empties, several of one label: the unit takes each object out of a holder in the node the unit
names, never out of one that lists more.

FOON-GEN's omelette pour (`0042-perfect_omelette.txt:79`, GEN trial 4, goal 92 of the experiment) takes
`plates and trays (contains {alliums})` and `plates and trays (contains {peppers})` and leaves both out of its
outputs. Emptied by a conditional effect on whichever plate held each, with no precondition on that plate's node,
the task let it pour the alliums and the peppers off one plate that a scrape had made `contains {alliums, peppers}`:
the plate kept that node with nothing on it, and the plan did not decode (`no plates and trays is plates and trays
(contains {alliums})`). Here the smallest such task, searched exhaustively."""

from __future__ import annotations

from node_words import contains, n
from task_search import explore

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.task import type_closure


def _on(holder: str):
    return make_state("on", holder)


PLATE, BOWL = n("plate", "empty"), n("bowl", "empty")
ONION_BOARD, ONION = n("board", contains("onion")), n("onion", "chopped", _on("board"))
PEPPER_BOARD, PEPPER = n("board", contains("pepper")), n("pepper", "chopped", _on("board"))
ONION_PLATE, PEPPER_PLATE = n("plate", contains("onion")), n("plate", contains("pepper"))
ONION_ON, PEPPER_ON = n("onion", "chopped", _on("plate")), n("pepper", "chopped", _on("plate"))
SALSA = n("bowl", contains("onion", "pepper"))
UNITS = (
    FunctionalUnit((ONION_BOARD, ONION, PLATE), Motion("scrape"), (ONION_PLATE, ONION_ON, n("board", "dirty"))),
    FunctionalUnit((PEPPER_BOARD, PEPPER, PLATE), Motion("scrape"), (PEPPER_PLATE, PEPPER_ON, n("board", "dirty"))),
    # the pepper scraped onto the onion's plate: a plate that lists both
    FunctionalUnit((PEPPER_BOARD, PEPPER, ONION_PLATE), Motion("scrape"),
                   (n("plate", contains("onion", "pepper")), PEPPER_ON, n("board", "dirty"))),
    # both plates left out of the outputs: emptied of what leaves them
    FunctionalUnit((ONION_PLATE, ONION_ON, PEPPER_PLATE, PEPPER_ON, BOWL), Motion("pour"), (SALSA,)),
)
LISTS = {"plate_empty": set(), "plate_contains_onion": {"onion"}, "plate_contains_pepper": {"pepper"},
         "plate_contains_onion_pepper": {"onion", "pepper"}}


def test_no_reachable_state_has_a_plate_listing_what_is_not_on_it():
    kitchen = Kitchen(frozenset({ONION_BOARD, ONION, PEPPER_BOARD, PEPPER, PLATE, BOWL}))
    task = compile_goal(Foon(UNITS), kitchen, Goal(GoalSpec("bowl"), (SALSA,)), "relational").task
    label = {x.name: x.label for x in task.instances}
    states, applied = explore(task, type_closure(task))
    # the pour applies, and a plate lists both in some reachable state: the case is reached
    assert "pour_u3" in applied and any("plate_contains_onion_pepper" in a.args for s in states for a in s)
    for s in states:
        for atom in s:
            if atom.predicate == "is" and atom.args[1] in LISTS:
                plate = atom.args[0]
                on_it = {label[a.args[1]] for a in s if a.predicate == "on" and a.args[0] == plate}
                assert on_it == LISTS[atom.args[1]], (plate, atom.args[1], sorted(on_it), sorted(map(str, s)))
