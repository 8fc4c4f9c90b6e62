"""Integer action costs for the encodings (`--costs unit|success-rate`).

`unit`: every functional unit costs 1, so a cost-optimal plan has the fewest units.
`success-rate`: a unit costs `round(1000 * -ln(rate)) + 1` for its motion's
success rate (`io.rates`): minimizing the sum maximizes the product of
success rates up to rounding (0.001 in log space), and the `+ 1` keeps a
motion that always succeeds (rate 1) from being free, so among equally likely
plans the shortest wins. Auxiliary goal actions cost 0.
"""

from __future__ import annotations

from ..errors import UsageError
from ..io.rates import Rates
from ..model.foon import FunctionalUnit

COST_MODES = ("unit", "success-rate")

#: Fixed-point scale of -ln(rate): planners need integer costs.
SCALE = 1000


def check_costs(costs: str | None, rates: Rates | None) -> None:
    """Validate a cost mode and its inputs (UsageError with what to give)."""
    if costs is not None and costs not in COST_MODES:
        raise UsageError(f"costs must be one of {', '.join(COST_MODES)}, not {costs!r}")
    if costs == "success-rate" and rates is None:
        raise UsageError("success-rate costs need motion success rates (a rates file)")


def unit_cost(unit: FunctionalUnit, costs: str | None, rates: Rates | None) -> int | None:
    """The action cost of `unit` under `costs` (None when costs are off)."""
    if costs is None:
        return None
    if costs == "unit":
        return 1
    if rates is None:
        raise UsageError("success-rate costs need motion success rates")
    return round(SCALE * rates.cost(unit.motion.label)) + 1


def goal_cost(costs: str | None) -> int | None:
    """Cost of an auxiliary goal action: 0 when costs are on."""
    return None if costs is None else 0
