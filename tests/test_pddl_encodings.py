"""Encodings: solvable sets, pruning, state change, compat format, costs, rendering, determinism."""

from __future__ import annotations

import os
import subprocess
import sys
from collections import deque
from dataclasses import replace

import pddl.parser.domain
import pddl.parser.problem
import pytest
from conftest import ROOT, SUBGRAPHS
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.analysis.reachability import reachable
from foon2pddl.io.files import load
from foon2pddl.io.rates import Rates
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.model.levels import project, project_node
from foon2pddl.pddl.compile import ENCODINGS, GROUND_ENCODINGS, compile_task
from foon2pddl.pddl.prune import prune_task, relevant_units
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Action, Atom, PlanningTask, Predicate
from foon2pddl.planners import fd

PARSE_DOMAIN = pddl.parser.domain.DomainParser()  # building a parser takes 0.2 s: build once
PARSE_PROBLEM = pddl.parser.problem.ProblemParser()

# --- random networks over a small node pool, so that units share nodes -----------------------------

STATES = [
    make_state("chopped"), make_state("whole"), make_state("on"), make_state("in", "bowl"),
    make_state("on", "cutting board"), make_state("contains", "", ["salt", "water"]),
    make_state("contains", "", ["salt"]), make_state("seasoned", "", ["pepper"]),
]
node_pool_items = st.builds(
    lambda label, states: make_node(label, states),
    st.sampled_from(["onion", "bowl", "knife", "water", "salt", "and", "7up"]),
    st.lists(st.sampled_from(STATES), max_size=2),
)


@st.composite
def cases(draw, max_units=7):
    """(foon, kitchen, goal, level): a network, a kitchen and a goal at level 3, and a level to encode at."""
    pool = draw(st.lists(node_pool_items, min_size=2, max_size=8, unique=True))
    side = st.lists(st.sampled_from(pool), min_size=1, max_size=3)
    units = tuple(
        FunctionalUnit(tuple(draw(side)), Motion(draw(st.sampled_from(["chop", "pour", "pour*", "mix"]))),
                       tuple(draw(side)), (Source("recipe.foon", i + 1),))
        for i in range(draw(st.integers(1, max_units)))
    )
    foon = Foon(units)
    kitchen = Kitchen(frozenset(draw(st.lists(st.sampled_from(pool), max_size=4))), 3, "k.txt")
    produced = sorted({n for u in units for n in u.outputs})
    cands = draw(st.lists(st.sampled_from(produced), min_size=1, max_size=3, unique=True))
    goal = Goal(GoalSpec("goal"), tuple(sorted(cands)), 3)
    return foon, kitchen, goal, draw(st.sampled_from([1, 2, 3]))


def native_solvable(foon: Foon, kitchen: Kitchen, goal: Goal, level: int) -> bool:
    """The fixpoint's verdict at `level`."""
    reach = reachable(project(foon, level), kitchen.project(level).nodes)
    return any(reach.can_make(project_node(c, level)) for c in goal.candidates)


def delete_free_solvable(task: PlanningTask) -> bool:
    """Own check of delete-free STRIPS semantics: apply every applicable action until nothing changes."""
    assert all(not a.delete and not a.params for a in task.actions)
    facts = set(task.init)
    changed = True
    while changed:
        changed = False
        for a in task.actions:
            if set(a.pre) <= facts and not set(a.add) <= facts:
                facts |= set(a.add)
                changed = True
    return set(task.goal) <= facts


def strips_solvable(task: PlanningTask, limit: int = 20000) -> bool:
    """Breadth-first search of the real state space (with deletes); small tasks only."""
    start = frozenset(task.init)
    goal = set(task.goal)
    seen = {start}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        if goal <= state:
            return True
        for a in task.actions:
            if set(a.pre) <= state:
                nxt = (state - set(a.delete)) | set(a.add)
                if nxt not in seen:
                    seen.add(nxt)
                    queue.append(nxt)
        assert len(seen) < limit, "state space too large for this test"
    return False


# --- tree: exactly the fixpoint's solvable set ---------------------------------------------------------


