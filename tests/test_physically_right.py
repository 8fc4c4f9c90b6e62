"""Dish tasks with more objects in `relational` than in `instances`, proved physically right: `instances`' own plan,
replayed object by object with holders tracked (`planners.instance_physical`), breaks where its count falls short,
and the relational task with that one object fewer has no plan."""

from __future__ import annotations

from conftest import SUBGRAPHS
from relational_checks import clean_plan, dish_goal

from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.planners.instance_physical import physical_trace
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.replay_findings import DisagreementKind
from foon2pddl.planners.solve import plan

BLOODY_MARY = SUBGRAPHS / "0076-bloody_mary.txt"


def _bloody_mary():
    foon, goal = dish_goal(BLOODY_MARY)
    return foon, default_kitchen(foon), goal


def test_the_bloody_marys_one_lemon_is_rolled_into_the_glass_and_squeezed_where_it_is_in_no_glass():
    foon, kitchen, goal = _bloody_mary()
    # `instances`' one lemon: the roll at 0076-bloody_mary.txt:1 leaves the glass `contains {lemon}` and the lemon's
    # node `lemon (halved)`, which both squeezes (:66, :74) take; replayed, the glass lists a lemon nothing in it
    # is, from the roll on
    theirs = plan(foon, kitchen, goal, "instances", time_limit=60)
    assert theirs.status == "solved" and [x.label for x in theirs.task.instances].count("lemon") == 1
    report = replay(physical_trace(theirs.task, theirs.trace).trace)
    missing = [d for d in report.disagreements if d.kind is DisagreementKind.MISSING_CONTENT and "lists lemon," in d.message]
    assert [(d.step, d.source.endswith("0076-bloody_mary.txt:1")) for d in missing] == [(0, True)], missing
    # relational: the rolled lemon is in the glass (`lemon (halved, in [highball glass])`) until the bloody mary
    # is made, so the squeezes take another: 11 objects, and with one lemon the search proves there is no plan
    ours = clean_plan(foon, kitchen, goal, time_limit=60)
    assert [x.label for x in ours.task.instances].count("lemon") == 2 and len(ours.task.objects) == 11
    assert plan(foon, kitchen, goal, "relational", time_limit=60, instances=(("lemon", 1),)).status == "unsolvable"
