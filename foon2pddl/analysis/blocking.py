"""Why a goal cannot be made under constraints: the smallest set of constraints to relax.

Relaxing constraints only ever adds units or drops requirements, so "the goal is
reachable with the set R relaxed" is monotone in R. The minimum such R is found by
trying the subsets of the *relevant* constraints by increasing size (each check is
one fixpoint, `Removal.solvable`): the first that works is a smallest one, and by
monotonicity no smaller set works. Relevant are the must-use constraints and the
bans that remove a unit of the goal's cone (the units that can contribute to a goal
candidate or to a unit using a must-use object); relaxing any other ban adds no unit
that could help. The search stops after `max_checks` subsets; then an irredundant
set (no constraint in it can be dropped) is returned instead, marked `minimum=False`.
Worst case 2^relevant fixpoints; in practice the answer has one or two constraints.

The message names, for a ban in the set, the first node of a tree for the goal (with the
set relaxed) whose every maker needs it: "every way to make 'dough (mixed)' needs `without-motion mix`".
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

from ..model.constraints import Constraint, Kind, describe_all, mentions
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.goal import Goal
from .constraints import Removal
from .reachability import UNREACHED, blocker_words, reachable, relevant_units

#: Subsets tried before settling for an irredundant set.
MAX_CHECKS = 4096


@dataclass(frozen=True)
class Blocking:
    """The constraints to relax (None: the goal cannot be made even without constraints) and the words."""

    relax: tuple[Constraint, ...] | None
    message: str
    minimum: bool = True
    checks: int = 0


def relevant_constraints(rm: Removal, kitchen: frozenset[ObjectNode], goal: Goal) -> tuple[Constraint, ...]:
    """Must-use constraints and the bans that remove a unit of the goal's cone (module doc)."""
    from .index import index_of

    ix = index_of(rm.foon)
    in_kitchen = bytearray(len(ix.nodes))
    for k in ix.kitchen_ids(kitchen):
        in_kitchen[k] = 1
    targets = set(ix.ids(goal.candidates))
    for units in rm.users.values():
        for u in units:
            targets.update(ix.inputs[u])
    cone = set(relevant_units(ix, targets, in_kitchen)) | set().union(*rm.users.values())
    return tuple(c for c in rm.constraints.items
                 if c.kind is Kind.MUST_USE or rm.removed.get(c, frozenset()) & cone
                 or (c.kind is Kind.WITHOUT and any(mentions(n, c.value) for n in goal.candidates)))


def minimal_blocking_set(rm: Removal, kitchen: Iterable[ObjectNode], goal: Goal,
                         max_checks: int = MAX_CHECKS) -> tuple[tuple[Constraint, ...] | None, bool, int]:
    """(smallest set of constraints to relax, whether proven smallest, checks made); () when nothing
    blocks; None when the goal cannot be made even with every constraint relaxed."""
    kitchen = frozenset(kitchen)
    if rm.solvable(kitchen, goal):
        return (), True, 1
    pool = relevant_constraints(rm, kitchen, goal)
    if not rm.solvable(kitchen, goal, pool):
        return None, True, 2
    checks = 2
    for size in range(1, len(pool) + 1):
        for subset in itertools.combinations(pool, size):
            if checks >= max_checks:
                return _irredundant(rm, kitchen, goal, pool), False, checks
            checks += 1
            if rm.solvable(kitchen, goal, subset):
                return subset, True, checks
    raise AssertionError("unreachable: relaxing the whole pool works")


def _irredundant(rm: Removal, kitchen: frozenset[ObjectNode], goal: Goal,
                 pool: tuple[Constraint, ...]) -> tuple[Constraint, ...]:
    """Drop constraints from the relaxed set while the goal stays reachable (one pass, sorted order)."""
    relax = list(pool)
    for c in pool:
        trial = [x for x in relax if x != c]
        if rm.solvable(kitchen, goal, trial):
            relax = trial
    return tuple(relax)


def blocked_node(rm: Removal, kitchen: frozenset[ObjectNode], ban: Constraint, relax: tuple[Constraint, ...],
                 tree: Sequence[FunctionalUnit]) -> ObjectNode | None:
    """The first node made by `tree` (a tree for the goal with `relax` relaxed, in executable order)
    that the constraints make unreachable and whose every maker that can fire with `relax` relaxed
    is removed by `ban`."""
    removed = rm.removed.get(ban, frozenset())
    relaxed = reachable(rm.foon, kitchen, None, rm.skipped(relax))
    strict = reachable(rm.foon, kitchen, None, rm.skipped())
    ix = relaxed.index
    for unit in tree:
        for node in unit.outputs:
            o = ix.node_id.get(node)
            if o is None or strict.node_round[o] != UNREACHED or relaxed.node_round[o] == UNREACHED:
                continue
            makers = [u for u in ix.makers[o] if relaxed.unit_round[u] != UNREACHED]
            if makers and all(u in removed for u in makers):
                return node
    return None


def explain_blocked(rm: Removal, kitchen: Iterable[ObjectNode], goal: Goal,
                    tree: Callable[[tuple[Constraint, ...]], Sequence[FunctionalUnit]] = lambda relax: ()) -> Blocking:
    """The minimal blocking set of an unreachable goal with words naming what each constraint blocks.

    `tree(relax)` gives a task tree for the goal with `relax` relaxed (the retrieval layer's);
    the first node of it that a ban blocks is named (`blocked_node`), else the goal.
    """
    kitchen = frozenset(kitchen)
    relax, minimum, checks = minimal_blocking_set(rm, kitchen, goal)
    what = repr(goal.describe())
    if relax is None:
        reach = reachable(rm.foon, kitchen, goal.candidates)
        lacking = blocker_words(reach, goal.candidates)
        why = ("; missing (no unit makes them): " + lacking) if lacking else ""
        return Blocking(None, f"{what} cannot be made from the kitchen even without the constraints{why}",
                        True, checks)
    if not relax:
        return Blocking((), f"{what} can be made under the constraints", True, checks)
    parts = []
    for c in relax:
        if c.kind is Kind.MUST_USE:
            parts.append(f"no unit using {c.value!r} can run with the goal under the other constraints")
        elif c.kind is Kind.WITHOUT and all(mentions(n, c.value) for n in goal.candidates):
            parts.append(f"every candidate of {what} mentions {c.value!r}")
        else:
            node = blocked_node(rm, kitchen, c, relax, tree(relax))
            target = repr(node.describe()) if node is not None else what
            parts.append(f"every way to make {target} needs `{c.describe()}`")
    names = " + ".join(f"`{d}`" for d in describe_all(relax))
    size = "smallest" if minimum else "an irredundant"
    return Blocking(relax, "; ".join(parts) + f"; {size} set of constraints to relax: {names}", minimum, checks)
