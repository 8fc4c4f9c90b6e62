"""`optimal` and `weighted` retrieval: exact branch and bound over partial task trees.

`optimal` minimizes the number of distinct units (a subtree shared by two
branches counts once); `weighted` maximizes the success probability, the
product of the units' motion success rates, i.e. minimizes the sum of
-log(rate). Both run the same search with a different unit cost.

Search space. A partial solution is a set S of chosen units, a commitment
node -> unit for every node already explained, and the open nodes (inputs of
chosen units, or the goal, that are neither in the kitchen nor committed).
A search node picks one open node (the one with fewest possible makers, then
the lowest id) and branches over its makers: a unit already in S (free), or a
new one (its cost; its inputs become open). A commitment that would make a
node depend on itself is refused, so every complete solution is executable:
its units, ordered by the commitments, form a valid task tree. Conversely the
first-achiever commitments of any valid tree are acyclic, so the search misses
no solution; each branch fixes a different maker for the chosen node, so no
partial solution is generated twice. Only units the fixpoint can fire and that
lie backwards from the goal are considered.

Bound. g = cost of S; h = LM-cut (`lmcut.py`) of making the open nodes with
the units of S free, a relaxation (commitments and cycles ignored), hence
admissible. A branch is cut when g + h cannot beat the best tree found so
far; a partial solution is bounded when taken from the stack and its children
inherit the bound until they branch. The first incumbent is the cheaper of
the `complete` and `greedy` trees, so the answer is never worse than theirs.

Complexity. Finding a cheapest delete-free plan is NP-hard (minimum-cost
relaxed planning; set cover reduces to it: one unit per set, making all of its
elements' nodes, and a goal unit needing every element), so the search is
exponential in the worst case. `node_limit` caps the search nodes expanded;
when it is hit the best tree found so far is returned with
`proven_optimal=False` (there always is one, since the fixpoint is run first
and unreachable goals are answered `unreachable` without search).

Ties between equally good trees go to the first found: makers already chosen
first, then by their cost plus the static h_max of the nodes they open, then
in unit content order; candidates in order of their static h_max cost, then
sorted. Costs are compared with a tolerance of 1e-9.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

from ..analysis.index import FoonIndex
from ..analysis.reachability import UNREACHED, Reachability, reachable
from ..io.rates import Rates
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from .complete import complete, unreachable_detail
from .extract import make_tree, ordered_units
from .greedy import DEFAULT_BUDGET, greedy
from .lmcut import Cone
from .result import UNREACHABLE, Retrieval

DEFAULT_NODE_LIMIT = 20_000
EPS = 1e-9


def optimal(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal, *,
            rates: Rates | None = None, weighted: bool = False,
            node_limit: int = DEFAULT_NODE_LIMIT, budget: int = DEFAULT_BUDGET,
            reach: Reachability | None = None) -> Retrieval:
    """Fewest units (`weighted=False`) or highest success product (`weighted=True`, needs `rates`)."""
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
                             proven_optimal=True)

    if weighted:
        assert rates is not None
        by_motion = {m: rates.cost(m) for m in set(ix.motions)}
        weight = [by_motion[m] for m in ix.motions]
    else:
        weight = [1.0] * len(ix.motions)

    search = _Search(foon, ix, reach, weight, cands, node_limit)
    for seed in (complete(foon, kitchen_nodes, goal, reach), greedy(foon, kitchen_nodes, goal, budget, reach)):
        if seed.tree is not None:
            search.offer_tree(seed.tree)
    search.run(cands)
    gid, commit = search.best
    units = ordered_units(ix, gid, commit.__getitem__, lambda n: rounds[n] == 0)
    tree = make_tree(foon, ix, gid, units)
    proven = not search.cut_off
    detail = f"{search.expanded} search nodes expanded over {len(search.units)} candidate units"
    if not proven:
        detail += f"; node limit {node_limit} hit: best tree found so far, not proven optimal"
    return Retrieval(tree, None, method, detail, search.expanded, proven)


class _Search:
    """Depth-first branch and bound over commitments (see the module doc)."""

    def __init__(self, foon: Foon, ix: FoonIndex, reach: Reachability, weight: list[float],
                 cands: list[int], node_limit: int) -> None:
        self.foon = foon
        self.ix = ix
        self.weight = weight
        self.node_limit = node_limit
        kitchen = [r == 0 for r in reach.node_round]
        self.kitchen = kitchen
        fires = reach.unit_round
        # Units that can fire and lie backwards from a candidate, and the makers among them.
        units: set[int] = set()
        makers: dict[int, tuple[int, ...]] = {}
        stack = list(cands)
        while stack:
            n = stack.pop()
            if n in makers or kitchen[n]:
                continue
            makers[n] = tuple(u for u in ix.makers[n] if fires[u] != UNREACHED)
            for u in makers[n]:
                if u not in units:
                    units.add(u)
                    stack.extend(ix.inputs[u])
        self.units = units
        self.makers = makers
        self.deps = {u: tuple(i for i in ix.inputs[u] if not kitchen[i]) for u in units}
        self.cone = Cone(units, self.deps, ix.outputs, makers, weight)
        self.static = self.cone.node_costs()
        self.best_cost = math.inf
        self.best: tuple[int, dict[int, int]] = (-1, {})
        self.expanded = 0
        self.cut_off = False  # the node limit stopped the search

    # -- incumbents --------------------------------------------------------------------------------

    def offer_tree(self, tree) -> None:
        """Take a valid tree (of this network's units) as the incumbent if it is cheaper."""
        ix = self.ix
        position = {id(x): i for i, x in enumerate(self.foon.units)}
        units = [position[id(x)] for x in tree.units]
        commit: dict[int, int] = {}
        for u in units:  # first achievers in the tree's own order: acyclic
            for n in ix.outputs[u]:
                if not self.kitchen[n] and n not in commit:
                    commit[n] = u
        cost = sum(self.weight[u] for u in set(units))
        if cost < self.best_cost - EPS:
            self.best_cost = cost
            self.best = (ix.node_id[tree.goal], commit)

    # -- search ------------------------------------------------------------------------------------

    def run(self, cands: list[int]) -> None:
        static = self.static
        for c in sorted(cands, key=lambda c: (static.get(c, math.inf), c)):
            if self.cut_off:
                return
            self._dfs(c)

    def _creates_cycle(self, commit: dict[int, int], node: int, unit: int) -> bool:
        """Whether committing `node` to `unit` makes `node` depend on itself."""
        stack = list(self.deps[unit])
        seen: set[int] = set()
        while stack:
            n = stack.pop()
            if n == node:
                return True
            if n in seen:
                continue
            seen.add(n)
            u = commit.get(n)
            if u is not None:
                stack.extend(self.deps[u])
        return False

    def _children(self, g: float, chosen: frozenset[int], commit: dict[int, int], open_nodes: frozenset[int]):
        """Branch on the open node with the fewest makers: one child per maker that closes no cycle."""
        weight, makers, deps = self.weight, self.makers, self.deps
        node = min(open_nodes, key=lambda n: (len(makers[n]), n))
        rest = open_nodes - {node}
        for u in makers[node]:
            if self._creates_cycle(commit, node, u):
                continue
            new_commit = dict(commit)
            new_commit[node] = u
            if u in chosen:
                yield u, (g, chosen, new_commit, rest)
            else:
                opened = [i for i in deps[u] if i not in new_commit]
                yield u, (g + weight[u], chosen | {u}, new_commit, rest.union(opened))

    def _dfs(self, goal: int) -> None:
        """Depth-first branch and bound from the partial solution 'make `goal`'.

        A partial solution is bounded (LM-cut) when it is taken from the stack and
        has more than one way on; a child inherits its parent's bound until then,
        so a branch is often cut without bounding its children one by one. Children
        are tried cheapest first by their cost plus the static h_max of the nodes
        they open (ties: unit content order); a node with a single possible maker
        is committed at once (forced chains are common).
        """
        rank, lmcut, static = self.ix.rank, self.cone.lmcut, self.static
        # frame: (lower bound f, g, chosen units, commitments, open nodes)
        stack = [(0.0, 0.0, frozenset(), {}, frozenset((goal,)))]
        while stack:
            f, g, chosen, commit, open_nodes = stack.pop()
            while True:
                if f >= self.best_cost - EPS:
                    break
                if not open_nodes:
                    self.best_cost = g
                    self.best = (goal, commit)
                    break
                if self.expanded >= self.node_limit:
                    self.cut_off = True
                    return
                self.expanded += 1
                kids = list(self._children(g, chosen, commit, open_nodes))
                if len(kids) == 1:  # forced: the parent's bound still holds
                    g, chosen, commit, open_nodes = kids[0][1]
                    f = max(f, g)
                    continue
                room = self.best_cost - EPS - g
                f = max(f, g + lmcut(chosen, open_nodes, room))
                if f >= self.best_cost - EPS:
                    break
                order = []
                for u, (g2, ch2, co2, op2) in kids:
                    est = g2 + max((static.get(i, math.inf) for i in op2 - open_nodes), default=0.0)
                    order.append(((0 if u in chosen else 1, est, rank[u]), (max(f, g2), g2, ch2, co2, op2)))
                order.sort(key=lambda c: c[0], reverse=True)
                stack.extend(frame for _, frame in order)
                break
