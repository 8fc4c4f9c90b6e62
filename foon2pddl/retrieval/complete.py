"""`complete` retrieval: a task tree whenever one exists, from the reachability fixpoint.

Among the goal's candidates that can be made, the one made in the earliest
round is chosen (ties: candidate order, i.e. sorted). Its tree follows first
achievers back to the kitchen (acyclic, see `reachability`), reusing a unit
already in the tree that fired earlier when it makes a needed node, keeps only
the units needed and orders them topologically (`extract.ordered_units`).
Time: the fixpoint, O(network size), plus the size of the tree.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..analysis.reachability import Reachability, blocker_words, reachable
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from .extract import make_tree, ordered_units
from .result import UNREACHABLE, Retrieval


def none_can_be_made(goal: Goal) -> str:
    """`none of the 3 nodes matching 'x' can be made from the kitchen` (`the one node ... cannot be made` for one)."""
    if len(goal.candidates) == 1:
        return f"the one node matching {goal.describe()!r} cannot be made from the kitchen"
    return f"none of the {len(goal.candidates)} nodes matching {goal.describe()!r} can be made from the kitchen"


def unreachable_detail(reach: Reachability, goal: Goal) -> str:
    """Words for why no candidate of `goal` can be made."""
    lacking = blocker_words(reach, goal.candidates)
    head = none_can_be_made(goal)
    if lacking:
        return head + "; missing (no unit makes them): " + lacking
    return head + " (every way to make them needs a node that itself needs them)"


def best_candidate(reach: Reachability, goal: Goal) -> ObjectNode | None:
    """The reachable candidate with the earliest round (first in candidate order on ties)."""
    best, best_round = None, None
    for c in goal.candidates:
        r = reach.round_of(c)
        if r is not None and (best_round is None or r < best_round):
            best, best_round = c, r
    return best


def complete(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal,
             reach: Reachability | None = None) -> Retrieval:
    """Retrieve a tree for `goal` if the kitchen can make it at all (`reach` may be precomputed)."""
    reach = reach if reach is not None else reachable(foon, kitchen_nodes, goal.candidates)
    target = best_candidate(reach, goal)
    if target is None:
        return Retrieval(None, UNREACHABLE, "complete", unreachable_detail(reach, goal), len(reach.fired))
    ix = reach.index
    gid = ix.node_id[target]  # candidates are produced nodes, so always indexed
    rounds = reach.node_round
    fired_at = {u: i for i, u in enumerate(reach.fired)}
    units = ordered_units(ix, gid, reach.achiever.__getitem__, lambda n: rounds[n] == 0, fired_at.__getitem__)
    return Retrieval(make_tree(foon, ix, gid, units), None, "complete", expansions=len(reach.fired))
