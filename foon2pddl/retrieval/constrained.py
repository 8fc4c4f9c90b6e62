"""Retrieval under constraints: every method runs unchanged on the filtered network.

The network loses the units the bans remove, the kitchen its banned objects and the
goal its banned candidates (`analysis.constraints`). Must-use objects are reduced to
an ordinary goal by two kinds of auxiliary units that never reach the caller: each unit
using X also outputs a marker node `used X`, and one goal unit per candidate takes the
candidate and every `used X` marker to a single goal node. A tree for that node is a
tree for a candidate plus, for each X, a unit using X (shared units counted once):
- complete: exact, since it finds a tree iff the fixpoint reaches the goal node,
  i.e. iff the goal can be made and a unit using each X can fire (`Removal.solvable`);
- greedy: finds a tree whenever one exists (as without constraints);
- optimal: fewest units over all such trees (every tree has the same goal units);
- weighted: highest success product (auxiliary motions have rate 1).
The unit using X is in the tree, but need not contribute to the goal (when no way
of making the goal uses X, it is a side step; `detail` says so). When there is no
tree, `blocking` holds the smallest set of constraints whose relaxing makes the goal
reachable, and `detail` says which constraint blocks what.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from ..analysis.blocking import Blocking, explain_blocked
from ..analysis.constraints import Filtered, Removal, removal
from ..io.rates import Rates
from ..model.constraints import Constraints, Kind, mentions, unit_uses
from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, make_node, make_state
from ..model.goal import Goal, GoalSpec
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree, justify
from ..model.words import count, first_of
from .api import kitchen_nodes, retrieve
from .methods import get_method
from .result import UNREACHABLE, Retrieval

#: Labels of the auxiliary nodes and motion: the unit separator cannot occur in a real label.
USED = "\x1fused"
GOAL = "\x1fgoal"


@dataclass(frozen=True)
class ConstrainedRetrieval:
    """A retrieval under constraints, with what the constraints removed and, if blocked, why."""

    result: Retrieval
    removal: Removal
    filtered: Filtered
    blocking: Blocking | None = None


def used_marker(obj: str) -> ObjectNode:
    return make_node(USED, [make_state(obj)])


def with_must_use(filtered: Filtered, must_use: tuple[str, ...]) -> tuple[Foon, Goal, dict[int, FunctionalUnit]]:
    """The filtered network with the auxiliary units of `must_use` (module doc), its goal, and
    id(auxiliary-network unit) -> real unit."""
    goal_node = make_node(GOAL)
    markers = {x: used_marker(x) for x in must_use}
    real: dict[int, FunctionalUnit] = {}
    units: list[FunctionalUnit] = []
    for u in filtered.foon.units:
        extra = tuple(markers[x] for x in must_use if unit_uses(u, x))
        v = FunctionalUnit(u.inputs, u.motion, u.outputs + extra, u.sources) if extra else u
        real[id(v)] = u
        units.append(v)
    for c in filtered.candidates:
        units.append(FunctionalUnit((c, *markers.values()), Motion(GOAL), (goal_node,)))
    foon = Foon(tuple(units), filtered.foon.level)
    return foon, Goal(GoalSpec(GOAL), (goal_node,), filtered.goal.level), real


def _real_tree(tree: TaskTree, real: dict[int, FunctionalUnit], must: tuple[str, ...],
               kitchen: frozenset[ObjectNode]) -> TaskTree:
    """The auxiliary network's tree as a tree of real units for the candidate it reached; when the units
    the candidate needs already use every must-use object, only those (side steps dropped)."""
    aux = next(u for u in tree.units if u.motion.label == GOAL)
    units = tuple(real[id(u)] for u in tree.units if id(u) in real)
    needed = justify(units, kitchen, aux.inputs[0])
    if all(any(unit_uses(u, x) for u in needed) for x in must):
        units = needed
    return TaskTree(units, aux.inputs[0], tree.level)


def retrieve_constrained(foon: Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal, constraints: Constraints,
                         method: str = "complete", rates: Rates | None = None, rm: Removal | None = None,
                         **limits) -> ConstrainedRetrieval:
    """`retrieve` on the network filtered by `constraints` (module doc); `limits`: budget, node_limit.
    `rm`: the removal of `constraints` from `foon` when already computed."""
    nodes = kitchen_nodes(kitchen, foon.level)
    rm = rm if rm is not None else removal(foon, constraints)
    filtered = rm.filtered(nodes, goal)
    must = constraints.must_use
    if filtered.candidates:
        if must or not all(c in filtered.foon.producers for c in filtered.candidates):
            aux_foon, aux_goal, real = with_must_use(filtered, must)
            if rates is not None or get_method(method).needs_rates:
                base = rates or Rates()
                rates = Rates({**base.table, GOAL: 1.0}, base.default, base.source)
            result = retrieve(aux_foon, filtered.kitchen, aux_goal, method, rates=rates, **limits)
            if result.tree is not None:
                tree = _real_tree(result.tree, real, must, filtered.kitchen)
                result = replace(result, tree=tree, detail=_side_note(tree, must, filtered.kitchen, result.detail),
                                 **_without_goal_unit(result, tree))
        else:
            result = retrieve(filtered.foon, filtered.kitchen, filtered.goal, method, rates=rates, **limits)
        if result.tree is not None or result.reason != UNREACHABLE:
            return ConstrainedRetrieval(result, rm, filtered)
    def relaxed_tree(relax):
        loose = rm.relaxed(relax)
        done = retrieve_constrained(foon, nodes, goal, loose.constraints, "complete", rm=loose)
        return done.result.tree.units if done.result.tree is not None else ()

    blocking = explain_blocked(rm, nodes, goal, relaxed_tree)
    return ConstrainedRetrieval(Retrieval(None, UNREACHABLE, method, blocking.message), rm, filtered, blocking)


def _without_goal_unit(result: Retrieval, tree: TaskTree) -> dict:
    """Cost and bound of the real tree: the auxiliary goal unit costs 1 unit (optimal), 0 (weighted: rate 1)."""
    if result.bound is None:
        return {}
    extra = float(len(result.tree) - len(tree)) if not get_method(result.method).needs_rates else 0.0
    return {"cost": result.cost - extra, "bound": max(0.0, result.bound - extra)}


def _side_note(tree: TaskTree, must: tuple[str, ...], kitchen: frozenset[ObjectNode], detail: str) -> str:
    """`detail`, plus which must-use objects are used only by side steps the goal does not need."""
    needed = justify(tree.units, kitchen, tree.goal)
    side = [x for x in must if not any(unit_uses(u, x) for u in needed)]
    if not side:
        return detail
    note = "used by a side step, not on the way to the goal: " + ", ".join(side)
    return f"{detail}; {note}" if detail else note


@dataclass(frozen=True)
class Shaping:
    """How one constraint shaped a solved goal's tree."""

    constraint: str
    removed: int  # units of the network it removes
    avoided: tuple[FunctionalUnit, ...]  # units of the unconstrained tree (same method) it removes


