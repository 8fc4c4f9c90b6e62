"""Whether a made object leaves a holder the unit does not name whole (`relational_plan.plan_unit`: no node of the
task lists its label in a holder of that label) is read through the task's aliases (`holder_words.task_aliases`),
as the count reads a late emptying (`relational_plan.late_emptied`): a place written `in [pan]` in a task whose
pan is `cooking pan` names the cooking pan, so the task is the one its label written out gives."""

from __future__ import annotations

from node_words import contains, inside, n

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.compile import compile_goal

ON = lambda holder: make_state("on", holder)  # noqa: E731
DISH = n("plate", contains("egg"))


def _units(place: str) -> tuple[tuple[FunctionalUnit, ...], tuple]:
    """The cook makes the egg `in [place]` in the cooking pan, which lists it before and after; the pick-and-place
    takes it onto a plate without naming the pan (a pan no unit fills with egg: the pan's own name decides)."""
    raw, cooked = n("egg", "raw", inside(place)), n("egg", "cooked", inside(place))
    pan = n("cooking pan", contains("egg"))
    units = (FunctionalUnit((raw, pan, n("stove", "on")), Motion("cook"), (cooked, pan)),
             FunctionalUnit((cooked, n("plate", "empty")), Motion("pick-and-place"),
                            (n("egg", "cooked", ON("plate")), DISH)))
    return units, (raw, pan, n("stove", "on"), n("plate", "empty"))


def _labels(place: str, **options) -> list[str]:
    units, kitchen = _units(place)
    task = compile_goal(Foon(units), Kitchen(frozenset(kitchen)), Goal(GoalSpec("plate"), (DISH,)), "relational",
                        **options).task
    return sorted(x.label for x in task.instances)


def test_a_holder_named_by_an_alias_is_read_as_its_label():
    for options in ({"narrow": True}, {}):
        assert _labels("pan", **options) == _labels("cooking pan", **options)
