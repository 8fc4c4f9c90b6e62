"""An item a container's list gains with no object of the unit, read as arriving with the unit (a relational
reading).

The easy tomato soup's add (0011-easy_tomato_soup.txt:118) puts ten ingredients into the blender jar, whose output
node lists `refined sugar` too, though no node of the unit is sugar; the blend at :206, which takes the jar on
from the cover after the add, takes `refined sugar (granulated, in [blender jar])`, a node no unit makes, with the
jar listing it. FOON's semantics takes that node from the kitchen; over objects it is sugar in a second jar (every
jar of the kitchen is empty), while the blend needs it in the jar the add filled, and no plan exists. Read from
those units, the add put the sugar in too.

Rule (`arrivals`): a unit U whose output node of label C lists a name L that its input node of label C (the
pairing's, `pairing.unit_roles`) does not, where no node of U is of label L (read through U's names) and no input
node of U lists L (the tuna poured from a bowl that lists it came from there); and a unit V
on the path of U's node of C (`list_drops.path_taker`: the units that take that node on, each later in the same
recipe file) that takes a node N of label L placed in or on C (read through V's names) that no unit of the
network makes, with a node of label C that lists L. Then U also gives N as an output: an object the unit makes,
where the unit's node of C says. The container's path, not the recipe file, ties U and V: a universal FOON
written as one file has every recipe in it, and another recipe's jar listing sugar is no evidence. FOON's tree
keeps FOON's unit (the blend's N is in the kitchen, as FOON's semantics reads it); where the sugar came from FOON
does not say, and the reading is reported with U's file:line. O(d r) per name gained, for a path of d units
(`list_drops.DEPTH`) of r roles.
"""

from __future__ import annotations

from dataclasses import replace

from ..model.aliases import unit_aliases
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.memo import per_network_reading
from ..model.pairing import unit_roles
from ..model.places import listed, place_of
from ..model.where import short_path, unit_where
from .encoding import LevelInputs
from .list_drops import path_taker, placed_at

__all__ = ["arrival_notes", "arrivals", "read_arrivals"]


def _gained(unit: FunctionalUnit) -> list[tuple[ObjectNode, str]]:
    """(container's output node, name) per name a role's output node lists and its input node does not, that is
    no object of the unit (through its names)."""
    labels = {n.label for n in (*unit.inputs, *unit.outputs)}
    given = {x for n in unit.inputs for x in listed(n)}  # poured from a container that lists it: no arrival
    new = [(r.after, x) for r in unit_roles(unit) if r.after is not None and r.before is not None
           for x in sorted(listed(r.after) - listed(r.before)) if x not in labels and x not in given]
    names = dict(unit_aliases(unit)) if new else {}  # only for a unit whose list gains a name
    return [(box, x) for box, x in new if names.get(x, x) not in labels]


def arrivals(foon: Foon) -> dict[int, tuple[ObjectNode, FunctionalUnit]]:
    """Unit index -> (the node it is read as also making, the later unit taking it), per the module doc."""
    made, every = foon.producers, frozenset(range(len(foon.units)))
    out: dict[int, tuple[ObjectNode, FunctionalUnit]] = {}
    for u, unit in enumerate(foon.units):
        for box, label in _gained(unit):
            taker = path_taker(foon, every, u, box, label, made=False)
            if taker is None or not any(n.label == box.label and label in listed(n) for n in taker.inputs):
                continue
            node = next(n for n in placed_at(taker, label, box.label) if n not in made)
            out.setdefault(u, (node, taker))
    return out


def _network(foon: Foon, found: dict[int, tuple[ObjectNode, FunctionalUnit]]) -> Foon:
    """The network with each unit of `found` giving its node too."""
    units = tuple(replace(x, outputs=(*x.outputs, found[u][0])) if u in found else x for u, x in enumerate(foon.units))
    return Foon(units, foon.level)


_arrived_network = per_network_reading(arrivals, _network)


def read_arrivals(inp: LevelInputs) -> tuple[LevelInputs, dict[int, tuple[FunctionalUnit, str]]]:
    """`inp` with the units of `arrivals` read so; and unit index -> (unit, note) per reading, for the notes of
    a task with that unit."""
    foon, found = _arrived_network(inp.foon)
    if foon is None:
        return inp, {}
    return replace(inp, foon=foon), arrival_notes(inp.foon, found)


def arrival_notes(foon: Foon, found: dict[int, tuple[ObjectNode, FunctionalUnit]]
                  ) -> dict[int, tuple[FunctionalUnit, str]]:
    """`add's blender jar lists refined sugar, which no object of the unit is, and blend at F:L takes refined sugar
    (...), which no unit makes: read as put in with the rest`, per unit index."""
    notes = {}
    for u, (node, taker) in sorted(found.items()):
        unit = foon.units[u]
        holder = place_of(node)
        notes[u] = (unit, f"{unit.motion.label}'s {holder[1] if holder else '?'} lists {node.label}, which no object "
                      f"of the unit is, and {taker.motion.label} at {unit_where(taker, short_path)} takes "
                      f"{node.describe()}, which no unit makes: read as put in with the rest")
    return notes
