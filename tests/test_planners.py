"""Planners: status mapping, plan parsing, Fast Downward runs (fresh, optimal, concurrent, reused), external commands."""

from __future__ import annotations

import sys
import textwrap
from concurrent.futures import ThreadPoolExecutor

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.model.foon import ObjectNode
from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Action, Atom, PlanningTask, Predicate, candidate_atoms
from foon2pddl.planners import external, fd, run_planner
from foon2pddl.planners.fd_reuse import TranslatedTask
from foon2pddl.planners.result import PlanResult, parse_plan_text


def chain_task(goal: str = "c", init: tuple[str, ...] = ("a",), costs: bool = False) -> PlanningTask:
    """a -> b -> c (cost 1 each), and a direct a -> c costing 5; d is made by nothing."""
    preds = tuple(Predicate(p) for p in "abcd")
    acts = (
        Action("mk-b", (Atom("a"),), (Atom("b"),), cost=1 if costs else None, unit=0),
        Action("mk-c", (Atom("b"),), (Atom("c"),), cost=1 if costs else None, unit=1),
        Action("direct-c", (Atom("a"),), (Atom("c"),), cost=5 if costs else None, unit=2),
    )
    return PlanningTask("chain", "p", "tree", 3, preds, acts, tuple(Atom(x) for x in init), (Atom(goal),))


def fd_solve(task: PlanningTask, **kw) -> PlanResult:
    return fd.solve(*render(task), **kw)


# ------------------------------------------------------------------ plan files and exit codes


def test_parse_plan_text_reads_ipc_plans():
    text = "; a comment\n(MK-B)\n  (mk-c  x   Y) ; trailing\n\n; cost = 2 (unit cost)\n"
    assert parse_plan_text(text) == ("mk-b", "mk-c x y")


@pytest.mark.parametrize(
    ("code", "status"),
    [(0, "solved"), (2, "solved"), (10, "unsolvable"), (11, "unsolvable"), (12, "gave up"), (13, "gave up"),
     (21, "timeout"), (23, "timeout"), (22, "error"), (31, "error"), (34, "error"), (99, "error"), (-9, "error")],
)
def test_fd_exit_codes_map_to_statuses(code, status):
    assert fd.exit_status(code)[0] == status


def test_alias_options_come_from_the_driver():
    assert any("lazy_greedy" in o for o in fd.search_options(False))
    assert fd.search_options(True) == ("--search", "astar(lmcut())")


def test_plan_result_rejects_unknown_status():
    with pytest.raises(ValueError):
        PlanResult("maybe")


# ------------------------------------------------------------------ Fast Downward


def test_fd_solves_and_times_phases():
    result = fd_solve(chain_task())
    assert result.status == "solved"
    assert result.plan in (("mk-b", "mk-c"), ("direct-c",))
    assert {"write", "translate", "search"} <= set(result.timings)


def test_fd_unsolvable_by_translator():
    result = fd_solve(chain_task(goal="d"))
    assert result.status == "unsolvable"
    assert result.message == "translator: no relaxed solution"


def test_fd_unsolvable_by_search_with_deletes():
    # Two single-use tokens, three products wanted: relaxed reachable and no mutex the translator finds.
    tokens, products = ("t1", "t2"), ("p1", "p2", "p3")
    task = PlanningTask(
        "tok", "p", "state", 3, tuple(Predicate(p) for p in tokens + products),
        tuple(Action(f"use-{t}-{p}", (Atom(t),), (Atom(p),), (Atom(t),), unit=0) for t in tokens for p in products),
        tuple(Atom(t) for t in tokens), tuple(Atom(p) for p in products),
    )
    result = fd_solve(task)
    assert result.status == "unsolvable"
    assert "search" in result.message
    assert fd_solve(task, optimal=True).status == "unsolvable"


def test_fd_goal_true_initially_gives_empty_plan():
    result = fd_solve(chain_task(goal="a"))
    assert (result.status, result.plan) == ("solved", ())


def test_fd_timeout_with_tiny_limit():
    result = fd_solve(chain_task(), time_limit=0.001)
    assert result.status == "timeout"


