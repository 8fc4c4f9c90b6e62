"""Stitches: a unit's input that no unit makes, read as the node an earlier unit left that object in.

FOON's annotators describe one object again at each unit, and the words do not always agree: the add puts
`brussel sprout (peeled, in [plastic bag])` into the bag, and the shake that takes the bag next takes `brussel
sprout (peeled, uncooked, in [plastic bag])`, a node no unit makes. FOON's own semantics takes such a node from
the kitchen (which is why the `tree` encoding solves these dishes); over physical objects it is a second sprout in
a second bag, while the bag the shake needs holds the first one, so no plan exists.

A stitch reads the input as the made node, on FOON's evidence in the unit itself (`stitches`):

* the unit takes the input N (label L, place `in [C]` / `on [C]`), and no unit of the network makes N;
* the unit takes a container of label C (C read through the unit's names, `pan` for `cooking pan`) whose node
  lists L and is made by a unit (of the units given, `with_stitches` gives all): that container was filled by
  the plan, and the L it lists is N;
* the made node M read for N: of label L, at the same place (read through its unit's names), made by a unit
  other than this one, and the latest such node (no other unit takes it and leaves an L at that place: the pizza's parsley is sprinkled on before the pick-and-place, so the pizza before the
  sprinkle is not read for the pizza it takes); one made by a unit that makes the container's node, else the
  only one, of those the input only adds words to (`said_words.words_only_added`: four cooks leave the universal FOON's
  `cooking pan (contains {omelette})`, and only one omelette lists no more than the pour's), unless a unit making the container's node took N itself (it put that very object there, and the
  relational reading moves it: on the universal FOON the grilled cheese's pour takes `mustard (ground, in
  [bowl])` into the bowl of cheddar, and the mix takes that node again; the potato salad's `mustard (in
  [bowl])`, the only other, ran the plan through the stitches through the potato salad). A made node that names no place is where the one output of its unit that lists it is (the pour
  and stir makes `filling (contains {...})` and `cooking pan (contains {filling})`: the pour after it takes
  `filling (contains {...}, in [cooking pan])`). Anything else is ambiguous and not stitched.

Without such a container, the input is read as the one made node of its label at its place that no unit takes,
that says all the input says and more (`said_words.said_less`), and whose unit made another input of this unit: the
uncover's `pot (contains {soup}, covered [pot lid], on [stove])` for the cover's `..., hot, ...` (0011), the cover
having put on the `pot lid (on [pot])` the uncover takes: where a unit left the object, and nothing goes on from.
The shared maker, not the recipe file, ties the two (a universal FOON written as one file has every recipe in it).

An input naming no place and no contents (an appliance: the turn on's `oven (off (ready))`) is read as the one
node of its label, made by another unit, that names no place and no contents and that no unit takes (the remove's
`oven (off)`: where a unit left the object and nothing goes on from); two such are ambiguous. A state with a word
in parentheses says both words (`off (ready)` says `off` and `ready`).

A made input is read so too (`_left_by`) when the unit takes it with an object in or on it that only units
taking that node make, each leaving the object in one other node by only dropping words: the remove takes the
pick-and-place's `oven (contains {pizza pan}, on, preheated)` with `pizza pan (contains {cheese pizza}, in
[oven])`, which only the bake makes, and the bake leaves `oven (on)`; and a made container node as the one
another unit taking it leaves listing more, when the unit's own output lists that more and no object of the unit
is it (`_held_before`: the salt's sprinkle takes the pot the cayenne's sprinkle takes too, and its output lists
the cayenne pepper); and a made container node listing what a mixture another unit taking it makes there was made
of, as that unit leaves it, when FOON names the mixture by its parts again where it is taken (`_mixed_in`: the
caesar salad's sprinkle takes the bowl of lettuce, crouton and dressing the mix turns into the salad mix).

What a stitch drops or assumes is said (`Stitch.describe`): the states N has that M lacks are assumed (`uncooked`),
those M has that N lacks are dropped. Only words are added (a list's items too), or a contents list dropped from a
node that names none (`said_words.words_only_added`). The stitched unit is one more action beside FOON's own (`with_stitches`): the plan's trace
holds M for the object (what the plan made); the tree keeps FOON's unit, and its check takes N as given by the
stitch (`Compiled.placed`). O(u n^2) in the network's units.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

from ..model.aliases import unit_aliases
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.memo import per_network
from ..model.physical import Relation
from ..model.places import describes_contents, listed, place_of, places
from .said_words import rest_same, said_less, unsaid_by, words_only_added

__all__ = ["Stitch", "Stitched", "stitched_inputs", "stitches", "with_stitches"]


@dataclass(frozen=True)
class Stitch:
    """Unit `unit` (an index of the network; `taker`) takes `node`, which no unit makes, read as `reads_as`."""

    unit: int
    node: ObjectNode
    reads_as: ObjectNode
    taker: FunctionalUnit = field(compare=False, repr=False)
    left_by: FunctionalUnit | None = field(default=None, compare=False, repr=False)  # a made input: the unit
    held: bool = field(default=False, compare=False, repr=False)  # `_held_before` (else `_left_by`) read it
    mixed: str = field(default="", compare=False, repr=False)  # `_mixed_in` read it: the mixture `left_by` made

    @property
    def assumed(self) -> tuple[str, ...]:
        """The states the unit's node says and the made node does not (`uncooked`), places aside."""
        return unsaid_by(self.node, self.reads_as)

    @property
    def dropped(self) -> tuple[str, ...]:
        """The states the made node says and the unit's node does not, places aside."""
        return unsaid_by(self.reads_as, self.node)

    def describe(self) -> str:
        """`shake takes brussel sprout (...), which no unit makes, as brussel sprout (...): assumes uncooked`."""
        said = [f"{w} {', '.join(x)}" for w, x in (("assumes", self.assumed), ("drops", self.dropped)) if x]
        by = self.left_by.motion.label if self.left_by is not None else ""
        if self.mixed:
            return (f"{self.taker.motion.label} takes {self.node.describe()} as {self.reads_as.describe()}, which the "
                    f"{by} taking that node leaves: the {self.mixed} it makes there lists "
                    f"{', '.join(sorted(listed(self.node)))}")
        if self.held:
            return (f"{self.taker.motion.label} takes {self.node.describe()} as {self.reads_as.describe()}, which the "
                    f"{by} taking that node leaves: its output lists {', '.join(sorted(listed(self.reads_as) - listed(self.node)))} "
                    "too, which no object of the unit is")
        return (f"{self.taker.motion.label} takes {self.node.describe()}, "
                f"{f'with what only the {by} makes' if by else 'which no unit makes'}, as {self.reads_as.describe()}"
                f"{f', which the {by} leaves' if by else ''}{': ' + '; '.join(said) if said else ': its place by another name'}")