@settings(max_examples=200, deadline=None)
@given(cases(), st.booleans())
def test_tree_solvable_iff_the_fixpoint_reaches_the_goal(case, prune):
    foon, kitchen, goal, level = case
    task = compile_task(foon, kitchen, goal, "tree", level, prune)
    assert delete_free_solvable(task) == native_solvable(foon, kitchen, goal, level)


@settings(max_examples=200, deadline=None)
@given(cases())
def test_foon_compat_solvable_iff_the_fixpoint_reaches_the_goal(case):
    foon, kitchen, goal, level = case
    task = compile_task(foon, kitchen, goal, "foon-compat", level, prune=False)
    assert delete_free_solvable(task) == native_solvable(foon, kitchen, goal, level)


@settings(max_examples=100, deadline=None)
@given(cases())
def test_tree_actions_map_back_to_their_units(case):
    foon, kitchen, goal, level = case
    task = compile_task(foon, kitchen, goal, "tree", level, prune=False)
    units = project(foon, level).units
    assert task.units == units
    unit_actions = [a for a in task.actions if a.unit is not None]
    assert [a.unit for a in unit_actions] == list(range(len(units)))
    for a in unit_actions:
        u = units[a.unit]
        assert {task.labels[x.predicate] for x in a.pre} == {n.describe() for n in u.inputs}
        assert {task.labels[x.predicate] for x in a.add} == {n.describe() for n in u.outputs}
        assert task.action_for(a.name.upper()) is a


# --- pruning never changes solvability -----------------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(cases())
def test_relevant_units_keep_the_goals_reachability_and_only_fired_units(case):
    foon, kitchen, goal, level = case
    f = project(foon, level)
    k = kitchen.project(level).nodes
    cands = [project_node(c, level) for c in goal.candidates]
    kept = relevant_units(f, k, cands)
    before = reachable(f, k)
    after = reachable(Foon(tuple(f.units[i] for i in kept), level), k)
    assert any(before.can_make(c) for c in cands) == any(after.can_make(c) for c in cands)
    assert all(before.unit_round[i] > 0 for i in kept)


def test_pruning_drops_units_that_cannot_help():
    a, b, c, d, x = (make_node(s) for s in ("a", "b", "c", "d", "x"))
    units = (
        FunctionalUnit((a,), Motion("m"), (b,)),   # needed
        FunctionalUnit((b,), Motion("m"), (c,)),   # makes the goal
        FunctionalUnit((a,), Motion("m"), (d,)),   # reachable, irrelevant
        FunctionalUnit((x,), Motion("m"), (c,)),   # relevant, never fires (no x)
    )
    foon = Foon(units)
    task = compile_task(foon, Kitchen(frozenset({a}), 3), Goal(GoalSpec("c"), (c,), 3), "tree")
    assert sorted(act.unit for act in task.actions) == [0, 1]
    assert {p.comment for p in task.predicates} == {"a", "b", "c"}


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases(max_units=5), st.sampled_from(["state", "ocp"]))
def test_strips_pruning_keeps_solvability_of_the_real_state_space(case, encoding):
    foon, kitchen, goal, level = case
    full = compile_task(foon, kitchen, goal, encoding, level, prune=False)
    pruned = compile_task(foon, kitchen, goal, encoding, level, prune=True)
    assert strips_solvable(pruned) == strips_solvable(full)
    assert prune_task(pruned).actions == pruned.actions  # a fixpoint


def test_an_action_that_requires_what_it_adds_is_not_its_achiever():
    p, q, g = Atom("p"), Atom("q"), Atom("g")
    keeps = Action("keeps", pre=(p,), add=(p, q))  # re-adds p (as ocp writes what a unit leaves as it was)
    makes = Action("makes", pre=(p,), add=(g,))
    preds = (Predicate("p"), Predicate("q"), Predicate("g"))
    task = PlanningTask(domain="d", problem="x", encoding="state", level=3, predicates=preds,
                        actions=(keeps, makes), init=(p,), goal=(g,))
    assert [a.name for a in prune_task(task).actions] == ["makes"]
    needs_q = replace(task, goal=(g, q))
    assert [a.name for a in prune_task(needs_q).actions] == ["keeps", "makes"]


# --- state encoding: what is modelled ------------------------------------------------------------------


