"""Plans of the `instances` encoding as physical traces: the encoding's replay and view hooks.

`instance_trace` maps each plan step to its functional unit and the instance
bound to each of the unit's objects (`Action.roles`, one per parameter), and
records the new node of every object the step moves or makes. A unit may fire
several times with different instances. The encoding does not model which
object holds which, so every holder is None (`in [bowl]` stays part of a node's
state). Whether the plan is physically right (each bound object is in the node
its role needs) is not decided here: `planners.trace_check` replays the trace.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..model.foon import ObjectNode
from ..model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, TraceStep
from ..model.where import unit_where
from .registry import PlanDecodeError
from .task import PlanningTask
from .trace_view import TraceView, binding_kind, show_node, step_text

__all__ = ["INSTANCE_VIEW", "InstancePlanError", "instance_json", "instance_text", "instance_trace",
           "source_of", "trace_lines"]


class InstancePlanError(PlanDecodeError):
    """A plan step that names no action of the task, or binds the wrong number of objects."""


def source_of(unit) -> str:
    """`file.txt:12`, where the unit was read, as messages name it (`unit_where`); empty when unknown."""
    return "" if unit.source is None else unit_where(unit)


def instance_trace(task: PlanningTask, steps: Sequence[str]) -> PhysicalTrace:
    """The plan's unit firings with every object's instance; auxiliary steps (goal actions) skipped.

    Objects bound by a parameter take the plan's argument. The others (read-only
    objects in a stable state, checked by `(occupied s)`) take the first instance,
    by name, that the replayed plan has in the required state (InstancePlanError
    when none is, or when a step names no action or has the wrong number of
    arguments). O(steps x instances).
    """
    state: dict[str, ObjectNode | None] = {x.name: x.start for x in task.instances}
    label = {x.name: x.label for x in task.instances}
    out = []
    for n, step in enumerate(steps, start=1):
        name, *args = step.split()
        action = task.action_for(name)
        if action is None:
            raise InstancePlanError(f"plan step {n} ({step}) names no action of the task")
        if action.unit is None:
            continue
        if len(args) != len(action.params):
            raise InstancePlanError(f"plan step {n} ({step}): {len(action.params)} arguments expected, "
                                    f"got {len(args)}")
        given = iter(args)
        names = [next(given) if bound else None for _, bound in action.roles]
        for k, (role, bound) in enumerate(action.roles):
            if not bound:
                names[k] = next((x for x in sorted(state) if label[x] == role.label and state[x] == role.before
                                 and x not in names), None)
                if names[k] is None:
                    raise InstancePlanError(f"plan step {n} ({step}): no {role.label} is "
                                            f"{show_node(role.before)} for the unit to read")
        unknown = [x for x in names if x not in state]
        if unknown:
            raise InstancePlanError(f"plan step {n} ({step}): {unknown[0]} is not an instance of the task")
        bindings = tuple(Binding(x, role.before, role.after) for (role, _), x in zip(action.roles, names, strict=True))
        changes = []
        for (role, _), x in zip(action.roles, names, strict=True):
            if role.changes:
                state[x] = role.after
                changes.append(ObjectState(x, role.after))
        unit = task.units[action.unit]
        out.append(TraceStep(len(out), unit, bindings, tuple(changes), source_of(unit)))
    return PhysicalTrace(tuple(PhysicalObject(x.name, x.label) for x in task.instances),
                         tuple(ObjectState(x.name, x.start) for x in task.instances), tuple(out))


def trace_lines(trace: PhysicalTrace) -> list[str]:
    """Text of a trace: the start of the objects the plan uses, then after each step the objects it changed."""
    used = {b.object for step in trace.steps for b in step.bindings}
    snapshots = list(trace.states())
    lines = ["start: " + "; ".join(f"{n}: {show_node(s.node)}" for n, s in sorted(snapshots[0].items()) if n in used)]
    for k, step in enumerate(trace.steps, start=1):
        before, after = snapshots[k - 1], snapshots[k]
        moved = [f"{n}: {show_node(after[n].node)}" for n in sorted(after) if after[n] != before[n]]
        lines.append(f"{k}. {step_text(step)}: " + ("; ".join(moved) or "no state change"))
    return lines


def instance_text(task: PlanningTask, trace: PhysicalTrace) -> str:
    """The lines printed after the task tree."""
    return "physical objects, step by step (instances encoding):\n" + "\n".join(trace_lines(trace)) + "\n"


def instance_json(task: PlanningTask, trace: PhysicalTrace) -> list[dict]:
    """The firings as JSON-ready dicts: unit index, motion, text, and per role the instance and its nodes."""
    index: dict[int, int] = {}
    for i, u in enumerate(task.units):
        index.setdefault(id(u), i)
    return [
        {"step": k, "unit": index.get(id(s.unit)), "motion": s.unit.motion.label, "text": step_text(s),
         "bindings": [{"instance": b.object, "role": str(binding_kind(b)),
                       "before": b.before.describe() if b.before is not None else None,
                       "after": b.after.describe() if b.after is not None else None}
                      for b in s.bindings]}
        for k, s in enumerate(trace.steps, start=1)
    ]


INSTANCE_VIEW = TraceView("instances", instance_text, instance_json)
