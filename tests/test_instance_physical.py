"""`instances` plans as physical traces: holders inferred by tracking, then judged by the physical replay."""

from __future__ import annotations

from physical_world import node as n

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.model.pairing import unit_roles
from foon2pddl.model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, TraceStep
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.instance_replay import instance_trace
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Instance, PlanningTask
from foon2pddl.planners import fd
from foon2pddl.planners.instance_physical import HolderEvidence as E
from foon2pddl.planners.instance_physical import physical_trace
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.replay_findings import DisagreementKind as K


def unit(motion, ins, outs, line=1):
    return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs), (Source("brine.txt", line),))


WATER_CUP, CUP_FULL, BOWL_EMPTY = n("water", ("in", "cup")), n("cup", ("contains", ["water"])), n("bowl", "empty")
WATER_BOWL, CUP_EMPTY, BOWL_W = n("water", ("in", "bowl")), n("cup", "empty"), n("bowl", ("contains", ["water"]))
SALT_SHAKER, SHAKER_FULL = n("salt", ("in", "shaker")), n("shaker", ("contains", ["salt"]))
SALT_BOWL, SHAKER_EMPTY = n("salt", ("in", "bowl")), n("shaker", "empty")
BOWL_WS, SPOON = n("bowl", ("contains", ["salt", "water"])), n("spoon")
BRINE, BOWL_B = n("brine", ("in", "bowl")), n("bowl", ("contains", ["brine"]))
POUR_WATER = unit("pour", [WATER_CUP, CUP_FULL, BOWL_EMPTY], [WATER_BOWL, CUP_EMPTY, BOWL_W], 10)
POUR_SALT = unit("pour", [SALT_SHAKER, SHAKER_FULL, BOWL_W], [SALT_BOWL, SHAKER_EMPTY, BOWL_WS], 20)
MIX = unit("mix", [WATER_BOWL, SALT_BOWL, BOWL_WS, SPOON], [BRINE, BOWL_B, SPOON], 30)
BRINE_FOON = Foon((POUR_WATER, POUR_SALT, MIX))
BRINE_KITCHEN = Kitchen(frozenset({WATER_CUP, CUP_FULL, BOWL_EMPTY, SALT_SHAKER, SHAKER_FULL, SPOON}))


def test_planned_brine_is_physically_consistent():
    """Pour water, pour salt, mix: every holder follows from the units; the mix consumes water and salt."""
    task = compile_task(BRINE_FOON, BRINE_KITCHEN, Goal(GoalSpec("brine"), (BRINE,)), "instances")
    res = fd.solve(*render(task), time_limit=60)
    assert res.solved
    inferred = physical_trace(task, instance_trace(task, res.plan))
    t = inferred.trace
    assert [s.unit.motion.label for s in t.steps] == ["pour", "pour", "mix"]
    assert t.holder_of("water_1", 0) == "bowl_1" and t.holder_of("salt_1", 0) == "shaker_1"
    assert t.contents("bowl_1", 1) == ("salt_1", "water_1")
    assert t.final["water_1"].consumed and t.final["salt_1"].consumed
    assert t.contents("bowl_1") == ("brine_1",)
    assert inferred.evidence[E.UNRESOLVED] == 0 and inferred.evidence[E.SINGLE] >= 4
    report = replay(t)
    assert report.ok, [d.describe() for d in report.disagreements]


def _trace(instances, firings) -> tuple[PlanningTask, PhysicalTrace]:
    """A task with `instances` (name, label, start node) and the holder-less trace of `firings` (unit, names)."""
    task = PlanningTask("d", "p", "instances", 3, (), (), (), (), instances=tuple(Instance(*x) for x in instances))
    steps = []
    for k, (u, names) in enumerate(firings):
        roles = list(zip(unit_roles(u), names, strict=True))
        steps.append(TraceStep(k, u, tuple(Binding(x, r.before, r.after) for r, x in roles),
                               tuple(ObjectState(x, r.after) for r, x in roles if r.changes)))
    return task, PhysicalTrace(tuple(PhysicalObject(x, lab) for x, lab, _ in instances),
                               tuple(ObjectState(x, start) for x, _, start in instances), tuple(steps))


def test_tracking_keeps_the_salmon_in_its_bowl_and_the_replay_sees_the_wrong_bowl():
    """Two bowls list the one salmon; a defrost uses bowl_2 while the salmon sits in bowl_1."""
    frozen, thawed = n("salmon", "frozen", ("in", "bowl")), n("salmon", "thawed", ("in", "bowl"))
    bowl, micro = n("bowl", ("contains", ["salmon"])), n("microwave", "on")
    defrost = unit("defrost", [frozen, bowl, micro], [thawed, bowl, micro])
    task, plain = _trace([("bowl_1", "bowl", bowl), ("bowl_2", "bowl", bowl), ("microwave_1", "microwave", micro),
                  ("salmon_1", "salmon", frozen)], [(defrost, ["salmon_1", "bowl_2", "microwave_1"])])
    inferred = physical_trace(task, plain)
    t = inferred.trace
    assert t.holder_of("salmon_1", -1) == "bowl_1" and t.holder_of("salmon_1") == "bowl_1"
    assert inferred.evidence[E.LISTED] == 1 and inferred.evidence[E.TRACKED] == 1
    kinds = [(d.kind, d.step) for d in replay(t).disagreements]
    assert (K.CLAIMED_TWICE, -1) in kinds and (K.HOLDER_NOT_BOUND, 0) in kinds


