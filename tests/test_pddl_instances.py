"""The `instances` encoding: pairing, counts, encoding, plans with bindings, the instance-level validator."""

from __future__ import annotations

import itertools
from collections import deque
from dataclasses import replace

import pddl.parser.domain
import pddl.parser.problem
import pytest
from foon_strategies import foons
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.reachability import reachable
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.model.pairing import RoleKind, unit_roles
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.encode_instances import IS, LANE, NOT_MADE, TOGETHER, encode_instances
from foon2pddl.pddl.encoding import EncodeOptions
from foon2pddl.pddl.instance_counts import delete_free_plan, derive_counts, unfold
from foon2pddl.pddl.instance_replay import InstancePlanError, instance_trace, trace_lines
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Atom, PlanningTask
from foon2pddl.pddl.trace_view import step_text
from foon2pddl.planners import fd
from foon2pddl.planners.trace_check import check_states


def n(label, *states):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states])


def unit(motion, ins, outs):
    return FunctionalUnit(tuple(ins), Motion(motion), tuple(outs))


# The knife story: cutting and spreading both dirty the knife; washing cleans it. FOON's delete-free
# semantics uses one knife for both; physically that needs two knives or a wash in between.
BREAD, SLICE, BUTTERED = n("bread", "whole"), n("bread", "sliced"), n("bread", "buttered")
CLEAN, DIRTY = n("knife", "clean"), n("knife", "dirty")
BUTTER, FAUCET = n("butter", "soft"), n("faucet")
CUT = unit("cut", [BREAD, CLEAN], [SLICE, DIRTY])
SPREAD = unit("spread", [SLICE, BUTTER, CLEAN], [BUTTERED, DIRTY])
WASH = unit("wash", [DIRTY, FAUCET], [CLEAN, FAUCET])
KNIFE_FOON = Foon((CUT, SPREAD, WASH))
KNIFE_KITCHEN = Kitchen(frozenset({BREAD, CLEAN, BUTTER, FAUCET}))
KNIFE_GOAL = Goal(GoalSpec("bread"), (BUTTERED,))


def roles_of(u):
    return [(r.kind, r.label, r.before, r.after) for r in unit_roles(u)]


def test_pairing_moves_keeps_reads_and_creates():
    squeeze = unit("squeeze", [n("lime", "halved"), n("juicer", "empty"), n("carton")],
                   [n("lime", "squeezed"), n("juicer", ("contains", "", ["lime juice"])), n("lime juice")])
    kinds = [(k, label) for k, label, _, _ in roles_of(squeeze)]
    assert kinds == [(RoleKind.MOVED, "lime"), (RoleKind.MOVED, "juicer"), (RoleKind.READ_ONLY, "carton"),
                     (RoleKind.NEW, "lime juice")]
    assert roles_of(WASH)[1] == (RoleKind.KEPT, "faucet", FAUCET, FAUCET)


def test_pairing_prefers_identical_then_shared_states_then_shared_ingredients():
    with_a = n("bowl", ("contains", "", ["a"]))
    with_b = n("bowl", ("contains", "", ["b"]), "cold")
    both = n("bowl", ("contains", "", ["a", "b"]))
    combine = unit("pour", [with_b, with_a], [both])
    kinds = {r.before: r.kind for r in unit_roles(combine)}
    # No shared state with either input; `a` shares an ingredient... and so does `b`: input order decides.
    assert kinds == {with_b: RoleKind.MOVED, with_a: RoleKind.READ_ONLY}
    warm_both = n("bowl", ("contains", "", ["a", "b"]), "cold")
    assert {r.before: r.kind for r in unit_roles(unit("pour", [with_a, with_b], [warm_both]))} == {
        with_a: RoleKind.READ_ONLY, with_b: RoleKind.MOVED}  # shares the state `cold`
    same = unit("chop", [n("onion", "whole"), CLEAN, n("onion", "peeled")], [n("onion", "peeled"), CLEAN])
    assert [r.kind for r in unit_roles(same)] == [RoleKind.READ_ONLY, RoleKind.KEPT, RoleKind.KEPT]


def test_pairing_gives_a_node_listed_twice_two_roles():
    """A node listed twice on one side is two objects (a level-2 unit's two bowls; the readers keep a line written
    twice once)."""
    u = unit("stir", [n("bowl", "full"), n("bowl", "full"), n("spoon")], [n("bowl", "stirred"), n("spoon")])
    assert [r.kind for r in unit_roles(u)] == [RoleKind.MOVED, RoleKind.READ_ONLY, RoleKind.KEPT]


