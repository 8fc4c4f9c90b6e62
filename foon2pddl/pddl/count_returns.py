"""Ways back: the units that bring an object back to a node a later unit of a delete-free plan takes.

`instance_counts.delete_free_plan` makes each needed node once. When a unit of the plan moves an object out of a
node that a later unit of the plan takes (0011's first cook and stir leaves the pot of soup `hot`, while the
second cook and stir takes `pot (contains {soup}, on [stove])`, the node the first took), the unfolding counts a
second object for the later unit, and doubles everything that object's chain needs (a second pot, a second
soup, a second blender jar with each of its ten ingredients: 2^12 groundings of the relational add). The task's
units often lead the object back (the cover and the uncover): `with_returns` puts them into the plan after the
unit, and the later unit takes the object that came back.

Rule (`with_returns`): for each role of a plan's unit that changes an object out of a node N no kitchen holds
and that a later unit of the plan takes, the fewest units of the task outside the plan (at most `RETURN_DEPTH`)
that change the object from the role's output node back to N, one after the other, each taking otherwise only
kitchen nodes and nodes the units before it on the way make (`_way_back`), are inserted after that unit, each
unit once. With `stitched` (a task that reads inputs no unit makes as `input_stitch` does), a unit on the way
may take the object in a node no unit makes that says less than the one it is in (`said_words.said_less`: the
uncover's pot, no longer `hot`, is the cover's). With `plan_made` (`relational`), a unit on the way may also take a node a unit of the plan up to that unit makes:
the fries' remove (`0035-oven-baked_sweet_potato_fries.txt:212`) takes the oven the put inside leaves `with
[baking tray]` (`count_order.readers_first` then fires it after the bake). The way is searched breadth-first over the spare units with a
role of the object's label, each node reached once. Without such a way, with `again`, the last unit of the plan
before that unit with a role changing an object of the label from the role's output node back to N is fired once
more right after it (`_again`; its other inputs are counted again): the universal FOON's omelette flip leaves the
pan `contains {omelette}` and the cook after it takes the pan `contains {bacon, omelette}` again, which the
sprinkle before the flip makes from the flip's node, so a second bacon is sprinkled, not a second omelette's whole
chain counted (`instance_counts.derive_counts` keeps that plan when its counts are fewer). Else the plan stays
(a second object it is).
O(p^2 r) for a plan of p units of r roles, plus O(n s) per way back for n nodes reached and s spare units;
what each node offers as a step is found once per `changers` (`Changers.steps_from`, O(s r) a node).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.pairing import Role, unit_roles
from .said_words import said_less

__all__ = ["RETURN_DEPTH", "Changers", "changers", "with_returns"]

#: How many units a way back to a node a later unit reads may have.
RETURN_DEPTH = 4


#: One unit that may be on a way back from a node: (unit, its step, the nodes its other roles take, the nodes its
#: roles leave).
Step = tuple[int, Role, tuple[ObjectNode, ...], frozenset[ObjectNode]]


@dataclass(frozen=True, eq=False)
class Changers:
    """The task's units with a role changing an object out of a node, by label (`by_label`), in the task's order:
    (unit, its roles, the nodes of that label it changes one out of, whether a unit makes none of those: a stitched
    way may take it in a node that says more, and those roles in role order, each with whether a unit makes none of
    its node). `steps_from` keeps what `_way_back` finds from a node: the many ways back of one count
    (`instance_counts.derive_counts`: a thousand in GEN trial 10 goal 57) walk from the same few nodes.

    Frozen but for `_from`, the cache `steps_from` fills: pddl/'s one frozen object that caches. That is sound
    because an answer depends only on its key (node, stitched) and on `by_label`, which nothing changes once
    `changers` builds it, never on the plan asking; a Changers shared by many plans answers as fresh ones do
    (tests/test_relational_tomato_soup.py). Not an lru_cache: one Changers lives for one count's plans, and its
    cache goes with it (eq=False: hashed by identity, never compared)."""

    by_label: dict[str, list[tuple[int, tuple[Role, ...], frozenset[ObjectNode], bool, tuple[tuple[Role, bool], ...]]]]
    _from: dict[tuple[ObjectNode, bool], tuple[Step, ...]] = field(default_factory=dict)

    def steps_from(self, node: ObjectNode, stitched: bool) -> tuple[Step, ...]:
        """The units that may change an object out of `node` (the others have no step from it), in order: those
        with a role from it, and, `stitched`, those with one from a node no unit makes; each with its step, its
        first role from `node`, or, stitched, from a node no unit makes that says less (`said_less`), and the
        nodes its other roles take and those its roles leave. Found once per node: O(units of its label x roles)."""
        key = (node, stitched)
        if (found := self._from.get(key)) is None:
            found = self._from[key] = tuple(
                (v, step, tuple(r.before for r in roles if r.before is not None and r is not step),
                 frozenset(r.after for r in roles if r.after is not None))
                for v, roles, out_of, unmade, tries in self.by_label.get(node.label, ())
                if node in out_of or (stitched and unmade)
                if (step := next((r for r, new in tries if r.before == node
                                  or (stitched and new and said_less(r.before, node))), None)) is not None)
        return found


def changers(foon: Foon, units: Iterable[int], roles_of: Callable[[FunctionalUnit], tuple[Role, ...]] = unit_roles
             ) -> Changers:
    """The units of `units` that may be on a way back, by label (`Changers`): `instance_counts.derive_counts` finds
    them once for the many plans it puts ways back in (each way back looked them up again: 63 of the 305 s a GEN
    experiment cell spent under cProfile). O(units x roles)."""
    out: dict[str, list] = {}
    for v in units:
        roles = roles_of(foon.units[v])
        out_of = [r for r in roles if r.changes and r.before is not None]
        for label in dict.fromkeys(r.before.label for r in out_of):
            tries = tuple((r, r.before not in foon.producers) for r in out_of if r.before.label == label)
            out.setdefault(label, []).append((v, roles, frozenset(r.before for r, _ in tries),
                                              any(new for _, new in tries), tries))
    return Changers(out)


def _way_back(start: ObjectNode, end: ObjectNode, steps: Changers, spent: set[int], kitchen: frozenset[ObjectNode],
              stitched: bool) -> list[int]:
    """The fewest units of `steps` but those in `spent` (the spare units that may change an object of a label; at
    most `RETURN_DEPTH`) that change an object from `start` back to `end`, one after the other, each taking
    otherwise only kitchen nodes and nodes the units before it make; [] if none. Breadth-first, each node reached
    once (a universal FOON has hundreds of spare units)."""
    frontier: list[tuple[ObjectNode, list[int], frozenset[ObjectNode]]] = [(start, [], frozenset())]
    seen = {start}
    for _ in range(RETURN_DEPTH):
        nxt = []
        for node, path, made in frontier:
            for v, step, others, leaves in steps.steps_from(node, stitched):
                if v in spent or v in path or any(b not in kitchen and b not in made for b in others):
                    continue
                if step.after == end:
                    return [*path, v]
                if step.after is not None and step.after not in seen:
                    seen.add(step.after)
                    nxt.append((step.after, [*path, v], made | leaves))
        frontier = nxt
    return []


def _again(plan: Sequence[int], taken: Sequence[tuple[Role, ...]], i: int, r: Role) -> int | None:
    """The last unit of `plan` before `plan[i]` (`taken`: each unit's roles) with a role that changes an object
    from the node `r` leaves it in back to the node `r` takes it from (None: no such unit)."""
    for u, roles in zip(reversed(plan[:i]), reversed(taken[:i]), strict=True):
        if any(x.changes and x.before == r.after and x.after == r.before for x in roles):
            return u
    return None


def with_returns(foon: Foon, plan: Sequence[int], units: Iterable[int], kitchen: frozenset[ObjectNode],
                 roles_of: Callable[[FunctionalUnit], tuple[Role, ...]] = unit_roles,
                 stitched: bool = False, again: bool = False, plan_made: bool = False,
                 changing: Changers | None = None) -> tuple[int, ...]:
    """`plan` with the ways back of the task's `units` put in (module doc); `again`: a unit of the plan fired
    again where no unit of the task leads back; `plan_made`: a unit on the way may also take a node a unit of the
    plan up to that unit makes; `changing`: `changers` of `units` (found here when a way back is looked for)."""
    spent = set(plan)  # the units no way back takes: the plan's and those on the ways back put in
    order = list(plan)
    steps: Changers | None = None  # the spare units, found when a way back is first looked for
    taken = [roles_of(foon.units[m]) for m in plan]
    later: list[set[ObjectNode | None]] = [set() for _ in range(len(plan) + 1)]  # nodes the units after i take
    for i in range(len(plan) - 1, -1, -1):
        later[i] = later[i + 1] | {x.before for x in taken[i]}
    made: set[ObjectNode] = set()  # nodes the plan's units up to `m` make (`plan_made`)
    for i, m in enumerate(plan):
        if plan_made:
            made.update(x.after for x in taken[i] if x.changes)
        for r in taken[i]:
            if r.before is None or not r.changes or r.before in kitchen:
                continue
            if r.before not in later[i + 1]:
                continue
            if steps is None:
                steps = changers(foon, units, roles_of) if changing is None else changing
            if back := _way_back(r.after, r.before, steps, spent, kitchen | made if plan_made else kitchen, stitched):
                at = order.index(m) + 1
                order[at:at] = back
                spent.update(back)
            elif again and (repeat := _again(plan, taken, i, r)) is not None:
                at = order.index(m) + 1
                order[at:at] = [repeat]
    return tuple(order)
