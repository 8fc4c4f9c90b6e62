"""How many physical instances of each object the `instances` encoding declares, and where they start.

The kitchen lists labels and states, not counts. Per goal, counts are derived by
unfolding a delete-free plan backwards:

1. A delete-free plan: back from the goal candidate made in the fewest rounds
   of the kitchen's fixpoint (`analysis.reachability`), each needed node's
   first achiever, in firing order (`relational`: a container's node and its
   content's node one unit takes, from one earlier unit that makes both, else
   the content's from one that makes it in that container, else both from one
   taking them out of a kitchen container, whose contents then count as the
   kitchen's: `count_together`);
   after a unit that moves an object out of a node a later unit takes, the
   task's units that lead it back there (`count_returns.with_returns`: the pot
   the cover and uncover bring back from `hot`; `relational`, else a unit of the
   plan fired again, when that plan counts fewer objects). `relational` keeps, of
   these plans as they are, readers first and takers last, the fewest-counting (`count_order`);
   also of the plan whose held nodes keep their first makers where those lead them
   into the container (`count_together`'s `first`: the universal scrambled eggs'
   pan from 0062's own pour, not 0056's) and of the plan taking makers it has
   (`in_plan`: `count_together.made_in_plan`), each counted after, so kept only
   when it counts fewer (three plans: the counting at most triples); and of each plan
   with one needed node made by another of its makers, and with those swaps together,
   that has fewer units (or one unit for one taking only some of its inputs) and counts
   fewer as it is (`count_plans._other_makers`), counted after those (`other_makers`;
   without it, FOON's own plan: what `plan` falls back on last, as such a plan's
   objects may give no valid plan).
2. Unfolding, from the last unit to the first: a node's *demand* is the number
   of instances that must pass through it: one per role that moves an instance
   out of it (`pairing.RoleKind.MOVED`) per firing of the consuming unit, plus
   the most one unit reads at once (one; two for the two `bowl (contains)` of a level-2 pour,
   `levels.project_unit`) when some unit only reads it (read-only and kept roles, the goal) after
   every unit that moves one out of it, and so needs one instance to stay (a
   reader before a mover reads the instance the mover takes later). A unit fires F times, F being the largest
   demand among the nodes it is credited with making (moved and new roles);
   each firing moves one instance per moved role and needs one not-yet-made
   instance per new role. Kitchen nodes are not credited to a unit: their
   demand is the number of instances the kitchen must hold in that state,
   less one per firing of a unit that reads the node and makes a new instance
   in it (`relational`: a portion poured off into the state it was taken from,
   `cheese (grated, in [bowl])` from one bowl into another): that portion
   serves a later taker, and one instance stays in the source.

So the unfolded plan (each unit fired F times, in plan order) is executable at
the instance level with exactly these counts: the task is solvable whenever
FOON's delete-free semantics is. O(sum of unit sizes) after the fixpoint.

Objects the unfolded plan does not need are left out, even when the kitchen
lists their state (one of each would put ~340 objects into a task on the
universal FOON and make grounding take seconds to minutes); a unit outside the
unfolded plan (washing a knife) keeps its schema only when its objects exist.
Counts can be stated instead: in the kitchen (`2 x bowl (empty)`: exactly that
many in that state) and per label (`--instances bowl=3`: three in each place the
task can start a bowl: each of its kitchen states the task uses, and the
not-yet-made pool when a unit makes bowls). Precedence: override, then the
kitchen's count, then the derived one. When the goal cannot be made in FOON's
semantics there is no plan to unfold, and every place gets one instance.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.pairing import Role, RoleKind, unit_roles
from .count_order import orders
from .count_plans import delete_free_plan, delete_free_plans
from .count_returns import changers, with_returns
from .count_reuse import reused
from .count_together import kitchen_held

#: A unit's object roles, for counting what passes through each node.
RolesOf = Callable[[FunctionalUnit], tuple[Role, ...]]


@dataclass(frozen=True)
class InstanceCounts:
    """Where instances start: per kitchen node, and per label not yet made; plus the unfolded firings.

    `firings` maps unit index -> times it fires in the unfolded plan (empty when there was none).
    """

    at_node: tuple[tuple[ObjectNode, int], ...]
    unmade: tuple[tuple[str, int], ...]
    firings: tuple[tuple[int, int], ...] = ()
    #: The unfolded plan (unit indexes in firing order, each firing `firings` times) when every count is
    #: the derived one (no stated, overridden or extra count changed it) and no unit is in it twice; () otherwise.
    unfolded: tuple[int, ...] = ()
    #: an object the plan leaves in a kitchen node serves a later taker there (`count_reuse`)
    reused: bool = False
    #: a container a unit fills, left in a kitchen node, serves a later taker in place of a kitchen one
    #: (`count_reuse._refilled_with`; `derive_counts`' `refill`): fewer objects at that node than the plan's count
    #: without that reuse
    refilled: bool = False
    #: the plan counted has a needed node made by another of its makers (`count_plans._other_makers`): only then do
    #: the counts without those plans (`derive_counts(other_makers=False)`, FOON's own plan unfolded) differ
    other_maker: bool = False

    def labels(self) -> dict[str, int]:
        """Label -> total instances."""
        out: Counter[str] = Counter()
        for node, k in self.at_node:
            out[node.label] += k
        for label, k in self.unmade:
            out[label] += k
        return {label: k for label, k in sorted(out.items()) if k > 0}

    @property
    def total(self) -> int:
        return sum(k for _, k in self.at_node) + sum(k for _, k in self.unmade)

    def widest(self, other: InstanceCounts) -> InstanceCounts:
        """Enough objects for both plans: per kitchen node and per label the larger count; this one's firings
        (its plan explains the counts), and no unfolded plan unless the counts are this one's."""
        at_node = tuple(sorted((Counter(dict(self.at_node)) | Counter(dict(other.at_node))).items()))
        unmade = tuple(sorted((Counter(dict(self.unmade)) | Counter(dict(other.unmade))).items()))
        same = (at_node, unmade) == (self.at_node, self.unmade)
        return InstanceCounts(at_node, unmade, self.firings, self.unfolded if same else (), self.reused or other.reused,
                              self.refilled or other.refilled, self.other_maker or other.other_maker)

    def renumbered(self, index: Sequence[int]) -> InstanceCounts:
        """These counts with unit `u` of the plan named `index[u]` (the network counted in has other indexes than
        the task's: `input_stitch.Stitched.in_task`), the firings in their order (a count's reasons name the units
        in it: a stitched unit where the unit it reads was); firings of units named alike add up, and the unfolded
        plan is kept only while no unit is in it twice. O(firings)."""
        firings: Counter[int] = Counter()
        for u, k in self.firings:
            firings[index[u]] += k
        unfolded = tuple(index[u] for u in self.unfolded)
        return replace(self, firings=tuple(firings.items()),
                       unfolded=unfolded if len(set(unfolded)) == len(unfolded) else ())


