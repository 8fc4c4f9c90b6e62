"""bench/planner_compat: the planner x encoding table, with the planners every install has (FD, pyperplan)."""

from __future__ import annotations

from bench.planner_compat import Cell, available, measure, table, validated
from foon2pddl.pddl.compile import compile_task
from foon2pddl.pddl.render import render


def test_fd_and_pyperplan_read_and_solve_tree_and_gen_lifted(tmp_path):
    planners = ["fd", "up:pyperplan"]
    cells = measure(planners, {}, ["tree", "gen-lifted"], ["whipped cream"], 60, log=open(tmp_path / "log", "w"))
    assert {k: (c.tried, c.parsed, c.solved) for k, c in cells.items()} == {
        ("fd", "tree"): (1, 1, 1), ("up:pyperplan", "tree"): (1, 1, 1),
        ("fd", "gen-lifted"): (2, 2, 2), ("up:pyperplan", "gen-lifted"): (2, 2, 2)}  # + lemonade
    text = table(cells, planners, ["tree", "gen-lifted"], 60)
    assert "| up:pyperplan | gen-lifted | 2/2 | 2/2 |  |" in text and "planners available: fd, up:pyperplan" in text


def test_a_wrong_plan_is_not_counted_and_missing_engines_are_named():
    from foon2pddl.io.goal_files import parse_goal_spec
    from foon2pddl.io.inputs import load_kitchen, load_network
    from foon2pddl.model.goal import resolve_goal

    net = load_network([])
    task = compile_task(net.at(3), load_kitchen(None, net, 3),
                        resolve_goal(parse_goal_spec("whipped cream"), net.at(3)), "tree")
    domain, problem = render(task)
    last = task.actions[-1].name
    assert validated(domain, problem, (last,)) is not None  # its preconditions do not hold at the start
    assert validated(domain, problem, ("no-such-action",)).startswith("plan not checkable")
    assert available(["fd", "up:no-such-engine"]) == (["fd"], ["up:no-such-engine"])
    cell = Cell(2, 1, 0)
    cell.notes["timeout: time limit reached"] += 2
    assert cell.text() == ("1/2", "0/2", "timeout: time limit reached (2)")
