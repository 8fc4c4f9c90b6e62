"""`plan`'s gate for the count with makers by holder reach (`planners.solve.plan`'s `smallest`): when FOON's plan
counted small is out of holder reach, the task counted with makers chosen by holder reach is planned only when that
count is kept (`Compiled.narrowed`: fewer objects than the wide count); otherwise it is the wide task, planned after.

The omelette's shape of tests/test_relational_counted_through.py, its beaten egg made in the network: the muffin's
blend (first in FOON order: the egg's first maker) beats an egg in a pan of butter and sugar, the omelette's mix beats
it in the pan on the stove the cook takes, with a fork, a whisk and a towel. Counted from first makers (small: 12
objects, through the stitches: 12, wide: 15) no plan has the beaten egg in the cook's pan. With makers by holder
reach the plan with the mix and its three tools counts more than the plan from first makers, which the counting keeps
(the fewest-counting, `instance_counts.derive_counts`): the count is the wide one (15 objects, not narrowed). With
the fork alone the mix's plan is kept: 11 objects, narrowed."""

from __future__ import annotations

from node_words import contains, inside, n
from relational_checks import planned_counts
from test_relational_counted_through import DISH, KITCHEN, ON_STOVE, UNITS

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.planners.solve import plan

PAN_EGG, RAW, BEATEN = n("pan", contains("egg"), ON_STOVE), n("egg", inside("pan")), n("egg", "beaten", inside("pan"))
MUFFIN = n("pan", contains("butter", "egg", "sugar"))
TOOLS = (n("fork", "clean"), n("whisk", "clean"), n("towel", "clean"))
GOAL = Goal(GoalSpec("omelette"), (DISH,))


def omelette(tools: tuple = TOOLS) -> tuple[Foon, Kitchen]:
    """The network (the blend, the crack, the mix with `tools`, the counted-through omelette's units) and its
    kitchen: the counted-through omelette's, without the pan of beaten egg the crack and the mix make."""
    made = (FunctionalUnit((MUFFIN, RAW, n("hand mixer", "on")), Motion("blend"), (MUFFIN, BEATEN),
                           (Source("muffin.txt", 55),)),
            FunctionalUnit((n("pan", "empty", ON_STOVE), n("egg", "uncracked")), Motion("crack"), (PAN_EGG, RAW),
                           (Source("omelette.txt", 1),)),
            FunctionalUnit((PAN_EGG, RAW, *tools), Motion("mix"), (PAN_EGG, BEATEN), (Source("omelette.txt", 11),)))
    start = {MUFFIN, n("hand mixer", "on"), n("pan", "empty", ON_STOVE), n("egg", "uncracked"), *tools, *KITCHEN[2:]}
    return Foon(made + UNITS), Kitchen(frozenset(start))


def test_the_counts_of_the_omelette():
    def counted(tools: tuple = TOOLS, **options) -> tuple[int, bool]:
        out = compile_goal(*omelette(tools), GOAL, "relational", **options)
        return len(out.task.instances), bool(out.narrowed)

    assert counted(narrow=True) == (12, True)
    assert counted(narrow=True, through=True) == (12, True)
    assert counted(narrow=True, placed=True) == (15, False)  # the wide count: not kept
    assert counted() == (15, False)
    assert counted(TOOLS[:1], narrow=True, placed=True) == (11, True)  # the fork alone: kept


def test_a_count_with_makers_by_holder_reach_that_is_not_kept_is_not_planned(monkeypatch):
    planned = planned_counts(monkeypatch)
    outcome = plan(*omelette(), GOAL, "relational", time_limit=60)
    assert outcome.status == "unsolvable", outcome.message  # every count is out of holder reach
    # counted with makers by holder reach (compiled, not kept): the wide task, planned once, after the small ones;
    # counted wide with those makers it is the wide count again: that task, not planned again (`reached`)
    assert planned == ["small", "small through", "wide"]
