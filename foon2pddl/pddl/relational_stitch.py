"""Kitchen containers the relational task reads as a unit's output: FOON gives their contents only as what units
make (module doc of `encode_relational`, "Init").

A kitchen container node K (a starting node: no unit makes it) whose list names contents that the units taking
K take in nodes only units make (`mixing bowl (contains {instant coffee, sugar, hot water})`, whose beat takes
`water (in [mixing bowl])`, which only the pour makes) would start holding objects in those nodes: the plan
then skips the units FOON makes them with, and its task tree does not validate from FOON's kitchen. When
exactly one unit output P of K's label is K by another wording, the relational task reads K as P: K is no
kitchen object, and the units taking K take P. "Another wording": K's states but lists and places among P's
(P may add one: the cook leaves the bacon macaroni's pot `hot`, which the scoop's kitchen pot does not say), K's
places among P's, K's list (read through the task's aliases, `holder_words.task_aliases`) within P's, and
whatever else P lists no object of P's unit is and its input nodes of that label do not list (the onigiri's
`bowl (contains {rice, water})` for the kitchen's `bowl (contains {rice})`: no water is poured). A unit taking K
makes K after it, not K in other words (a universal FOON's `jar (contains {peanut butter}, opened)`, which the
buckeye candy's open makes of the kitchen's `jar (contains {peanut butter})`). FOON's tree
keeps K, which FOON's kitchen has; each reading is reported with the unit's file:line and the words it assumes
and drops. A word of K naming only objects P's unit leaves in or on it, in the node every unit taking K takes
them in, is that object lying there, which P says by its own word (`_laid_words`: the unwrap's `bowl (contains
{pizza dough}, wrapped {plastic wrap})` with `plastic wrap (on [bowl])`, read as the pick-and-place's `bowl
(contains {pizza dough}, covered)`, which leaves that wrap there). Of several such P, the one a unit makes that
takes what the units taking K take in it; K's list is read with each label every unit taking K takes on an object it takes in K as that
object (`_held_in`: the remove's `oven (contains {apple pie}, on)` is the bake's `oven (contains {baking tray}, on)`).
"""

from __future__ import annotations

from collections.abc import Callable, Container, Iterable, Mapping, Sequence
from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode, State
from ..model.memo import per_network
from ..model.places import CONTENT_STATES, listed, place_of, place_state, places
from .encoding import LevelInputs
from .holder_words import listed_as, read_names, task_aliases
from .relational_init import kitchen_placed

__all__ = ["kitchen_stitches", "stitch_notes", "stitched"]


def _rest(node: ObjectNode) -> frozenset:
    """The node's states but its lists and places."""
    return frozenset(s for s in node.states if place_state(s) is None and s.label not in CONTENT_STATES)


def _nested(a: Iterable, b: Iterable) -> bool:
    """One of two nodes' places names all the other's (one node may leave a place out)."""
    return set(a) <= set(b) or set(b) <= set(a)


def kitchen_stitches(units: Sequence[FunctionalUnit], kitchen: Iterable[ObjectNode],
                     makers: Foon | None = None) -> dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]:
    """K -> (P, the unit making P) for each kitchen container a task of `units` reads as an output of one of
    `makers` (the network; default the task's units; module doc). Names are read as in that task: a universal
    FOON's `sugar` is a label of its own, a dish's task may read it as `refined sugar`. O(kitchen containers x
    units x outputs)."""
    kitchen = frozenset(kitchen)
    makers = Foon(tuple(units)) if makers is None else makers
    taking = _taking(units, kitchen)  # the task's units taking each kitchen node (no index of all its nodes)
    made = makers.producers  # the nodes a unit makes (the network's index, built once per network object)
    full = sorted(k for k in kitchen if listed(k) and k not in made)
    labels = {n.label for u in units for n in (*u.inputs, *u.outputs)}
    alias = dict(task_aliases(units, labels, full))

    out = {}
    for k in full:
        if k not in taking:  # no unit of the task takes K
            continue
        items, takers = read_names(_held_in(k, taking[k], listed_as(k, alias)), alias), taking[k]
        taken = {x for u in takers for x in u.inputs
                 if (p := place_of(x)) is not None and alias.get(p[1], p[1]) == k.label and x.label in items}
        if not {x for x in taken if x not in kitchen and x in made} - kitchen_placed(taken, kitchen):
            continue  # what K holds the kitchen has, or nothing of it is taken
        found, makers_of = {}, {}
        rest, where = _rest(k), places(k)
        for p, u in _outputs_of(makers, k.label):  # the cheap tests first: a label's outputs are many in FOON-GEN
            if k in u.inputs or not _nested(where, places(p)):  # what a unit makes of K is K after it, not K
                continue
            laid = _laid_words(k, u, takers)
            if not rest - laid <= _rest(p):
                continue
            kept, says = (items - read_names((x for s in laid for x in (*s.ingredients, s.related) if x), alias),
                          listed_as(p, alias))
            if not kept <= says:
                continue
            roles = {n.label for n in (*u.inputs, *u.outputs)}
            before = frozenset().union(*(listed_as(i, alias) for i in u.inputs if i.label == k.label))
            if not (says - kept) & (roles | before):
                found.setdefault(p, u)
                makers_of.setdefault(p, []).append(u)
        if len(found) > 1:  # of several, those whose unit takes what the units taking K take in it
            found = {p: v[0] for p, us in makers_of.items()
                     if (v := [u for u in us if any(t in u.inputs for t in taken)])} or found
        if len(found) == 1:
            out[k] = next(iter(found.items()))
    return out | _taken_off(taking, kitchen, makers, made)


