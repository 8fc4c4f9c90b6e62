"""The smallest kitchen additions that make an unreachable goal reachable.

"Missing: every leaf of every recipe" is true but useless: one or two nodes
usually unblock a goal. This is a hitting set over the AND/OR alternatives,
computed on the goal's backward cone as a least fixpoint of families of sets:

- a node the kitchen can already make: {{}} (nothing to add);
- an *addable* node (one a kitchen could hold: by default the network's default
  kitchen, i.e. starting nodes and base-state inputs) that cannot be made: {{node}};
- any node: the union, over the units making it, of the element-wise unions of
  their inputs' families (a unit needs all inputs: AND; any maker will do: OR).

Families keep only inclusion-minimal sets of at most `max_size` nodes (larger sets
cannot shrink again, so dropping them loses nothing) and at most `keep` sets per
node, the smallest first (ties: node ids); when a family had to be cut the answer
is marked inexact (it may miss some sets, never reports a wrong one).
Rounds repeat until nothing changes: a set first derived by a chain of d units
appears by round d, so at most (cone size + 1) rounds run. Cost per round:
the cone's units times `keep`**2 set unions per input.

`first_additions` asks growing sizes and stops at the first that finds a set (the
same smallest sets as one search of the largest size), after one cheap fixpoint
that proves no set of any size exists (a goal behind a cycle): a batch's
unreachable goals mostly end there.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ..model.foon import ObjectNode
from .reachability import UNREACHED, Reachability

Family = tuple[frozenset[int], ...]


@dataclass(frozen=True)
class Additions:
    """Inclusion-minimal sets of addable nodes (smallest first) that make a goal reachable."""

    sets: tuple[tuple[ObjectNode, ...], ...]
    max_size: int
    exact: bool
    #: False when no set of any size works (every way to the goal needs a node that itself needs it)
    possible: bool = True

    @property
    def smallest(self) -> tuple[tuple[ObjectNode, ...], ...]:
        """The sets of the fewest nodes."""
        if not self.sets:
            return ()
        n = len(self.sets[0])
        return tuple(s for s in self.sets if len(s) == n)


def _minimal(sets: Iterable[frozenset[int]], max_size: int, keep: int) -> tuple[Family, bool]:
    """Inclusion-minimal sets of at most `max_size`, smallest first (ties: sorted ids), cut to `keep`."""
    ordered = sorted({s for s in sets if len(s) <= max_size}, key=lambda s: (len(s), sorted(s)))
    out: list[frozenset[int]] = []
    for s in ordered:
        if not any(t <= s for t in out):
            out.append(s)
    return tuple(out[:keep]), len(out) > keep


def _product(families: list[Family], max_size: int, keep: int) -> tuple[Family, bool]:
    """Every union of one set per family (minimal, bounded)."""
    acc: Family = (frozenset(),)
    cut = False
    for fam in families:
        acc, c = _minimal((a | b for a in acc for b in fam), max_size, keep)
        cut = cut or c
        if not acc:
            break
    return acc, cut


def smallest_additions(reach: Reachability, goal_nodes: Iterable[ObjectNode], addable: Iterable[ObjectNode] | None,
                       max_size: int = 3, keep: int = 16) -> Additions:
    """The inclusion-minimal sets of `addable` nodes, at most `max_size` each, whose addition to the
    kitchen lets some of `goal_nodes` be made (smallest first; ties in node order). `addable=None`:
    any node the goal nodes depend on, except the goal nodes themselves."""
    ix = reach.index
    rounds = reach.node_round
    goal_ids = list(ix.ids(n for n in goal_nodes if n in ix.node_id))
    cone = _cone(reach, goal_ids)
    add_ids = set(cone) - set(goal_ids) if addable is None else set(ix.ids(n for n in addable if n in ix.node_id))
    fam: dict[int, Family] = {n: ((frozenset((n,)),) if n in add_ids else ()) for n in cone}
    empty: Family = (frozenset(),)
    cut = False
    for _ in range(len(cone) + 1):
        changed = False
        for n in cone:
            options = list(fam[n])
            for u in ix.makers[n]:
                prod, c = _product([fam[i] if rounds[i] == UNREACHED else empty for i in ix.inputs[u]],
                                   max_size, keep)
                cut = cut or c
                options.extend(prod)
            new, c = _minimal(options, max_size, keep)
            cut = cut or c
            if new != fam[n]:
                fam[n], changed = new, True
        if not changed:
            break
    if any(rounds[g] != UNREACHED for g in goal_ids):
        found: Family = (frozenset(),)
    else:
        found, c = _minimal((s for g in goal_ids for s in fam.get(g, ())), max_size, keep)
        cut = cut or c
    sets = tuple(tuple(sorted(ix.nodes[i] for i in s)) for s in found)
    return Additions(sets, max_size, not cut)


def _cone(reach: Reachability, goal_ids: list[int]) -> list[int]:
    """The unreachable nodes the goals depend on, through the makers of unreachable nodes, in id order."""
    ix, rounds = reach.index, reach.node_round
    cone: list[int] = []
    seen: set[int] = set()
    stack = [g for g in goal_ids if rounds[g] == UNREACHED]
    while stack:
        n = stack.pop()
        if n in seen:
            continue
        seen.add(n)
        cone.append(n)
        for u in ix.makers[n]:
            stack.extend(i for i in ix.inputs[u] if rounds[i] == UNREACHED and i not in seen)
    return sorted(cone)


def first_additions(reach: Reachability, goal_nodes: Iterable[ObjectNode], addable: Iterable[ObjectNode] | None,
                    sizes: Iterable[int], keep: int = 16) -> Additions:
    """`smallest_additions` for each of `sizes` (growing) until one finds a set: the same smallest sets as one
    search of the largest size (a family's sets of at most k nodes come from its inputs' sets of at most k alone,
    and a cut keeps the smallest first), where a small size costs a fraction. `exact` holds when no search cut
    a family (a cut at a size is a cut at every larger one).

    First one fixpoint of the goals' cone with every addable node added: when even that makes no goal node, no
    set of any size does, and the answer is exact and empty without a search (the cycle of a dough that needs
    its own starter; most of a batch's unreachable goals on the shared network)."""
    goal_nodes = list(goal_nodes)
    sizes = sorted(sizes)
    if addable is not None:
        addable = frozenset(addable)
    if not _some_set_works(reach, goal_nodes, addable):
        return Additions((), sizes[-1], True, possible=False)
    exact = True
    for size in sizes:
        fixes = smallest_additions(reach, goal_nodes, addable, max_size=size, keep=keep)
        exact = exact and fixes.exact
        if fixes.sets:
            return Additions(fixes.sets, size, exact)
    return Additions((), sizes[-1], exact)


def _some_set_works(reach: Reachability, goal_nodes: list[ObjectNode], addable: frozenset[ObjectNode] | None) -> bool:
    """Whether adding every `addable` node of the goals' cone (None: every cone node but the goals) lets a goal node
    be made, by the same AND/OR rule over the same makers as the families: a node is made when it is added or
    some maker has every input reachable or made (rounds over the cone until nothing changes)."""
    ix, rounds = reach.index, reach.node_round
    goal_ids = [i for i in ix.ids(n for n in goal_nodes if n in ix.node_id)]
    if any(rounds[g] != UNREACHED for g in goal_ids):
        return True
    cone = _cone(reach, goal_ids)
    if addable is None:
        made = set(cone) - set(goal_ids)
    else:
        made = {n for n in cone if ix.nodes[n] in addable}
    changed = True
    while changed:
        changed = False
        for n in cone:
            if n not in made and any(all(rounds[i] != UNREACHED or i in made for i in ix.inputs[u])
                                     for u in ix.makers[n]):
                made.add(n)
                changed = True
    return any(g in made for g in goal_ids)
