"""Replay of a physical trace against FOON's nodes: every bound object is where its role needs it.

Independent of the PDDL that produced the plan: starting from the trace's
initial states, each step's bindings must name distinct objects of the role's
label, each in the node its role needs (`Binding.before`; not yet made for a new
object), and at the end some existing object must be in a goal candidate's node.
The first failing step ends the replay (later states follow from a broken one).
Holders are checked by the relational replay (`physical_replay`) for encodings
that model them. O(steps x bindings).

`emptied`: per step, the nodes of the holders it emptied that its unit does not list (the stove a pan is taken
off ends `stove (on)`): what the task tree's check takes as left by that step beside the unit's outputs, and
`emptied_notes` says where a later step takes such a node that nothing else gave it.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import ObjectNode
from ..model.physical import PhysicalTrace
from ..model.places import listed
from ..model.tasktree import Validation
from ..pddl.relational_plan import without
from ..pddl.trace_view import show_node, step_text

__all__ = ["check_states", "emptied", "emptied_notes"]


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


def emptied(trace: PhysicalTrace) -> tuple[tuple[ObjectNode, ...], ...]:
    """Per step, the node each object bound to it ends in when that is its node before with only items of its list
    gone (`relational_plan.without`: the stove the pick-and-place takes the pan off, `stove (on, with [pan])` ->
    `stove (on)`), and the unit's outputs do not have it. O(steps x bindings)."""
    return tuple(tuple(b.after for b in step.bindings if b.before is not None and b.after not in (None, b.before)
                       and b.after not in step.unit.outputs
                       and b.after == without(b.before, listed(b.before) - listed(b.after)))
                 for step in trace.steps)


def emptied_notes(trace: PhysicalTrace, given: Iterable[ObjectNode],
                  left: tuple[tuple[ObjectNode, ...], ...]) -> tuple[str, ...]:
    """One note per node of `left` (`emptied(trace)`, computed once by the caller) a later step takes that neither
    `given` (the kitchen the tree is checked from) nor an earlier unit's outputs hold, naming both steps with
    their file:line. O(steps^2 x inputs)."""
    have, out = set(given), []
    for k, step in enumerate(trace.steps):
        for node in dict.fromkeys(x for x in step.unit.inputs if x not in have):
            by = next((j for j in range(k - 1, -1, -1) if node in left[j]), None)
            if by is not None:
                out.append(f"tree check: step {k + 1} ({step.unit.motion.label}, {step.source}) takes "
                           f"{node.describe()}, which step {by + 1} ({trace.steps[by].unit.motion.label}, "
                           f"{trace.steps[by].source}) leaves by emptying it: its unit does not list it")
        have.update(step.unit.outputs)
    return tuple(dict.fromkeys(out))