def _held_in(k: ObjectNode, takers: Sequence[FunctionalUnit], items: frozenset[str]) -> frozenset[str]:
    """K's list with each item every unit taking K takes in or on one object it takes in K's label read as that
    object: the apple turnover's remove (`0086-apple_turnover.txt:614`) takes `oven (contains {apple pie}, on)`
    with `apple pie (cooked, on [baking tray])` and `baking tray (contains {apple pie}, in [oven])`."""
    def holder(x: str, u: FunctionalUnit) -> str | None:
        at = {p[1] for i in u.inputs if i.label == x and (p := place_of(i)) is not None}
        inner = {i.label for i in u.inputs if i.label in at and (p := place_of(i)) is not None and p[1] == k.label}
        return next(iter(inner)) if len(at) == 1 and len(inner) == 1 else None
    return frozenset(h if takers and (h := holder(x, takers[0])) is not None
                     and all(holder(x, u) == h for u in takers) else x for x in items)


def _laid(k: ObjectNode, u: FunctionalUnit, takers: Sequence[FunctionalUnit]) -> list[ObjectNode]:
    """The outputs of `u` placed in or on K's label that every unit taking K takes as they are (at least one)."""
    return [x for x in u.outputs if (w := place_of(x)) is not None and w[1] == k.label
            and takers and all(x in t.inputs for t in takers)]


def _laid_words(k: ObjectNode, u: FunctionalUnit, takers: Sequence[FunctionalUnit]) -> frozenset[State]:
    """K's states naming only objects that `u` leaves in or on K's label, in the node every unit taking K takes
    them in (`wrapped {plastic wrap}`, where the pick-and-place leaves and the unwrap takes `plastic wrap (on
    [bowl])`): words for that object lying there, which `u`'s output says by its own word (`covered`)."""
    laid = {x.label for x in _laid(k, u, takers)}
    return frozenset(s for s in _rest(k) if (names := {*s.ingredients, s.related} - {""}) and names <= laid)


def _taken_off(taking: Mapping[ObjectNode, list[FunctionalUnit]], kitchen: frozenset[ObjectNode], makers: Foon,
               made: Container[ObjectNode]) -> dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]:
    """K -> (P, the unit making P) for each kitchen node K naming no place that every unit taking it takes off or
    works on a container (the watermelon lemonade's uncover takes `blender lid` with `blender cup (contains
    {watermelon juice}, covered {blender lid})`, whose output node no longer lists the lid): the one output P with
    K's states and a place in or on such a container (the cover's `blender lid (on [blender cup])`). The unit
    making P may take K itself (the pick-and-place puts the kitchen's `watermelon (whole)` on the board the slice
    cuts it on): it keeps K, and so does every other unit making P (a universal FOON's smoothie puts it on a board
    in the same words), the others take P. O(kitchen x units x outputs)."""
    out = {}
    for k in sorted(x for x in kitchen if x in taking and not places(x) and x not in made):
        off = {u: {i.label for i in u.inputs if k.label in listed(i)
                   and not any(o.label == i.label and k.label in listed(o) for o in u.outputs)}
               for u in taking[k]}
        held = frozenset().union(*off.values())  # a P must be in or on one of these
        found: dict[ObjectNode, FunctionalUnit] = {}
        for p, u in _outputs_of(makers, k.label) if held else ():
            if not {c for _, c in places(p)} & held:
                continue
            others = [h for t, h in off.items() if p not in t.outputs]  # every unit making P keeps K
            if (_rest(k) <= _rest(p) and others and all(others)
                    and {c for _, c in places(p)} & frozenset().union(*others)):
                found.setdefault(p, u)
        if len(found) == 1:
            out[k] = next(iter(found.items()))
    return out


