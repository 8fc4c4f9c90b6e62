"""Local search on an incumbent tree: replace one unit at a time by a cheaper way to make what it made.

Works on a `lmcut.Cone` (dense local ids). For each unit x of the incumbent
(dearest first, then content order), x is forbidden, the other units of the
incumbent cost nothing, and a relaxed plan for the goal is extracted from the
h_add best supporters (`analysis.fixpoint.cheapest`, stopped at the first
candidate settled);
units the plan does not need are dropped (`prune`). A cheaper plan replaces
the incumbent and the pass starts again. Every plan is executable: a node's
best supporter fired after all its inputs were settled, so supporters never
form a cycle, and pruning keeps a set whose fixpoint still makes the goal.

Cost: one Dijkstra over the cone per attempt (it settles only the nodes no
dearer than the goal, few when most units are free); `attempts` caps them.
Tie-breaks: heap order (cost, node id), consumers in the cone's unit order
(content order), so the result does not depend on file order.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence

from ..analysis.fixpoint import cheapest
from .lmcut import Cone

INF = math.inf


def relaxed_plan(cone: Cone, rc: Sequence[float], goals: set[int]) -> tuple[int, list[int]] | None:
    """(candidate reached, units of a relaxed plan for it) by h_add best supporters; None if unreachable."""
    _, _, sup, goal = cheapest(cone.seeds, cone.dep_counts, cone.outs, cone.consumers, rc, True, goals)
    return None if goal < 0 else (goal, _extract(cone, sup, goal))


def _extract(cone: Cone, sup: list[int], goal: int) -> list[int]:
    plan: list[int] = []
    seen: set[int] = set()
    stack = [goal]
    while stack:
        u = sup[stack.pop()]
        if u not in seen:
            seen.add(u)
            plan.append(u)
            stack.extend(cone.deps[u])
    return plan


def _fire(cone: Cone, members: set[int], goal: int, users: dict[int, list[int]], counts: dict[int, int],
          seeds: list[int], stop_at_goal: bool) -> list[int] | None:
    """The units of `members` that fire from the kitchen, in firing order (the `seeds` in their order, then
    breadth-first), if `goal` gets made; else None. With `stop_at_goal` it returns as soon as the goal is
    made (the order then stops there). `users`: node -> the units (a superset of `members`) that consume
    it; `counts`: their input counts; `seeds`: those without inputs. O(members + their edges)."""
    outs = cone.outs
    missing = counts.copy()
    ready = [u for u in seeds if u in members]
    have: set[int] = set()
    k = 0
    while k < len(ready):
        u = ready[k]
        k += 1
        for o in outs[u]:
            if o not in have:
                if stop_at_goal and o == goal:
                    return ready
                have.add(o)
                for v in users.get(o, ()):
                    if v in members:
                        missing[v] -= 1
                        if not missing[v]:
                            ready.append(v)
    return ready if goal in have else None


def prune(cone: Cone, units: list[int], goal: int, weight: Sequence[float]) -> list[int]:
    """Drop units the goal does not need (dearest, then last in unit order, first); firing order.

    One fixpoint per unit tried, O(plan size x plan edges)."""
    users: dict[int, list[int]] = {}
    for u in dict.fromkeys(units):
        for i in cone.deps[u]:
            users.setdefault(i, []).append(u)
    keep = set(units)
    counts = {u: cone.dep_counts[u] for u in keep}
    seeds = sorted(u for u in keep if not counts[u])
    for u in sorted(units, key=lambda u: (-weight[u], -u)):
        keep.discard(u)
        if _fire(cone, keep, goal, users, counts, seeds, True) is None:
            keep.add(u)
    order = _fire(cone, keep, goal, users, counts, seeds, False)
    if order is None:  # `units` must make the goal; never silently return a broken plan
        raise ValueError("prune: the units do not make the goal")
    return order


def improve(cone: Cone, units: list[int], goal: int, goals: set[int], attempts: int,
            deadline: float | None = None, floor: float = 0.0) -> tuple[int, list[int], int]:
    """(goal, units in firing order, attempts used) of the cheapest plan the local search finds
    from the executable `units` making `goal` (local ids), within `attempts` and the deadline.
    It stops early once a plan costs no more than `floor`, a proven lower bound (nothing is cheaper)."""
    weight = cone.weight
    best = prune(cone, units, goal, weight)
    best_cost = math.fsum(weight[u] for u in best)
    used = 0
    improved = best_cost > floor + 1e-9
    while improved and used < attempts:
        improved = False
        for x in sorted(best, key=lambda u: (-weight[u], u)):
            if used >= attempts or (deadline is not None and time.perf_counter() >= deadline):
                return goal, best, used
            used += 1
            rc = list(weight)
            for u in best:
                rc[u] = 0.0
            rc[x] = INF
            found = relaxed_plan(cone, rc, goals)
            if found is None:
                continue
            g, plan = found
            plan = prune(cone, plan, g, weight)
            cost = math.fsum(weight[u] for u in plan)
            if cost < best_cost - 1e-9:
                goal, best, best_cost = g, plan, cost
                improved = best_cost > floor + 1e-9
                break
    return goal, best, used
