"""Which unit makes a container's node and the node of what is in it, in the delete-free plan counts are derived
from (`instance_counts.delete_free_plan`, `relational`): one unit for both where one does, else the content's from
a unit that makes it in that container, else the container's from a unit that takes the container where the
content's maker left it, else the content's from a chain working it where it lies (`_worked_there`), else both from
a unit taking them out of a kitchen container (`_from_kitchen_box`: what that container holds is at hand,
`AT_HAND`); or, asked for the plan with first makers (`first`), where the content's first makers already lead it
there (`_there_first`), those; asked for makers by holder reach (`placed`), a unit making both that puts the object
back into the container for the container's node (`_put_back`), and where no rule chooses, back along the held
node's chain a unit that makes the container's node too (`_placed_back`), or back along the container's chain a unit
that makes the held node in it (`_held_back`). A node whose first maker the plan
does not have may be made by a unit the plan has (`made_in_plan`)."""

from __future__ import annotations

import weakref

from ..analysis.reachability import Reachability
from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.places import listed, places
from .holder_words import listed_as
from .relational_init import kitchen_implied

__all__ = ["AT_HAND", "kitchen_held", "made_in_plan", "makers_together", "needs"]

#: `makers_together`'s maker of a node a kitchen container holds (`kitchen_held`): none, it is at hand.
AT_HAND = -1


#: What `makers_together` and `needs` found on a fixpoint, kept while it lives (keyed by identity: a `Reachability`
#: is immutable): `count_plans._chosen` asks the makers of the same units again for each plan it makes (163,603 calls
#: for 2,753 plans in GEN trial 10 goal 57), and the rules ask which nodes a unit needs as often (113,516 walks).
_KEPT: weakref.WeakKeyDictionary[Reachability, tuple[dict[tuple[int, bool, bool], dict[int, int]],
                                                     dict[int, frozenset[int]]]] = weakref.WeakKeyDictionary()


def _kept(reach: Reachability) -> tuple[dict[tuple[int, bool, bool], dict[int, int]], dict[int, frozenset[int]]]:
    """`_KEPT`'s (makers together by (unit, first, placed), nodes needed by unit) of `reach`."""
    if (kept := _KEPT.get(reach)) is None:
        kept = _KEPT[reach] = ({}, {})
    return kept


def makers_together(reach: Reachability, u: int, first: bool = False, placed: bool = False) -> dict[int, int]:
    """`_makers_together`, found once per fixpoint, unit and flags (`_KEPT`); the mapping is shared: not to be
    changed."""
    together = _kept(reach)[0]
    if (found := together.get(key := (u, first, placed))) is None:
        found = together[key] = _makers_together(reach, u, first, placed)
    return found


def _makers_together(reach: Reachability, u: int, first: bool = False, placed: bool = False) -> dict[int, int]:
    """Node id -> the unit to make it, for the pairs of unit `u`'s inputs that are a container's node listing a
    label and that label's node placed in it, made by two units (first achievers), when some unit firing before
    `u` makes both. On a universal FOON the onigiri's pour takes `measuring cup (contains {water})`, whose first
    achiever is the pizza's turn on (`water (from [faucet], in [measuring cup])`), and `water (in [measuring
    cup])`, the macaroni's fill into a cup below the faucet: two cups, and no plan has the water in the one poured
    from. The pesto's fill makes both, from the kitchen's `measuring cup (empty)`: its objects are counted. Names
    are read as `u` reads them (rule 0, `unit_aliases`): the apple turnover's heat takes `cooking pan (contains
    {butter})` with `butter (cubed, in [pan])`, its pan, which the pork chops' scoop makes with the pan's node.
    `first`: no chain working the held node where it lies where its first makers already lead it there
    (`_there_first`); `instance_counts.derive_counts` counts each plan and keeps the one counting fewest. `placed`:
    where no unit makes both without needing either, one that needs only the held node (`_put_back`); where no rule
    above chooses, a maker back along the held node's chain that makes the container's node too
    (`_placed_back`), else one back along the container's chain that makes the held node in it (`_held_back`; only
    for a task whose small counts are out of holder reach, `planners.solve.plan`)."""
    ix, out = reach.index, {}
    alias = dict(unit_aliases(reach.foon.units[u]))
    for c in ix.inputs[u]:
        for x in ix.inputs[u]:
            held, box = ix.nodes[x], ix.nodes[c]
            if (x == c or reach.node_round[x] == 0 or reach.node_round[c] == 0
                    or held.label not in listed_as(box, alias)
                    or box.label not in {alias.get(h, h) for _, h in places(held)}
                    or reach.achiever[x] == reach.achiever[c]):
                continue
            both = [m for m in set(ix.makers[c]) & set(ix.makers[x])
                    if 0 <= reach.unit_round[m] < reach.unit_round[u] and not needs(reach, m, {c, x})]
            if both:
                out[c] = out[x] = _earliest(reach, both)
            elif placed and (again := _put_back(reach, u, c, x)) is not None:
                out[c] = again
            elif tied := [m for m in ix.makers[x] if 0 <= reach.unit_round[m] < reach.unit_round[u]
                          and _in_box(reach, m, c) and not needs(reach, m, {x})]:
                out[x] = _earliest(reach, tied)
            elif after := [k for k in ix.makers[c] if 0 <= reach.unit_round[k] <= reach.unit_round[u] and k != u
                           and not needs(reach, k, {c}) and _from_held(reach, k, c, x)]:
                out[c] = _earliest(reach, after)
            elif not (first and _there_first(reach, c, x)):
                out.update(_worked_there(reach, u, c, x) or _from_kitchen_box(reach, u, c, x)
                           or placed and (_placed_back(reach, u, c, x) or _held_back(reach, u, c, x)) or {})
    return out


