"""A plan's macro steps decomposed into robot skills, solved per step, then replayed end to end.

For each step of a `PhysicalTrace`: the motion's skill (`skills.table`; its `by_hand` skill when the step lists no tool); none,
and the step stays **abstract** (reported by its motion, kept in place). Otherwise
its micro problem (`skills.micro`) is solved with Fast Downward on the skill
domain pruned to the transport skills and the step's own (`skills.fd_micro`), once
per shape (`skills.memo`: a task equal to an earlier step's up to renaming objects
takes its plan, renamed back), the plan rid of skills the step does not need
(`skills.shorten`); a step whose micro task has no plan (or whose skill the robot lacks) is **failed**
(a `dip` with nothing in its source to take is first tried as transport, `FALLBACK`),
with the planner's reason, and kept as an abstract step too. The skill sequences
are concatenated and replayed from the start by `skills.replay`, which checks
every precondition and, after every macro step, that the state is the trace's.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from enum import StrEnum

from ..model.physical import PhysicalTrace, Relation
from ..model.tasktree import Validation
from ..pddl.task import Atom, PlanningTask
from ..planners.process import cpu_seconds
from .domain import TRANSPORT, SkillDomain
from .fd_micro import solve_micro
from .memo import MicroMemo
from .micro import MicroProblem, Naming, _roles, dynamic_facts, micro_problem, set_aside
from .profile import Robot
from .replay import Replayer, SkillError, check
from .shorten import irredundant
from .table import MotionTable

__all__ = ["MacroSkills", "SkillCall", "SkillPlan", "StepStatus", "decompose", "uncarried"]


class StepStatus(StrEnum):
    """How a macro step came out: decomposed into skills, abstract (motion not mapped), or failed."""

    DECOMPOSED = "decomposed"
    ABSTRACT = "abstract"
    FAILED = "failed"


@dataclass(frozen=True)
class SkillCall:
    """One skill of a plan: macro step index (0-based), skill, hand, the objects it names (trace ids, or
    `workspace`), and each object's holder just before the skill (an id, a hand, or None: on the workspace)."""

    macro: int
    skill: str
    hand: str
    objects: tuple[str, ...]
    holders: tuple[str | None, ...]


@dataclass(frozen=True)
class MacroSkills:
    """One macro step: its index, motion, unit source (`file:line`), skill, status, reason and skill calls."""

    index: int
    motion: str
    source: str
    skill: str | None
    status: StepStatus
    reason: str
    calls: tuple[SkillCall, ...]
    problem: MicroProblem | None
    seconds: float  # planning this step (micro problem, memo lookup, translate + search): wall
    what: str = ""  # the unit: `lime (whole), knife -> lime (halved)`
    cpu: float = 0.0  # the same, CPU of this process and of the planner processes it waited for
    reused: bool = False  # the plan of an earlier step's equal micro task, renamed (`skills.memo`)


@dataclass(frozen=True)
class SkillPlan:
    """Every macro step with its skills, the replay's verdict, and the domain used."""

    steps: tuple[MacroSkills, ...]
    replay: Validation
    domain: SkillDomain

    @property
    def calls(self) -> tuple[SkillCall, ...]:
        return tuple(c for s in self.steps for c in s.calls)

    @property
    def decomposed(self) -> int:
        return sum(s.status is StepStatus.DECOMPOSED for s in self.steps)

    @property
    def share(self) -> float:
        """Share of macro steps that decomposed (1.0 for a plan without steps)."""
        return self.decomposed / len(self.steps) if self.steps else 1.0

    @property
    def ok(self) -> bool:
        """Every step decomposed and the replay holds."""
        return self.replay.ok and self.decomposed == len(self.steps)


#: A skill whose step, when it finds no plan, is carried out by transport: a FOON `dip` whose source holds
#: nothing to take (chopped onion and garlic on a board "dipped" into a bowl of ground beef, 0032
#: cheeseburger) moves them with pick and put-in.
FALLBACK = {"dip": "put-in"}

Solver = Callable[[str, str], tuple[str, tuple[str, ...], str, float]]


