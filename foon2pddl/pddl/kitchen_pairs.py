"""A container's node and the node of what is in it, taken together, that no unit makes together: the kitchen's.

A unit may take a container's node that lists a label L together with L's node placed in that container: the
greek salad dressing's pour (`ACT-0085-greek_salad_dressing.txt:29`) takes `bowl (contains {garlic})` with `garlic
(minced, in [bowl])`. Over objects the garlic must be in the very bowl, in the very node. In a network where units
make each node only beside a different node of the other (on the universal FOON the tomato soup's pick-and-place,
`0011-easy_tomato_soup.txt:65`, makes the bowl with the garlic `peeled` in it; the garlic bread's add,
`0015-garlic_bread-student-mealz.txt:88`, makes the minced garlic in a bowl that lists the butter too), no plan
has the pair; FOON's tree takes each node from its own maker, two bowls for one. The hamburger's sprinkle and the
gyoza's scrape take the same pair.

So too when one of the two is the kitchen's and only units make the other: on the universal FOON of the subgraphs of
even index the apple turnover's sprinkle (`0086-apple_turnover.txt:335`) takes the kitchen's `flour (in [bowl])`
with `bowl (contains {flour})`, which only the pancakes' pour makes, with its flour `powder` (in the turnover's own
kitchen both are at hand; merged, the pancakes' pour makes the bowl no longer the kitchen's), and the tuna
sandwich's pour (`ACT-0024-tuna_sandwich.txt:32`) takes the kitchen's `bowl (contains {mayonnaise, onion})` with
`onion (chopped, in [bowl])`, which the black beans' pour makes in a bowl of onion alone.

The reading (`kitchen_pairs`), on the makers' own outputs: each node is the kitchen's or made, not both the
kitchen's (a kitchen node no unit makes has no maker; one a unit makes has it: the pancake's bowl that the oil pour
takes and leaves in the same words, `0031-easy_pancakes.txt:178`, is no bowl at hand), neither a node a stitch
reads for the taker (`input_stitch.stitched_inputs`: the unit that left it there is known), nor, for a kitchen
container, a held node the kitchen already says (`relational_init.kitchen_implied`) or another node of the held
label the kitchen places there, the only one (GEN's `plates and trays (contains {peppers})` holds the kitchen's whole
peppers, not the chopped ones the omelette's pour, `0042-perfect_omelette.txt:79`, takes with it; with garlic chopped
and garlic peeled in bowls the kitchen does not say which its one `bowl (contains {garlic})` holds, and the minced
garlic the hamburger's sprinkle takes with it is read as the pair, on the universal FOON of the subgraphs of index 2
modulo 3), no unit makes both, every unit making the held node leaves beside it a node of the container's label other than the pair's
(the garlic is in another bowl), and every unit making the container's node leaves beside it a node of L at that
container other than the pair's (another garlic is in the bowl), a maker that makes the node only from that very
node aside when both nodes are made (`_moved_on`: the garlic bread's remove of the bowl of butter from the microwave
the put inside took it into leaves the pair only where it already was; with the held node the kitchen's, the french
toast's cubed butter, the pair stays unread: its kitchen bowl was counted for the turkey sandwich's spread, which
takes that bowl node with other butter, one object more in its task), and no maker of the one takes the other (the homemade cheese pizza's bake takes
the pick-and-place's `oven (contains {pizza pan}, on, preheated)` and makes the pan of baked pizza in that oven,
which the remove takes with that oven node: one oven in two units' words, which `input_stitch` reads). Then no
unit's outputs have the pair, and none
turns the one made into the pair's without naming the other (a unit that did would be a maker without such an
output: the mince of the garlic in its bowl, which may make the pair, is no evidence for the reading). The pair is
read as at hand, as the kitchen's (`read_pairs`): the task starts with the container in its node and the object in
it, the plan's tree check takes both as given (`Compiled.placed`), and the task says so with the taker's file:line
and every maker's (`Pair.describe`). Labels as written (no name readings). O(u i^2) for u units of i inputs.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.memo import per_network
from ..model.places import listed, places
from ..model.where import short_path, unit_where
from .encoding import LevelInputs
from .input_stitch import stitched_inputs
from .relational_init import kitchen_implied

__all__ = ["Pair", "kitchen_pairs", "read_pairs"]


@dataclass(frozen=True)
class Pair:
    """`taker` takes `box` (a container's node listing `held`'s label) with `held` (placed in or on it), which no
    unit makes together: per maker of each, the node of the other's label it leaves beside it."""

    taker: FunctionalUnit
    box: ObjectNode
    held: ObjectNode
    box_makers: tuple[tuple[FunctionalUnit, ObjectNode], ...]
    held_makers: tuple[tuple[FunctionalUnit, ObjectNode], ...]

    def describe(self) -> str:
        """`pour takes bowl (...) with garlic (...), which no unit makes together (pick-and-place at F:L makes the
        bowl beside garlic (...); ...): read as the kitchen's`."""
        made = [f"the {what} is the kitchen's" for what, makers in ((self.box.label, self.box_makers),
                                                                    (self.held.label, self.held_makers)) if not makers]
        made += [f"{m.motion.label} at {unit_where(m, short_path)} makes the {what} beside {other.describe()}"
                 for what, makers in ((self.box.label, self.box_makers), (self.held.label, self.held_makers))
                 for m, other in makers]
        return (f"{self.taker.motion.label} takes {self.box.describe()} with {self.held.describe()}, which no unit "
                f"makes together ({'; '.join(made)}): read as the kitchen's")