def test_unfolding_counts_a_node_two_units_consume():
    plan, target = delete_free_plan(KNIFE_FOON, KNIFE_KITCHEN.nodes, (BUTTERED,))
    assert [KNIFE_FOON.units[u].motion.label for u in plan] == ["cut", "spread"]
    at_kitchen, created, firings = unfold(KNIFE_FOON, plan, KNIFE_KITCHEN.nodes, target)
    assert at_kitchen == {CLEAN: 2, BREAD: 1, BUTTER: 1}
    assert not created and firings == {0: 1, 1: 1}


def test_unfolding_fires_a_producer_once_per_consumer():
    raw, soft, melted, pan = n("butter", "cold"), n("butter", "soft"), n("butter", "melted"), n("pan")
    toast = n("toast", "plain")
    soften = unit("soften", [raw], [soft])
    melt = unit("melt", [soft, pan], [melted, pan])
    spread = unit("spread", [soft, toast], [n("toast", "buttered")])
    dish = unit("serve", [melted, n("toast", "buttered")], [n("dish", "served")])
    foon = Foon((soften, melt, spread, dish))
    kitchen = frozenset({raw, pan, toast})
    plan, target = delete_free_plan(foon, kitchen, (n("dish", "served"),))
    at_kitchen, created, firings = unfold(foon, plan, kitchen, target)
    assert firings[0] == 2  # soft butter is consumed twice: soften fires twice, from two cold butters
    assert at_kitchen[raw] == 2 and at_kitchen[pan] == 1 and created == {"dish": 1}
    counts = derive_counts(foon, range(4), kitchen, (target,), overrides={"pan": 3}, stated={toast: 5})
    assert dict(counts.at_node) == {raw: 2, pan: 3, toast: 5}


def test_a_unit_that_only_reads_a_kitchen_state_shares_the_object_a_later_unit_takes():
    """Issue 24: the french toast counted two stoves. The pan goes onto a `stove (off)` (read only) and
    `turn on` takes a `stove (off)`: one stove does both when the pan goes on first. Objects needed at
    once, not per use; a reader that needs what the taker makes cannot go first, and then it is two."""
    off, on, butter, melted = n("stove", "off"), n("stove", "on"), n("butter", "solid"), n("butter", "melted")
    pan, pan_on = n("pan", "empty"), n("pan", "empty", ("on", "stove"))
    turn_on, place = unit("turn on", [off], [on]), unit("pick-and-place", [pan, off], [pan_on])
    melt = unit("melt", [on, pan_on, butter], [melted])
    foon, kitchen = Foon((turn_on, place, melt)), frozenset({off, pan, butter})
    counts = derive_counts(foon, range(3), kitchen, (melted,))
    assert dict(counts.at_node) == {off: 1, pan: 1, butter: 1}
    motions = [foon.units[u].motion.label for u in counts.unfolded]
    assert motions.index("pick-and-place") < motions.index("turn on")  # the plan the counts are made for
    task = encode_instances(foon, Kitchen(kitchen), Goal(GoalSpec("butter"), (melted,)))
    assert brute_force_solvable(task) is True
    # the same read after the stove is on (the pan goes on a cold stove beside a hot one): two at once
    check = unit("pick-and-place", [pan, off, on], [pan_on])
    foon = Foon((turn_on, check, melt))
    assert dict(derive_counts(foon, range(3), kitchen, (melted,)).at_node)[off] == 2


def test_encoding_structure_and_one_state_per_instance():
    task = encode_instances(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL)
    assert task.encoding == "instances" and task.goal == (Atom("goal-reached"),)
    assert sorted(name for name, _ in task.objects) == ["bread_1", "butter_1", "knife_1", "knife_2"]
    cut = next(a for a in task.actions if a.unit == 0)
    assert [t for _, t in cut.params] == ["physical-object", "physical-object"]  # flat types (Tamer)
    assert {Atom("type_bread", ("?bread",)), Atom("type_knife", ("?knife",))} <= set(cut.pre)  # labels as guards
    assert Atom(IS, ("?knife", "knife_clean")) in cut.pre and Atom(IS, ("?knife", "knife_clean")) in cut.delete
    assert Atom(IS, ("?knife", "knife_dirty")) in cut.add
    # Every instance starts in exactly one state.
    starts = [a.args[0] for a in task.init if a.predicate == IS]
    assert sorted(starts) == sorted(name for name, _ in task.objects)
    assert task.types == (("physical-object", "object"), ("object-state", "object"))
    assert Atom("type_knife", ("knife_2",)) in task.init and Atom("type_bread", ("knife_2",)) not in task.init