def kitchen_held(kitchen: frozenset[ObjectNode], unit: FunctionalUnit) -> frozenset[ObjectNode]:
    """The inputs of `unit` that a kitchen container it takes holds, though a unit makes them: not in `kitchen`,
    placed in or on the container's label, which lists theirs, and said by the kitchen (`relational_init.
    kitchen_implied`: the completion starts the container's object of that label in that node). The kofta's pour
    (`ACT-0053-lentil_kofta-1.txt:1`) takes the kitchen's `pitcher (contains {water})` with `water (in [pitcher])`,
    which on a universal FOON the watermelon lemonade's pour makes too. O(inputs^2)."""
    boxes = [b for b in unit.inputs if b in kitchen]
    return frozenset(x for x in unit.inputs if x not in kitchen and any(
        x.label != b.label and x.label in listed(b) and b.label in {h for _, h in places(x)} for b in boxes)
        and x in kitchen_implied((x,), kitchen))


def _from_kitchen_box(reach: Reachability, u: int, c: int, x: int) -> dict[int, int] | None:
    """Node id -> maker for the container's node `c` and the held node `x` when no rule above chooses: a unit other
    than `u` that makes both, taking only kitchen nodes and nodes a kitchen container it takes holds (`kitchen_held`,
    at hand: `AT_HAND`). In FOON's tree such a node is made by a unit, maybe late, maybe out of `c` and `x`
    themselves; over objects it is in the container from the start, so the unit fires at once. On the universal
    FOON of 70 subgraphs drawn with seed 56 the lemonade's pour (`0072-old-fashioned_lemonade.txt:109`) takes
    `measuring cup (contains {water})`, first made by the mini pizza's turn on, with `water (in [measuring cup])`,
    first made by the macaroni's fill into a cup below the faucet: two cups. The kofta's pour out of the kitchen's
    pitcher makes both; its `water (in [pitcher])` only the watermelon lemonade's pour of the cup's water makes,
    so in FOON's tree the kofta's pour fires after the lemonade's. Tie-break: FOON order (`rank`). O(makers x
    inputs^2)."""
    ix = reach.index
    for m in sorted(set(ix.makers[c]) & set(ix.makers[x]), key=lambda k: ix.rank[k]):
        unit = reach.foon.units[m]
        held = kitchen_held(reach.kitchen, unit)
        if m != u and held and all(n in reach.kitchen or n in held for n in unit.inputs):
            return {c: m, x: m} | {ix.node_id[n]: AT_HAND for n in held}
    return None