def _fd(domain_text: str, problem_text: str) -> tuple[str, tuple[str, ...], str, float]:
    r = solve_micro(domain_text, problem_text)
    return str(r.status), r.plan, r.message, r.timings.get("translate", 0.0) + r.timings.get("search", 0.0)


def _plan_step(trace: PhysicalTrace, index: int, table: MotionTable, domain: SkillDomain, robot: Robot,
               naming: Naming, roles, solver: Solver, memo: MicroMemo) -> tuple[MacroSkills, tuple[tuple[str, tuple[str, ...]], ...]]:
    wall0, cpu0 = time.perf_counter(), cpu_seconds()
    step = trace.steps[index]
    motion = step.unit.motion.label
    skill = table.skill_of(motion)

    def out(status, reason, problem=None, calls=(), reused=False):
        what = step.unit.describe().split(": ", 1)[-1]
        return MacroSkills(index, motion, step.source, skill, status, reason, (), problem,
                           time.perf_counter() - wall0, what, cpu_seconds() - cpu0, reused), calls

    if skill is None:
        return out(StepStatus.ABSTRACT, f"motion {motion!r} has no skill in the motion table")
    if robot.lacks(skill):
        return out(StepStatus.FAILED, f"the robot has no {skill} skill (motion {motion!r})")
    if skill not in domain.by_name:
        return out(StepStatus.FAILED, f"skill {skill!r} is not defined in {domain.path}")
    problem = micro_problem(trace, index, skill, naming, domain, roles)
    hand = table.hand_skill_of(motion)
    if hand is not None and hand in domain.by_name and not _has_tool(problem):
        if robot.lacks(hand):
            return out(StepStatus.FAILED, f"the step lists no tool and the robot has no {hand} skill (motion {motion!r})")
        skill = hand
        problem = micro_problem(trace, index, skill, naming, domain, roles)

    def finish(found: tuple[str, ...], task: PlanningTask) -> tuple[str, ...]:
        return irredundant(found, domain, dict(task.objects), task.init, task.goal)

    def attempt(problem: MicroProblem):
        keep = {a for a in problem.actions if not robot.lacks(a)}
        return memo.solve(solver, domain.pruned(keep, robot.cost_table, problem.init), problem,
                          (*naming.hands, naming.workspace), finish)

    (status, plan, message, _), reused = attempt(problem)
    other = FALLBACK.get(skill)
    if status != "solved" and other in domain.by_name and not robot.lacks(other):
        moved = micro_problem(trace, index, other, naming, domain, roles)
        (status2, plan2, message2, _), reused2 = attempt(moved)
        if status2 == "solved":
            skill, problem, status, plan, reused = other, moved, status2, plan2, reused2
    if status != "solved" and "?t" in {v for v, _ in domain.by_name[skill].params} and not _has_tool(problem):
        lacking = (f"the motion table gives {motion!r} no by-hand skill" if hand is None else
                   f"the motion table's by-hand skill {hand!r} for {motion!r} is not defined in {domain.path}")
        lying = "; ".join(f"{o} is {'in' if r is Relation.IN else 'on'} {h}" for o, r, h in set_aside(trace, index))
        why = f": {lying}, a place the step names, so not taken as a tool" if lying else ""
        return out(StepStatus.FAILED, f"the step lists no tool to {skill} with (none stands free on the table{why}) "
                   "and " + lacking, problem, reused=reused)
    if status != "solved":
        return out(StepStatus.FAILED, f"micro task {status}: {message}", problem, reused=reused)
    calls = tuple((line.split()[0], tuple(line.split()[1:])) for line in plan)
    return out(StepStatus.DECOMPOSED, "", problem, calls, reused)


def _has_tool(problem: MicroProblem) -> bool:
    return any(a.predicate == "tool" for a in problem.statics)