def _beside(maker: FunctionalUnit, label: str, holder: str | None = None) -> ObjectNode | None:
    """The first output of `maker` of `label` (placed at `holder` when given)."""
    return next((o for o in maker.outputs if o.label == label
                 and (holder is None or holder in {h for _, h in places(o)})), None)


#: Kitchens whose pairs are kept per network object (`_read`): a trial's goals read a few, a long run's trials more.
KITCHENS_KEPT = 8


@per_network
def _read(foon: Foon) -> dict[frozenset[ObjectNode], dict[int, tuple[Pair, ...]]]:
    """Kitchen -> unit index -> the pairs that unit takes, filled as `kitchen_pairs` reads units. Sound: a unit's
    pairs read only the network (its units, makers and `stitched_inputs`, fixed for a network object, which this is
    kept per) and the kitchen, the key; a trial's goals share the network object, and their tasks most of their
    hundreds of units (FOON-GEN), which each goal read again."""
    return {}


def kitchen_pairs(foon: Foon, kitchen: frozenset[ObjectNode], takers: Iterable[int] | None = None) -> tuple[Pair, ...]:
    """Every pair of the module doc that the units `takers` (indexes; default all) take, in unit order; makers
    from the whole network. Each unit is read once per network object and kitchen (`_read`)."""
    read = _read(foon)
    if kitchen not in read:
        while len(read) >= KITCHENS_KEPT:
            read.pop(next(iter(read)))
        read[kitchen] = {}
    known = read[kitchen]
    out: list[Pair] = []
    for i in (range(len(foon.units)) if takers is None else sorted(takers)):
        if i not in known:
            known[i] = _taken_pairs(foon, kitchen, i)
        out.extend(known[i])
    return tuple(dict.fromkeys(out))


