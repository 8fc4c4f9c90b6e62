"""A holder bound late must exist when bound (`pddl/live_holders.py`): the planner may not put an object on one it
consumed earlier."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import clean_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.render import render
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan

# The club sandwich on the universal FOON of the even-index subgraphs: the bacon is `on [bread]`
# (`0061-club_sandwich.txt:196`) in a unit that names no bread, and the planner bound it to the bread the step before
# had consumed into the sandwich (`holder-gone`). Here the spread puts the butter `on [bread]` beside a sandwich whose
# output node does not list the butter: the bread is bound late.
BREAD, HAM = n("bread", "sliced"), n("ham", "sliced")
SANDWICH = n("sandwich", contains("bread", "ham"))
ASSEMBLE = FunctionalUnit((BREAD, HAM), Motion("assemble"), (SANDWICH,), (Source("club.txt", 150),))
BOWL, BUTTER = n("bowl", contains("butter")), n("butter", inside("bowl"))
SPREAD = FunctionalUnit((BUTTER, BOWL, SANDWICH), Motion("spread"),
                        (n("butter", make_state("on", "bread")), n("sandwich", contains("bread", "ham"), "wrapped"),
                         n("bowl", "empty")), (Source("club.txt", 196),))
GOAL = Goal(GoalSpec("butter"), (SPREAD.outputs[0],))


def test_a_late_bound_holder_the_plan_consumed_is_not_bound():
    # one bread, consumed into the sandwich before the spread: no bread exists to hold the butter (before, the plan
    # put it on the consumed bread, and its replay found `holder-gone`)
    outcome = plan(Foon((ASSEMBLE, SPREAD)), Kitchen(frozenset({BREAD, HAM, BOWL, BUTTER})), GOAL, "relational",
                   time_limit=20)
    assert outcome.status == "unsolvable", (outcome.status, outcome.message)
    domain, _ = render(outcome.task)
    assert "(live ?bread_here)" in domain  # the late-bound target's precondition


def test_a_late_bound_holder_is_one_that_exists():
    kitchen = Kitchen(frozenset({BREAD, HAM, BOWL, BUTTER}), counts=((BREAD, 2),))
    outcome = clean_plan(Foon((ASSEMBLE, SPREAD)), kitchen, GOAL, time_limit=20)
    spread = outcome.trace.steps[-1]
    holder = next(o.holder for o in spread.changes if o.id.startswith("butter"))
    consumed = {o.id for s in outcome.trace.steps[:-1] for o in s.changes if o.consumed}
    assert spread.unit.motion.label == "spread" and holder.startswith("bread") and holder not in consumed
    assert replay(outcome.trace).ok