def _outputs_of(foon: Foon, label: str) -> list[tuple[ObjectNode, FunctionalUnit]]:
    """(output node, a unit making it) of `label`, from the network's indexes (`Foon.produced_by_label`,
    `Foon.producers`): the candidates P of a kitchen node K of that label, each node's first maker first."""
    return [(p, foon.units[i]) for p in foon.produced_by_label.get(label, ()) for i in foon.producers[p]]


def _taking(units: Sequence[FunctionalUnit], kitchen: frozenset[ObjectNode]) -> dict[ObjectNode, list[FunctionalUnit]]:
    """Kitchen node -> the units of `units` taking it, in order, each once (`Foon.consumers` of the task's units for
    the kitchen's nodes only: a task of a FOON-GEN goal has hundreds of units, whose other nodes need no index)."""
    out: dict[ObjectNode, list[FunctionalUnit]] = {}
    last: dict[ObjectNode, int] = {}
    for i, u in enumerate(units):
        for n in u.inputs:
            if n in kitchen and last.get(n) != i:
                last[n] = i
                out.setdefault(n, []).append(u)
    return out


Stitches = dict[ObjectNode, tuple[ObjectNode, FunctionalUnit]]
#: Networks read by kitchen stitches kept per network object (`_read_networks`).
READINGS_KEPT = 8


@per_network
def _read_networks(foon: Foon) -> dict[frozenset, Foon]:
    """The networks `stitched` read from `foon`, by reading (its K -> P pairs): one object per reading, so what is
    kept per network object (`input_stitch`'s stitches, the indexes) is computed once per reading, not once per
    goal (an experiment's goals over one kitchen share a few readings)."""
    return {}


def stitched(inp: LevelInputs, relevant: Callable[[LevelInputs], tuple[int, ...]],
             ) -> tuple[LevelInputs, Stitches, tuple[int, ...]]:
    """`inp` with each kitchen node K that the task of its `relevant` units reads as a unit output P
    (`kitchen_stitches`) read so: out of the kitchen, and P in every unit taking K; the readings; and the units
    relevant then. Until no more: a unit a reading makes relevant may take a kitchen node to read too (the
    watermelon lemonade's pitcher brings in the pour that takes the kitchen's squeezer). O(rounds x
    `kitchen_stitches`), a round per kitchen node at most."""
    stitches: Stitches = {}
    units = relevant(inp)
    while new := kitchen_stitches([inp.foon.units[u] for u in units], inp.kitchen, inp.foon):
        stitches |= new

        def unit(u: FunctionalUnit, new: Stitches = new) -> FunctionalUnit:
            read = {k: p for k, (p, _) in new.items() if k in u.inputs and p not in u.outputs}  # its makers keep K
            if not read:
                return u
            return FunctionalUnit(tuple(dict.fromkeys(read.get(n, n) for n in u.inputs)), u.motion, u.outputs,
                                  u.sources)

        kept = {k for k, (_, maker) in new.items() if k in maker.inputs}
        read = _read_networks(inp.foon)
        key = frozenset((k, p) for k, (p, _) in new.items())
        if key not in read:
            while len(read) >= READINGS_KEPT:  # a long run's trials read other kitchens
                read.pop(next(iter(read)))
            read[key] = Foon(tuple(map(unit, inp.foon.units)), inp.foon.level)
        inp = replace(inp, foon=read[key], kitchen=inp.kitchen - (new.keys() - kept))
        units = relevant(inp)
    return inp, stitches, units


def stitch_notes(stitches: Mapping[ObjectNode, tuple[ObjectNode, FunctionalUnit]]) -> list[tuple[FunctionalUnit, str]]:
    """(the unit making P, what is read) per reading, for the task's notes with the unit's file:line."""
    return [(u, f"the kitchen's {k.describe()} is read as {p.describe()}, which this {u.motion.label} makes: FOON "
             "gives what it holds only as what units make" + _words(k, p, u) if listed(k) else
             f"the kitchen's {k.describe()} is read as {p.describe()}, which this {u.motion.label} makes: the units "
             "taking it find it on a holder") for k, (p, u) in sorted(stitches.items())]


def _words(k: ObjectNode, p: ObjectNode, u: FunctionalUnit) -> str:
    """`; assumes covered, drops wrapped {plastic wrap}: plastic wrap (on [bowl]) in both units`: the states but
    lists and places that reading K as P assumes and drops, and the objects a dropped word names as lying there."""
    said = [f"{w} {', '.join(sorted(s.describe() for s in x))}" for w, x in
            (("assumes", _rest(p) - _rest(k)), ("drops", _rest(k) - _rest(p))) if x]
    named = {x for s in _rest(k) - _rest(p) for x in (*s.ingredients, s.related)}
    laid = [x.describe() for x in u.outputs if x.label in named and (w := place_of(x)) and w[1] == k.label]
    return ("; " + ", ".join(said) if said else "") + (f": {', '.join(laid)} in both units" if laid else "")
