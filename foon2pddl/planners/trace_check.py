"""Replay of a physical trace against FOON's nodes: every bound object is where its role needs it.

Independent of the PDDL that produced the plan: starting from the trace's
initial states, each step's bindings must name distinct objects of the role's
label, each in the node its role needs (`Binding.before`; not yet made for a new
object), and at the end some existing object must be in a goal candidate's node.
The first failing step ends the replay (later states follow from a broken one).
Holders are checked by the relational replay (`physical_replay`) for encodings
that model them. O(steps x bindings).
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import ObjectNode
from ..model.physical import PhysicalTrace
from ..model.tasktree import Validation
from ..pddl.trace_view import show_node, step_text

__all__ = ["check_states"]


def check_states(trace: PhysicalTrace, candidates: Iterable[ObjectNode]) -> Validation:
    """The trace replayed on FOON's nodes (see the module doc)."""
    problems: list[str] = []
    for step, state in zip(trace.steps, trace.states(), strict=False):
        where = f"step {step.index + 1} ({step_text(step)})"
        names = step.objects
        if len(set(names)) != len(names):
            problems.append(f"{where}: one instance bound to two objects of the unit")
        for b in step.bindings:
            label = trace.by_id[b.object].label
            node = b.before if b.before is not None else b.after
            need = label if node is None else node.label
            have = state[b.object]
            if label != need:
                problems.append(f"{where}: {b.object} is a {label}, the unit needs a {need}")
            elif have.node != b.before or (have.consumed and b.before is not None):
                now = "consumed" if have.consumed else show_node(have.node)
                problems.append(f"{where}: {b.object} is {now}, the unit needs it {show_node(b.before)}")
        if problems:
            return Validation(False, tuple(problems))
    wanted = set(candidates)
    if not any(s.node in wanted and not s.consumed for s in trace.final.values()):
        problems.append("goal not reached: no instance is in a goal candidate's state at the end")
    return Validation(not problems, tuple(problems))