def _chop_foon(level_states=True):
    onion_whole = make_node("onion", [make_state("whole"), make_state("on", "cutting board")])
    onion_chopped = make_node("onion", [make_state("chopped"), make_state("on", "cutting board")])
    knife = make_node("knife")
    bowl = make_node("bowl", [make_state("empty")])
    bowl_full = make_node("bowl", [make_state("contains", "", ["onion", "salt"])])
    units = (
        FunctionalUnit((onion_whole, knife), Motion("chop"), (onion_chopped,), (Source("/x/soup.txt", 7),)),
        FunctionalUnit((bowl, onion_chopped), Motion("pour"), (bowl_full,), (Source("/x/soup.txt", 15),)),
    )
    return Foon(units), Kitchen(frozenset({onion_whole, knife, bowl}), 3, "kitchen.txt"), bowl_full


def test_state_encoding_changes_states_and_declares_related_objects():
    foon, kitchen, bowl_full = _chop_foon()
    task = compile_task(foon, kitchen, Goal(GoalSpec("bowl"), (bowl_full,), 3), "state", prune=False)
    chop, pour = task.actions
    atoms = lambda xs: {(x.predicate, *x.args) for x in xs}  # noqa: E731
    assert ("is-whole", "onion") in atoms(chop.pre) and ("available", "knife") in atoms(chop.pre)
    assert atoms(chop.add) == {("is-chopped", "onion")}
    assert atoms(chop.delete) == {("is-whole", "onion")}  # knife: input only, left alone
    assert atoms(pour.add) == {("contains", "bowl", "onion"), ("contains", "bowl", "salt")}
    assert atoms(pour.delete) == {("is-empty", "bowl")}
    names = {name for name, _ in task.constants}
    assert {"cutting_board", "salt", "onion", "knife", "bowl"} <= names  # related objects and ingredients
    assert ("on", "onion", "cutting_board") in atoms(task.init)
    level2 = compile_task(foon, kitchen, Goal(GoalSpec("bowl"), (bowl_full,), 3), "state", level=2, prune=False)
    assert {(x.predicate, *x.args) for x in level2.actions[1].add} == {("is-contains", "bowl")}
    assert fd.solve(*render(task)).status == "solved"


def test_state_encoding_unsolvable_when_a_reused_state_was_deleted():
    # Two units both need the one cutting board empty; the first fills it: FOON can, the state encoding cannot.
    board = make_node("cutting board", [make_state("empty")])
    board_a = make_node("cutting board", [make_state("contains", "", ["a"])])
    board_b = make_node("cutting board", [make_state("contains", "", ["b"])])
    a, b = make_node("a"), make_node("b")
    a_cut, b_cut = make_node("a", [make_state("cut")]), make_node("b", [make_state("cut")])
    units = (FunctionalUnit((board, a), Motion("cut"), (board_a, a_cut)),
             FunctionalUnit((board, b), Motion("cut"), (board_b, b_cut)),
             FunctionalUnit((a_cut, b_cut), Motion("mix"), (make_node("salad"),)))
    foon = Foon(units)
    kitchen = Kitchen(frozenset({board, a, b}), 3)
    goal = resolve_goal(GoalSpec("salad"), foon)
    assert native_solvable(foon, kitchen, goal, 3)
    assert not strips_solvable(compile_task(foon, kitchen, goal, "state"))
    assert delete_free_solvable(compile_task(foon, kitchen, goal, "tree"))


# --- foon-compat: the converter's format ---------------------------------------------------------------


def test_foon_compat_has_one_predicate_typed_constants_and_parameterless_actions():
    foon, kitchen, bowl_full = _chop_foon()
    onion_chopped = foon.units[0].outputs[0]
    task = compile_task(foon, kitchen, Goal(GoalSpec("x"), (bowl_full, onion_chopped), 3), "foon-compat", prune=False)
    assert [p.name for p in task.predicates] == ["is_available"]
    assert task.types == (("object_node", "object"),)
    assert all(t == "object_node" for _, t in task.constants)
    assert all(not a.params for a in task.actions)
    assert [a.name for a in task.actions[:2]] == ["functional_unit_0", "functional_unit_1"]
    assert task.goal[0].args == ("goal_reached",)
    domain, problem = render(task)
    assert "(:requirements :strips :typing)" in domain
    assert "(is_available ?obj - object_node)" in domain
    assert delete_free_solvable(task)


