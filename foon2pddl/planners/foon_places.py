"""Trace-level readings of FOON's words: which labels' lists are contents, and where a step comes from.

`container_labels(trace)` the labels whose lists are contents; `step_source` a
step's `file:line`. The node-level readers (`places`, `listed`) are
`model.places`.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.physical import PhysicalTrace, TraceStep
from ..model.places import describes_contents, places
from ..model.where import unit_where

__all__ = ["container_labels", "step_source"]


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
    return frozenset(n.label for n in nodes if describes_contents(n) and n.label in placed)


def step_source(step: TraceStep) -> str:
    """The step's `source`, else its unit's first `file:line`."""
    if step.source:
        return step.source
    return unit_where(step.unit) if step.unit.source is not None else ""
