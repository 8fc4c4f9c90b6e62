"""Native task trees scheduled over a kitchen's objects: answers known by hand on small networks."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from physical_world import node as n

from foon2pddl.model.dedupe import dedupe_units
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.tasktree import TaskTree
from foon2pddl.planners.executable import Verdict, needed, schedule
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.replay_findings import DisagreementKind as K
from foon2pddl.retrieval.api import retrieve


def unit(motion, ins, outs, line=1):
    return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs), (Source("r.txt", line),))


BREAD, SLICE, BUTTERED = n("bread", "whole"), n("bread", "sliced"), n("bread", "buttered")
CLEAN, DIRTY, BUTTER, FAUCET = n("knife", "clean"), n("knife", "dirty"), n("butter", "soft"), n("faucet")
CUT = unit("cut", [BREAD, CLEAN], [SLICE, DIRTY], 5)
SPREAD = unit("spread", [SLICE, BUTTER, CLEAN], [BUTTERED, DIRTY], 9)
WASH = unit("wash", [DIRTY, FAUCET], [CLEAN, FAUCET], 13)
KNIFE_KITCHEN = frozenset({BREAD, CLEAN, BUTTER, FAUCET})


def test_one_knife_runs_short_at_the_spread_unless_washed_or_doubled():
    tree = TaskTree((CUT, SPREAD), BUTTERED)
    got = schedule(tree, KNIFE_KITCHEN)
    assert (got.verdict, got.step, got.label, got.node) == (Verdict.SHORT, 1, "knife", CLEAN)
    assert "step 2 (spread)" in got.message and "one more knife in 'knife (clean)'" in got.message
    assert schedule(tree, KNIFE_KITCHEN, {"knife": 2}).ok
    assert schedule(tree, KNIFE_KITCHEN, per_item=2).ok
    washed = schedule(TaskTree((CUT, WASH, SPREAD), BUTTERED), KNIFE_KITCHEN)
    assert washed.ok and dict(washed.drawn)[CLEAN] == 1
    assert [b.object for b in washed.trace.steps[2].bindings] == ["bread_1", "butter_1", "knife_1"]
    assert dict(needed(tree, KNIFE_KITCHEN).drawn) == {BREAD: 1, CLEAN: 2, BUTTER: 1}


def test_only_what_is_counted_limits_when_uncounted_is_no_limit():
    """`cli/reasons.short_step` (a count stated too low, `--instances knife=1`) gave every other label "plenty" of
    objects by hand, as `schedule` had no such mode: `uncounted=None` is it. A label `counts` names, and a node
    the kitchen states, still limit; every other kitchen node has as many objects as the tree draws."""
    tree = TaskTree((CUT, SPREAD), BUTTERED)
    assert schedule(tree, KNIFE_KITCHEN, {"bread": 1}, uncounted=None).ok  # the knife is not counted
    short = schedule(tree, KNIFE_KITCHEN, {"knife": 1}, uncounted=None)
    assert (short.verdict, short.step, short.label) == (Verdict.SHORT, 1, "knife")
    stated = schedule(tree, KNIFE_KITCHEN, uncounted=None, stated={CLEAN: 1})
    assert (stated.verdict, stated.label) == (Verdict.SHORT, "knife")
    assert schedule(tree, KNIFE_KITCHEN, uncounted=None).drawn == needed(tree, KNIFE_KITCHEN).drawn
    assert dict(schedule(tree, KNIFE_KITCHEN, uncounted=2).drawn)[CLEAN] == 2


# A salad and its dressing in two bowls at once, then combined into the first.
EMPTY = n("bowl", "empty")
LETTUCE, DRESSING = n("lettuce", "chopped"), n("oil")
L_IN, D_IN = n("lettuce", "chopped", ("in", "bowl")), n("oil", ("in", "bowl"))
B_L, B_D, B_LD = n("bowl", ("contains", ["lettuce"])), n("bowl", ("contains", ["oil"])), n("bowl", ("contains", ["lettuce", "oil"]))
SALAD = n("salad", ("in", "bowl"))
PUT_L = unit("put", [LETTUCE, EMPTY], [L_IN, B_L])
PUT_D = unit("pour", [DRESSING, EMPTY], [D_IN, B_D])
COMBINE = unit("pour", [D_IN, B_D, B_L], [n("oil", ("in", "bowl")), EMPTY, B_LD])
MIX = unit("mix", [L_IN, D_IN, B_LD], [SALAD, n("bowl", ("contains", ["salad"]))])
SALAD_KITCHEN = frozenset({EMPTY, LETTUCE, DRESSING})


def test_two_bowls_at_once():
    tree = TaskTree((PUT_L, PUT_D, COMBINE, MIX), SALAD)
    got = schedule(tree, SALAD_KITCHEN)
    assert (got.verdict, got.step, got.label) == (Verdict.SHORT, 1, "bowl")
    ok = schedule(tree, SALAD_KITCHEN, {"bowl": 2})
    assert ok.ok and dict(needed(tree, SALAD_KITCHEN).drawn)[EMPTY] == 2
    final = ok.trace.final
    assert final["lettuce_1"].consumed and final["oil_1"].consumed and final["salad_1"].exists
    assert len(ok.trace.steps) == 4 and replay(ok.trace).disagreements  # no holders: the replay sees that


def test_the_emptied_bowl_is_free_again():
    """After the pour one bowl is `bowl (empty)` again (by FOON's pairing, the first: the input listed first
    among equally similar ones becomes the fuller output): a later unit needing an empty bowl reuses it."""
    again = unit("put", [n("tomato"), EMPTY], [n("tomato", ("in", "bowl")), n("bowl", ("contains", ["tomato"]))])
    tree = TaskTree((PUT_L, PUT_D, COMBINE, again), SALAD)
    got = schedule(tree, SALAD_KITCHEN | {n("tomato")}, {"bowl": 2})
    assert got.ok and dict(got.drawn)[EMPTY] == 2
    assert got.trace.final["bowl_2"].node == B_LD
    assert got.trace.steps[3].bindings[1].object == "bowl_1"


def test_an_intermediate_needed_twice_is_used_up():
    whole, chopped, fried = n("onion", "whole"), n("onion", "chopped"), n("onion", "fried")
    chop = unit("chop", [whole], [chopped])
    fry = unit("fry", [chopped], [fried])
    stew = unit("stew", [chopped], [n("stew")])
    got = schedule(TaskTree((chop, fry, stew), n("stew")), {whole})
    assert (got.verdict, got.step, got.label, got.node) == (Verdict.USED_UP, 2, "onion", chopped)
    assert "but step 2 moved the onion on" in got.message and "must fire again" in got.message
    missing = schedule(TaskTree((fry,), fried), {whole})
    assert (missing.verdict, missing.step) == (Verdict.MISSING, 0)


def test_kitchen_counts_apply_per_node():
    """`counts` is per kitchen node of the label (as `--instances bowl=3`): two bowl nodes, one object each."""
    clean_bowl = n("bowl", "clean")
    u1 = unit("use", [EMPTY], [n("bowl", "dirty")])
    u2 = unit("use", [clean_bowl], [n("bowl", "dirty")])
    got = schedule(TaskTree((u1, u2), n("bowl", "dirty")), {EMPTY, clean_bowl})
    assert got.ok and [o.id for o in got.trace.objects] == ["bowl_1", "bowl_2"]


# ---- properties on random networks: the schedule's own bookkeeping, checked by the replay, and monotonicity

POOL = [n("a"), n("b"), n("b", "cut"), n("c", ("in", "b")), n("d"), n("e", "mixed"), n("f"), n("f", "dirty")]


@st.composite
def trees(draw):
    ins = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    outs = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    units = draw(st.lists(st.tuples(ins, st.sampled_from(["chop", "mix", "pour"]), outs), min_size=2, max_size=8))
    foon = Foon(dedupe_units(FunctionalUnit(tuple(i), Motion(m), tuple(o)) for i, m, o in units))
    kitchen = frozenset(foon.nodes) - set(foon.producers) | set(draw(st.lists(st.sampled_from(POOL), max_size=2)))
    goal = draw(st.sampled_from(sorted(foon.producers)))
    return retrieve(foon, kitchen, Goal(GoalSpec("goal"), (goal,), 3)).tree, kitchen


BOOKKEEPING = {K.UNBOUND_CHANGE, K.NOT_AVAILABLE, K.REMADE, K.STATE_MISMATCH}


@settings(max_examples=200, deadline=None)
@given(trees())
def test_schedules_are_consistent_and_more_objects_never_hurt(case):
    tree, kitchen = case
    if tree is None:
        return
    got = schedule(tree, kitchen)
    assert not replay(got.trace).kinds() & BOOKKEEPING
    assert got.ok or (got.step is not None and got.label and got.node is not None and got.message)
    if got.ok:
        assert schedule(tree, kitchen, per_item=3).ok
    if got.verdict is Verdict.SHORT:
        assert schedule(TaskTree(tree.units[:got.step], tree.goal), kitchen).ok
    need = needed(tree, kitchen)
    assert need.verdict is not Verdict.SHORT
    if need.ok:
        counts = {}
        for node_, k in need.drawn:
            counts[node_.label] = max(counts.get(node_.label, 0), k)
        assert schedule(tree, kitchen, counts).ok
    assert got.verdict in (Verdict.EXECUTABLE, Verdict.SHORT) or got.verdict is need.verdict
