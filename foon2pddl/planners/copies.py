"""Objects a plan uses one after another where one would do: the copies a restoring unit could spare.

Objects that start in one kitchen node are interchangeable (`knife (clean)`): a bowl of flour and a bowl of
sugar are no copies of each other. An object is *in use* from the first step that binds it as a role to the
last; one consumed in the plan is no copy (it cannot be used again). Per kitchen node, `at_once` is the most
in use at any step, and the node's *copies* are the objects used less that (`copies`, summed per label).
O(steps x bindings + objects x steps).
"""

from __future__ import annotations

from collections import Counter

from ..model.foon import ObjectNode
from ..model.physical import PhysicalTrace

__all__ = ["at_once", "copies", "spans"]


def spans(trace: PhysicalTrace) -> dict[ObjectNode, list[tuple[int, int]]]:
    """Kitchen node -> (first, last) step index of each object that starts there, is bound as a role and is
    never consumed (module doc)."""
    start = {o.id: o.node for o in trace.initial if o.node is not None}
    gone = {c.id for s in trace.steps for c in s.changes if c.consumed}
    used: dict[str, list[int]] = {}
    for k, step in enumerate(trace.steps):
        for b in step.bindings:
            if b.role and b.object in start and b.object not in gone:
                used.setdefault(b.object, []).append(k)
    out: dict[ObjectNode, list[tuple[int, int]]] = {}
    for x, ks in sorted(used.items()):
        out.setdefault(start[x], []).append((min(ks), max(ks)))
    return out


def at_once(trace: PhysicalTrace) -> dict[ObjectNode, int]:
    """Kitchen node -> the most objects that start there in use at one step (module doc)."""
    return {node: max(sum(a <= k <= b for a, b in s) for k in range(len(trace.steps)))
            for node, s in spans(trace).items()}


def copies(trace: PhysicalTrace) -> dict[str, int]:
    """Label -> copies used one after another (module doc); labels with none are left out."""
    peak = at_once(trace)
    out: Counter[str] = Counter()
    for node, s in spans(trace).items():
        out[node.label] += len(s) - peak[node]
    return {label: k for label, k in sorted(out.items()) if k}