def _at_hand(foon: Foon, plan: Sequence[int], kitchen: frozenset[ObjectNode]) -> frozenset[ObjectNode]:
    """The nodes `plan`'s units take that no unit of it makes and a kitchen container holds (`count_together.
    kitchen_held`, chosen `AT_HAND`): counted as the kitchen's, where the completion starts them. O(plan x inputs)."""
    made = {o for u in plan for o in foon.units[u].outputs}
    return frozenset(x for u in plan if any(i not in kitchen and i not in made for i in foon.units[u].inputs)
                     for x in kitchen_held(kitchen, foon.units[u]) if x not in made)


def unfold(foon: Foon, plan: Sequence[int], kitchen: frozenset[ObjectNode], target: ObjectNode,
           roles_of: RolesOf = unit_roles, steps: list[tuple[int, int]] | None = None
           ) -> tuple[Counter[ObjectNode], Counter[str], dict[int, int]]:
    """(demand per kitchen node, not-yet-made instances per label, firings per unit) of `plan` (module doc);
    `roles_of` gives a unit's object roles (an encoding with other rules of what becomes of objects); `steps`
    gets (unit, times) per firing unit, last first."""
    consumed: Counter[ObjectNode] = Counter()
    read: Counter[ObjectNode] = Counter({target: 1})  # the most one unit reads at once (two bowls at level 2)
    created: Counter[str] = Counter()
    firings: dict[int, int] = {}

    def demand(node: ObjectNode) -> int:
        return consumed[node] + read[node]

    for u in reversed(plan):
        roles = roles_of(foon.units[u])
        makes = [r.after for r in roles if r.changes and r.after not in kitchen]
        times = max((demand(n) for n in makes), default=0)
        if times == 0:
            continue
        firings[u] = firings.get(u, 0) + times
        if steps is not None:
            steps.append((u, times))
        for n in makes:
            consumed.pop(n, None)
            read.pop(n, None)
        read_only = {r.before for r in roles if r.kind is RoleKind.READ_ONLY}
        for n in {r.after for r in roles if r.kind is RoleKind.NEW and r.after in kitchen and r.after in read_only}:
            consumed[n] = max(0, consumed[n] - times)  # each firing's portion serves one later taker of the node
        reads = Counter(r.before for r in roles if r.kind in (RoleKind.READ_ONLY, RoleKind.KEPT))
        for r in roles:
            if r.kind is RoleKind.NEW:
                created[r.label] += times
            elif r.kind is RoleKind.MOVED:
                consumed[r.before] += times
            elif not consumed[r.before]:  # a later unit moves one out of that state: read it before
                read[r.before] = max(read[r.before], reads[r.before])
    at_kitchen = Counter({n: demand(n) for n in set(consumed) | set(read) if n in kitchen and demand(n) > 0})
    return at_kitchen, created, firings


