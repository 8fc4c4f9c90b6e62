"""What FOON's own nodes say about where an object is and what a container holds.

`places(node)` reads `in [C]` / `on [C]` (a bare `on` is an appliance switched
on); `listed(node)` the labels a container's `contains` states list;
`container_labels(trace)` the labels whose lists are contents. Shared by the
physical replay and the code that builds traces for it, so both read FOON alike.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.foon import ObjectNode
from ..model.physical import PhysicalTrace, Relation, TraceStep

__all__ = ["container_labels", "listed", "places", "step_source"]


def places(node: ObjectNode | None) -> tuple[tuple[Relation, str], ...]:
    """The places a node names: `(in, bowl)` for `in [bowl]`, `(on, stove)` for `on [stove]` (a bare `on`
    is an appliance switched on, not a place)."""
    if node is None:
        return ()
    return tuple((Relation(s.label), s.related) for s in node.states if s.label in ("in", "on") and s.related)


def listed(node: ObjectNode | None) -> frozenset[str]:
    """The labels a container node lists: the ingredients and related objects of its `contains` states, and
    the related object of a `with` state (`baking tray (with [aluminium foil])`: the foil is on the tray)."""
    if node is None:
        return frozenset()
    items = {i for s in node.states if s.label == "contains" for i in (*s.ingredients, s.related) if i}
    items |= {s.related for s in node.states if s.label == "with" and s.related}
    return frozenset(items - {node.label})


def _describes_contents(node: ObjectNode) -> bool:
    return any(s.label in ("contains", "empty") for s in node.states)


def container_labels(trace: PhysicalTrace, aliases: Mapping[str, str] | None = None) -> frozenset[str]:
    """Labels some node of the trace (initial, binding or change) gives a `contains` or `empty` state and
    some node names as a place (`in [bowl]`): a `contains` list on anything else (`biscuit dough (contains
    {butter, flour})`) names the ingredients of a mixture, not objects in it."""
    nodes = [s.node for s in trace.initial]
    for step in trace.steps:
        nodes += [n for b in step.bindings for n in (b.before, b.after)] + [c.node for c in step.changes]
    nodes = [n for n in nodes if n is not None]
    aliases = aliases or {}
    placed = {aliases.get(c, c) for n in nodes for _, c in places(n)}
    return frozenset(n.label for n in nodes if _describes_contents(n) and n.label in placed)


def step_source(step: TraceStep) -> str:
    """The step's `source`, else its unit's first `file:line`."""
    if step.source:
        return step.source
    src = step.unit.source
    return f"{src.path}:{src.line}" if src is not None else ""