def test_fd_rejects_bad_pddl_as_error():
    result = fd.solve("(define (domain d)", "(define (problem p))")
    assert result.status == "error"
    assert "translator" in result.message


def test_fd_optimal_minimizes_cost_where_satisficing_minimizes_length():
    task = chain_task(costs=True)
    assert fd_solve(task, optimal=True).plan == ("mk-b", "mk-c")  # cost 2 < 5
    assert fd_solve(task).plan == ("direct-c",)  # lama-first counts steps (cost_type=one)


def test_concurrent_fd_solves_do_not_mix_results():
    goals = ["c", "d", "b", "c", "d", "b"]

    def one(goal):
        return goal, fd_solve(chain_task(goal=goal))

    with ThreadPoolExecutor(max_workers=3) as pool:
        results = list(pool.map(one, goals))
    for goal, result in results:
        if goal == "d":
            assert result.status == "unsolvable"
        else:
            assert result.status == "solved"
            assert any(f"mk-{goal}" == s or (goal == "c" and s == "direct-c") for s in result.plan[-1:])


def test_run_planner_dispatches_to_fd():
    task = chain_task()
    assert run_planner(task, *render(task)).planner.startswith("fd")


# ------------------------------------------------------------------ FD translation reuse


def test_reuse_matches_fresh_runs_and_handles_special_goals():
    base = chain_task()
    tt = TranslatedTask.build(base)
    assert tt.solve([(Atom("c"),)]).status == "solved"
    assert tt.solve([(Atom("d"),)]).status == "unsolvable"
    initial = tt.solve([(Atom("a"),)])
    assert (initial.status, initial.plan) == ("solved", ())
    both = tt.solve([(Atom("d"),), (Atom("b"),)])  # d unreachable, b reachable: b
    assert both.status == "solved" and both.plan == ("mk-b",)
    several = tt.solve([(Atom("b"),), (Atom("c"),)])
    assert several.status == "solved" and not any(s.startswith("foon2pddl") for s in several.plan)
    for goal in "abcd":
        fresh = fd_solve(chain_task(goal=goal))
        assert tt.solve([(Atom(goal),)]).status == fresh.status


def test_reuse_sas_goal_swap_searches_each_goal():
    tt = TranslatedTask.build(chain_task())
    sas = tt.goal_sas([(Atom("b"),), (Atom("c"),)])
    assert isinstance(sas, str)
    assert sas.count("begin_operator") == 3 + 2  # three actions, two goal operators, no anchor action
    assert "begin_goal\n1\n" in sas


def test_candidate_atoms_read_the_goal_actions_candidates():
    task = chain_task()
    reached = Atom("goal-reached")
    b, c = ObjectNode("b"), ObjectNode("c")
    aux = (Action("reach-goal-1", (Atom("c"),), (reached,), candidate=c),
           Action("reach-goal-2", (Atom("b"),), (reached,), candidate=b))
    task = PlanningTask(task.domain, task.problem, task.encoding, 3, task.predicates + (Predicate("goal-reached"),),
                        task.actions + aux, task.init, (reached,))
    assert candidate_atoms(task, (b, c)) == {b: (Atom("b"),), c: (Atom("c"),)}  # by candidate, not by position
    assert list(candidate_atoms(task, (b, c))) == [b, c]
    with pytest.raises(ValueError, match="one goal action per candidate"):
        candidate_atoms(task, (b, c, ObjectNode("d")))
    with pytest.raises(ValueError, match="one goal action per candidate"):
        candidate_atoms(task, (b,))
    single = chain_task()
    assert candidate_atoms(single, (c,)) == {c: (Atom("c"),)}  # one candidate: the goal is its atoms


# ------------------------------------------------------------------ external commands


def _script(tmp_path, body: str) -> str:
    path = tmp_path / "planner.py"
    path.write_text(textwrap.dedent(body))
    return f"{sys.executable} {path} {{domain}} {{problem}} {{plan}}"


