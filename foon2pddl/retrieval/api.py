"""`retrieve`: one entry point for every retrieval method (`retrieval.methods.METHODS`)."""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace

from ..analysis.index import index_of
from ..analysis.reachability import Reachability
from ..errors import UsageError
from ..io.rates import Rates
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .greedy import DEFAULT_BUDGET
from .methods import Limits, get_method
from .optimal import DEFAULT_NODE_LIMIT, DEFAULT_TIME_LIMIT
from .result import Retrieval


def kitchen_nodes(kitchen: Kitchen | Iterable[ObjectNode], level: int) -> frozenset[ObjectNode]:
    """The kitchen's nodes as seen at `level` (a Kitchen is projected; plain nodes are taken as they are)."""
    if isinstance(kitchen, Kitchen):
        return kitchen.project(level).nodes
    return frozenset(kitchen)


def success_probability(units, rates: Rates) -> float:
    """Product of the motion success rates of `units` (summed as logs, in a fixed order)."""
    return math.exp(-math.fsum(rates.cost(u.motion.label) for u in units))


def retrieve(foon: Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal, method: str = "complete",
             rates: Rates | None = None, budget: int = DEFAULT_BUDGET,
             node_limit: int | None = DEFAULT_NODE_LIMIT, time_limit: float | None = DEFAULT_TIME_LIMIT,
             reach: Reachability | None = None) -> Retrieval:
    """A task tree for `goal` (any of its candidates) from `kitchen` in `foon`, by `method`.

    `method` names an entry of `retrieval.methods.METHODS`: greedy: the seed paper's search
    (iteration `budget`); complete: a tree whenever one exists; optimal: fewest distinct
    units; weighted: highest product of motion success `rates` (defaults for every motion
    when None). optimal/weighted are anytime: they
    expand at most `node_limit` search nodes and run at most `time_limit` seconds (None:
    no cap; both None: exact), and return the best tree found with its `cost` and a
    proven lower `bound`. With `rates`, every found tree's success probability is set.
    `reach`: the fixpoint of `foon` from this kitchen, when already computed (batches share one).

    >>> from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
    >>> from foon2pddl.model.goal import Goal, GoalSpec
    >>> whole, chopped, knife = make_node("onion", [make_state("whole")]), make_node("onion", [make_state("chopped")]), make_node("knife")
    >>> foon = Foon((FunctionalUnit((whole, knife), Motion("chop"), (chopped, knife)),), 3)
    >>> goal = Goal(GoalSpec("onion"), (chopped,), 3)
    >>> len(retrieve(foon, [whole, knife], goal).tree)
    1
    >>> retrieve(foon, [whole], goal).reason    # no knife
    <RetrievalStatus.UNREACHABLE: 'unreachable'>
    """
    entry = get_method(method)
    known = index_of(foon).node_id
    stray = [c for c in goal.candidates if c not in known]
    if stray:
        raise UsageError(f"goal candidate {stray[0].describe()!r} is not a node of the network "
                         f"(goal resolved at level {goal.level}, network at level {foon.level}?)")
    nodes = kitchen_nodes(kitchen, foon.level)
    if entry.needs_rates and rates is None:
        rates = Rates()
    result = entry.run(foon, nodes, goal, Limits(budget, node_limit, time_limit, rates, reach))
    if result.tree is not None and rates is not None:
        result = replace(result, probability=success_probability(result.tree.units, rates))
    return result