def start_places(foon: Foon, units: Iterable[int], kitchen: frozenset[ObjectNode],
                 candidates: Iterable[ObjectNode], roles_of: RolesOf = unit_roles) -> tuple[set[ObjectNode], set[str]]:
    """Kitchen nodes the units (or the goal) use, and labels the units create: where instances can start."""
    nodes: set[ObjectNode] = {c for c in candidates if c in kitchen}
    labels: set[str] = set()
    for u in units:
        for r in roles_of(foon.units[u]):
            if r.before is None:
                labels.add(r.label)
            elif r.before in kitchen:
                nodes.add(r.before)
    return nodes, labels


def derive_counts(foon: Foon, units: Sequence[int], kitchen: frozenset[ObjectNode],
                  candidates: Sequence[ObjectNode], *, stated: Mapping[ObjectNode, int] | None = None,
                  overrides: Mapping[str, int] | None = None, extra: int = 0,
                  roles_of: RolesOf = unit_roles, together: bool = False, stitched: bool = False,
                  reuse: bool = False, placed: bool = False, other_makers: bool = True,
                  refill: bool = True, unfilled: list[InstanceCounts] | None = None) -> InstanceCounts:
    """Instance counts for a task made of `units` (see the module doc).

    `stated`: kitchen node -> count from the kitchen file; `overrides`: label -> count per place;
    `extra`: instances added to every place (for measuring the cost of too many); `roles_of`: a unit's
    object roles (default `pairing.unit_roles`, the `instances` encoding's); `together`: `delete_free_plan`'s;
    `stitched`: the task reads inputs no unit makes as `input_stitch` does (`count_returns.with_returns`);
    `reuse`: an object the unfolded plan leaves in a kitchen node serves a later taker (`count_reuse`); `placed`:
    makers by holder reach (`count_together.makers_together`); `other_makers` (with `together`): the plans with a
    needed node made by another of its makers count too (`count_plans._other_makers`); the relational counts take
    them but the one `plan` falls back on last (`EncodeOptions.own`); those plans are counted after the others, so
    counts that keep none of them (`InstanceCounts.other_maker` false) are those without them. `refill` (with
    `reuse`): a container a unit fills in a kitchen node serves a later taker too (`count_reuse._refilled_with`), for
    the plan chosen without it: fewer objects for that plan, never another plan (`InstanceCounts.refilled` says when
    it lowered the count); `unfilled` gets the counts `refill=False` gives, the same derivation less that last step,
    so that a caller wanting both derives once (`relational_reading.read_units`: the small count's kitchen is read
    with and without it).
    """
    stated = stated or {}
    overrides = overrides or {}
    kinds = ((False, False), (True, False), (False, True)) if together else ((False, False),)  # (first, in_plan)
    swapped: list[tuple[int, ...]] = []  # `relational`: needed nodes made by other makers, counting fewer as they are

    def as_is(plan: tuple[int, ...], target: ObjectNode) -> int:  # objects `plan` counts unfolded as it is
        at, new, _ = unfold(foon, plan, kitchen | _at_hand(foon, plan, kitchen), target, roles_of)
        return at.total() + new.total()
    refilled = False  # a container filled in a kitchen node serves a later taker: fewer for the plan chosen
    found, *other = delete_free_plans(foon, kitchen, candidates, together, kinds, placed,
                                      swapped if together and other_makers else None, as_is)
    # where instances can start: with a plan, a place the plan does not use gets an object only when counts are
    # stated, overridden or added (else it counts 0 and is left out), so it is looked for only then
    nodes, labels = (start_places(foon, units, kitchen, candidates, roles_of)
                     if found is None or stated or overrides or extra else (set(), set()))
    if found is None:
        at_kitchen: Counter[ObjectNode] = Counter(dict.fromkeys(nodes, 1))
        created: Counter[str] = Counter(dict.fromkeys(labels, 1))
        firings: dict[int, int] = {}
        other_maker = False
    else:
        changing = changers(foon, units, roles_of)  # the units on ways back, found once for every plan below

        def ways_of(plan: tuple[int, ...]) -> dict[bool, tuple[tuple[int, ...], ...]]:  # stitched: fired again
            # each distinct (made, again) put in once: without `stitched` or `together` two of them are the same
            put = {(made, again): with_returns(foon, plan, units, kitchen, roles_of, stitched, again, plan_made=made,
                                               changing=changing)
                   for made in dict.fromkeys((False, together)) for again in dict.fromkeys((False, stitched))}
            return {made: tuple(put[made, again] for again in (False, stitched)) for made in (False, together)}
        ways = ways_of(found[0])
        plans = orders(foon, ways[True], ways[False], roles_of) if together else tuple(dict.fromkeys(ways[False]))
        for again in dict.fromkeys(o[0] for o in other if o is not None and o != found):  # kept when fewer
            more = ways_of(again)
            plans = tuple(dict.fromkeys((*plans, *orders(foon, more[True], more[False], roles_of))))
        unswapped = len(plans)  # the plans counted without `other_makers`: a prefix of all of them
        for alt in swapped:  # counted after the others, so kept only when fewer
            more = ways_of(alt)
            plans = tuple(dict.fromkeys((*plans, *orders(foon, more[True], more[False], roles_of))))
        steps: list[list[tuple[int, int]]] = [[] for _ in plans]
        homes = [kitchen | _at_hand(foon, p, kitchen) for p in plans]  # with what kitchen containers hold
        unfolds = [unfold(foon, p, k, found[1], roles_of, s) for p, k, s in zip(plans, homes, steps, strict=True)]
        reuse = reuse and not (stated or overrides or extra)
        if reuse:  # objects left in a kitchen node serve later takers
            unfolds = [(r, c, f) if (r := reused(foon, s[::-1], k, found[1], roles_of, False)) is not None
                       else (a, c, f) for (a, c, f), k, s in zip(unfolds, homes, steps, strict=True)]
        best = min(range(len(plans)), key=lambda i: (unfolds[i][0].total() + unfolds[i][1].total(), i))
        found, (at_kitchen, created, firings) = (plans[best], found[1]), unfolds[best]
        other_maker = best >= unswapped
        plain = at_kitchen  # the counts without the filled container taken again (`unfilled`)
        if reuse and refill and (r := reused(foon, steps[best][::-1], homes[best], found[1], roles_of)) is not None:
            at_kitchen, refilled = r, r != at_kitchen
        labels |= set(created)

    def count(derived: int, label: str, node: ObjectNode | None = None) -> int:
        if label in overrides:
            return overrides[label]
        if node is not None and node in stated:
            return stated[node]
        return derived + extra

    def finished(at_kitchen: Counter[ObjectNode], refilled: bool) -> InstanceCounts:  # at the places found
        places = nodes | set(at_kitchen)
        counted = {n: k for n in places if (k := count(at_kitchen[n], n.label, n)) > 0}  # sorted once filtered
        at_node = tuple((n, counted[n]) for n in sorted(counted))
        unmade = tuple((label, k) for label in sorted(labels) if (k := count(created[label], label)) > 0)
        exact = (found is not None and at_node == tuple((n, at_kitchen[n]) for n in sorted(n for n in places if at_kitchen[n] > 0))
                 and unmade == tuple((label, created[label]) for label in sorted(labels) if created[label] > 0))
        once = found is not None and len(set(found[0])) == len(found[0])  # a unit fired again (`with_returns`): none
        unfolded = tuple(u for u in found[0] if u in firings) if exact and once else ()
        return InstanceCounts(at_node, unmade, tuple(sorted(firings.items())), unfolded, reuse and found is not None,
                              refilled, other_maker)
    if unfilled is not None:
        unfilled.append(finished(at_kitchen if found is None else plain, False))
    return finished(at_kitchen, refilled)


