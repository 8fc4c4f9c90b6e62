"""`optimal` and `weighted` retrieval: anytime exact search for the cheapest task tree.

`optimal` minimizes the number of distinct units (a subtree shared by two
branches counts once); `weighted` maximizes the success probability, the
product of the units' motion success rates, i.e. minimizes the sum of
-log(rate). Both run the same search with a different unit cost.

Steps: the `complete` tree is the first incumbent; the root LM-cut bound of
each candidate (`branch.BranchAndBound.root`) often proves it optimal at once;
otherwise the `greedy` tree and a local search (`improve.py`) improve the
incumbent, and iterative deepening on the bound (`branch.py`) proves it or
finds a better one. The search stops at `node_limit` search nodes
(deterministic) or `time_limit` seconds (a wall-clock safety cap) and returns
the best tree found, its cost and a proven lower bound (`Retrieval.cost`,
`.bound`, `.proven_optimal`). There always is a tree: unreachable goals are
answered `unreachable` by the fixpoint, without search.

Complexity. Finding a cheapest delete-free plan is NP-hard (minimum-cost
relaxed planning; set cover reduces to it: one unit per set, making all of its
elements' nodes, and a goal unit needing every element), so the exact search
is exponential in the worst case; the budgeted one is O(node_limit x cone).

Ties between equally good trees go to the first found (see `branch.py`,
`improve.py`); candidates in order of their root bound, then static h_max,
then id. Costs are compared with a tolerance of 1e-9.
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterable

from ..analysis.reachability import Reachability, reachable
from ..io.rates import Rates
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from .branch import EPS, BranchAndBound
from .complete import complete, unreachable_detail
from .extract import make_tree, ordered_units
from .greedy import DEFAULT_BUDGET, greedy
from .result import UNREACHABLE, Retrieval

#: Default cap on search nodes expanded per goal (deterministic; None: no cap). With it, 96.8 % of the
#: experiment protocol's solved goals are proven optimal (docs/retrieval.md).
DEFAULT_NODE_LIMIT = 100
#: Default wall-clock cap per goal in seconds (a safety net; None: no cap).
DEFAULT_TIME_LIMIT = 10.0
#: Relaxed plans the local search on the incumbent may try per goal (deterministic).
IMPROVE_ATTEMPTS = 25


def unit_weights(ix, rates: Rates | None) -> list[float]:
    """Cost of every unit of the index: 1 (rates None), or -log of its motion's success rate.

    Remembered for the last rates asked (the same list for rates with the same table and
    default: the search caches per-fixpoint bounds by it); do not modify it."""
    def make() -> list[float]:
        if rates is None:
            return [1.0] * len(ix.motions)
        by_motion = {m: rates.cost(m) for m in set(ix.motions)}
        return [by_motion[m] for m in ix.motions]

    key = None if rates is None else (rates.default, tuple(sorted(rates.table.items())))
    return ix.remember("unit_weights", key, make)


def optimal(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal, *,
            rates: Rates | None = None, weighted: bool = False,
            node_limit: int | None = DEFAULT_NODE_LIMIT, time_limit: float | None = DEFAULT_TIME_LIMIT,
            budget: int = DEFAULT_BUDGET, reach: Reachability | None = None) -> Retrieval:
    """Fewest units (`weighted=False`) or highest success product (`weighted=True`, needs `rates`).

    Anytime: stops after `node_limit` search nodes or `time_limit` seconds (None: no cap)
    with the best tree found and a proven lower bound (`Retrieval.cost`, `.bound`).
    `budget` is the iteration budget of the greedy seed.
    """
    deadline = None if time_limit is None else time.perf_counter() + time_limit
    method = "weighted" if weighted else "optimal"
    if weighted and rates is None:
        rates = Rates()
    kitchen_nodes = frozenset(kitchen_nodes)
    reach = reach if reach is not None else reachable(foon, kitchen_nodes, goal.candidates)
    ix = reach.index
    cands = [ix.node_id[c] for c in goal.candidates if reach.can_make(c)]
    if not cands:
        return Retrieval(None, UNREACHABLE, method, unreachable_detail(reach, goal))
    rounds = reach.node_round
    for c in cands:
        if rounds[c] == 0:
            return Retrieval(make_tree(foon, ix, c, ()), None, method, "goal is in the kitchen",
                             proven_optimal=True, cost=0.0, bound=0.0)

    weight = unit_weights(ix, rates if weighted else None)
    search = BranchAndBound(foon, ix, reach, weight, cands, node_limit, deadline)
    search.offer_tree(complete(foon, kitchen_nodes, goal, reach).tree)
    if not search.root(cands):
        seed = greedy(foon, kitchen_nodes, goal, budget, reach).tree
        if seed is not None:
            search.offer_tree(seed)
        if search.lower_bound() < search.best_cost - EPS:
            search.improve(cands, IMPROVE_ATTEMPTS)
        search.run(cands)
    gid, commit = search.best
    units = ordered_units(ix, gid, commit.__getitem__, lambda n: rounds[n] == 0)
    tree = make_tree(foon, ix, gid, units)
    cost = math.fsum(weight[u] for u in units)
    bound = min(search.lower_bound(), cost)
    proven = bound >= cost - 1e-9
    bound = cost if proven else bound
    detail = f"{search.expanded} search nodes expanded over {len(search.cone.unit_ids)} candidate units"
    if search.improved:
        detail += f", {search.improved} relaxed plans tried by the local search"
    if not proven:
        limit = f"node limit {node_limit}" if search.stopped == "node limit" else f"time budget {time_limit:g} s"
        detail += (f"; {limit} hit: best tree found so far, not proven optimal "
                   f"(cost {cost:.6g}, lower bound {bound:.6g})")
    return Retrieval(tree, None, method, detail, search.expanded, proven, cost=cost, bound=bound)