def _place(node: ObjectNode, unit: FunctionalUnit, made: bool = False) -> tuple[Relation, str] | None:
    """The node's first place, its holder read through the unit's names; for a node the unit `made` that names
    none, `in` the one output of the unit that lists it (`filling (contains {...})` beside `cooking pan (contains
    {filling})`)."""
    where = place_of(node)
    if where is None:
        lists = {o.label for o in unit.outputs if made and node.label in listed(o)}
        return (Relation.IN, lists.pop()) if len(lists) == 1 else None
    return where[0], dict(unit_aliases(unit)).get(where[1], where[1])


def stitches(foon: Foon, units: Sequence[int]) -> tuple[Stitch, ...]:
    """The stitches of `units` (see the module doc), in unit order."""
    made: dict[ObjectNode, list[int]] = {}  # node -> the units that make it
    task = frozenset(units)
    for u in units:
        for n in foon.units[u].outputs:
            made.setdefault(n, []).append(u)
    produced = foon.producers
    at: dict[tuple[str, object], list[ObjectNode]] = {}  # (label, place) -> made nodes there
    for n, us in made.items():
        for p in {_place(n, foon.units[u], made=True) for u in us} - {None}:
            at.setdefault((n.label, p), []).append(n)
    # nodes no unit takes, naming no place and no contents (`oven (off)` after the remove): where a unit left it
    ends = {}
    for n in made:
        if n not in foon.consumers and place_of(n) is None and not describes_contents(n):
            ends.setdefault(n.label, []).append(n)
    found = []
    for u in units:
        unit = foon.units[u]
        names = dict(unit_aliases(unit))
        for n in unit.inputs:
            if n in produced:
                found.extend(Stitch(u, n, m, unit, foon.units[b]) for m, b in _left_by(foon, made, unit, n))
                found.extend(Stitch(u, n, m, unit, foon.units[b], True) for m, b in _held_before(foon, u, n))
                found.extend(Stitch(u, n, m, unit, foon.units[b], mixed=x) for m, b, x in _mixed_in(foon, u, n))
                continue
            if (p := _place(n, unit)) is None:
                pick = [m for m in ends.get(n.label, ()) if set(made[m]) - {u} and words_only_added(n, m)]
                if len(pick) == 1 and not describes_contents(n):
                    found.append(Stitch(u, n, pick[0], unit))
                continue
            holders = [h for h in unit.inputs if h.label == p[1] and h in made
                       and (n.label in listed(h) or any(names.get(x) == n.label for x in listed(h)))]
            cands = [m for m in at.get((n.label, p), ()) if m != n and set(made[m]) - {u}
                     and not _changed_there(foon, task, m, p, u)]
            by_holder = [m for m in cands if any(set(made[h]) & set(made[m]) for h in holders)]
            took = any(n in foon.units[b].inputs for h in holders for b in made[h])  # it put this very object there
            # of several, the one the input only adds words to (the omelette listing bacon, not black pepper)
            pick = [m for m in (by_holder if by_holder or took else cands) if words_only_added(n, m)]
            if holders and len(pick) == 1:
                found.append(Stitch(u, n, pick[0], unit))
            elif len(left := [m for m in cands if m not in foon.consumers and said_less(n, m) and any(
                    set(made[m]) & set(made.get(x, ())) for x in unit.inputs if x != n)]) == 1:
                found.append(Stitch(u, n, left[0], unit))  # where a unit left the object, and nothing goes on
    return tuple(found)


