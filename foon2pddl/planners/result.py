"""What every planner returns: a status, the plan's steps, a message and timings.

Statuses (`status.PlanStatus`): `solved` (a plan was found), `unsolvable` (the
planner proved there is none), `gave up` (its search stopped without a plan or a
proof), `timeout` (the time limit ran out first), `error` (the planner failed or does not support the task). Plan steps are the
lower-cased text between the parentheses of an IPC plan line: the action name,
then any arguments separated by single spaces.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

from ..status import PlanStatus

#: Every plan status, in report order.
STATUSES = tuple(PlanStatus)


@dataclass(frozen=True)
class PlanResult:
    """Outcome of one planner run."""

    status: PlanStatus
    plan: tuple[str, ...] = ()
    planner: str = ""
    message: str = ""
    timings: dict[str, float] = field(default_factory=dict, compare=False, hash=False)
    #: CPU seconds the planner's processes used, when measured (Fast Downward's; None otherwise).
    cpu: float | None = field(default=None, compare=False, hash=False)

    def __post_init__(self) -> None:
        # Accept the plain strings too (`PlanStatus("solved")`); anything else is a bug.
        object.__setattr__(self, "status", PlanStatus(self.status))

    @property
    def solved(self) -> bool:
        return self.status == PlanStatus.SOLVED

    def with_timings(self, **extra: float) -> PlanResult:
        """A copy with more phase timings (seconds)."""
        return replace(self, timings={**self.timings, **extra})


def parse_plan_text(text: str) -> tuple[str, ...]:
    """Steps of an IPC plan file: one `(action arg ...)` per line, `;` starts a comment."""
    steps = []
    for raw in text.splitlines():
        line = raw.split(";", 1)[0].strip()
        if not line:
            continue
        if line.startswith("(") and line.endswith(")"):
            line = line[1:-1]
        line = " ".join(line.lower().split())
        if line:
            steps.append(line)
    return tuple(steps)


def sas_plan_text(steps, cost: int | None = None) -> str:
    """A plan in Fast Downward's `sas_plan` format (what VAL and other tools read): one
    `(action arg ...)` per line, then `; cost = N (unit cost)`, or `(general cost)` when
    `cost` (the sum of action costs) is given."""
    kind = "unit cost" if cost is None else "general cost"
    total = len(steps) if cost is None else cost
    return "".join(f"({s})\n" for s in steps) + f"; cost = {total} ({kind})\n"


def plan_cost(task, steps) -> int | None:
    """The sum of the steps' action costs when `task` (a PlanningTask) has action costs, else None."""
    if all(a.cost is None for a in task.actions):
        return None
    return sum((task.action_for(step_action(s)).cost or 0) for s in steps)


def step_action(step: str) -> str:
    """The action name of a plan step."""
    return step.split(" ", 1)[0]


#: A Python traceback's frame line (`  File "x.py", line 3, in main`).
_FRAME = re.compile(r'^\s+File ".*", line \d+')


def tail(text: str, lines: int = 8) -> str:
    """The last lines of a process's output, for error messages. When it ends in a Python traceback (a planner
    written in Python that raised: pyperplan on `forall`), its exception: the lines after the last frame and
    that frame's indented source lines, not a stack cut `lines` from the end. O(n) in the output's lines."""
    kept = text.strip().splitlines()
    frames = [i for i, line in enumerate(kept) if _FRAME.match(line)]
    if frames:
        after = kept[frames[-1] + 1:]
        while after and after[0][:1].isspace():
            after = after[1:]
        if after:
            return "\n".join(after[-lines:])
    return "\n".join(kept[-lines:])
