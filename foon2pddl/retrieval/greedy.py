"""`greedy` retrieval: the seed paper's task tree search, with guaranteed termination.

As in Paulius et al. (ICRA 2018): a queue of objects still needed starts with
the goal; for the object taken from the queue, the units that make it are
tried in order and the first one whose inputs are all available fires (its
outputs become available); if none can fire yet, the missing inputs of all of
them are queued (breadth-wise among a unit's objects) and the object goes back
to the end of the queue, to be retried once more has been made (depth-wise by
functional unit). The search ends when a goal candidate is available.

What is done differently from the public reference, and why:
- Termination without a depth guess: an object is queued at most once and a
  unit that consumes an object is never tried as its maker (no cycles). If a
  whole pass over the queue makes nothing and queues nothing new, nothing more
  can ever be made: the answer is `unreachable`. Progress (an object made or a
  new object queued) happens at most twice per node, so the search stops after
  O(nodes x queue length) steps even without its iteration `budget`; when the
  budget runs out first the answer is `budget exhausted`.
- All goal candidates are sought at once (reaching any satisfies the goal).
- Bookkeeping that changes no answer: each unit looked at keeps a count of its
  missing inputs, updated as nodes get made, so a maker is checked in O(1);
  a retried object none of whose makers became ready is put back at once, its
  missing inputs being queued already (FOON-EXP protocol goals: 3.1 s -> 2.2 s).
- Tie-break order (never file order): the queue starts with the candidates in
  sorted node order; an object's makers are tried in unit content order
  (motion label, then sorted inputs, then sorted outputs; `index.FoonIndex`);
  missing inputs are queued in that order of units, then sorted node order.
- The returned tree keeps only the units needed: following, from the goal,
  the first fired unit that made each node (or a unit already kept that fired
  earlier, `extract`); units fired for sub-goals that ended up unused are
  dropped (`detail` says how many).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable

from ..analysis.index import index_of
from ..analysis.reachability import Reachability, reachable
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.words import count
from .complete import unreachable_detail
from .extract import make_tree, ordered_units
from .result import BUDGET_EXHAUSTED, UNREACHABLE, Retrieval

#: Default iteration budget (objects taken from the queue). The hardest goal
#: of the universal FOON of the shared subgraphs needs a few thousand.
DEFAULT_BUDGET = 200_000

#: Iterations after which a search not given a fixpoint checks the goal's reachability.
FIXPOINT_CHECK_AFTER = 256


def greedy(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal,
           budget: int = DEFAULT_BUDGET, reach: Reachability | None = None) -> Retrieval:
    """Run the greedy search for any candidate of `goal` within `budget` iterations.

    Unreachable goals are also answered by the reachability fixpoint: at the start when
    `reach` is given, else (computed for the goal's cone) once the search has taken
    `FIXPOINT_CHECK_AFTER` iterations. The greedy search finds a tree whenever one
    exists, so this changes no answer, but its own proof of unreachability (a full
    pass over its queue that makes nothing) costs O(nodes x queue) where the fixpoint
    is linear (FOON-EXP of the shared subgraphs: 133 ms -> ~14 ms per unreachable goal).
    """
    ix = index_of(foon)
    kitchen_nodes = frozenset(kitchen_nodes)

    def unreachable(reach: Reachability) -> Retrieval | None:
        if reach.makes_any(goal.candidates):
            return None
        return Retrieval(None, UNREACHABLE, "greedy", unreachable_detail(reach, goal))

    if reach is not None and (answer := unreachable(reach)) is not None:
        return answer
    kitchen = ix.kitchen_ids(kitchen_nodes)
    in_kitchen = bytearray(len(ix.nodes))
    for k in kitchen:
        in_kitchen[k] = 1
    available = bytearray(in_kitchen)
    candidates = [ix.node_id[c] for c in goal.candidates]
    for c in candidates:
        if available[c]:
            return Retrieval(make_tree(foon, ix, c, ()), None, "greedy", "goal is in the kitchen")
    is_candidate = set(candidates)

    makers, inputs, outputs, consumers = ix.makers, ix.inputs, ix.outputs, ix.consumers
    queue: deque[int] = deque(sorted(is_candidate))
    seen: set[int] = set(queue)
    # unavailable inputs per unit looked at (kept up to date as nodes get made): a retried object's
    # makers are checked in O(1) each instead of scanning their inputs again
    missing: dict[int, int] = {}
    expanded: set[int] = set()  # objects whose makers' missing inputs are queued (they stay queued or made)
    ready = bytearray(len(ix.nodes))  # some unit looked at and making this node has all its inputs now
    achiever: dict[int, int] = {}
    fired_at: dict[int, int] = {}
    fired = 0
    iterations = 0
    since_progress, window = 0, len(queue)
    while queue:
        if iterations >= budget:
            return Retrieval(None, BUDGET_EXHAUSTED, "greedy",
                             f"{count(budget, 'iteration')} spent, {count(len(queue), 'object')} still queued", iterations)
        iterations += 1
        if iterations == FIXPOINT_CHECK_AFTER and reach is None:
            answer = unreachable(reachable(foon, kitchen_nodes, targets=goal.candidates))
            if answer is not None:
                return answer
        obj = queue.popleft()
        if available[obj]:
            since_progress += 1
            if since_progress >= window:
                break
            continue
        if obj in expanded and not ready[obj]:  # a retry that still can fire nothing
            queue.append(obj)
            since_progress += 1
            if since_progress >= window:
                break
            continue
        progress = False
        for u in makers[obj]:
            m = missing.get(u)
            if m is None:
                ins = inputs[u]
                m = missing[u] = len(ins) - sum(map(available.__getitem__, ins))
            if not m:
                fired_at[u] = fired
                fired += 1
                made = None
                for n in outputs[u]:
                    if not available[n]:
                        available[n] = 1
                        achiever[n] = u
                        for v in consumers[n]:
                            if v in missing:
                                missing[v] -= 1
                                if not missing[v]:
                                    for o in outputs[v]:
                                        ready[o] = 1
                        if made is None and n in is_candidate:
                            made = n
                if made is not None:
                    done = min((c for c in candidates if available[c]), key=candidates.index)
                    units = ordered_units(ix, done, achiever.__getitem__, in_kitchen.__getitem__,
                                          fired_at.__getitem__)
                    return Retrieval(make_tree(foon, ix, done, units), None, "greedy",
                                     f"{count(fired, 'unit')} fired, {len(units)} kept", iterations)
                progress = True
                break
        else:
            if obj not in expanded:  # on a retry every missing input is already queued
                expanded.add(obj)
                for u in makers[obj]:
                    for i in inputs[u]:
                        if not available[i] and i not in seen:
                            seen.add(i)
                            queue.append(i)
                            progress = True
            if makers[obj]:
                queue.append(obj)  # retry once more is available; an object nobody makes is dropped
        if progress:
            since_progress, window = 0, len(queue)
        else:
            since_progress += 1
            if since_progress >= window:
                break
    return Retrieval(None, UNREACHABLE, "greedy",
                     "a full pass over the objects still needed made nothing new", iterations)
