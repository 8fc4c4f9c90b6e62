"""A CPU budget for planner runs (`cpu_limit`): the small relational task's retry window is the planner's CPU time,
which a loaded machine does not stretch (at load 4-5 the odd-index universal FOON's chocolate cake spent its 10 s
of wall time translating, 7 s of CPU, and was planned wide)."""

from __future__ import annotations

import signal
import sys

from foon2pddl.pddl.task import PlanningTask
from foon2pddl.planners import fd
from foon2pddl.planners.process import ProcessRun, cpu_limit, run_process
from foon2pddl.planners.registry import PlanRequest
from foon2pddl.planners.result import PlanResult


def test_the_cpu_budget_is_the_runs_cpu_limit_when_lower_than_the_backstop():
    assert cpu_limit(3.0) == 7 and cpu_limit(None) is None
    assert cpu_limit(60.0, 10.0) == 10 and cpu_limit(None, 2.5) == 3 and cpu_limit(None, 0.2) == 1
    assert cpu_limit(3.0, 10.0) == 7  # the wall limit's backstop stays when it is lower


def test_a_run_past_its_cpu_budget_is_stopped_and_says_the_cpu_it_used(tmp_path):
    run = run_process([sys.executable, "-c", "while True: pass"], tmp_path, 60.0, cpu=1.0)
    assert run.returncode == -signal.SIGXCPU and not run.timed_out
    assert run.cpu is not None and 0.5 <= run.cpu < 30  # the kernel counts CPU finer than rusage reports it


def test_the_search_gets_what_translation_left_of_the_budget(tmp_path, monkeypatch):
    asked = {}
    monkeypatch.setattr(fd, "translate", lambda *a, **k: asked.update(translate=k["cpu"]) or ProcessRun(0, "", 9.0,
                                                                                                       cpu=2.5))

    def search(cwd, options, timeout, name, **k):
        asked["search"] = k["cpu"]
        return PlanResult("solved", ("a",), name, "plan found", {"search": 0.5}, cpu=0.5)

    monkeypatch.setattr(fd, "search", search)
    result = fd.solve("(define (domain d))", "(define (problem p))", time_limit=60, cpu_limit=10.0)
    assert asked == {"translate": 10.0, "search": 7.5}
    assert result.solved and result.cpu == 3.0 and result.timings["translate"] == 9.0


def test_a_search_killed_at_its_cpu_budget_timed_out(tmp_path, monkeypatch):
    monkeypatch.setattr(fd, "run_process", lambda *a, **k: ProcessRun(-signal.SIGXCPU, "", 1.5, cpu=1.0))
    result = fd.search(tmp_path, (), 60.0, "fd", sas_text="", cpu=1.0)
    assert result.status == "timeout" and result.message == "time limit reached during search"
    assert result.cpu == 1.0
    assert fd.search(tmp_path, (), 60.0, "fd", sas_text="", cpu=-0.5).status == "timeout"


def test_a_planner_that_cannot_bound_cpu_takes_the_budget_as_wall_time():
    task = PlanningTask("d", "p", "tree", 3, (), (), (), ())
    assert PlanRequest(task, "", "", "x", time_limit=60, cpu_limit=10).wall_limit == 10
    assert PlanRequest(task, "", "", "x", time_limit=5, cpu_limit=10).wall_limit == 5
    assert PlanRequest(task, "", "", "x").wall_limit is None