@per_network
def _network_stitches(foon: Foon) -> tuple[tuple[Stitch, ...], dict[int, dict[ObjectNode, ObjectNode]], list[int],
                                           Foon | None]:
    """`stitches` of every unit of the network, each stitched unit's readings, the stitched units needed beside
    FOON's (an appliance's), and the network through the stitches (`with_stitches`): once per network object (an
    experiment encodes a hundred goals over one)."""
    found = stitches(foon, range(len(foon.units)))
    reads: dict[int, dict[ObjectNode, ObjectNode]] = {}
    for s in found:
        reads.setdefault(s.unit, {})[s.node] = s.reads_as
    # an appliance's stitch is needed beside FOON's unit (the first turn on takes the kitchen's `oven (off
    # (ready))`, the second the `oven (off)` the remove leaves): one more unit; the others take FOON's place
    beside = [u for u in reads if all(place_of(x.node) is None for x in found if x.unit == u)]
    if not reads:  # no network of its own (and the cache must not keep its key alive)
        return found, reads, beside, None
    through = Foon(tuple(_sewn(foon, reads, u) if u in reads and u not in beside else x
                         for u, x in enumerate(foon.units))
                   + tuple(_sewn(foon, reads, u) for u in beside), foon.level)
    return found, reads, beside, through


def stitched_inputs(foon: Foon) -> frozenset[tuple[int, ObjectNode]]:
    """(unit index, input node) of every stitch of the network (`_network_stitches`, computed once per network)."""
    return frozenset((s.unit, s.node) for s in _network_stitches(foon)[0])


#: Networks with stitched units `_wider` keeps per network object.
WIDER_KEPT = 8


@per_network
def _widened(foon: Foon) -> dict[tuple[int, ...], Foon]:
    """The networks `with_stitches` made of `foon`, by the stitched units they add (`_wider`)."""
    return {}