def made_in_plan(reach: Reachability, chosen: set[int], n: int, by: int) -> int:
    """The unit to make node `n` (an id) for unit `by`: its first achiever when the delete-free plan so far
    (`chosen`) has it, else a unit of the plan that makes it, needing neither it nor what `by` makes (through first
    achievers), else the first achiever. Pulled in for that one node, another recipe's chain also makes nodes the
    plan's own chain takes, later in firing order, where the unfolding fires it (`instance_counts.unfold` has a node
    made by the last unit of the plan making it). On the shared universal FOON the 0050 omelette's sprinkle
    (`0050-scrambled_eggs_with_bacon-cheese.txt:242`) takes `cooking pan (contains {omelette}, on [stove])`, first
    made by the plain omelette's cook (`0063-plain_omelette_mahalo.txt:140`); its chain's mix (`:73`) makes `bowl
    (contains {egg mixture})` after 0050's own mix (`:54`), and the egg was cracked twice, salted and peppered for
    it: 25 objects in the problem, 20 used. 0050's spread (`:227`), in the plan for the omelette the flip takes,
    makes that pan's node. Tie-break: the earliest round, then FOON order. O(makers x the first achievers' inputs)."""
    ix = reach.index
    if reach.achiever[n] in chosen:
        return reach.achiever[n]
    took = {n, *ix.outputs[by]}
    found = [m for m in ix.makers[n] if m in chosen and m != by and not needs(reach, m, took)]
    return _earliest(reach, found) if found else reach.achiever[n]


#: How many units deep `_worked_there` follows a held node worked where it lies.
WORKED_DEPTH = 12


def _worked_there(reach: Reachability, u: int, c: int, x: int, depth: int = WORKED_DEPTH) -> dict[int, int] | None:
    """Node id -> maker for the held node `x` made where it lies, when no unit makes it in the container `c` before
    `u`: a maker of `x` firing only after `u` in the fixpoint (a maker by `u`'s round is the rules' above, never one
    of `u`'s round: the universal hamburger's garlic, 77 objects against 75) that makes it in `c` (`_in_box`), or one
    taking a node of its label at its place that such a chain makes (at most `depth` units, none needing what `u`
    makes; the round test is the top call's, on `x` itself). The homemade cheese pizza's pick-and-place
    (`0082-homemade_cheese_pizza.txt:328`) takes `table (contains {flour, pizza dough})` with `pizza dough
    (flattened, on [table])`; the knead takes the table's node and kneads the dough on it, the cut, shape and press
    work it there. On the universal FOON of the odd-index subgraphs the mini pizza's press makes the flattened dough
    first, on a table of its own: counted from it, no dough lay on the pizza's table (unsolvable at once)."""
    ix, held = reach.index, reach.index.nodes[x]
    mine = {o for o in ix.outputs[u] if reach.achiever[o] == u}  # what only `u` makes first
    for m in sorted(ix.makers[x], key=lambda k: (reach.unit_round[k], ix.rank[k])):
        if m == u or reach.unit_round[m] < 0 or depth == WORKED_DEPTH and reach.unit_round[m] <= reach.unit_round[u] or needs(
                reach, m, mine):  # one firing by the taker's round is the rules' above (c476cc6: not the same round)
            continue
        if _in_box(reach, m, c):
            return {x: m}
        for i in ix.inputs[m]:
            if depth and i != x and ix.nodes[i].label == held.label and places(ix.nodes[i]) == places(held) and (
                    found := _worked_there(reach, u, c, i, depth - 1)):
                return {x: m} | found
    return None


def _placed_back(reach: Reachability, u: int, c: int, x: int, depth: int = WORKED_DEPTH) -> dict[int, int] | None:
    """Node id -> maker for a node `y` on the held node `x`'s chain (`x`, then back through first achievers' inputs
    of its label at its place, at most `depth` units) and the container's node `c`: a unit other than `y`'s first
    achiever that makes both, firing before `u` and needing neither (None when a first achiever on the chain makes
    `c`, or none is found). The even universal half's kofta mix: its cook (`ACT-0053-lentil_kofta-1.txt:92`) takes
    `stove (on, with [pot])`, first made by the garlic rice's pick-and-place of an empty pot
    (`0023-garlic_rice.txt:1`), with the pot of lentils on it, whose chain starts with the miso soup's pour
    (`0033-miso_soup.txt:70`) into a pot on a stove no unit switches on: no plan has the two together (holder
    reach). The kofta's own pick-and-place (`:25`) makes `pot (contains {water}, on [stove])` and the stove with
    the pot: counted from it, one pot and one stove. Tie-break: the earliest round, then FOON order (`rank`).
    O(depth x makers x the first achievers' inputs)."""
    ix, held = reach.index, reach.index.nodes[x]
    y = x
    for _ in range(depth):
        m = reach.achiever[y]
        if m < 0 or c in ix.outputs[m]:
            return None
        both = [k for k in ix.makers[y] if k != m and c in ix.outputs[k]
                and 0 <= reach.unit_round[k] < reach.unit_round[u] and not needs(reach, k, {c, y})]
        if both:
            k = _earliest(reach, both)
            return {y: k, c: k}
        y = _back(reach, m, held)
        if y < 0:
            return None
    return None