def test_pour_between_same_label_containers_follows_the_lists():
    """Water `in [pot]` both before and after: the pot whose list gains water receives it (rule 1's exception)."""
    water = n("water", "hot", ("in", "pot"))
    src, drained = n("pot", ("contains", ["water"]), "dirty", "hot"), n("pot", "empty", "dirty", "hot")
    dst, filled = n("pot", "clean"), n("pot", ("contains", ["water"]), "clean")
    pour = unit("pour", [water, src, dst], [water, drained, filled])
    task, plain = _trace([("pot_1", "pot", src), ("pot_2", "pot", dst), ("water_1", "water", water)], [(pour, ["water_1", "pot_1", "pot_2"])])
    inferred = physical_trace(task, plain)
    assert inferred.trace.holder_of("water_1", -1) == "pot_1"
    assert inferred.trace.holder_of("water_1") == "pot_2"
    assert replay(inferred.trace).ok


def test_read_only_content_goes_where_the_list_names_it_or_into_the_product():
    """`pour*` lists the cream in the mixing bowl (it moves there; its node stays stale: misplaced), and a
    mix that makes a salad in the bowl consumes the lettuce FOON leaves out of the outputs."""
    cream, cup = n("cream", ("in", "cup")), n("cup", ("contains", ["cream"]))
    mb0, mb1 = n("mixing bowl", "empty"), n("mixing bowl", ("contains", ["cream"]))
    pour = unit("pour*", [cream, cup, mb0], [mb1])
    task, plain = _trace([("cream_1", "cream", cream), ("cup_1", "cup", cup), ("mixing_bowl_1", "mixing bowl", mb0)], [(pour, ["cream_1", "cup_1", "mixing_bowl_1"])])
    t = physical_trace(task, plain).trace
    assert t.holder_of("cream_1") == "mixing_bowl_1" and not t.final["cream_1"].consumed
    assert K.MISPLACED in replay(t).kinds()

    lettuce, b0 = n("lettuce", "chopped", ("in", "bowl")), n("bowl", ("contains", ["lettuce"]))
    salad, b1 = n("salad", ("in", "bowl")), n("bowl", ("contains", ["salad"]))
    mix = unit("mix", [lettuce, b0], [salad, b1])
    task, plain = _trace([("bowl_1", "bowl", b0), ("lettuce_1", "lettuce", lettuce), ("salad_1", "salad", None)], [(mix, ["lettuce_1", "bowl_1", "salad_1"])])
    t = physical_trace(task, plain).trace
    assert t.final["lettuce_1"].consumed and t.contents("bowl_1") == ("salad_1",)
    assert replay(t).ok


def test_unresolved_holder_is_left_free_and_reported():
    """A product `in [bowl]` of a unit that binds no bowl: no evidence, no holder, the replay says misplaced."""
    juice = n("juice", ("in", "bowl"))
    squeeze = unit("squeeze", [n("lime", "halved")], [n("lime", "squeezed"), juice])
    task, plain = _trace([("bowl_1", "bowl", n("bowl", "empty")), ("bowl_2", "bowl", n("bowl", "empty")),
                  ("juice_1", "juice", None), ("lime_1", "lime", n("lime", "halved"))], [(squeeze, ["lime_1", "juice_1"])])
    inferred = physical_trace(task, plain)
    assert inferred.trace.holder_of("juice_1") is None and inferred.evidence[E.UNRESOLVED] == 1
    d = next(d for d in replay(inferred.trace).disagreements if d.kind is K.MISPLACED)
    assert d.objects == ("juice_1",) and d.source == "brine.txt:1"


def test_plan_notes_what_the_replay_finds_with_inferred_holders(example):
    """`instances` models no holders: `plan` keeps its verdict and notes the physical replay's findings."""
    from foon2pddl.io.inputs import load_goal, load_kitchen
    from foon2pddl.planners.solve import plan

    foon, kitchen = example.at(3), load_kitchen(None, example, 3)
    outcome = plan(foon, kitchen, load_goal("guacamole", None, foon), "instances")
    note = next(n for n in outcome.decoded.notes if n.startswith("not checked physically"))
    assert "07-guacamole.foon:" in note and "disagreement" in note
    clean = plan(BRINE_FOON, BRINE_KITCHEN, Goal(GoalSpec("brine"), (BRINE,)), "instances")
    assert not any(n.startswith("not checked physically") for n in clean.decoded.notes)


def test_the_only_holder_of_a_label_that_the_unit_never_lists():
    """`bread (in [oven])` from a unit that binds no oven, with one oven in the task: that oven (rule 4)."""
    bake = unit("bake", [n("bread", "raw")], [n("bread", "baked", ("in", "oven"))])
    task, plain = _trace([("bread_1", "bread", n("bread", "raw")), ("oven_1", "oven", n("oven", "on"))],
                         [(bake, ["bread_1"])])
    inferred = physical_trace(task, plain)
    assert inferred.trace.holder_of("bread_1") == "oven_1" and inferred.evidence[E.ONLY] == 1
    assert [d.kind for d in replay(inferred.trace).disagreements] == [K.UNBOUND_TARGET]