def decompose(trace: PhysicalTrace, table: MotionTable, domain: SkillDomain, robot: Robot | None = None,
              solver: Solver = _fd, memo: MicroMemo | None = None) -> SkillPlan:
    """Decompose and replay (see the module doc). One micro task per step, solved once per shape (`skills.memo`:
    a step whose task equals an earlier one's up to renaming objects takes its plan, renamed); the replay is
    linear in the skills.

    `robot`: default one hand, every skill, each costing 1. `solver(domain text, problem text)` returns
    (status, plan lines, message, seconds); default Fast Downward (`fd_micro`). `memo`: default a fresh one
    (the result depends on this trace alone); pass one to share solved shapes between plans.
    """
    robot = robot if robot is not None else Robot()
    memo = memo if memo is not None else MicroMemo()
    naming = Naming(trace, domain, robot.hands)
    roles = _roles(trace)
    everyone = tuple(o.id for o in trace.objects)
    types = {**{h: "hand" for h in naming.hands}, naming.workspace: "thing", **{n: "thing" for n in naming.ids.values()}}
    base = {Atom("placed", (naming.workspace,))} | {Atom("hand-empty", (h,)) for h in naming.hands}
    planned = [_plan_step(trace, k, table, domain, robot, naming, roles, solver, memo) for k in range(len(trace.steps))]
    for states in trace.states():  # name every phase before the replay's universe is fixed
        dynamic_facts(naming, states, everyone)
    phases = {n: "phase" for (key, n) in _phase_names(naming)}
    rep = Replayer(domain, {**types, **phases}, dynamic_facts(naming, trace.after(-1), everyone) | base,
                   robot.cost_table)
    problems: list[str] = []
    steps = []
    for (macro, calls) in planned:
        done = []
        if not problems and macro.status is StepStatus.DECOMPOSED:
            rep.add(macro.problem.statics | macro.problem.split)  # a portion now stands where its source is
            rep.remove({Atom("unmade", (a.args[0],)) for a in macro.problem.split if a.predicate == "placed"})
            rep.remove({old for old, _ in macro.problem.restated})  # FOON restates what the step does not move
            rep.add({new for _, new in macro.problem.restated})
            for name, args in calls:
                things = args[1:]
                holders = tuple(None if h == naming.workspace else _back(naming, h) for h in map(rep.holder, things))
                try:
                    rep.apply(name, args)
                except SkillError as exc:
                    problems.append(f"step {macro.index + 1} ({macro.source}): {exc}")
                    break
                done.append(SkillCall(macro.index, name, args[0], tuple(_back(naming, a) for a in things), holders))
            rep.remove(macro.problem.statics)
        expected = dynamic_facts(naming, trace.after(macro.index), everyone) | base
        if not problems:
            if macro.status is StepStatus.DECOMPOSED:
                diff = check(rep, expected)
                if diff:
                    problems.append(f"after step {macro.index + 1} ({macro.source}): " + "; ".join(diff))
            else:
                rep.reset_dynamic(expected)
        steps.append(replace(macro, calls=tuple(done)))
    return SkillPlan(tuple(steps), Validation(not problems, tuple(problems)), domain)


def _phase_names(naming: Naming):
    """(label, name) of every phase name handed out so far."""
    return [(label, name) for name, label in naming.table.labels.items() if label.startswith("phase ")]


def _back(naming: Naming, name: str | None) -> str | None:
    if name is None or name == naming.workspace:
        return None if name is None else "workspace"
    return naming.back.get(name, name)


def uncarried(plan: SkillPlan, trace: PhysicalTrace) -> list[tuple[int, str]]:
    """(step index, object id) of every object that stands free before a decomposed step (the robot can grasp
    it), is in or on something else after it, and is named by no transport skill of that step: moved by a
    skill that does not hold it (floor 0; `bench.skills` counts them). Read from the trace and the skill calls
    alone, not from the micro problems, so it checks what `skills.micro` builds. O(steps x objects)."""
    out = []
    for s in plan.steps:
        if s.status is not StepStatus.DECOMPOSED:
            continue
        before, after = trace.after(s.index - 1), trace.after(s.index)
        carried = {c.objects[0] for c in s.calls if c.skill in TRANSPORT}
        out += [(s.index, oid) for oid, b in sorted(before.items())
                if b.exists and after[oid].exists and b.holder is None and after[oid].holder is not None
                and oid not in carried]
    return out