def test_override_and_kitchen_counts():
    task = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", instances=(("knife", 1),))
    assert [x.name for x in task.instances if x.label == "knife"] == ["knife_1"]
    stated = Kitchen(KNIFE_KITCHEN.nodes, 3, "k", ((CLEAN, 3),))
    task = encode_instances(KNIFE_FOON, stated, KNIFE_GOAL)
    assert sum(x.label == "knife" for x in task.instances) == 3


def _fd(task: PlanningTask):
    return fd.solve(*render(task), time_limit=60)


def test_one_knife_needs_a_wash_and_the_validator_catches_the_tree_plan():
    task = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", instances=(("knife", 1), ("faucet", 1)))
    res = _fd(task)
    assert res.solved
    trace = instance_trace(task, res.plan)
    assert [s.unit.motion.label for s in trace.steps] == ["cut", "wash", "spread"]
    assert check_states(trace, (BUTTERED,)).ok
    assert trace.final["knife_1"].node == DIRTY and trace.final["bread_1"].node == BUTTERED
    assert all(s.holder is None for s in trace.final.values())  # instances does not model holders
    assert step_text(trace.steps[0]) == "cut bread_1, knife_1"
    assert step_text(trace.steps[1]) == "wash knife_1 with faucet_1"  # the faucet: read in a stable state, bound on replay
    # FOON's tree plan (cut, spread) is not physically executable with one knife.
    cut, spread = (next(a.name for a in task.actions if a.unit == u) for u in (0, 1))
    broken = instance_trace(task, [f"{cut} bread_1 knife_1", f"{spread} bread_1 knife_1"])
    verdict = check_states(broken, (BUTTERED,))
    assert not verdict.ok
    assert "step 2 (spread bread_1, knife_1 with butter_1): knife_1 is knife (dirty), the unit needs it knife (clean)" \
        in verdict.problems[0]
    assert "cut bread_1, knife_1: bread_1: bread (sliced); knife_1: knife (dirty)" in trace_lines(broken)[1]
    with pytest.raises(InstancePlanError):
        instance_trace(task, [f"{cut} bread_1"])
    with pytest.raises(InstancePlanError):
        instance_trace(task, ["fly bread_1"])
    with pytest.raises(InstancePlanError, match="not an instance"):
        instance_trace(task, [f"{cut} bread_1 knife_9"])


def test_derived_counts_solve_without_washing():
    task = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances")
    res = _fd(task)
    trace = instance_trace(task, res.plan)
    assert check_states(trace, (BUTTERED,)).ok
    assert sorted(b.object for s in trace.steps for b in s.bindings if b.object.startswith("knife")) == [
        "knife_1", "knife_2"]


def test_a_unit_fires_twice_with_different_instances():
    lemon, juice = n("lemon", "halved"), n("juice", "squeezed")
    squeeze = unit("squeeze", [lemon, n("glass", "empty")], [n("lemon", "squeezed"), n("glass", "full"), juice])
    pour = unit("pour", [n("glass", "full"), n("jug", "empty")], [n("glass", "empty"), n("jug", "half")])
    top = unit("pour", [n("glass", "full"), n("jug", "half")], [n("glass", "empty"), n("jug", "full")])
    foon = Foon((squeeze, pour, top))
    kitchen = Kitchen(frozenset({lemon, n("glass", "empty"), n("jug", "empty")}))
    goal = Goal(GoalSpec("jug"), (n("jug", "full"),))
    task = encode_instances(foon, kitchen, goal, options=EncodeOptions(instances=(("lemon", 2), ("glass", 2))))
    res = _fd(task)
    trace = instance_trace(task, res.plan)
    assert check_states(trace, goal.candidates).ok
    squeezes = [s for s in trace.steps if s.unit.motion.label == "squeeze"]
    assert len(squeezes) == 2 and squeezes[0].bindings != squeezes[1].bindings


PARSE_DOMAIN = pddl.parser.domain.DomainParser()
PARSE_PROBLEM = pddl.parser.problem.ProblemParser()