@dataclass(frozen=True)
class Shortfall:
    """A stated count below what the unfolded plan uses: `place` (a kitchen node, or a label not yet made)."""

    place: ObjectNode | str
    given: int
    used: int
    by_override: bool

    def describe(self) -> str:
        what = self.place.describe() if isinstance(self.place, ObjectNode) else f"{self.place} (not yet made)"
        source = "the count stated for the label" if self.by_override else "the kitchen's count"
        return (f"{self.given} x `{what}` ({source}) where the derived count is {self.used} (the plan FOON's "
                f"semantics finds passes {self.used} through that state; fewer do when the plan can reuse one)")


def count_shortfalls(foon: Foon, kitchen: frozenset[ObjectNode], candidates: Sequence[ObjectNode], *,
                     stated: Mapping[ObjectNode, int] | None = None,
                     overrides: Mapping[str, int] | None = None) -> tuple[Shortfall, ...]:
    """The stated counts (kitchen, then `--instances` overrides) below the derived ones (module doc).

    The derived counts make the unfolded plan executable, so when the instance task is
    unsolvable but FOON's semantics makes the goal, these are the counts to raise (or to
    leave to derivation). Sorted by place; () when nothing is short or no plan exists.
    """
    stated = stated or {}
    overrides = overrides or {}
    found = delete_free_plan(foon, kitchen, candidates)
    if found is None:
        return ()
    at_kitchen, created, _ = unfold(foon, found[0], kitchen, found[1])
    out: list[Shortfall] = []
    for node in sorted(at_kitchen):
        given = overrides.get(node.label, stated.get(node))
        if given is not None and given < at_kitchen[node]:
            out.append(Shortfall(node, given, at_kitchen[node], node.label in overrides))
    out.extend(Shortfall(label, overrides[label], created[label], True)
               for label in sorted(created) if label in overrides and overrides[label] < created[label])
    return tuple(out)