def shaping(foon: Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal, done: ConstrainedRetrieval,
            method: str = "complete", rates: Rates | None = None, **limits) -> tuple[Shaping, ...]:
    """For each ban, the units it removes and those of the unconstrained tree (by `method`) it avoided."""
    base = retrieve(foon, kitchen_nodes(kitchen, foon.level), goal, method, rates=rates, **limits)
    index = {u.key: i for i, u in enumerate(foon.units)}
    units = base.tree.units if base.tree is not None else ()
    return tuple(Shaping(c.detail(), len(gone), tuple(u for u in units if index[u.key] in gone))
                 for c, gone in sorted(done.removal.removed.items()))


def constraint_notes(removal: Removal, read_from: Foon | None = None, name: str = "") -> list[str]:
    """One line saying what each constraint removes, and a warning per constraint that matches nothing.

    `read_from`: the network as read, when `removal`'s network names its objects by category (FOON-`name`):
    a ban of an object only that one names is no typo; a note says why it removes no unit.
    """
    total = len(removal.foon.units)
    parts, warnings = [], []
    skills: dict[str, set[int]] = {}  # a lacking skill's motion bans, read as the one option the user gave
    for c in removal.constraints.items:
        if c.skill:
            skills.setdefault(c.skill, set()).update(removal.removed.get(c, ()))
            continue
        if c.kind is Kind.MUST_USE:
            n = len(removal.users.get(c.value, ()))
            parts.append(f"`{c.describe()}`: {count(n, 'unit')} {'uses' if n == 1 else 'use'} it")
        else:
            n = len(removal.removed.get(c, ()))
            parts.append(f"`{c.detail()}` removes {n} of {count(total, 'unit')}")
        if not n and c.kind is Kind.WITHOUT and read_from is not None and \
                any(mentions(node, c.value) for node in read_from.nodes):
            warnings.append(f"note: FOON-{name} reads {c.value!r} as its category: `{c.detail()}` removes none of "
                            f"its units; the kitchen loses what mentions it before it is abstracted")
        elif not n:
            warnings.append(f"warning: no unit of the network mentions {c.value!r} (`{c.detail()}`, "
                            f"from {c.source or 'the options'})")
    for skill, gone in sorted(skills.items()):
        parts.append(f"`without-skill {skill}` removes {len(gone)} of {count(total, 'unit')}")
        if not gone:
            warnings.append(f"warning: no unit of the network has a motion the table maps to the skill {skill!r} "
                            f"(`without-skill {skill}`)")
    return (["constraints: " + "; ".join(parts)] if parts else []) + warnings


def explain_line(s: Shaping) -> str:
    """`explain: without-motion pour removes 21 units; the unconstrained tree's ... avoided`."""
    text = f"explain: `{s.constraint}` removes {count(s.removed, 'unit')}"
    if not s.avoided:
        return text + "; the unconstrained tree uses none of them"
    shown = first_of(s.avoided, 3, FunctionalUnit.describe)
    return text + f"; avoided {count(len(s.avoided), 'unit')} of the unconstrained tree: {shown}"
