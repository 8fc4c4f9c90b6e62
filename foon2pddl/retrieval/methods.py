"""The retrieval methods: one table (name -> callable, description, what it honours).

`retrieve` (and through it the API, the CLI and the experiment) looks a method up
here; nothing else branches on a method's name. A method's `run` gets the network,
the kitchen's nodes at the network's level, the goal and a `Limits`; it reads only
the limits it `honours`. Adding a method is one module with its search and one
`register(Method(...))` (docs/extending.md).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ..analysis.reachability import Reachability
from ..errors import UsageError
from ..io.rates import Rates
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from .complete import complete
from .greedy import DEFAULT_BUDGET, greedy
from .optimal import DEFAULT_NODE_LIMIT, DEFAULT_TIME_LIMIT, optimal
from .result import Retrieval

__all__ = ["LIMITS", "METHODS", "Limits", "Method", "get_method", "register"]

#: The limits a method may honour, by `Limits` field.
LIMITS = ("budget", "node_limit", "time_limit", "rates")


@dataclass(frozen=True)
class Limits:
    """How far a method may search: greedy iterations (`budget`), search nodes and seconds of the anytime
    methods (None: no cap), motion success `rates`, and the kitchen's fixpoint when already computed."""

    budget: int = DEFAULT_BUDGET
    node_limit: int | None = DEFAULT_NODE_LIMIT
    time_limit: float | None = DEFAULT_TIME_LIMIT
    rates: Rates | None = None
    reach: Reachability | None = None


@dataclass(frozen=True)
class Method:
    """A retrieval method. `honours`: the `LIMITS` it reads; `needs_rates`: it ranks by motion success rates
    (defaults for every motion when none are given); `bounded`: it minimizes a cost and reports a proven
    lower bound (`Retrieval.cost`, `bound`)."""

    name: str
    description: str
    run: Callable[[Foon, frozenset[ObjectNode], Goal, Limits], Retrieval]
    honours: frozenset[str]
    needs_rates: bool = False
    bounded: bool = False

    def __post_init__(self) -> None:
        unknown = self.honours - set(LIMITS)
        if unknown:
            raise ValueError(f"method {self.name}: unknown limits {sorted(unknown)} (known: {', '.join(LIMITS)})")


def _optimal(weighted: bool) -> Callable[[Foon, frozenset[ObjectNode], Goal, Limits], Retrieval]:
    def run(foon: Foon, nodes: frozenset[ObjectNode], goal: Goal, limits: Limits) -> Retrieval:
        return optimal(foon, nodes, goal, rates=limits.rates, weighted=weighted, node_limit=limits.node_limit,
                       time_limit=limits.time_limit, budget=limits.budget, reach=limits.reach)

    return run


#: The methods by name, in the CLI's order.
METHODS: dict[str, Method] = {m.name: m for m in (
    Method("greedy", "the seed paper's search",
           lambda foon, nodes, goal, lim: greedy(foon, nodes, goal, lim.budget, lim.reach), frozenset({"budget"})),
    Method("complete", "a tree whenever one exists",
           lambda foon, nodes, goal, lim: complete(foon, nodes, goal, lim.reach), frozenset()),
    Method("optimal", "fewest units", _optimal(False), frozenset({"budget", "node_limit", "time_limit"}),
           bounded=True),
    Method("weighted", "highest success probability", _optimal(True),
           frozenset({"budget", "node_limit", "time_limit", "rates"}), needs_rates=True, bounded=True),
)}


def register(method: Method) -> Method:
    """Add (or replace) a retrieval method; returns it."""
    METHODS[method.name] = method
    return method


def get_method(name: str) -> Method:
    """The method called `name` (UsageError listing the known ones)."""
    try:
        return METHODS[name]
    except KeyError:
        raise UsageError(f"unknown retrieval method {name!r} (expected one of {', '.join(METHODS)})") from None