# --- costs ---------------------------------------------------------------------------------------------


def test_success_rate_costs_make_the_optimal_plan_the_likeliest():
    a, goal_node = make_node("a"), make_node("g")
    units = (FunctionalUnit((a,), Motion("risky"), (goal_node,)), FunctionalUnit((a,), Motion("safe"), (goal_node,)))
    foon = Foon(units)
    rates = Rates({"risky": 0.2, "safe": 0.95})
    task = compile_task(foon, Kitchen(frozenset({a}), 3), Goal(GoalSpec("g"), (goal_node,), 3), "tree",
                        costs="success-rate", rates=rates)
    assert [x.cost for x in task.actions] == [1610, 52]  # round(1000 * -ln rate) + 1
    domain, problem = render(task)
    assert ":action-costs" in domain and "(:functions (total-cost) - number)" in domain
    assert "(= (total-cost) 0)" in problem and "(:metric minimize (total-cost))" in problem
    result = fd.solve(domain, problem, optimal=True)
    assert result.plan == ("safe_u1",)
    unit_task = compile_task(foon, Kitchen(frozenset({a}), 3), Goal(GoalSpec("g"), (goal_node,), 3), "tree",
                             costs="unit")
    assert [x.cost for x in unit_task.actions] == [1, 1]
    plain = render(compile_task(foon, Kitchen(frozenset({a}), 3), Goal(GoalSpec("g"), (goal_node,), 3)))
    assert "total-cost" not in plain[0] + plain[1] and "(:requirements :strips)" in plain[0]


def test_goal_actions_cost_zero_and_success_rate_needs_rates():
    foon, kitchen, bowl_full = _chop_foon()
    goal = Goal(GoalSpec("x"), (bowl_full, foon.units[0].outputs[0]), 3)
    task = compile_task(foon, kitchen, goal, "tree", costs="unit")
    assert [a.cost for a in task.actions if a.unit is None] == [0, 0]
    with pytest.raises(ValueError, match="rates"):
        compile_task(foon, kitchen, goal, "tree", costs="success-rate")
    with pytest.raises(ValueError, match="encoding"):
        compile_task(foon, kitchen, goal, "lifted")


# --- rendering -----------------------------------------------------------------------------------------


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases(), st.sampled_from(GROUND_ENCODINGS), st.sampled_from([None, "unit"]))
def test_rendered_pddl_parses_and_round_trips_the_actions(case, encoding, costs):
    foon, kitchen, goal, level = case
    task = compile_task(foon, kitchen, goal, encoding, level, costs=costs)
    domain_text, problem_text = render(task)
    assert render(task) == (domain_text, problem_text)
    domain = PARSE_DOMAIN(domain_text)
    problem = PARSE_PROBLEM(problem_text)
    assert {a.name for a in domain.actions} == {a.name for a in task.actions}
    costed = costs is not None and bool(task.actions)  # no action, no cost to count
    assert len(problem.init) == len(task.init) + costed
    physical = ENCODINGS[encoding].physical
    assert set(task.requirements) == {":strips"} | ({":typing"} if encoding == "foon-compat" or physical else set()) | (
        {":action-costs"} if costed else set()) | (
        {":conditional-effects"} if any(a.conditional for a in task.actions) else set())


def test_empty_precondition_is_written_as_an_empty_and():
    from foon2pddl.pddl.task import Action, Atom, Predicate

    task = PlanningTask("d", "p", "tree", 3, (Predicate("q"),), (Action("a", (), (Atom("q"),)),), (), (Atom("q"),))
    domain, _ = render(task)
    assert ":precondition (and)" in domain
    PARSE_DOMAIN(domain)


