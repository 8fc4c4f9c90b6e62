"""A container node a unit takes and leaves in the same words, listing what the unit puts in (a relational reading).

The easy pancakes' oil pour (`0031-easy_pancakes.txt:178`) takes `bowl (contains {egg white and yolk, flour mixture,
milk, vegetable oil})` with the bowl of vegetable oil, and leaves the bowl in the same words: the annotator listed
the oil before it was poured. No unit makes that node but the pour itself, so FOON's semantics takes it from the
kitchen, and the egg pour's `bowl (contains {egg white and yolk, flour mixture, milk})` goes nowhere. Over objects the
kitchen's bowl holds a flour mixture in no node a unit makes (`relational_init`), and the mix, which takes the flour
mixture made in the bowl the pours fill, applies to no reachable state: the dish was unsolvable, on the subgraph
alone as on a universal FOON.

Rule (`brought`): a unit U takes a node N of label C that no other unit makes, and gives N as an output; its other
inputs list items of N that no other output of U lists (what U puts in); and exactly one node M of label C, made by
a unit other than U, says all N says but those items (places too). Nothing but M's words and its being made by a
unit other than U ties M to N, not the recipe file (a universal FOON written as one file has every recipe in it).
Then, when a unit can make M from the kitchen (FOON's fixpoint, `read_brought`), U takes M and N is no kitchen
object (U makes it). When none can, U taking M could never apply, and N stays the kitchen's, as FOON's semantics
has it: EXP trial 5 goal 2's kitchen holds the banana pudding's bowl listing the pudding mix
(`0071-banana_pudding.txt:55`), the goal at once, but no condensed milk in a tin can, so no unit makes the bowl
without the mix; read, the kitchen's bowl was gone and the dish unsolvable. The kitchen is what tells the two
apart: the same units from a kitchen that can fill the bowl need the reading.
FOON's tree keeps FOON's unit; the reading is reported with U's file:line. O(units x made nodes of C) for the rare U
that takes and leaves one node.
"""

from __future__ import annotations

from dataclasses import replace

from ..analysis.reachability import reachable
from ..model.foon import Foon, ObjectNode
from ..model.memo import per_network, per_network_reading
from ..model.places import listed
from .encoding import LevelInputs

__all__ = ["brought", "read_brought"]


def _says(node: ObjectNode, but: frozenset[str] = frozenset()) -> frozenset:
    """What a node says, its `contains` list item by item, less the items `but`."""
    return frozenset(w for s in node.states for w in (
        [("contains", x) for x in (*s.ingredients, s.related) if x and x not in but] if s.label == "contains" else [s]))


def brought(foon: Foon) -> dict[int, tuple[ObjectNode, ObjectNode, tuple[str, ...]]]:
    """Unit index -> (N, M, the items it puts in), per the module doc."""
    out = {}
    for u, unit in enumerate(foon.units):
        for n in unit.inputs:
            if n not in unit.outputs or set(foon.producers.get(n, ())) != {u}:
                continue
            items = frozenset(x for i in unit.inputs if i != n for x in listed(i)) - frozenset(
                x for o in unit.outputs if o != n for x in listed(o))
            said = _says(n, items)
            if said == _says(n):
                continue
            found = {m for m in foon.produced_by_label.get(n.label, ()) if m != n and _says(m) == said
                     and set(foon.producers[m]) - {u}}
            if len(found) == 1:
                out[u] = (n, found.pop(), tuple(sorted(items & listed(n))))
    return out


def _network(foon: Foon, found: dict[int, tuple[ObjectNode, ObjectNode, tuple[str, ...]]]) -> Foon:
    """The network with each unit of `found` taking its M."""
    return Foon(tuple(replace(x, inputs=tuple(found[u][1] if i == found[u][0] else i for i in x.inputs))
                      if u in found else x for u, x in enumerate(foon.units)), foon.level)


_brought_network = per_network_reading(brought, _network)


#: Networks of some of the readings (`_network`) `read_brought` keeps per network object.
SUBSETS_KEPT = 8


@per_network
def _kept_networks(foon: Foon) -> dict[frozenset[int], Foon]:
    """Unit indexes -> `_network` of those readings of `brought(foon)`. Which readings a task keeps depends on the
    kitchen alone, so a trial's goals share one network object, and with it what is kept per network object (the
    stitches, indexes, kitchen pairs: 1.7 s per goal on EXP when each goal built its own)."""
    return {}


def read_brought(inp: LevelInputs) -> tuple[LevelInputs, dict[int, tuple]]:
    """`inp` with the units of `brought` whose M a unit can make from the kitchen (FOON's fixpoint) read so, their N
    out of the kitchen; and unit index -> (unit, note)."""
    foon, found = _brought_network(inp.foon)
    if foon is None:
        return inp, {}
    reach = reachable(inp.foon, inp.kitchen)
    kept = {u: x for u, x in found.items() if reach.can_make(x[1])}
    if not kept:
        return inp, {}
    if kept != found:
        nets, key = _kept_networks(inp.foon), frozenset(kept)
        if key not in nets:
            while len(nets) >= SUBSETS_KEPT:
                nets.pop(next(iter(nets)))
            nets[key] = _network(inp.foon, kept)
        foon = nets[key]
    notes = {u: (inp.foon.units[u], f"{inp.foon.units[u].motion.label} takes and leaves {n.describe()}, which no other "
                 f"unit makes, as {m.describe()}, which another unit makes: {', '.join(items)} put in by it")
             for u, (n, m, items) in sorted(kept.items())}
    return replace(inp, foon=foon, kitchen=inp.kitchen - {n for n, _, _ in kept.values()}), notes
