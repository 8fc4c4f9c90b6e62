"""The physical trace a plan's skills are planned from.

An encoding that models holders (`relational`) gives its plan's trace as it is; an
`instances` plan's trace has no holders, so they are inferred from FOON's evidence
(`planners.instance_physical`). Encodings without physical objects (`tree`) give
none: their plans have no objects to hand a robot.
"""

from __future__ import annotations

from ..model.physical import PhysicalTrace
from ..planners.instance_physical import physical_trace
from ..planners.solve import PlanOutcome

__all__ = ["trace_of"]


def trace_of(outcome: PlanOutcome) -> PhysicalTrace | None:
    """The plan object by object with holders (None when the plan has no physical objects or no plan)."""
    trace = outcome.trace
    if trace is None:
        return None
    return trace if outcome.compiled.holders else physical_trace(outcome.task, trace).trace