def test_external_command_plan_is_read_back(tmp_path):
    cmd = _script(tmp_path, """
        import sys
        assert "(define" in open(sys.argv[1]).read()
        open(sys.argv[3], "w").write("; found\\n(MK-B)\\n(mk-c)\\n; cost = 2 (unit cost)\\n")
    """)
    task = chain_task()
    result = external.solve(cmd, *render(task))
    assert (result.status, result.plan) == ("solved", ("mk-b", "mk-c"))


@pytest.mark.parametrize(
    ("body", "status"),
    [("import sys; sys.exit(0)", "error"),  # no plan and no word on why: a planner error (issue 11)
     ("print('Completely explored state space -- no solution!')", "unsolvable"),
     ("import sys; sys.exit(11)", "unsolvable"),
     ("import sys; sys.exit(12)", "gave up"),  # an incomplete search stopped: no proof
     ("raise SystemExit('crash')", "error"),
     ("import time; time.sleep(30)", "timeout")],
)
def test_external_command_statuses(tmp_path, body, status):
    result = external.solve(_script(tmp_path, body), *render(chain_task()), time_limit=1.0)
    assert result.status == status


def test_external_command_that_cannot_start_is_an_error():
    assert external.solve("/nonexistent/planner {domain}", "d", "p").status == "error"
    assert external.solve("'unbalanced", "d", "p").status == "error"


def test_external_pyperplan_solves_via_its_solution_file():
    task = chain_task()
    result = run_planner(task, *render(task), planner_cmd=f"{sys.executable} -m pyperplan {{domain}} {{problem}}")
    assert result.status == "solved"
    assert result.plan in (("mk-b", "mk-c"), ("direct-c",))


# ------------------------------------------------------------------ random delete-free tasks (hypothesis)

FACTS = [f"f{i}" for i in range(7)]


@st.composite
def delete_free_tasks(draw):
    """A random delete-free STRIPS task whose goal is a disjunction of conjunctions (via goal actions)."""
    subsets = st.lists(st.sampled_from(FACTS), max_size=3, unique=True).map(lambda xs: tuple(sorted(xs)))
    actions = [Action(f"a{i}", tuple(Atom(f) for f in draw(subsets)),
                      tuple(Atom(f) for f in draw(subsets.filter(bool))), unit=i)
               for i in range(draw(st.integers(1, 7)))]
    init = tuple(Atom(f) for f in draw(subsets))
    alternatives = draw(st.lists(subsets.filter(bool), min_size=1, max_size=3, unique=True))
    reached = Atom("goal-reached")
    aux = [Action(f"reach-goal-{k}", tuple(Atom(f) for f in alt), (reached,), candidate=ObjectNode(f"goal {k}"))
           for k, alt in enumerate(alternatives)]
    task = PlanningTask("rnd", "p", "tree", 3, tuple(Predicate(f) for f in [*FACTS, "goal-reached"]),
                        tuple(actions + aux), tuple(sorted(init)), (reached,))
    return task, [tuple(Atom(f) for f in alt) for alt in alternatives]


def closure(task: PlanningTask) -> set[Atom]:
    have = set(task.init)
    changed = True
    while changed:
        changed = False
        for a in task.actions:
            if a.unit is not None and set(a.pre) <= have and not set(a.add) <= have:
                have |= set(a.add)
                changed = True
    return have


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(delete_free_tasks())
def test_fd_fresh_and_reused_solve_exactly_the_reachable_goals(case):
    task, alternatives = case
    have = closure(task)
    expected = "solved" if any(set(alt) <= have for alt in alternatives) else "unsolvable"
    nodes = tuple(ObjectNode(f"goal {k}") for k in range(len(alternatives)))
    assert list(candidate_atoms(task, nodes).values()) == alternatives
    fresh = run_planner(task, *render(task))
    reused = TranslatedTask.build(task).solve(alternatives)
    assert fresh.status == reused.status == expected
    for result in (fresh, reused):
        state = set(task.init)
        for step in result.plan:  # every plan is executable and reaches an alternative
            action = task.action_for(step)
            assert set(action.pre) <= state
            state |= set(action.add)
        if expected == "solved":
            assert any(set(alt) <= state for alt in alternatives)
