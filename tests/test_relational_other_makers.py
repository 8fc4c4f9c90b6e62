"""`count_plans._chosen` bounded (`most`, what `_other_makers` keeps of a swap: no more units than the plan, or two
more when swaps are tried together): the walk stops once the plan it builds has more units, and gives the plan
it gives unbounded otherwise."""

from __future__ import annotations

from foon2pddl.analysis.reachability import reachable
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.count_plans import _chosen
from foon2pddl.pddl.count_together import needs


def test_a_bounded_walk_gives_the_unbounded_plan_or_none_when_that_is_longer(universal):
    # every swap `_other_makers` tries for three universal dishes (the 0050 omelette, whose swaps count fewer,
    # among them), each walked unbounded and bounded one unit short of and at its length
    foon = universal[0]
    kitchen = default_kitchen(foon).nodes
    dishes = [x for x in sorted(foon.dishes)
              if x.describe().startswith(("omelette (contains {bacon", "hamburger", "garlic bread (baked"))]
    tried = stopped = 0
    for dish in dishes:
        candidates = resolve_goal(spec_of_node(dish), foon).candidates
        reach = reachable(foon, kitchen, candidates)
        target = min((c for c in candidates if reach.can_make(c)), key=lambda c: (reach.round_of(c), c))
        made: dict[int, int] = {}
        plan = _chosen(reach, target, True, False, made_by=made)
        assert _chosen(reach, target, True, False, most=len(plan)) == plan
        assert _chosen(reach, target, True, False, most=len(plan) - 1) is None
        for n, u in sorted(made.items()):
            for m in reach.index.makers[n]:
                if m == u or reach.unit_round[m] < 0 or needs(reach, m, {n}):
                    continue
                whole = _chosen(reach, target, True, False, preset={n: m})
                for most in (len(whole) - 1, len(whole), len(plan)):
                    bounded = _chosen(reach, target, True, False, preset={n: m}, most=most)
                    assert bounded == (whole if len(whole) <= most else None), (n, m, most)
                    stopped += bounded is None
                tried += 1
    assert len(dishes) >= 3 and tried >= 20 and stopped > tried
