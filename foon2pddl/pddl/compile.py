"""`compile_task`: one entry point from (network, kitchen, goal) to a `PlanningTask` in any encoding."""

from __future__ import annotations

from ..io.rates import Rates
from ..model.constraints import Constraints
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .constraints import add_must_use, constrained_inputs, must_use_cone
from .encode_compat import encode_compat
from .encode_instances import encode_instances
from .encode_state import encode_state
from .encode_tree import encode_tree
from .encoding import EncodeOptions
from .task import PlanningTask

#: Encoding name -> encoder; the first is the default.
ENCODINGS = {"tree": encode_tree, "instances": encode_instances, "state": encode_state, "foon-compat": encode_compat}


def compile_task(
    foon: Foon,
    kitchen: Kitchen,
    goal: Goal,
    encoding: str = "tree",
    level: int = 3,
    prune: bool = True,
    costs: str | None = None,
    rates: Rates | None = None,
    constraints: Constraints | None = None,
    *,
    instances: tuple[tuple[str, int], ...] = (),
    categories: tuple[tuple[str, tuple[str, ...]], ...] = (),
) -> PlanningTask:
    """Encode `goal` from `kitchen` over `foon` at `level` (ValueError on an unknown encoding or cost mode).

    `instances` and `categories` are read by the `instances` encoding only (see `EncodeOptions`).
    With `constraints`, the one place they apply to every encoding (`constraints.py`): the network,
    kitchen and goal are filtered before encoding (GoalExcluded when no candidate remains) and
    must-use objects join the goal after.
    """
    try:
        encoder = ENCODINGS[encoding]
    except KeyError:
        raise ValueError(f"encoding must be one of {', '.join(ENCODINGS)}, not {encoding!r}") from None
    if constraints:
        foon, kitchen, goal = constrained_inputs(foon, kitchen, goal, constraints)
        if constraints.must_use and prune:
            foon, prune = must_use_cone(foon, kitchen, goal, constraints.must_use), False
    task = encoder(foon, kitchen, goal, level, EncodeOptions(prune=prune, costs=costs, rates=rates, instances=instances,
                                                             categories=categories))
    return add_must_use(task, constraints.must_use) if constraints else task
