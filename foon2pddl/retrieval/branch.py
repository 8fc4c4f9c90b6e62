"""Depth-first branch and bound over partial task trees, anytime (see `optimal` for the model).

A partial solution is a set S of chosen units, a commitment node -> unit for
every node already explained, and the open nodes. A search node branches on
the open node with the fewest possible makers (then the lowest id) over its
makers: a unit already in S (free) or a new one (its cost; its inputs open).
A commitment that would make a node depend on itself is refused.

Bounds. Each frame on the stack carries f, a lower bound on every completion
of its partial solution (g = cost of S, plus LM-cut of the open nodes with
S free, inherited by children until they branch). All completions not yet
explored lie below some frame on the stack, so when the search stops early
the least f on the stack (and of the frame in hand) is a proven lower bound
for the candidate being searched; a candidate not yet started has its root
LM-cut as bound, a finished one the incumbent's cost. `lower_bound` is the
least of these, never above the incumbent.

Budget. `node_limit` caps the search nodes expanded (deterministic: the same
inputs give the same tree and bound on every machine); `deadline` (a
`time.perf_counter` value) is a wall-clock safety cap checked before every
expansion, which makes the result depend on machine speed when it is hit.
"""

from __future__ import annotations

import math
import time
import weakref

from ..analysis.index import FoonIndex
from ..analysis.reachability import UNREACHED, Reachability
from ..model.foon import Foon
from .improve import improve
from .lmcut import Cone, HMax

EPS = 1e-9


class BranchAndBound:
    """The search state: cone, incumbent (`best`, `best_cost`), counters and bounds."""

    def __init__(self, foon: Foon, ix: FoonIndex, reach: Reachability, weight: list[float],
                 cands: list[int], node_limit: int | None, deadline: float | None) -> None:
        self.foon = foon
        self.ix = ix
        self.weight = weight
        self.node_limit = math.inf if node_limit is None else node_limit
        self.deadline = deadline
        fix = _per_fixpoint(reach)
        self.kitchen = fix.kitchen
        self.deps = fix.deps
        # The units that can fire and lie backwards from a candidate, and h_max over them with no unit
        # chosen (the base of every bound), cut out of those of the whole fixpoint.
        wide, wide_top = fix.top(weight)
        self.cone, self.top = wide.restrict([wide.local_n[c] for c in cands], wide_top)
        self.makers = fix.makers  # every cone node's makers are all in the cone
        self._static: dict[int, float] | None = None
        self.integral = all(float(w).is_integer() for w in set(self.cone.weight))
        self.best_cost = math.inf
        self.best: tuple[int, dict[int, int]] = (-1, {})
        self.expanded = 0
        self.stopped = ""  # why the search stopped early: "", "node limit" or "time budget"
        # candidate -> lower bound on its trees (0 until its root LM-cut is known)
        self.cand_bound = {c: 0.0 for c in cands}
        self.proven = 0.0  # lower bound proven by the completed iterations of `run`
        self.h_cache: dict[tuple[frozenset[int], frozenset[int]], float] = {}
        self.improved = 0  # relaxed plans tried by the local search

    @property
    def static(self) -> dict[int, float]:
        """h_max of every cone node with no unit free (child and candidate order), computed when first needed."""
        if self._static is None:
            self._static = dict(zip(self.cone.node_ids, self.top.cost, strict=True))
        return self._static

    # -- incumbents --------------------------------------------------------------------------------

    def offer_tree(self, tree) -> None:
        """Take a valid tree (of this network's units) as the incumbent if it is cheaper."""
        position = self.ix.positions(self.foon)
        self.offer_units(self.ix.node_id[tree.goal], [position[id(x)] for x in tree.units])

    def offer_units(self, goal: int, units: list[int]) -> None:
        """Take executable `units` (in an executable order) making `goal` as the incumbent if cheaper."""
        commit: dict[int, int] = {}
        for u in units:  # first achievers in the given order: acyclic
            for n in self.ix.outputs[u]:
                if not self.kitchen[n] and n not in commit:
                    commit[n] = u
        cost = math.fsum(self.weight[u] for u in set(units))
        if cost < self.best_cost - EPS:
            self.best_cost = cost
            self.best = (goal, commit)

    # -- bounds ------------------------------------------------------------------------------------

    def _sharpen(self, bound: float) -> float:
        """With integral costs a bound can be rounded up to the next integer."""
        return float(math.ceil(bound - EPS)) if self.integral and bound < math.inf else bound

    def lower_bound(self) -> float:
        """Proven lower bound on the cost of every tree for the goal (at most the incumbent's cost)."""
        roots = min(self._sharpen(b) for b in self.cand_bound.values())
        return min(self.best_cost, max(self.proven, roots))

    def _out_of_budget(self) -> bool:
        if self.expanded >= self.node_limit:
            self.stopped = "node limit"
        elif self.deadline is not None and time.perf_counter() >= self.deadline:
            self.stopped = "time budget"
        return bool(self.stopped)

    # -- search ------------------------------------------------------------------------------------

    def root(self, cands: list[int]) -> bool:
        """Root LM-cut of every candidate; whether that already proves the incumbent optimal."""
        lmcut = self.cone.lmcut
        for c in cands:
            if self.deadline is not None and time.perf_counter() >= self.deadline:
                self.stopped = "time budget"
                return False
            self.cand_bound[c] = max(self.cand_bound[c], lmcut(self.top, (c,)))
        return self.lower_bound() >= self.best_cost - EPS

    def improve(self, cands: list[int], attempts: int) -> None:
        """Local search on the incumbent (`improve.improve`), at most `attempts` relaxed plans."""
        cone = self.cone
        gid, commit = self.best
        units = sorted({cone.local_u[u] for u in commit.values()})
        goal, order, used = improve(cone, units, cone.local_n[gid], {cone.local_n[c] for c in cands}, attempts,
                                    self.deadline, self.lower_bound())
        self.improved = used
        self.offer_units(cone.node_ids[goal], [cone.unit_ids[u] for u in order])

    def run(self, cands: list[int]) -> None:
        """Iterative deepening on the bound: search every tree of cost <= t, raise t, repeat.

        t starts at the least root LM-cut of the candidates (`root`). An iteration
        that finds no tree of cost <= t proves t' (the least bound it pruned above t)
        a lower bound; a tree found within t is optimal (its cost is at least the
        proven t). It stops when t reaches the incumbent's cost (proven), or the
        budget runs out.
        """
        if self.stopped:
            return
        order = sorted(cands, key=lambda c: (self.cand_bound[c], self.static.get(c, math.inf), c))
        t = self.lower_bound()
        while t < self.best_cost - EPS:
            nxt = math.inf
            for c in order:
                root = self._sharpen(self.cand_bound[c])
                if root > t + EPS:
                    nxt = min(nxt, root)
                    continue
                left = self._dfs(c, root, t)
                if self.stopped or self.best_cost <= t + EPS:
                    return
                nxt = min(nxt, left)
            self.proven = t = min(self._sharpen(nxt), self.best_cost)

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

    def _dfs(self, goal: int, root: float, t: float) -> float:
        """Depth-first search from 'make `goal`' (root bound `root`) of the trees of cost <= `t`.

        Returns the least bound pruned above `t` (inf if none). A partial solution is
        bounded (LM-cut, cached across iterations) when taken from the stack and it has
        more than one way on; a node with a single possible maker is committed at
        once. Children are tried cheapest first by their cost plus the static h_max
        of the nodes they open (ties: a unit already chosen, then content order).
        """
        rank, lmcut, static, cache = self.ix.rank, self.cone.lmcut, self.static, self.h_cache
        state = self.cone.state
        sharpen = self._sharpen
        above = math.inf
        # frame: (lower bound f, g, chosen units, commitments, open nodes, h_max of a subset of the chosen units)
        stack = [(root, 0.0, frozenset(), {}, frozenset((goal,)), self.top)]
        while stack:
            f, g, chosen, commit, open_nodes, base = stack.pop()
            while True:
                bound = sharpen(f)
                if bound > t + EPS or bound >= self.best_cost - EPS:
                    above = min(above, bound)
                    break
                if not open_nodes:
                    self.best_cost = g
                    self.best = (goal, commit)
                    return above
                if self._out_of_budget():
                    return above
                self.expanded += 1
                kids = list(self._children(g, chosen, commit, open_nodes))
                if len(kids) == 1:  # forced: the parent's bound still holds
                    g, chosen, commit, open_nodes = kids[0][1]
                    f = max(f, g)
                    continue
                key = (chosen, open_nodes)
                h = cache.get(key)
                if h is None:
                    base = state(chosen, base)  # the children's base too: they only add units
                    h = cache[key] = lmcut(base, open_nodes, self.best_cost - EPS - g)
                f = max(f, g + h)
                bound = sharpen(f)
                if bound > t + EPS or bound >= self.best_cost - EPS:
                    above = min(above, bound)
                    break
                order = []
                for u, (g2, ch2, co2, op2) in kids:
                    est = g2 + max((static.get(i, math.inf) for i in op2 - open_nodes), default=0.0)
                    order.append(((0 if u in chosen else 1, est, rank[u]), (max(f, g2), g2, ch2, co2, op2, base)))
                order.sort(key=lambda c: c[0], reverse=True)
                stack.extend(frame for _, frame in order)
                break
        return above


