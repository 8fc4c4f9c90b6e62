"""Objects a plan uses one after another where one would do: the copies a restoring unit could spare.

Objects that start in one kitchen node are interchangeable (`knife (clean)`): a bowl of flour and a bowl of
sugar are no copies of each other. An object is *in use* from the first step that binds it as a role to the
last; one consumed in the plan is no copy (it cannot be used again). Per kitchen node, `at_once` is the most
in use at any step, and the node's *copies* are the objects used less that (`copies`, summed per label).
`busy` counts what a plan with fewer objects needs (`planners.solve.plan_restoring`): an object is busy from
the first step that binds or changes it to the last, and to the plan's end when it is consumed or ends in a
node that neither is its start nor can be turned back into it. O(steps x bindings + objects x steps).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable

from ..model.foon import ObjectNode
from ..model.physical import PhysicalTrace

__all__ = ["at_once", "busy", "copies", "spans"]


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
    return {node: _most(s, len(trace.steps)) for node, s in spans(trace).items()}


def busy(trace: PhysicalTrace, back: Callable[[ObjectNode, ObjectNode], bool]) -> dict[ObjectNode, int]:
    """Kitchen node -> the most objects that start there busy at one step (module doc); `back(node, start)`:
    whether an object left in `node` can be turned back into `start` (a restoring unit)."""
    start = {o.id: o.node for o in trace.initial if o.node is not None}
    last = len(trace.steps) - 1
    seen: dict[str, list[int]] = {}
    now = dict(start)
    gone: set[str] = set()
    for k, step in enumerate(trace.steps):
        for x in {b.object for b in step.bindings} | {c.id for c in step.changes}:
            if x in start:
                seen.setdefault(x, []).append(k)
        for c in step.changes:
            gone |= {c.id} if c.consumed else set()
            now[c.id] = c.node if c.node is not None else now.get(c.id)
    out: dict[ObjectNode, list[tuple[int, int]]] = {}
    for x, ks in sorted(seen.items()):
        held = x in gone or (now[x] != start[x] and (now[x] is None or not back(now[x], start[x])))
        out.setdefault(start[x], []).append((min(ks), last if held else max(ks)))
    return {node: _most(s, len(trace.steps)) for node, s in out.items()}


def _most(spans: Iterable[tuple[int, int]], steps: int) -> int:
    """The most of `spans` (first, last step) that cover one step of `steps`."""
    spans = list(spans)
    return max((sum(a <= k <= b for a, b in spans) for k in range(steps)), default=0)


def copies(trace: PhysicalTrace) -> dict[str, int]:
    """Label -> copies used one after another (module doc); labels with none are left out."""
    peak = at_once(trace)
    out: Counter[str] = Counter()
    for node, s in spans(trace).items():
        out[node.label] += len(s) - peak[node]
    return {label: k for label, k in sorted(out.items()) if k}