def _taken_pairs(foon: Foon, kitchen: frozenset[ObjectNode], i: int) -> tuple[Pair, ...]:
    """The pairs of the module doc unit `i` of `foon` takes from `kitchen`, in its inputs' order."""
    made = foon.producers

    def given(node: ObjectNode) -> bool:  # the kitchen's, or made
        return node in kitchen or node in made

    def makers(node: ObjectNode) -> list[FunctionalUnit]:  # none for the kitchen's that no unit makes
        return [foon.units[i] for i in dict.fromkeys(made.get(node, ()))]

    sewn = stitched_inputs(foon)
    out: list[Pair] = []
    u = foon.units[i]
    for box in u.inputs:
        if not given(box) or (i, box) in sewn:
            continue
        box_makers = makers(box)
        for held in u.inputs:
            if (not given(held) or (i, held) in sewn or (box in kitchen and held in kitchen) or held.label == box.label
                    or held.label not in listed(box) or box.label not in {h for _, h in places(held)}):
                continue
            held_makers = makers(held)
            if set(box_makers) & set(held_makers) or (box in kitchen and held in kitchen_implied((held,), kitchen)):
                continue
            if box in kitchen and _holds_other(box, held.label, kitchen):
                continue  # the kitchen says what of that label its container holds (the plate of whole peppers)
            cycle = bool(box_makers) and bool(held_makers)  # both made: a maker from the node itself is no way
            boxes = [(m, _beside(m, held.label, box.label)) for m in box_makers if not (cycle and _moved_on(foon, m, box))]
            helds = [(m, _beside(m, box.label)) for m in held_makers if not (cycle and _moved_on(foon, m, held))]
            if all(o is not None and o != held and held not in m.inputs for m, o in boxes) and all(
                    o is not None and o != box and box not in m.inputs for m, o in helds):
                out.append(Pair(u, box, held, tuple(boxes), tuple(helds)))  # type: ignore[arg-type]
    return tuple(out)


def _moved_on(foon: Foon, maker: FunctionalUnit, node: ObjectNode) -> bool:
    """Whether `maker` makes `node` only from `node` itself: it takes a node of `node`'s label, and every unit
    making each such input takes `node` (the garlic bread's remove, `0016-easy_garlic_bread-one-pot-chef.txt:62`,
    makes `bowl (contains {butter})` from the bowl in the microwave, which only the put inside at `:26` makes, from
    `bowl (contains {butter})`). It leaves the pair only where the pair already was, so it is no other way to it.
    O(i m) for i inputs of `maker` and m makers of each."""
    made = foon.producers
    taken = [i for i in maker.inputs if i.label == node.label]
    return bool(taken) and all(made.get(i) and all(node in foon.units[k].inputs for k in made[i]) for i in taken)


def _holds_other(box: ObjectNode, label: str, kitchen: frozenset[ObjectNode]) -> bool:
    """Whether the kitchen says its `box` holds a node of `label` of its own: it places exactly one in the box's
    label (two, chopped and peeled garlic in bowls, do not say which the bowl of garlic holds), no
    other kitchen node of that label lists `label` (the whole onion may be in another bowl of onion), and it places
    a node of every label the box lists there (REG's bowl of mayonnaise and onion, whose mayonnaise the kitchen has
    in a jar, is no bowl the kitchen fills: another recipe's whole onion in a bowl is not in it, trial 9 goal 29)."""
    there = [k for k in kitchen if box.label in {h for _, h in places(k)}]
    inside = {k.label for k in there}
    return (sum(k.label == label for k in there) == 1 and listed(box) <= inside
            and not any(k.label == box.label and k != box and label in listed(k) for k in kitchen))


def read_pairs(inp: LevelInputs, units: Iterable[int]) -> tuple[LevelInputs, tuple[Pair, ...]]:
    """`inp` whose kitchen has both nodes of every pair the task's relevant `units` take, and those pairs (only
    those: a bowl of minced garlic at hand is no shortcut for a task that takes no such pair, as the black beans'
    pour of chopped garlic, whose tree check found the bowl not available)."""
    pairs = kitchen_pairs(inp.foon, frozenset(inp.kitchen), units)
    if not pairs:
        return inp, pairs
    return replace(inp, kitchen=frozenset(inp.kitchen) | {n for p in pairs for n in (p.box, p.held)}), pairs