def _wider(foon: Foon, reads: dict[int, dict[ObjectNode, ObjectNode]], kept: tuple[int, ...]) -> Foon:
    """`foon` with the stitched units `kept` added: one object per set of units, so what is kept per network object
    (its indexes, its fixpoints) is computed once per set, not once per goal (an experiment's goals share a few)."""
    made = _widened(foon)
    if kept not in made:
        while len(made) >= WIDER_KEPT:
            made.pop(next(iter(made)))
        made[kept] = Foon(foon.units + tuple(_sewn(foon, reads, u) for u in kept), foon.level)
    return made[kept]


def _sewn(foon: Foon, reads: dict[int, dict[ObjectNode, ObjectNode]], u: int) -> FunctionalUnit:
    """Unit `u` taking the made nodes its stitches read."""
    return replace(foon.units[u], inputs=tuple(reads[u].get(n, n) for n in foon.units[u].inputs))


def _left_by(foon: Foon, made: dict[ObjectNode, list[int]], unit: FunctionalUnit,
             node: ObjectNode) -> list[tuple[ObjectNode, int]]:
    """[(M, a unit leaving it)] when `unit` takes the made `node` (label L) with an object in or on L, or holding
    one `with [L]`, that only units taking `node` make (or units making it), and each of them leaves L as M, another node, by only adding
    or dropping words of `node` (places aside): the remove takes `oven (contains {pizza pan}, on, preheated)` with
    `pizza pan (contains {cheese pizza}, in [oven])`, which only the bake makes, and the bake takes that oven and
    leaves `oven (on)`: the oven the remove finds is the bake's. The muffins' bake takes `muffin pan (contains
    {muffin batter})` with `oven (on, with [pan])`, which only the put inside makes, leaving the pan `in [oven]`."""
    names = dict(unit_aliases(unit))
    left, by = set(), -1
    for x in unit.inputs:
        at = {w[1] for w in places(x)} | {s.related for s in x.states if s.label == "with"}
        if node.label not in {names.get(c, c) for c in at} or not made.get(x):
            continue
        for b in made[x]:
            maker = foon.units[b]
            if node in maker.outputs:  # put there as `node` was made (the batter the scoop puts in the pan)
                continue
            if node not in maker.inputs:
                return []
            by = b
            left |= {o for o in maker.outputs if o.label == node.label}
    return [(m, by)] if len(left) == 1 and (m := left.pop()) != node and words_only_added(node, m) else []


def _held_before(foon: Foon, u: int, node: ObjectNode) -> list[tuple[ObjectNode, int]]:
    """[(M, the unit making it)] when unit `u`'s output of `node`'s label lists items that neither `node` nor any
    object of the unit is, and exactly one other unit taking `node` leaves that label as M, `node` with just those
    items more: the salt's sprinkle takes `pot (contains {black bean, cilantro, garlic, onion}, on [stove])` and
    leaves the pot listing `cayenne pepper` too, which the sprinkle before it, taking that pot, put in."""
    unit = foon.units[u]
    names = dict(unit_aliases(unit))
    objects = {x.label for x in (*unit.inputs, *unit.outputs)}
    extra = {x for o in unit.outputs if o.label == node.label for x in listed(o)
             if x not in listed(node) and names.get(x, x) not in objects and x not in objects}
    if not extra:
        return []
    found = [(o, v) for v in foon.consumers.get(node, ()) if v != u for o in foon.units[v].outputs
             if o.label == node.label and listed(o) == listed(node) | extra and rest_same(o, node)]
    return found[:1] if len({m for m, _ in found}) == 1 else []


