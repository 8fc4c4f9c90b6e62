"""Applying constraints to a network: which units each constraint removes, and the filtered network.

`Removal` is computed once per (network, constraints): for every ban the units it
removes (a motion ban: units whose motion label mentions the motion, so `pour` also
bans `scoop and pour`; an object ban: units any of whose nodes mention the object,
`model.constraints.mentions`) and for every must-use object the units that use it.
From it, without recomputing any match:

- `filtered()`: the network without the removed units (original order kept, so the
  searches' tie-breaks are those of the full network), the kitchen without nodes
  mentioning a banned object, the goal candidates that remain possible;
- `solvable()`: whether a goal can be made under the constraints, optionally with
  some of them relaxed (the oracle of `blocking.py`). Must-use is *plan* semantics,
  the same as the PDDL goal `(used X)`: the goal is made and some unit using X fires.
  Delete-free, so this holds iff the fixpoint without the removed units reaches a
  candidate and fires a unit using X. Time: one fixpoint, O(network).
Everything is pure; `removed` remembers which units were removed by which constraint.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property

from ..model.constraints import Constraint, Constraints, Kind, label_mentions, mentions, node_labels
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from .index import index_of
from .reachability import reachable


@dataclass(frozen=True)
class Filtered:
    """A network, kitchen and goal with the constraints applied."""

    foon: Foon
    kept: tuple[int, ...]  # index in the original network of each unit of `foon`
    kitchen: frozenset[ObjectNode]
    candidates: tuple[ObjectNode, ...]  # goal candidates still possible (sorted)
    goal: Goal


@dataclass(frozen=True, eq=False)
class Removal:
    """What each constraint removes from one network (see the module doc)."""

    foon: Foon
    constraints: Constraints
    removed: dict[Constraint, frozenset[int]] = field(hash=False)  # ban -> unit indexes it removes
    users: dict[str, frozenset[int]] = field(hash=False)  # must-use object -> unit indexes using it
    masks: dict[str, bytearray] = field(hash=False, default_factory=dict)  # object -> node id -> mentions it

    def relaxed(self, drop: Iterable[Constraint]) -> Removal:
        """The removal of these constraints with `drop` relaxed (no label is matched again)."""
        cons = self.constraints.without(drop)
        keep = set(cons.items)
        return Removal(self.foon, cons, {c: u for c, u in self.removed.items() if c in keep},
                       {x: u for x, u in self.users.items() if x in cons.must_use}, self.masks)

    def skipped(self, relaxed: Iterable[Constraint] = ()) -> frozenset[int]:
        """Unit indexes removed by the bans not in `relaxed`."""
        gone = set(relaxed)
        return frozenset().union(*(units for c, units in self.removed.items() if c not in gone))

    def banned_objects(self, relaxed: Iterable[Constraint] = ()) -> tuple[str, ...]:
        gone = set(relaxed)
        return tuple(c.value for c in self.constraints.items if c.kind is Kind.WITHOUT and c not in gone)

    def node_allowed(self, node: ObjectNode, relaxed: Iterable[Constraint] = ()) -> bool:
        """Whether `node` mentions none of the banned objects (those in `relaxed` aside)."""
        i = index_of(self.foon).node_id.get(node)
        for x in self.banned_objects(relaxed):
            mask = self.masks.get(x)
            if (mentions(node, x) if mask is None or i is None else mask[i]):
                return False
        return True

    @cached_property
    def removed_units(self) -> frozenset[int]:
        return self.skipped()

    @cached_property
    def kept(self) -> tuple[int, ...]:
        """Indexes of the units no ban removes."""
        drop = self.removed_units
        return tuple(i for i in range(len(self.foon.units)) if i not in drop)

    @cached_property
    def network(self) -> Foon:
        """The network without the removed units (original order; the network itself when nothing is removed)."""
        if not self.removed_units:
            return self.foon
        return Foon(tuple(self.foon.units[i] for i in self.kept), self.foon.level)

    def filtered(self, kitchen: Iterable[ObjectNode], goal: Goal) -> Filtered:
        """The network without the removed units, the kitchen without banned objects, the possible candidates."""
        kept, foon = self.kept, self.network
        kitchen = frozenset(n for n in kitchen if self.node_allowed(n))
        present = set(foon.producers) | kitchen
        cands = tuple(c for c in goal.candidates if c in present and self.node_allowed(c))
        return Filtered(foon, kept, kitchen, cands, Goal(goal.spec, cands, goal.level))

    def solvable(self, kitchen: Iterable[ObjectNode], goal: Goal, relaxed: Iterable[Constraint] = ()) -> bool:
        """Whether `goal` can be made with these constraints, except those in `relaxed` (module doc)."""
        relaxed = frozenset(relaxed)
        cands = [c for c in goal.candidates if self.node_allowed(c, relaxed)]
        if not cands:
            return False
        needs = [x for x in self.constraints.must_use if Constraint(Kind.MUST_USE, x) not in relaxed]
        skip = self.skipped(relaxed)
        kitchen = frozenset(kitchen)
        if not needs:  # only the goal's cone needs to run
            reach = reachable(self.foon, kitchen, cands, skip)
            return reach.makes_any(cands)
        reach = reachable(self.foon, kitchen, None, skip)
        fired = set(reach.fired)
        return reach.makes_any(cands) and all(self.users[x] & fired for x in needs)


def _motion_units(ix, motion: str) -> frozenset[int]:
    hits = {m for m in set(ix.motions) if label_mentions(m, motion)}
    return frozenset(u for u, m in enumerate(ix.motions) if m in hits)


def _node_mask(ix, obj: str) -> bytearray:
    """Per node id: 1 when the node mentions `obj`; label checks memoized per distinct label."""
    memo: dict[str, bool] = {}
    mask = bytearray(len(ix.nodes))
    for i, n in enumerate(ix.nodes):
        for label in node_labels(n):
            hit = memo.get(label)
            if hit is None:
                hit = memo[label] = label_mentions(label, obj)
            if hit:
                mask[i] = 1
                break
    return mask


def removal(foon: Foon, constraints: Constraints) -> Removal:
    """Which units each constraint of `constraints` removes from `foon`, and which use each must-use object.

    Time: O(network size x constraints) label comparisons, each distinct label compared once per constraint.
    """
    ix = index_of(foon)
    removed: dict[Constraint, frozenset[int]] = {}
    users: dict[str, frozenset[int]] = {}
    masks: dict[str, bytearray] = {}
    for c in constraints.items:
        if c.kind is Kind.WITHOUT_MOTION:
            removed[c] = _motion_units(ix, c.value)
            continue
        mask = masks[c.value] = masks.get(c.value) or _node_mask(ix, c.value)
        if c.kind is Kind.WITHOUT:
            removed[c] = frozenset(u for u in range(len(foon.units))
                                   if any(mask[n] for n in ix.inputs[u]) or any(mask[n] for n in ix.outputs[u]))
        else:
            users[c.value] = frozenset(u for u in range(len(foon.units)) if any(mask[n] for n in ix.inputs[u]))
    return Removal(foon, constraints, removed, users, masks)