def _put_back(reach: Reachability, u: int, c: int, x: int) -> int | None:
    """A unit making both the container's node `c` and the held node `x` that needs `x` (it puts the object back
    into the container) but not `c`, firing before `u`: it makes `c`, and `x` keeps its maker, the object's earlier
    node (None when there is none). On the universal FOON of 70 subgraphs drawn with seed 56 the egg noodles' stir
    (`0044-egg_noodles_from_scratch.txt:118`) takes `bowl (contains {egg mixture, flour})`, first made by the apple
    cake's pour of a bowl of flour `powder` (`ACT-0068-apple_cake.txt:249`), with `flour (in [bowl], sifted)`: the
    noodles' pour (`:102`) makes both, of the sifted flour the sift (`:15`) left in a bowl and the pour (`:29`) took
    into a measuring cup. Tie-break: the earliest round, then FOON order (`rank`). O(makers x their chains)."""
    ix = reach.index
    again = [m for m in set(ix.makers[c]) & set(ix.makers[x])
             if 0 <= reach.unit_round[m] < reach.unit_round[u] and needs(reach, m, {x}) and not needs(reach, m, {c})]
    return _earliest(reach, again) if again else None


def _held_back(reach: Reachability, u: int, c: int, x: int, depth: int = WORKED_DEPTH) -> dict[int, int] | None:
    """Node id -> maker for the held node `x` from a unit that makes it in a node `y` on the container's chain (`c`,
    then back through first achievers' inputs of its label at its place, at most `depth` units), firing before `u`
    and not needing `x`: the container reaches `c` from `y` with the object still in it (None when none is found).
    `_placed_back` mirrored: on the universal FOON of 70 subgraphs drawn with seed 55 the southern macaroni's stir
    (`0055-southern-baked_macaroni_and_cheese.txt:97`) takes `egg white and yolk (beaten, in [bowl])`, first made by
    the blueberry muffin's blend (`ACT-0003-blueberry_muffin.txt:55`) in a bowl of butter and sugar, with the bowl
    of egg, milk, salt, pepper and cheese, whose chain of pours and sprinkles (`:86`, `:72`, `:58`, `:46`) goes back
    to `bowl (contains {egg white and yolk})`, which the omelette's mix (`0042-perfect_omelette.txt:11`) leaves with
    the beaten egg in it. Tie-break: the latest node on the chain, then the earliest round, then FOON order (`rank`).
    O(depth x makers)."""
    ix, box = reach.index, reach.index.nodes[c]
    y = c
    for _ in range(depth):
        found = [k for k in ix.makers[x] if y in ix.outputs[k] and 0 <= reach.unit_round[k] < reach.unit_round[u]
                 and not needs(reach, k, {x})]
        if found:
            return {x: _earliest(reach, found)}
        m = reach.achiever[y]
        if m < 0:
            return None
        y = _back(reach, m, box)
        if y < 0:
            return None
    return None