def _mixed_in(foon: Foon, u: int, node: ObjectNode) -> list[tuple[ObjectNode, int, str]]:
    """[(M, the unit making it, the mixture's label)] when unit `u` takes the container node `node` listing items
    no object of the unit is, and exactly one other unit taking `node`, needing nothing `u` makes, leaves its label
    as M, `node` listing only a mixture X instead, and makes X there listing exactly those items, and a unit takes
    X with a node of that label listing them all (FOON names the mixture by its parts there too): the caesar
    salad's sprinkle takes `bowl (contains {lettuce, crouton, salad dressing})`, which the mix taking it leaves
    `bowl (contains {salad mix})` beside `salad mix (contains {lettuce, crouton, salad dressing}, in [bowl])`, and
    the last mix takes that salad mix with the bowl listing the lettuce, the crouton and the dressing. The greek
    salad's grind, which puts in the salt its mix takes, comes before it. O(takers of the node x outputs^2)."""
    unit, items = foon.units[u], listed(node)
    objects = {x.label for x in (*unit.inputs, *unit.outputs)}
    names = dict(unit_aliases(unit))
    if not items or any(x in objects or names.get(x, x) in objects for x in items):
        return []
    found = {(o, v, x) for v in foon.consumers.get(node, ()) if v != u and node not in foon.units[v].outputs
             and not set(unit.outputs) & set(foon.units[v].inputs)
             for o in foon.units[v].outputs if o.label == node.label and len(listed(o)) == 1 and rest_same(o, node)
             for x in foon.units[v].outputs if {x.label} == listed(o) and listed(x) == items
             and (p := _place(x, foon.units[v])) is not None and p[1] == node.label}
    named = [(o, v, x.label) for o, v, x in found if any(
        any(h.label == node.label and items <= listed(h) for h in foon.units[w].inputs)
        for w in foon.consumers.get(x, ()))]
    return sorted(named, key=lambda f: (f[1], f[2]))[:1] if len({m for m, _, _ in named}) == 1 else []


def _changed_there(foon: Foon, units: frozenset[int], node: ObjectNode, place: tuple[object, str], but: int) -> bool:
    """Whether a unit of `units` other than `but` takes `node` and leaves an object of its label at `place` (the
    network's consumer index: O(takers of the node))."""
    return any(any(o.label == node.label and o != node and _place(o, foon.units[v]) == place
                   for o in foon.units[v].outputs)
               for v in foon.consumers.get(node, ()) if v != but and v in units)


@dataclass(frozen=True)
class Stitched:
    """A task's units with its stitches (`with_stitches`).

    `foon`: the network with one more unit per stitched unit, taking the made nodes instead of its own; `units`:
    the task's units of it; `origin`: each added unit's index -> the FOON unit it reads (the plan's tree shows
    FOON's unit); `own`: the units FOON's own plan needs; `through`: the network with each added unit in the
    place of the one it reads (an appliance's after FOON's units, beside FOON's own), and `needed`, the units a
    plan through the stitches needs; `in_task`: each unit index of `through` as an index of `foon` (a stitched unit
    at its added index; one the task does not keep at FOON's unit it reads), so a plan counted through the stitches
    names the task's units."""

    foon: Foon
    units: tuple[int, ...]
    origin: dict[int, int]
    found: tuple[Stitch, ...]
    own: tuple[int, ...]
    through: Foon
    needed: tuple[int, ...]
    in_task: tuple[int, ...]


def with_stitches(foon: Foon, relevant: Callable[[Foon], Sequence[int]]) -> Stitched:
    """The task's units with one more per stitch of the network (`Stitched`); `relevant` gives a network's units
    a task needs (relevance pruning). A stitch is read over the whole network (the pizza topped with parsley by a
    unit FOON's own plan skips is still the latest pizza), and kept when a plan through the stitches needs its
    unit, with the units that plan needs (the sprinkle).

    FOON's unit stays (taking its node from the kitchen, as FOON's semantics does): a stitch is one more way,
    never a rewrite, so a plan that solved without it still does; a stitched unit needed only beside FOON's own
    (the second turn on of one oven) is kept when relevant in the network that has both."""
    own = tuple(relevant(foon))
    found, reads, beside, through = _network_stitches(foon)
    through = foon if through is None else through
    n = len(foon.units)
    needed = tuple(relevant(through)) if reads else own
    used = set(needed)
    kept = [u for u in reads if (n + beside.index(u) if u in beside else u) in used]
    origin = {n + k: u for k, u in enumerate(kept)}
    wider = _wider(foon, reads, tuple(kept)) if kept else foon
    units = (*sorted(set(own) | {u for u in used if u < n and u not in kept}), *origin)
    added = {(n + beside.index(u) if u in beside else u): n + k for k, u in enumerate(kept)}
    in_task = tuple(added.get(t, t if t < n else beside[t - n]) for t in range(len(through.units)))
    return Stitched(wider, units, origin, tuple(s for s in found if s.unit in kept), own, through, needed, in_task)
