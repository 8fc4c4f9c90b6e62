"""Readers first: a delete-free plan reordered so a unit that only reads a node fires before one that moves the
object out of it.

`instance_counts.delete_free_plan` lists units in the order the kitchen's fixpoint fires them. A unit that
changes an object out of a node N may then come before a unit that only reads N (its role keeps the object
there), though nothing the reader needs comes from it: the chocolate cake's turn off
(`0058-chocolate_cake.txt:242`) fires in the round the mixer is on, before the mix (`:228`) that needs the
mixer on. Unfolded in that order the mix needs a second mixer on, and everything that mixer's chain takes is
counted again: the mixer's attach and turn on, the bowl's four pours, the flour mixture's mix and its five
pours and sprinkles (50 objects in the problem against 43 for `instances`).

Rule (`readers_first`): for each unit M of the plan, in order, and the last later unit R that takes a node M
moves an object out of without changing it there, M is moved right after R when no unit after M up to R takes
a node M's roles leave an object in (nothing between needs M), else R right before M when R takes no node a
unit from M up to R leaves an object in (R needs nothing made between): every unit still fires after the units
that make its inputs. The fries' remove (`0035-oven-baked_sweet_potato_fries.txt:212`), which
`count_returns.with_returns` puts in right after the put inside as the tray's way back, so fires after the bake
that reads the tray in the oven. Repeated until no unit moves (at most p^2 moves). The moves can cycle, M after R
and back: in the GEN trial 10 goal 83 cell of the experiment, 96 of the 468 plans ordered (70-74 units) met an order
again and went round that cycle up to the p^2 cap (4,900-5,476 moves, most of that cell's time); the
order the cap stops at is read off the cycle instead (the same order). The plan unfolds as before
otherwise; only the order, and so which takings share an object, changes. Only in `relational`
(`instance_counts.derive_counts` with `together`): `instances`' counts are the floor this one is compared with.
O(p^3 u) at worst for a plan of p units (`readers_first`'s doc); plans have tens of units.

Readers first can also count more: the ribs' remove (`0018-barbecue-style_country_ribs.txt:197`), put in as the
tray's way back, fired after the second cook leaves the oven `off`, and that cook counted an oven of its own (11
objects in the problem; 10 in the fixpoint's order). So `orders` lists every plan readers first and as it was,
and `derive_counts` keeps the one that counts fewest objects, readers first on a tie.

Takers last (`takers_last`): a unit T that moves an object out of a node N fires right after the first later unit
that leaves an object in N, when no unit from T up to that one takes a node T leaves an object in; `count_reuse`
then gives T the object left there instead of counting another. The shared universal's watermelon lemonade filled
a measuring cup with water at the faucet (`0075-pesto_linguine.txt:13`, for the pour at
`0084-watermelon_lemonade.txt:296`) in an early round, before the pour and stir (`:277`) left the juice's cup
`measuring cup (empty)`: two measuring cups, 24 objects in the problem against `instances`' 23; one, 23, with the
fill after it. Each plan `orders` lists is listed again takers last, after all of them: kept only when it counts
fewer. O(p^4 r) at worst for p units of r roles (`takers_last`'s doc).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.pairing import Role

__all__ = ["orders", "readers_first", "takers_last"]


def readers_first(foon: Foon, plan: Sequence[int], roles_of: Callable[[FunctionalUnit], tuple[Role, ...]]
                  ) -> tuple[int, ...]:
    """`plan` with each unit that moves an object out of a node after the later units that only read that node,
    where no unit between needs it (module doc). A unit's node sets are bit masks over the plan's nodes, and for each
    unit the units that read what it moves out, take what it leaves and leave what it takes are found once: a pass
    looks only at those units' positions, never walks the plan between two units; an order met again is a cycle, and
    the order after the p^2 moves is read off it (module doc). O(p^3 u) at worst for p units, u the most positions
    of a unit's related units: at most p^2 passes, each O(p) to index the positions, then O(u) for each unit tried
    before the one that moves; a plan may list a unit twice (`count_returns.with_returns`)."""
    order = list(plan)
    units = set(order)
    roles = {u: roles_of(foon.units[u]) for u in units}
    bit: dict[ObjectNode, int] = {}  # each node one bit: the sets below are built with int `&`s

    def nodes(u: int, keep: Callable[[Role], ObjectNode | None]) -> int:
        return sum({1 << bit.setdefault(n, len(bit)) for r in roles[u] if (n := keep(r)) is not None})

    moved_out = {u: nodes(u, lambda r: r.before if r.changes else None) for u in units}
    leaves = {u: nodes(u, lambda r: r.after if r.changes else None) for u in units}
    takes = {u: nodes(u, lambda r: r.before) for u in units}
    read = {u: nodes(u, lambda r: None if r.changes else r.before) for u in units}

    def those(mask: int, of: dict[int, int]) -> frozenset[int]:  # the units whose `of` nodes meet `mask`
        return frozenset(u for u in units if of[u] & mask)

    readers = {m: rs for m in units if moved_out[m] and (rs := those(moved_out[m], read))}
    needers = {m: those(leaves[m], takes) for m in readers}  # take a node M leaves an object in
    feeders = {r: those(takes[r], leaves) for r in set().union(*readers.values())}  # leave one in a node R takes
    cap = len(order) ** 2  # moves at most: the rule can cycle (a unit moved after a reader, then back before it)
    met: dict[tuple[int, ...], int] = {}  # each order the moves met -> the move it was met before
    trail: list[tuple[int, ...]] = []
    for t in range(cap):
        if (now := tuple(order)) in met:  # a cycle: the order `cap` moves stop at, taken from the cycle
            return trail[met[now] + (cap - met[now]) % (t - met[now])]
        met[now] = t
        trail.append(now)
        at: dict[int, list[int]] = {}  # unit -> its positions in `order`, ascending
        for k, u in enumerate(order):
            at.setdefault(u, []).append(k)
        for i, m in enumerate(order):
            if (rs := readers.get(m)) is None:
                continue
            j = max((k for r in rs for k in at.get(r, ()) if k > i), default=None)  # the last later reader
            if j is None:
                continue
            if not any(i < k <= j for u in needers[m] for k in at[u]):
                order.insert(j, order.pop(i))  # M right after R
            elif not any(i <= k < j for u in feeders[order[j]] for k in at[u]):
                order.insert(i, order.pop(j))  # R right before M
            else:
                continue
            break
        else:
            break
    return tuple(order)


def takers_last(foon: Foon, plan: Sequence[int], roles_of: Callable[[FunctionalUnit], tuple[Role, ...]]
                ) -> tuple[int, ...]:
    """`plan` with each unit that moves an object out of a node right after the first later unit that leaves an
    object in that node, where no unit from the taker up to that one takes a node the taker leaves one in (module
    doc). Repeated until no unit moves: at most p^2 passes, each O(p^2 r) (for each unit, a walk of the plan after
    it), so O(p^4 r) at worst for p units of r roles."""
    order = list(plan)
    roles = {u: roles_of(foon.units[u]) for u in order}
    moved_out = {u: {r.before for r in roles[u] if r.changes and r.before is not None} for u in order}
    leaves = {u: {r.after for r in roles[u] if r.changes} for u in order}
    takes = {u: {r.before for r in roles[u] if r.before is not None} for u in order}
    for _ in range(len(order) ** 2):
        for i, t in enumerate(order):
            j = next((k for k in range(i + 1, len(order)) if leaves[order[k]] & moved_out[t]), None)
            if j is not None and not any(takes[order[k]] & leaves[t] for k in range(i + 1, j + 1)):
                order.insert(j, order.pop(i))  # T right after L
                break
        else:
            break
    return tuple(order)


def orders(foon: Foon, plans: Sequence[Sequence[int]], own: Sequence[Sequence[int]],
           roles_of: Callable[[FunctionalUnit], tuple[Role, ...]]) -> tuple[tuple[int, ...], ...]:
    """The plans `relational`'s counts unfold, distinct, first kept on a tie: `plans` (ways back through what the
    plan makes) readers first, then as they are, then `own` (ways back through the kitchen only) as they are and
    readers first, then each of these takers last (module doc)."""
    first = tuple(readers_first(foon, p, roles_of) for p in plans)
    listed = tuple(dict.fromkeys((*first, *map(tuple, plans), *map(tuple, own),
                                  *(readers_first(foon, p, roles_of) for p in own))))
    return tuple(dict.fromkeys((*listed, *(takers_last(foon, p, roles_of) for p in listed))))