def test_renders_to_pddl_the_pddl_package_parses_with_types():
    task = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", costs="unit",
                        categories=(("knife", ("cutlery", "utensil")), ("bread", ("baked goods",))))
    domain_text, problem_text = render(task)
    domain = PARSE_DOMAIN(domain_text)
    problem = PARSE_PROBLEM(problem_text)
    assert {a.name for a in domain.actions} == {a.name for a in task.actions}
    assert len(problem.objects) == len(task.objects)
    # categories group labels as static predicates (flat types): a knife is cutlery and a utensil, bread is not
    assert {"(type_knife knife_1)", "(type_cutlery knife_1)", "(type_utensil knife_1)"} <= set(
        line.strip() for line in problem_text.splitlines())
    assert "(type_utensil bread_1)" not in problem_text and "(type_baked_goods bread_1)" in problem_text
    assert render(compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", costs="unit", categories=(
        ("knife", ("cutlery", "utensil")), ("bread", ("baked goods",))))) == (domain_text, problem_text)


# -- an independent oracle: brute-force search of the ground task ----------------------------------


def brute_force_solvable(task: PlanningTask, limit: int = 20000) -> bool | None:
    """Breadth-first search over the grounded task (None when the state space exceeds `limit`)."""
    by_type: dict[str, list[str]] = {}
    for name, typ in task.objects:
        by_type.setdefault(typ, []).append(name)
    ground = []
    for a in task.actions:
        for args in itertools.product(*(by_type.get(t, []) for _, t in a.params)):
            bind = dict(zip((v for v, _ in a.params), args, strict=True))

            def g(atoms, bind=bind):
                return frozenset(Atom(x.predicate, tuple(bind.get(y, y) for y in x.args)) for x in atoms)

            ground.append((g(a.pre), g(a.add), g(a.delete)))
    start = frozenset(task.init)
    seen, queue = {start}, deque([start])
    while queue:
        state = queue.popleft()
        if set(task.goal) <= state:
            return True
        for pre, add, delete in ground:
            if pre <= state:
                nxt = (state - delete) | add
                if nxt not in seen:
                    if len(seen) >= limit:
                        return None
                    seen.add(nxt)
                    queue.append(nxt)
    return False


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(foons(max_units=4), st.data())
def test_derived_counts_solve_exactly_what_foon_solves(foon, data):
    produced = sorted(foon.producers)
    target = data.draw(st.sampled_from(produced))
    inputs = sorted({x for u in foon.units for x in u.inputs})
    kitchen = Kitchen(frozenset(data.draw(st.lists(st.sampled_from(inputs), max_size=4))))
    goal = Goal(GoalSpec(target.label), (target,))
    task = encode_instances(foon, kitchen, goal)
    verdict = brute_force_solvable(task)
    if verdict is None:
        return
    assert verdict == reachable(foon, kitchen.nodes).can_make(target)


def _ground_count(task: PlanningTask) -> int:
    """Groundings of the task's actions whose static preconditions (`lane`, `together`, `precedes`) hold."""
    static_names = (LANE, TOGETHER, "precedes")
    static = {a for a in task.init if a.predicate in static_names}
    by_type: dict[str, list[str]] = {}
    for name, typ in task.objects:
        by_type.setdefault(typ, []).append(name)
    total = 0
    for a in task.actions:
        for args in itertools.product(*(by_type.get(t, []) for _, t in a.params)):
            bind = dict(zip((v for v, _ in a.params), args, strict=True))
            pre = [Atom(x.predicate, tuple(bind.get(y, y) for y in x.args)) for x in a.pre]
            total += all(x in static for x in pre if x.predicate in static_names)
    return total


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(foons(max_units=5), st.data())
def test_lanes_keep_the_task_solvable_and_shrink_its_groundings(foon, data):
    """With derived counts, each instance may change state only as the unfolded plan changes it, and only with
    instances it changed state with there: the task
    is still solvable exactly when FOON makes the goal (brute force), never has more groundings than
    without lanes (their only effect is to rule bindings out), and has lanes whenever FOON makes the goal
    with at least one unit."""
    target = data.draw(st.sampled_from(sorted(foon.producers)))
    inputs = sorted({x for u in foon.units for x in u.inputs})
    kitchen = Kitchen(frozenset(data.draw(st.lists(st.sampled_from(inputs), max_size=5))))
    goal = Goal(GoalSpec(target.label), (target,))
    task = encode_instances(foon, kitchen, goal)
    makes = reachable(foon, kitchen.nodes).can_make(target)
    has_lanes = any(p.name == LANE for p in task.predicates)
    plan = delete_free_plan(foon, kitchen.nodes, (target,))
    assert has_lanes == bool(makes and plan[0])  # an empty plan (the goal is in the kitchen) needs no lanes
    verdict = brute_force_solvable(task)
    if verdict is not None:
        assert verdict == makes
    if has_lanes:
        plain = replace(task, actions=tuple(replace(a, pre=tuple(x for x in a.pre if x.predicate not in (LANE, TOGETHER)))
                                            for a in task.actions))
        assert _ground_count(task) <= _ground_count(plain)