class _Fixpoint:
    """What the goals of one fixpoint share: the kitchen mask; for every unit that fires its inputs not in
    the kitchen (`deps`) and its outputs neither in the kitchen nor among its inputs (`effects`); for every
    node they make its firing makers (content order); and the h_max of all firing units (`top`)."""

    def __init__(self, reach: Reachability) -> None:
        ix, fires = reach.index, reach.unit_round
        self.kitchen = kitchen = [r == 0 for r in reach.node_round]
        self.units = units = [u for u, r in enumerate(fires) if r != UNREACHED]
        self.deps = {u: tuple(i for i in ix.inputs[u] if not kitchen[i]) for u in units}
        self.effects = {u: tuple(o for o in ix.outputs[u] if not kitchen[o] and o not in ix.inputs[u])
                        for u in units}
        made = sorted({n for e in self.effects.values() for n in e})
        self.makers = {n: tuple(u for u in ix.makers[n] if fires[u] != UNREACHED) for n in made}
        self.rank = ix.rank.__getitem__
        self._top: tuple[list[float], Cone, HMax] | None = None

    def top(self, weight: list[float]) -> tuple[Cone, HMax]:
        """The cone of every firing unit and its h_max with no unit free, for `weight` (the last list asked
        is remembered, by identity: `optimal.unit_weights` returns the same list for rates of equal content)."""
        hit = self._top
        if hit is None or hit[0] is not weight:
            cone = Cone.of(self.units, self.deps, self.effects, self.makers, weight, self.rank)
            hit = self._top = (weight, cone, cone.state(frozenset()))
        return hit[1], hit[2]


_FIXPOINT_CACHE: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _per_fixpoint(reach: Reachability) -> _Fixpoint:
    """The shared data of `reach`'s goals, cached while `reach` lives."""
    hit = _FIXPOINT_CACHE.get(reach)
    if hit is None:
        hit = _FIXPOINT_CACHE[reach] = _Fixpoint(reach)
    return hit
