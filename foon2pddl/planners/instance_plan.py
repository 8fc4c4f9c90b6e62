"""Plans of the `instances` encoding at the level of physical objects.

`instance_steps` maps each plan step to its functional unit and the instance
bound to each of the unit's objects (`Action.roles`, one per parameter); a unit
may fire several times with different instances. `simulate_instances` checks
the plan independently of the PDDL: it replays the units on the instances with
FOON's own nodes (`pairing.Role`: each role's instance must be in the role's
input node, or not yet made for a new object; moved and new objects go to the
output node), and records the state of every instance after every step.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from ..model.foon import FunctionalUnit, ObjectNode
from ..model.tasktree import Validation
from ..pddl.pairing import Role, RoleKind
from ..pddl.task import PlanningTask
from .result import step_action


class InstancePlanError(ValueError):
    """A plan step that names no action of the task, or binds the wrong number of objects."""


@dataclass(frozen=True)
class InstanceStep:
    """One firing of a unit: its index in `task.units`, the unit, and the instance bound to each role."""

    index: int
    unit: FunctionalUnit
    bindings: tuple[tuple[Role, str], ...]

    def text(self) -> str:
        """`cut lime_1 on cutting_board_1 with knife_1`: the motion, changed objects, then the others.

        Objects the unit changes or makes come first; the others follow after `with`.
        """
        changed = [name for role, name in self.bindings if role.changes]
        others = [name for role, name in self.bindings if not role.changes]
        text = " ".join([self.unit.motion.label, ", ".join(changed)]).strip()
        return text + (f" with {', '.join(others)}" if others else "")

    def detail(self) -> str:
        """Every binding: `lime_1: lime (whole) -> lime (halved)`."""
        parts = []
        for role, name in self.bindings:
            before = role.before.describe() if role.before is not None else "(not yet made)"
            after = role.after.describe() if role.changes and role.after is not None else "unchanged"
            parts.append(f"{name}: {before} -> {after}")
        return "; ".join(parts)


def instance_steps(task: PlanningTask, steps: Sequence[str]) -> tuple[InstanceStep, ...]:
    """The unit firings of a plan with every object's instance; auxiliary steps (goal actions) skipped.

    Objects bound by a parameter take the plan's argument. The others (read-only
    objects in a stable state, checked by `(occupied s)`) take the first instance,
    by name, that the replayed plan has in the required state, or `?` when none
    is: `simulate_instances` then reports the step. InstancePlanError when a step
    names no action or has the wrong number of arguments.
    """
    state: dict[str, ObjectNode | None] = {name: start for name, _, start in task.instances}
    label = {name: lab for name, lab, _ in task.instances}
    out = []
    for n, step in enumerate(steps, start=1):
        action = task.action_for(step_action(step))
        if action is None:
            raise InstancePlanError(f"plan step {n} ({step}) names no action of the task")
        if action.unit is None:
            continue
        args = step.split()[1:]
        if len(args) != len(action.params):
            raise InstancePlanError(f"plan step {n} ({step}): {len(action.params)} arguments expected, "
                                    f"got {len(args)}")
        given = iter(args)
        names = [next(given) if bound else None for _, bound in action.roles]
        for k, (role, bound) in enumerate(action.roles):
            if not bound:
                names[k] = next((x for x in sorted(state) if label[x] == role.label and state[x] == role.before
                                 and x not in names), "?")
        bindings = tuple((role, name) for (role, _), name in zip(action.roles, names, strict=True))
        for role, name in bindings:
            if role.changes and name in state:
                state[name] = role.after
        out.append(InstanceStep(action.unit, task.units[action.unit], bindings))
    return tuple(out)


@dataclass(frozen=True)
class InstanceTrace:
    """The instance-level simulation of a plan: verdict, problems, and every instance's node after each step.

    `states[0]` is the start, `states[k]` the state after step k; None = not yet made.
    """

    validation: Validation
    states: tuple[dict[str, ObjectNode | None], ...]

    @property
    def ok(self) -> bool:
        return self.validation.ok

    def goal_instance(self, candidates: Iterable[ObjectNode]) -> str | None:
        """The first instance (by name) in a candidate's state at the end."""
        wanted = set(candidates)
        final = self.states[-1]
        return next((name for name in sorted(final) if final[name] in wanted), None)


def simulate_instances(task: PlanningTask, steps: Sequence[InstanceStep],
                       candidates: Iterable[ObjectNode]) -> InstanceTrace:
    """Replay `steps` on the task's instances from their start states (see the module doc)."""
    label = {name: lab for name, lab, _ in task.instances}
    state: dict[str, ObjectNode | None] = {name: start for name, _, start in task.instances}
    states = [dict(state)]
    problems: list[str] = []
    for k, step in enumerate(steps, start=1):
        where = f"step {k} ({step.text()})"
        names = [name for _, name in step.bindings]
        if len(set(names)) != len(names):
            problems.append(f"{where}: one instance bound to two objects of the unit")
        for role, name in step.bindings:
            if name not in state:
                problems.append(f"{where}: {name} is not an instance of the task")
            elif label[name] != role.label:
                problems.append(f"{where}: {name} is a {label[name]}, the unit needs a {role.label}")
            elif state[name] != role.before:
                have = "not yet made" if state[name] is None else state[name].describe()
                want = "not yet made" if role.kind is RoleKind.NEW else role.before.describe()
                problems.append(f"{where}: {name} is {have}, the unit needs it {want}")
        if problems:
            break
        for role, name in step.bindings:
            if role.changes:
                state[name] = role.after
        states.append(dict(state))
    wanted = set(candidates)
    if not problems and not any(node in wanted for node in state.values()):
        problems.append("goal not reached: no instance is in a goal candidate's state at the end")
    return InstanceTrace(Validation(not problems, tuple(problems)), tuple(states))


def trace_lines(trace: InstanceTrace, steps: Sequence[InstanceStep]) -> list[str]:
    """Text of a trace: the start of the instances the plan uses, then after each step the instances it changed."""
    used = {name for step in steps for _, name in step.bindings}
    lines = ["start: " + "; ".join(f"{n}: {_show(s)}" for n, s in sorted(trace.states[0].items()) if n in used)]
    for k, step in enumerate(steps, start=1):
        if k >= len(trace.states):
            break
        before, after = trace.states[k - 1], trace.states[k]
        changed = [f"{n}: {_show(after[n])}" for n in sorted(after) if after[n] != before[n]]
        lines.append(f"{k}. {step.text()}: " + ("; ".join(changed) or "no state change"))
    return lines


def _show(node: ObjectNode | None) -> str:
    return "not yet made" if node is None else node.describe()


def instance_plan_json(steps: Sequence[InstanceStep]) -> list[dict]:
    """The firings as JSON-ready dicts: unit index, motion, text, and per role the instance and its states."""
    return [
        {"step": k, "unit": s.index, "motion": s.unit.motion.label, "text": s.text(),
         "bindings": [{"instance": name, "role": str(role.kind),
                       "before": role.before.describe() if role.before is not None else None,
                       "after": role.after.describe() if role.after is not None else None}
                      for role, name in s.bindings]}
        for k, s in enumerate(steps, start=1)
    ]
