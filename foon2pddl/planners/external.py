"""Any planner as a command: `--planner-cmd 'cmd {domain} {problem} {plan}'`.

The command (or a preset name, `commands.PRESETS`) is split like a shell would
(shlex), its executable and relative paths resolved against the caller's working
directory and PATH (`commands.resolve_command`), and run without a shell, in its
own temporary directory, with `{domain}`, `{problem}`, `{plan}` (and `{time}`,
the time limit in whole seconds) replaced by paths in that directory. The plan
is read back as an IPC plan file (`(action arg ...)` lines, `;` comments) from
`{plan}`, or, when the planner writes elsewhere, from `sas_plan` (Fast
Downward's default) or `problem.pddl.soln` (pyperplan's). A planner that exits
without a plan reports the task unsolvable only when it says so: Fast
Downward's unsolvable codes 10-11, or output such as "unsolvable" or "no
solution" (`SAYS_UNSOLVABLE`); its codes 12-13 (search stopped without a proof)
are `gave up`; otherwise it is an error (a crash that exits 0 must not pass for a proof). Its codes 1-3 with a plan still mean a plan was
found; the plan is validated anyway.
"""

from __future__ import annotations

import math
import re
import tempfile
import time
from pathlib import Path

from .commands import PRESETS, resolve_command
from .process import bounded_timeout, run_process
from .result import PlanResult, parse_plan_text, tail

#: What planners print when they conclude there is no plan (FD, pyperplan, common wordings).
SAYS_UNSOLVABLE = re.compile(r"unsolvable|no solution|no plan (?:was |could be )?found|"
                             r"search stopped without finding a solution|goal (?:is )?unreachable", re.I)


def solve(cmd: str, domain_text: str, problem_text: str, *, time_limit: float | None = None) -> PlanResult:
    """Run a planner command on PDDL text and read its plan."""
    name = "external"
    try:
        words = resolve_command(cmd)  # here, before the run moves to its temporary directory
    except ValueError as exc:
        return PlanResult("error", (), name, f"bad planner command {cmd!r}: {exc}")
    name = f"external ({cmd.strip() if cmd.strip() in PRESETS else Path(words[0]).name})"
    with tempfile.TemporaryDirectory(prefix="foon2pddl-ext-") as tmp:
        work = Path(tmp)
        t0 = time.perf_counter()
        domain, problem, plan = work / "domain.pddl", work / "problem.pddl", work / "plan.txt"
        domain.write_text(domain_text)
        problem.write_text(problem_text)
        write_s = time.perf_counter() - t0
        bounded = bounded_timeout(time_limit)
        seconds = "" if bounded is None else str(max(1, math.ceil(bounded)))
        subst = {"{domain}": str(domain), "{problem}": str(problem), "{plan}": str(plan), "{time}": seconds}
        argv = []
        for word in words:
            for key, value in subst.items():
                word = word.replace(key, value)
            argv.append(word)
        try:
            run = run_process(argv, work, bounded)
        except OSError as exc:
            return PlanResult("error", (), name, f"cannot run planner command: {exc}", {"write": write_s})
        timings = {"write": write_s, "search": run.seconds}
        if run.timed_out:
            return PlanResult("timeout", (), name, "time limit reached", timings)
        found = next((p for p in (plan, work / "sas_plan", work / "problem.pddl.soln") if p.is_file()), None)
        if found is not None and run.returncode in (0, 1, 2, 3):
            return PlanResult("solved", parse_plan_text(found.read_text(errors="replace")), name, "plan found", timings)
        if run.returncode in (12, 13):  # Fast Downward's codes for a search that stopped without a proof
            return PlanResult("gave up", (), name, f"planner wrote no plan (exit code {run.returncode})", timings)
        if run.returncode in (10, 11) or (run.returncode == 0 and SAYS_UNSOLVABLE.search(run.output)):
            return PlanResult("unsolvable", (), name, f"planner wrote no plan (exit code {run.returncode})", timings)
        what = "wrote no plan and did not say the task is unsolvable" if run.returncode == 0 else "exit code"
        return PlanResult("error", (), name, f"planner {what} (exit code {run.returncode}): {tail(run.output)}",
                          timings)
