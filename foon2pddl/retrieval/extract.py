"""From achiever choices to a task tree: keep the needed units, in executable order.

Every search ends with a map node id -> the unit chosen to make it, acyclic by
construction (first achievers in a firing order, or commitments checked for
cycles). Walking back from the goal keeps only the units some needed node is
made by (pruning the rest); a depth-first post-order (inputs in node-id order)
emits each unit after the units making its inputs, so the order is
topological and the units of one subtree stay together.

When the units come from a firing order (`position`: unit -> when it fired),
a needed node is taken from a unit already in the tree if that unit fired
before the one needing it, instead of from its first achiever: every edge
still goes from an earlier to a later firing, so no cycle can arise, and a
subtree is not duplicated for a node the tree already makes.
"""

from __future__ import annotations

from collections.abc import Callable

from ..analysis.index import FoonIndex
from ..model.foon import Foon
from ..model.tasktree import TaskTree


def ordered_units(ix: FoonIndex, goal: int, achiever: Callable[[int], int],
                  in_kitchen: Callable[[int], bool],
                  position: Callable[[int], int] | None = None) -> tuple[int, ...]:
    """Unit indexes needed to make node `goal`, each after the makers of its inputs.

    `achiever(n)` is the unit chosen for node n (asked only for nodes for which
    `in_kitchen(n)` is false); the choices must not form a cycle (ValueError if they do).
    With `position`, a unit already in the tree that fired earlier is reused (module doc).
    """
    order: list[int] = []
    done: set[int] = set()      # units emitted
    active: set[int] = set()    # units on the DFS path
    made_by: dict[int, list[int]] = {}  # node -> emitted units outputting it (with `position`)
    if in_kitchen(goal):
        return ()
    stack: list[tuple[int, int]] = [(achiever(goal), 0)]
    active.add(stack[0][0])
    while stack:
        u, k = stack[-1]
        ins = ix.inputs[u]
        while k < len(ins):
            n = ins[k]
            k += 1
            if in_kitchen(n):
                continue
            v = -1
            if position is not None:
                here = position(u)
                v = next((w for w in made_by.get(n, ()) if position(w) < here), -1)
            if v < 0:
                v = achiever(n)
            if v in done:
                continue
            if v in active:
                raise ValueError(f"cyclic achievers at unit {u}")
            stack[-1] = (u, k)
            stack.append((v, 0))
            active.add(v)
            break
        else:
            stack.pop()
            active.discard(u)
            done.add(u)
            order.append(u)
            if position is not None:
                for o in ix.outputs[u]:
                    made_by.setdefault(o, []).append(u)
    return tuple(order)


def make_tree(foon: Foon, ix: FoonIndex, goal: int, units: tuple[int, ...]) -> TaskTree:
    """The TaskTree of the given unit indexes (already ordered) for node `goal`."""
    return TaskTree(tuple(foon.units[u] for u in units), ix.nodes[goal], foon.level)