def test_lanes_only_for_derived_counts():
    """A stated or overridden count may ask for a wash or a spare: then instances move freely, as before."""
    derived = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances")
    assert LANE in {p.name for p in derived.predicates}
    assert "lanes: each instance changes state only as in the unfolded plan" in derived.comments
    lanes = {a.args for a in derived.init if a.predicate == LANE}
    assert {("knife_1", "knife_clean", "knife_dirty"), ("knife_2", "knife_clean", "knife_dirty")} <= lanes
    together = {a.args for a in derived.init if a.predicate == TOGETHER}
    assert ("knife_1", "bread_1") in together and ("knife_1", "knife_2") not in together  # cut moves both
    for task in (compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", instances=(("knife", 1),)),
                 encode_instances(KNIFE_FOON, Kitchen(KNIFE_KITCHEN.nodes, 3, "k", ((CLEAN, 3),)), KNIFE_GOAL),
                 encode_instances(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, extra=1)):
        assert not {LANE, TOGETHER} & {p.name for p in task.predicates}
        assert not any(x.predicate in (LANE, TOGETHER) for a in task.actions for x in a.pre)


def test_no_instance_state_goes_unmentioned():
    task = encode_instances(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL)
    consts = {c for c, _ in task.constants}
    assert NOT_MADE in consts
    for a in task.actions:
        assert all(x.args[-1] in consts for x in (*a.pre, *a.add, *a.delete) if x.predicate == IS)


def test_plan_pipeline_checks_plans_at_the_instance_level():
    from foon2pddl.planners.solve import plan

    outcome = plan(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", instances=(("knife", 1), ("faucet", 1)))
    assert outcome.status == "solved" and outcome.decoded.trace_check.ok and outcome.trace is outcome.decoded.trace
    # Every step is kept (no justification): the wash is in the tree although FOON does not need it.
    assert [u.motion.label for u in outcome.tree.units] == ["cut", "wash", "spread"]
    assert outcome.validation.ok  # and the tree is a valid FOON task tree from the kitchen
    assert [step_text(s) for s in outcome.trace.steps][-1] == "spread bread_1, knife_1 with butter_1"


def test_kitchen_file_states_counts(tmp_path):
    from foon2pddl.io.kitchen_files import read_kitchen

    path = tmp_path / "kitchen.txt"
    path.write_text("# two knives\n2 x knife: clean\nbread: whole\n1x butter: soft\nfaucet\n")
    kitchen = read_kitchen(path)
    assert kitchen.nodes == KNIFE_KITCHEN.nodes
    assert dict(kitchen.counts) == {CLEAN: 2, BUTTER: 1}
    task = encode_instances(KNIFE_FOON, kitchen, KNIFE_GOAL, options=EncodeOptions(instances=(("bread", 2),)))
    counts = {label: sum(x.label == label for x in task.instances) for label in ("knife", "butter", "bread")}
    assert counts == {"knife": 2, "butter": 1, "bread": 2}
    path.write_text("2 x knife: in [bowl\n")
    with pytest.raises(Exception, match="kitchen.txt:1"):
        read_kitchen(path)


def test_to_up_problem_and_ups_validator_accept_an_instances_plan():
    from foon2pddl.pddl.up_problem import to_up_problem
    from foon2pddl.planners.decode import up_validation

    task = compile_task(KNIFE_FOON, KNIFE_KITCHEN, KNIFE_GOAL, "instances", instances=(("knife", 1), ("faucet", 1)))
    problem = to_up_problem(task)
    assert len(problem.actions) == len(task.actions) and not problem.kind.has_hierarchical_typing()
    res = _fd(task)
    assert up_validation(task, res.plan).ok
    assert not up_validation(task, [s for s in res.plan if not s.startswith("wash")]).ok