def _there_first(reach: Reachability, c: int, x: int, depth: int = WORKED_DEPTH) -> bool:
    """Whether the held node `x`'s first achievers, back through nodes of its label at its place (at most `depth`
    units), lead to one that makes it in the container's node `c` (`_in_box`) or makes `c` itself: the object is
    there as first made, and no later maker is looked for (`_worked_there`). The scrambled eggs' cook and stir
    (`0062-scrambled_eggs.txt:70`) takes `stove (on, with [pan])`, listing the pan, with the pan `contains {egg
    mixture}, on [stove]`: 0062's pour (`:44`) fills the pan the heat (`0061-club_sandwich.txt:13`) left on the
    stove it switched on; counted from 0056's pour (`0056-scrambled_eggs.txt:83`), which fires after the cook and
    stir, the plan had a second pan, stove and bowl and 0056's chain; the garlic breads' remove
    (`0015-garlic_bread-student-mealz.txt:241`) takes the tray 0015's bake (`:217`) left in the oven, not 0010's
    (`0010-cheesy_garlic_bread.txt:274`), whose chain fired the garlic butter's twice. O(depth x inputs)."""
    ix, held = reach.index, reach.index.nodes[x]
    for _ in range(depth):
        m = reach.achiever[x]
        if m < 0 or c in ix.outputs[m] or _in_box(reach, m, c):
            return m >= 0
        x = _back(reach, m, held)
        if x < 0:
            return False
    return False


def _back(reach: Reachability, m: int, held: ObjectNode) -> int:
    """The input of unit `m` that a unit makes with `held`'s label at its place (the chain `_there_first` and
    `_placed_back` follow back), or -1."""
    ix = reach.index
    return next((i for i in ix.inputs[m] if reach.node_round[i] > 0 and ix.nodes[i].label == held.label
                 and places(ix.nodes[i]) == places(held)), -1)


def _from_held(reach: Reachability, k: int, c: int, x: int) -> bool:
    """Whether unit `k` (a maker of the container's node `c`) takes a node of that container's label that the first
    achiever of the held node `x` leaves beside it: the tomato soup's turn on (`0011-easy_tomato_soup.txt:305`)
    switches on the stove its pick-and-place put the pot of soup on, `stove (off (ready), with [pot])`."""
    ix = reach.index
    made = set(ix.outputs[reach.achiever[x]])
    return any(i in made and ix.nodes[i].label == ix.nodes[c].label for i in ix.inputs[k])


def _in_box(reach: Reachability, m: int, c: int) -> bool:
    """Whether unit `m` makes what it makes in the container of node `c` (an id): it takes `c` and leaves no node of
    its label (the garlic rice's cut, `0023-garlic_rice.txt:260`, chops the cilantro on the board the sprinkle takes
    in that node), or it makes a node of that label that `c`'s first achiever takes (it leaves the object in the
    container that unit then changes: a scoop of butter into the pan the oil is poured into next)."""
    ix, box = reach.index, reach.index.nodes[c]
    if c in ix.inputs[m]:
        return not any(ix.nodes[o].label == box.label for o in ix.outputs[m])
    return any(ix.nodes[o].label == box.label and o in ix.inputs[reach.achiever[c]] for o in ix.outputs[m])


def _earliest(reach: Reachability, units: list[int]) -> int:
    """The unit of `units` (not empty) that fires first: the earliest round, then FOON order (`rank`), every rule's
    tie-break. O(units)."""
    return min(units, key=lambda m: (reach.unit_round[m], reach.index.rank[m]))


def needs(reach: Reachability, u: int, nodes: set[int]) -> bool:
    """Whether unit `u` needs one of `nodes` (ids), through first achievers: the hash browns' second mix makes
    `bowl (contains {potato mixture})` and the mixture with the egg, from the bowl the first mix leaves in that
    very node, so it cannot make that node for the unit that takes both. The nodes `u` needs are walked once per
    fixpoint (`_needed`)."""
    return not _needed(reach, u).isdisjoint(nodes)


def _needed(reach: Reachability, u: int) -> frozenset[int]:
    """The nodes (ids) unit `u` needs through first achievers: its inputs and, for each such node a unit makes,
    its first achiever's inputs, and so on. Kept per fixpoint and unit (`_KEPT`); O(nodes + edges) once."""
    needed = _kept(reach)[1]
    if (found := needed.get(u)) is None:
        seen: set[int] = set()
        met, stack = set(reach.index.inputs[u]), list(reach.index.inputs[u])
        while stack:
            n = stack.pop()
            if n not in seen and reach.node_round[n] > 0:
                seen.add(n)
                met.update(ins := reach.index.inputs[reach.achiever[n]])
                stack.extend(ins)
        found = needed[u] = frozenset(met)
    return found
