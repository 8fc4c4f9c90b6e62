"""What the unfolded plan of `instance_counts` does with each named instance (`lanes`), for `encode_instances`.

With derived counts the unfolded plan (each unit fired as often as `instance_counts.derive_counts` says, in plan
order) runs on exactly the declared instances. Running it once, binding each role to the first free instance in
the encoding's order, says which states each instance passes through and which instances change state together;
`encode_instances` confines each instance to that lane, so a unit grounds over the few bindings the plan uses
instead of the product of its labels' instance counts, and the task stays solvable.

Pure; O(sum over firings of the unit's roles x the instances in a role's state).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ..model.foon import Foon, ObjectNode
from ..model.pairing import unit_roles
from .instance_counts import InstanceCounts

__all__ = ["Lanes", "lanes"]


@dataclass(frozen=True)
class Lanes:
    """What the unfolded plan does with each instance (`lanes`): `steps`, its state changes `(name, before,
    after)` (`before` None: made) and `(name, s, s)` for every node `s` it is ever in; `together`, the ordered
    pairs of instances that change state in one firing."""

    steps: frozenset[tuple[str, ObjectNode | None, ObjectNode]]
    together: frozenset[tuple[str, str]]


def lanes(foon: Foon, counts: InstanceCounts, instances: Sequence[tuple[str, str, ObjectNode | None]]) -> Lanes | None:
    """Run the unfolded plan on exactly these instances and say what each one does (`Lanes`); None when
    there is no unfolded plan (`InstanceCounts.unfolded`) or it does not run on them.

    `instances`: (name, label, start node or None) in the encoding's order, which is also the order two
    roles needing one state bind in (`precedes`): each role takes the first instance (in that order) in
    its state that the firing has not taken yet, so an earlier role gets an earlier instance. Roles read
    the state before the firing; its changes apply after. Confining each instance to its lane and each
    firing's changing instances to ones that changed together (`encode_instances`) keeps the unfolded plan
    runnable, so the task stays solvable, and a unit grounds over the few bindings the plan uses instead
    of the product of its labels' instance counts.
    """
    if not counts.unfolded:
        return None
    firings = dict(counts.firings)
    order = {name: k for k, (name, _, _) in enumerate(instances)}
    at: dict[tuple[str, ObjectNode | None], list[str]] = {}  # (label, node or None: not made) -> instances there
    for name, label, start in instances:
        at.setdefault((label, start), []).append(name)
    steps = {(name, start, start) for name, _, start in instances if start is not None}
    together: set[tuple[str, str]] = set()
    for u in counts.unfolded:
        roles = unit_roles(foon.units[u])
        for _ in range(firings[u]):
            taken: set[str] = set()
            moves = []
            for r in roles:
                free = [x for x in at.get((r.label, r.before), ()) if x not in taken]
                if not free:
                    return None  # the counts do not run the unfolded plan: no lanes
                x = min(free, key=order.__getitem__)
                taken.add(x)
                if r.changes:
                    moves.append((x, r))
                elif r.before is not None:
                    steps.add((x, r.before, r.before))
            for x, r in moves:
                at[(r.label, r.before)].remove(x)
                at.setdefault((r.label, r.after), []).append(x)
                steps.add((x, r.before, r.after))
                steps.add((x, r.after, r.after))
            together.update((x, y) for x, _ in moves for y, _ in moves if x != y)
    return Lanes(frozenset(steps), frozenset(together))
