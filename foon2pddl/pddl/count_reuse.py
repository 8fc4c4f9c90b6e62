"""Objects an unfolded plan leaves in a kitchen node, taken again there: counted by what is there at once.

`instance_counts.unfold` counts, back from the goal, one object per taking of a kitchen node: FOON's units
never return an object to a kitchen state unless one of them does. In `relational` some do: a pour that
empties its source leaves a bowl `empty`, a measuring cup emptied into the bowl is `measuring cup (empty)`
again, and a later unit of the plan that takes `bowl (empty)` can take that bowl. `reused` runs the unfolded
plan forwards (each unit fired its times, in plan order) on objects: a role takes an object in its node when
one is there (`instance_lanes.lanes`' order: roles read the state before the firing, its changes apply
after), and a kitchen node gets a new object only when none is there at that moment. Only an object left in a
kitchen node that names no place and lists nothing (`_alone`: `bowl (empty)`, `spoon (clean)`) is taken there
again, and, as the unfolding counts it, a portion a unit makes in the kitchen node it reads: an object left in
`garlic (in [bowl], peeled)` is in a bowl of its own, not the kitchen's `bowl (contains {garlic})` a later pour
takes with it (the caesar salad, `ACT-0080-caesar_salad.txt:29`: no state applied the pour). A container
left in a kitchen node with everything it lists put in it by the same firing (`_refilled_with`: the turn on at
`0085-mini_bacon_egg_breakfast_pizza.txt:231` leaves `measuring cup (contains {water})` holding `water (from
[faucet], in [measuring cup])`) is taken there again by a unit that takes it with those contents' nodes (the pour
at `:251`), as it would be were the node no kitchen node: what it holds is what the taker pairs with it. That one
(`refill`, `instance_counts.derive_counts`') only lowers the counts of the plan chosen without it, never chooses
another plan: the kitchen container it stands for goes, and with it the node the completion starts its contents in,
which another count may take from the kitchen (`relational_objects.task_objects`). The plan
runs on these counts by construction, so the task stays solvable whenever FOON's semantics makes the goal; a node
no unit leaves an object in keeps the count the unfolding gives it.
O(firings x roles^2).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Sequence

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.pairing import Role
from ..model.places import listed, places

__all__ = ["reused"]


def reused(foon: Foon, steps: Sequence[tuple[int, int]], kitchen: frozenset[ObjectNode], target: ObjectNode,
           roles_of: Callable[[FunctionalUnit], tuple[Role, ...]], refill: bool = True) -> Counter[ObjectNode] | None:
    """Per kitchen node, the objects the plan `steps` ((unit, times) in firing order) needs to start there when
    an object a firing leaves in a kitchen node serves a later taker (module doc); the goal `target` must hold
    one at the end. None when the plan does not run (a node no kitchen holds has no object when a role takes
    it): the unfolding's counts stand. `refill`: a container left filled in a kitchen node is taken again too
    (`_refilled_with`)."""
    there: Counter[ObjectNode] = Counter()  # objects in each node now
    start: Counter[ObjectNode] = Counter()
    left_in: dict[ObjectNode, list[frozenset[ObjectNode]]] = {}  # kitchen node -> per container left there, its contents
    for u, times in steps:
        roles = roles_of(foon.units[u])
        need = Counter(r.before for r in roles if r.before is not None)
        read = {r.before for r in roles if r.before is not None and r.after is None}
        for _ in range(times):
            for n, k in need.items():
                left = left_in.get(n, [])
                while there[n] < k and (i := next((i for i, c in enumerate(left) if c <= need.keys()), None)) is not None:
                    left.pop(i)  # a container left there holding what this unit takes with it
                    there[n] += 1
                if there[n] < k:
                    if n not in kitchen:
                        return None
                    start[n] += k - there[n]
                    there[n] = k
            for r in roles:
                if r.changes:
                    if r.before is not None:
                        there[r.before] -= 1
                    if r.after not in kitchen or _alone(r.after) or (r.before is None and r.after in read):
                        there[r.after] += 1
                    elif refill and (inside := _refilled_with(r, roles, kitchen)) is not None:
                        left_in.setdefault(r.after, []).append(inside)
    if there[target] < 1:
        if target not in kitchen:
            return None
        start[target] += 1
    return +start


def _alone(node: ObjectNode) -> bool:
    """Whether an object in `node` is where it is alone: the node names no place and lists nothing. An object left
    in a kitchen node that does (`garlic (in [bowl], peeled)`) is in some holder, not necessarily the one a later
    taker needs it in (or holds what it lists, not necessarily what the taker's node pairs with it)."""
    return not places(node) and not listed(node)


def _refilled_with(container: Role, roles: Sequence[Role], kitchen: frozenset[ObjectNode]) -> frozenset[ObjectNode] | None:
    """The nodes the firing of `roles` leaves in or on `container`'s object, when they are everything its node
    after lists, each of a label it lists, placed in or on its label, and no kitchen node (so counted where they
    are); None otherwise: the container holds what the kitchen's node pairs with it, or more than its firing put
    there. O(roles)."""
    inside = frozenset(r.after for r in roles if r is not container and r.changes and r.after is not None
                       and any(h == container.label for _, h in places(r.after)))
    labels = {x.label for x in inside}
    if not inside or labels != listed(container.after) or any(x in kitchen for x in inside):
        return None
    return inside