def test_lifted_typed_actions_render():
    from foon2pddl.pddl.task import Action, Atom, Predicate

    task = PlanningTask(
        "d", "p", "lifted", 3,
        (Predicate("chopped", (("?x", "food"),)),),
        (Action("chop", (), (Atom("chopped", ("?x",)),), params=(("?x", "food"),)),),
        (), (Atom("chopped", ("onion",)),), types=(("food", "object"),), objects=(("onion", "food"),))
    domain, problem = render(task)
    assert ":parameters (?x - food)" in domain and "(chopped ?x - food)" in domain
    assert "onion - food" in problem
    assert ":typing" in domain
    parsed = PARSE_DOMAIN(domain)
    assert len(parsed.actions) == 1


def test_unsafe_name_in_a_task_is_refused():
    from foon2pddl.pddl.task import Predicate

    task = PlanningTask("d", "p", "tree", 3, (Predicate("bad name)"),), (), (), ())
    with pytest.raises(ValueError, match="bad name"):
        render(task)


# --- real data: determinism across processes, FD accepts every subgraph --------------------------------


def test_cli_output_is_byte_identical_across_hash_seeds(tmp_path):
    outs = []
    for seed in ("1", "2"):
        out = tmp_path / seed
        env = {**os.environ, "PYTHONHASHSEED": seed}
        subprocess.run([sys.executable, "-m", "foon2pddl", "compile", str(SUBGRAPHS / "0076-bloody_mary.txt"),
                        "--goal", "bloody mary", "--encoding", "state", "--no-prune", "-o", str(out)],
                       check=True, env=env, capture_output=True)
        outs.append(((out / "domain.pddl").read_bytes(), (out / "problem.pddl").read_bytes()))
    assert outs[0] == outs[1]


@pytest.mark.parametrize("name", ["0001-whipped_cream.txt", "0076-bloody_mary.txt", "ACT-0080-caesar_salad.txt"])
def test_fast_downward_accepts_every_encoding_of_a_subgraph(name):
    foon, _ = load([SUBGRAPHS / name])
    dish = sorted(n for n in foon.nodes if n.dish is not None)[0]
    goal = resolve_goal(spec_of_node(dish), foon)
    kitchen = default_kitchen(foon)
    native = native_solvable(foon, kitchen, goal, 3)
    for encoding in GROUND_ENCODINGS:
        result = fd.solve(*render(compile_task(foon, kitchen, goal, encoding)), time_limit=60)
        assert result.status in ("solved", "unsolvable"), result.message
        if ENCODINGS[encoding].complete:
            assert result.solved == native


def test_unit_comments_name_the_recipe_file_line_and_motion():
    foon, kitchen, bowl_full = _chop_foon()
    domain, _ = render(compile_task(foon, kitchen, Goal(GoalSpec("bowl"), (bowl_full,), 3)))
    assert "; unit 0: chop from soup.txt:7" in domain
    assert "/x/" not in domain  # output does not depend on where the inputs live


def test_example_paths_have_no_checkout_location():
    text = (ROOT / "domains" / "tree" / "pancake.pddl").read_text()
    assert str(ROOT) not in text and "01-lemonade.foon" not in text and "04-pancakes.foon:" in text


def test_unified_planning_reads_every_encoding_of_hostile_labels(tmp_path):
    from unified_planning.io import PDDLReader
    from unified_planning.shortcuts import get_environment

    get_environment().credits_stream = None
    bowl = make_node("and", [make_state("contains", "", ["7up", "x) (:init"])])
    onion = make_node("onion; (not", [make_state("in", "and")])
    out = make_node("and", [make_state("contains", "", ["7up", "onion; (not", "x) (:init"])])
    units = (FunctionalUnit((bowl, onion), Motion("pour*", composite=True), (out,), (Source("a\nb;c.foon", 3),)),)
    foon = Foon(units)
    kitchen = Kitchen(frozenset({bowl, onion}), 3)
    for encoding in GROUND_ENCODINGS:
        task = compile_task(foon, kitchen, Goal(GoalSpec("and"), (out,), 3), encoding, costs="unit")
        domain, problem = render(task)
        (tmp_path / "d.pddl").write_text(domain)
        (tmp_path / "p.pddl").write_text(problem)
        parsed = PDDLReader().parse_problem(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
        assert [a.name for a in parsed.actions] == [a.name for a in task.actions]
        assert len(parsed.goals) >= 1
