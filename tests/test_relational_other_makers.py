"""`count_plans._chosen` bounded (`most`, what `_other_makers` keeps of a swap: no more units than the plan, alone or
tried together): the walk stops once the plan it builds has more units, and gives the plan it gives unbounded
otherwise; and the one rule a swap is kept by (`_fewer_units`), alone and together."""

from __future__ import annotations

from node_words import n as node

from foon2pddl.analysis.reachability import reachable
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.count_plans import _chosen, _other_makers
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


def test_swaps_tried_together_pull_in_nothing_new_as_one_swap_must():
    """One rule for a swap (`count_plans._fewer_units`), alone and on the plan with the swaps kept before: there,
    a swap that keeps the plan's length is one unit for one taking only some of its inputs. Here the first swap (the
    fry for the cut: no grating) keeps the wash, so the second (the rub for the fry of q) is one for one on that plan,
    and the rub takes the sponge the fry does not: left, where the looser test of swaps together kept it."""
    def unit(ins, motion, outs):
        return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs))

    peel = unit([node("q", "whole")], "peel", [node("q", "raw")])
    wash = unit([node("pan", "dirty"), node("sponge")], "wash", [node("pan", "clean"), node("sponge")])
    grate = unit([node("x", "raw"), node("grater")], "grate", [node("x", "ready"), node("grater")])
    cut = unit([node("p", "raw"), node("x", "ready")], "cut", [node("p", "ready"), node("x", "ready")])
    fry_q = unit([node("q", "raw"), node("pan", "clean"), node("y")], "fry", [node("q", "ready"), node("pan", "clean"), node("y")])
    fry_p = unit([node("p", "raw"), node("pan", "clean")], "fry", [node("p", "ready"), node("pan", "clean")])
    rub = unit([node("q", "raw"), node("sponge")], "rub", [node("q", "ready"), node("sponge")])
    serve = unit([node("p", "ready"), node("q", "ready")], "serve", [node("dish")])
    units = (peel, wash, grate, cut, fry_q, fry_p, rub, serve)
    kitchen = [node("q", "whole"), node("pan", "dirty"), node("sponge"), node("x", "raw"), node("grater"), node("p", "raw"), node("y")]
    reach = reachable(Foon(units), kitchen, [node("dish")])

    def taken(plan, target):  # a stand-in for the objects counted: the kitchen nodes the plan's units take
        return len({a for u in plan for a in reach.index.inputs[u] if reach.node_round[a] == 0})

    named = [[units[u].motion.label + ("" if units[u] is not fry_q else " q") for u in p]
             for p in (_chosen(reach, node("dish"), True, False), *_other_makers(reach, node("dish"), True, False, taken))]
    assert named == [["grate", "peel", "wash", "cut", "fry q", "serve"],  # first achievers: 7 kitchen nodes
                     ["peel", "wash", "fry", "fry q", "serve"],  # 5: no grating
                     ["grate", "peel", "cut", "rub", "serve"]]  # 5: no washing; not both (4: the rub takes the sponge)
