"""The relational task's objects and where each starts: the kitchen completed with the holders and contents
its nodes name (module doc of `encode_relational`, "Init")."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import lru_cache

from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode, make_node, make_state
from ..model.physical import Relation
from ..model.places import describes_contents, holds_unsaid, listed, moved_into, place_of, place_state, places
from .holder_words import aliased, listed_as, task_aliases
from .instance_names import counted_objects, named_objects
from .names import NameTable
from .task import Instance

__all__ = ["completed_kitchen", "holder_init", "implied_contents", "kitchen_implied", "kitchen_placed",
           "placed_since_start",
           "unplaced"]


def holder_init(instances: list[Instance], alias: dict[str, str] | None = None,
                silent: frozenset[str] = frozenset(), nodes: Iterable[ObjectNode] = (),
                paired: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset(),
                filled: frozenset[tuple[str, str]] = frozenset(),
                follows: dict[ObjectNode, frozenset[ObjectNode]] | None = None) -> tuple[list[Instance], list[ObjectNode]]:
    """Instances with their starting holders, and the holders to add (module doc, "Init").

    An object whose node names `in [C]` goes into an object of label C whose node lists its label (the
    first not yet given one of that label), else, when no node of the task says what a C holds (`silent`:
    a stove, a table), into the first C, else into a C that holds what it does not say (`model.places.holds_unsaid`:
    level 2's `bowl (contains)`), one not yet given an object first, else into the first C whose node a unit takes
    with the object's
    (`paired`: the watermelon lemonade's pour takes `strainer (clean, empty, on [measuring cup])` with
    `measuring cup (clean, empty)`, FOON's contradiction the task reports; not when a unit takes the object's
    node with a C's node that lists it: the garlic-parmesan chicken's pour takes the spoon of basil and the spoon
    of pepper, and the kitchen's basil `in [spoon]`, with no spoon listing it, is not in the spoon of pepper);
    with none, into a holder to add: one per label C, listing
    everything that starts in it (`implied`; a `cutting board (clean)` a unit will fill is no place for the
    avocado the kitchen has on a board), and one more per further object of a label the task's units put into
    holders of label C (`filled`, `holder_flows.gained`): a unit taking it out of such a holder empties the holder
    (`relational_plan`), so two butters `in [bowl]` get two bowls listing butter, where one bowl holding both
    was left empty with the second in it; a C of the task's nodes that holds what it does not say and names no
    place, when no node lists it all (level 2: the garlic rice's `cutting board (contains)`, which the chop takes,
    where a `cutting board (contains {garlic})` is no node of the level). A holder added for a `silent` label is one plain node (`surface`),
    listing nothing, for every object placed there: its contents are not checked, as a place that says nothing of
    what it holds, and a unit may take them off it whole (the ribs' garlic scooped off the surface the kitchen
    has it on, in a task where another unit's output names a surface: listing the garlic, the surface
    still listed it once the garlic was in the spoon). An added holder starts in a node of `nodes` that lists exactly that
    and names no place (the kitchen's `pot (heated, on [stove])` is on the network's `stove (on, with
    [pot])`), of several first one from which units (`follows`, `same_place_steps`) lead it to a node `held_met`
    finds (the miso soup's stove: `stove (off (ready), with [pot])`, which a turn on switches on, not another
    recipe's `stove (off, with [pot])`, which none does), else in a node made of the list. Names (`filled`'s too) are read through the task's `alias`es. O(n^2) for n objects.
    """
    alias, follows = alias or {}, follows or {}
    filled = frozenset((alias.get(h, h), alias.get(x, x)) for h, x in filled)  # a unit's `oil` is the `olive oil`
    by_label: dict[str, list[Instance]] = {}
    for x in instances:
        if x.start is not None:
            by_label.setdefault(x.label, []).append(x)
    # an object's node a unit takes with a node of label C that lists it: that unit's C holds it, no other C it takes
    claimed = {(a, b.label) for a, b in paired if a is not None and a.label in listed_as(b, alias)}
    used: set[tuple[str, str]] = set()
    given: set[str] = set()  # the holders given an object
    wanted: dict[str, dict[str, int]] = {}
    picks: dict[str, tuple[str, Relation] | tuple[str, None]] = {}
    plain: set[str] = set()
    for x in instances:
        place = place_of(x.start)
        if place is None:
            continue
        rel, label = place[0], alias.get(place[1], place[1])
        pool = [h for h in by_label.get(label, ()) if h.name != x.name]
        listing = [h for h in pool if x.label in listed_as(h.start, alias)]
        free = [h for h in listing if (h.name, x.label) not in used]
        if label in silent:
            quiet = [h for h in pool if not describes_contents(h.start)]
        else:  # holders holding what they do not say (level 2's `bowl (contains)`): one each while there are more
            quiet = sorted((h for h in pool if holds_unsaid(h.start)), key=lambda h: h.name in given)
        together = [h for h in pool if (x.start, h.start) in paired and (x.start, label) not in claimed]
        pick = (free or listing or quiet or together or [None])[0]
        if pick is None and label in silent:  # a holder that says nothing of what it holds: one, in no list
            plain.add(label)
            picks[x.name] = (label, None)
            continue
        if pick is None:
            items = wanted.setdefault(label, {})
            items[x.label] = items.get(x.label, 0) + 1 if (label, x.label) in filled else 1
            picks[x.name] = (label, None)
            continue
        used.add((pick.name, x.label))
        given.add(pick.name)
        picks[x.name] = (pick.name, rel)
    met = held_met([x.start for x in instances if x.name in picks and picks[x.name][1] is None], follows, paired)
    listing_nodes: dict[tuple[str, frozenset[str]], ObjectNode] = {}
    unsaid: dict[str, ObjectNode] = {}  # per label, a node holding what it does not say (level 2's `bowl (contains)`)
    for n in sorted(nodes, key=lambda n: (n.label not in wanted or met.get(n.label, set()).isdisjoint(_reached([n], follows)), n)):
        if place_of(n) is None:  # a holder that is itself somewhere would need a holder of its own
            listing_nodes.setdefault((n.label, listed_as(n, alias)), n)
            if holds_unsaid(n):
                unsaid.setdefault(n.label, n)
    implied = [make_node(label, []) for label in sorted(plain)] + [listing_nodes.get((label, frozenset(items)), unsaid.get(
               label, make_node(label, [make_state("contains", "", sorted(items))])))
               for label, counts in sorted(wanted.items())
               for items in (frozenset(x for x, k in counts.items() if k > i) for i in range(max(counts.values())))]
    return [Instance(x.name, x.label, x.start, *picks[x.name]) if x.name in picks and picks[x.name][1] is not None
            else x for x in instances], implied


def same_place_steps(units: Iterable[FunctionalUnit]) -> dict[ObjectNode, frozenset[ObjectNode]]:
    """Per node, the nodes of its label at its place (or none, as it) a unit taking it leaves (`_reached`)."""
    out: dict[ObjectNode, set[ObjectNode]] = {}
    for u in units:
        for a in u.inputs:
            out.setdefault(a, set()).update(b for b in u.outputs if b.label == a.label and b != a
                                            and place_of(b) == place_of(a))
    return {a: frozenset(b) for a, b in out.items()}


def placed_since_start(units: Sequence[FunctionalUnit], kitchen: frozenset[ObjectNode],
                       alias: dict[str, str] | None = None) -> frozenset[ObjectNode]:
    """The nodes naming a place whose objects are where the kitchen started them: a kitchen node that names one, and
    a node every unit of `units` making it makes of inputs of its label all at its place (names read through the
    task's `alias`, as `relational_plan.late_emptied` reads the holder) and so placed (the peel at
    `0085-mini_bacon_egg_breakfast_pizza.txt:3` leaves the kitchen's onion `in [bowl]`); not one a unit puts there
    or makes there new (the buttered bread the pick-and-place at `0049-turkey_sandwich.txt:1` put on a board).
    The least fixpoint: a node only a cycle of units makes is not. O(passes x unit sizes), passes at most the nodes."""
    alias = alias or {}

    def at(n: ObjectNode) -> tuple[tuple[Relation, str], ...]:
        return places(aliased(n, alias))

    makers: dict[ObjectNode, list[tuple[ObjectNode, ...]]] = {}
    for u in units:
        for b in u.outputs:
            if b not in kitchen and places(b):
                makers.setdefault(b, []).append(tuple(a for a in u.inputs if a.label == b.label))
    out = {n for n in kitchen if places(n)}
    grew = True
    while grew:
        more = {b for b, ways in makers.items() if b not in out and all(
            ins and all(at(a) == at(b) and a in out for a in ins) for ins in ways)}
        out |= more
        grew = bool(more)
    return frozenset(out)


def started_notes(units: Sequence[FunctionalUnit], starts: Iterable[ObjectNode | None], implied: Iterable[ObjectNode],
                  follows: dict[ObjectNode, frozenset[ObjectNode]],
                  kitchen: frozenset[ObjectNode]) -> tuple[tuple[FunctionalUnit, str], ...]:
    """(unit, note) for each added holder (`implied`) that starts, not in a kitchen node, where `held_met` led it
    (`holder_init`): the unit that takes the node it is led to with the object, still where it started."""
    out, named = [], {a: b for u in units for a, b in unit_aliases(u)}  # a place's name for its holder's label
    for h in (h for h in implied if h not in kitchen):
        ahead = _reached([h], follows)
        for x in sorted(n for n in starts if (p := place_of(n)) is not None and named.get(p[1], p[1]) == h.label):
            near = _reached([x], follows)
            taken = [(near[a], i, a, m) for i, u in enumerate(units) for a in u.inputs if a in near
                     for m in u.inputs if m.label == h.label and m in ahead]
            if taken:
                _, i, a, m = min(taken)
                led = f", from which units leave {m.describe()}" if m != h else ""
                how = "it" if a == x else f"{a.describe()}, which units make of it without moving it"
                out.append((units[i], f"the {h.label} the kitchen's {x.describe()} is {place_of(x)[0].value} starts "
                                      f"in {h.describe()}{led}, a node only units make: this "
                                      f"{units[i].motion.label} takes that with {how}"))
                break
    return tuple(out)


def placed_notes(read: Iterable[tuple[ObjectNode, ObjectNode, Sequence[ObjectNode]]],
                 units: Sequence[FunctionalUnit]) -> tuple[tuple[FunctionalUnit, str], ...]:
    """(unit, note) per kitchen node `implied_contents` read as placed in a kitchen container (`read`: the box, the
    node there no kitchen node is, the kitchen's nodes of that label), at the unit making that node, else taking it."""
    out = []
    for box, bare, ks in read:
        u = next((u for u in units if bare in u.outputs), None) or next((u for u in units if bare in u.inputs), None)
        if u is None:
            continue
        first = (f" (the first in order of {len(ks)} kitchen nodes of {bare.label}; no unit of the task takes any there)"
                 if len(ks) > 1 else "")
        out.append((u, f"the kitchen's {box.describe()} lists {bare.label}, whose node there, {bare.describe()}, this "
                       f"{u.motion.label} {'makes' if bare in u.outputs else 'takes'}: read as the kitchen's "
                       f"{ks[0].describe()}, placed {place_of(bare)[0]} it{first}"))
    return tuple(out)


def held_met(starts: Iterable[ObjectNode | None], follows: dict[ObjectNode, frozenset[ObjectNode]],
             paired: Iterable[tuple[ObjectNode, ObjectNode]]) -> dict[str, set[ObjectNode]]:
    """Per holder label, the nodes of it a unit first takes with a node objects in `starts` reach where they are
    (`_reached`): the stir's `stove (on, with [pot])` for the miso soup's kitchen pot of hot water."""
    near = _reached(starts, follows)
    first: dict[str, int] = {}
    for a, b in paired:
        if a in near and b.label != a.label:
            first[b.label] = min(first.get(b.label, near[a]), near[a])
    met: dict[str, set[ObjectNode]] = {}
    for a, b in paired:
        if a in near and b.label != a.label and near[a] == first[b.label]:
            met.setdefault(b.label, set()).add(b)
    return met


def _reached(starts: Iterable[ObjectNode | None], follows: dict[ObjectNode, frozenset[ObjectNode]]) -> dict[ObjectNode, int]:
    """The nodes an object in one of `starts` reaches by units that leave its label at the same place (`follows`),
    each with the fewest such units."""
    near: dict[ObjectNode, int] = {}
    todo = sorted({n for n in starts if n is not None})
    for depth in range(len(follows) + 1):
        todo = [n for n in todo if n not in near]
        if not todo:
            break
        near.update((n, depth) for n in todo)
        todo = sorted({m for n in todo for m in follows.get(n, ())})
    return near


def implied_contents(instances: list[Instance], alias: dict[str, str], placed: frozenset[str],
                     nodes: Iterable[ObjectNode], paired: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset(),
                     kitchen: frozenset[ObjectNode] = frozenset(),
                     planned: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset()) -> tuple[
                         tuple[ObjectNode, ...], tuple[tuple[ObjectNode, ObjectNode, tuple[ObjectNode, ...]], ...]]:
    """What kitchen containers list but the task has too few objects in (`pot (contains {water})`, no water in
    any unit; three bowls of `contains {water}` and one `water (in [bowl])`): for every container (a label of
    `placed`, the labels nodes name as a place) that starts listing a label, one object of that label placed
    in it, counting the task's objects that start placed in a container of that label first. A new object
    starts in a node of the task that places its label there: a kitchen one first, then one that is a kitchen
    node in another place (`skillet (empty, on [stove])` for the kitchen's `skillet (empty)`, `milk (in
    [bowl])` for its `milk (in [carton])`: the kitchen's `stove (off, with [skillet])` and `bowl (contains
    {milk})` say they are there: `kitchen_placed`), one a unit takes with the container's own node first
    (`paired`; of those, one a unit of the plan the counts are derived from takes so, `planned`: on the
    experiment's GEN network a kitchen bowl of alliums, implied by both `alliums (chopped, on [surface])` and
    `alliums (on [surface], peeled)`, held the chopped one, which a pour the plan does not fire takes, while the
    plan's pour takes the peeled one, GEN trial 5 goal 51), never one that lists contents of its own (no object would stand for them), nor one the kitchen
    does not say (`kitchen_implied` over the `kitchen` and the objects' starts, as the tree check judges it:
    only a unit makes it, and FOON's tree would not find it there); else `water (in [pot])`, unless only a unit
    makes that node: then a kitchen node of the label placed there (EXP's `brown sugar (granulated, in [mixing
    bowl])` for the kitchen's `mixing bowl (contains {..., sugar})`, whose `sugar` the dalgona coffee's beat reads
    as its brown sugar, `0079-dalgona_coffee.txt:59`: not its `brown sugar (in [mixing bowl])`, which the pour
    makes; the first in order of several such kitchen nodes: none is a node any unit of the task takes there, or
    it would be one of the task's nodes above, so the object only stands for the list). Also, per such reading,
    (the container's node, the node only a unit makes, the kitchen nodes it was read as, the one taken first),
    for the task's note. In container-name order; O(n^2)."""
    out, read = [], []
    fits: dict[tuple[str, str], list[ObjectNode]] = {}
    for n in sorted(nodes):
        place = place_of(n)
        if place is not None:
            fits.setdefault((n.label, alias.get(place[1], place[1])), []).append(n)
    spare: dict[tuple[str, str], int] = {}
    for x in instances:
        place = place_of(x.start)
        if place is not None:
            key = (x.label, alias.get(place[1], place[1]))
            spare[key] = spare.get(key, 0) + 1
    starts = {x.start for x in instances if x.start is not None}
    for h in sorted(instances, key=lambda x: x.name):
        if h.start is None or h.label not in placed or not describes_contents(h.start):
            continue
        for item in sorted(listed_as(h.start, alias)):
            if spare.get((item, h.label), 0) > 0:
                spare[(item, h.label)] -= 1
                continue
            found = [n for n in fits.get((item, h.label), ()) if not listed(n)]  # lists nothing of its own
            moved = kitchen_placed(found, starts)
            said = kitchen_implied(found, kitchen | starts) | (starts & set(found))  # what FOON's tree may take from the kitchen
            known = sorted((n for n in found if n in said), key=lambda n: (n not in starts, n not in moved, (h.start, n) not in paired,
                                                               (h.start, n) not in planned, n))
            bare = make_node(item, [make_state("in", h.label)])  # else a kitchen node of it there, when that one only a unit makes
            there = sorted((moved_into(k, h.label), k) for k in kitchen if k.label == item) if bare in found else []
            out.append(known[0] if known else there[0][0] if there else bare)
            if there and not known:
                read.append((h.start, bare, tuple(k for _, k in there)))
    return tuple(out), tuple(read)


def unplaced(node: ObjectNode) -> ObjectNode:
    """`node` with its places dropped: `skillet (empty)` for `skillet (empty, on [stove])`."""
    return make_node(node.label, [s for s in node.states if place_state(s) is None])


def kitchen_placed(nodes: Iterable[ObjectNode | None], kitchen: Iterable[ObjectNode]) -> frozenset[ObjectNode]:
    """The `nodes` not in `kitchen` that are a kitchen node in another place (`milk (in [bowl])` for `milk (in
    [carton])`): where the kitchen completion starts an object a kitchen container lists, the kitchen says so."""
    given = frozenset(kitchen)
    loose = _unplaced_all(given)
    return frozenset(n for n in nodes if n is not None and n not in given and unplaced(n) in loose)


def kitchen_implied(nodes: Iterable[ObjectNode | None], kitchen: Iterable[ObjectNode]) -> frozenset[ObjectNode]:
    """`kitchen_placed`, and the `nodes` not in `kitchen` that say nothing but where they are, in or on a label
    whose kitchen node lists them (`peanut butter (in [jar])` beside the kitchen's `jar (contains {peanut
    butter})`, a node a universal FOON's buckeye candy makes by opening the jar): what the kitchen says too."""
    given, nodes = frozenset(kitchen), [n for n in nodes if n is not None]
    lists = {(k.label, x) for k in given for x in listed(k)}
    bare = {n for n in nodes if n not in given and n.states and all(place_state(s) is not None for s in n.states)
            and all((c, n.label) in lists for _, c in places(n))}
    return kitchen_placed(nodes, given) | bare


@lru_cache(maxsize=8)
def _unplaced_all(kitchen: frozenset[ObjectNode]) -> frozenset[ObjectNode]:
    """The kitchen's nodes with their places dropped (cached: the kitchen stitches ask once per kitchen node)."""
    return frozenset(unplaced(k) for k in kitchen)


def completed_kitchen(table: NameTable, counts, units: Sequence[FunctionalUnit], have: Iterable[str],
                      nodes: set[ObjectNode], named: Iterable[str], silent: frozenset[str],
                      filled: frozenset[tuple[str, str]] = frozenset(), kitchen: frozenset[ObjectNode] = frozenset(),
                      plan: Sequence[FunctionalUnit] = ()) -> tuple[list[Instance], dict[str, str], frozenset[str],
                                                                    frozenset[ObjectNode], tuple[tuple[FunctionalUnit, str], ...]]:
    """The counted objects with the kitchen completed: the contents its containers list, the holders its objects
    and the units name (`named`: the places the units' output nodes and portions name, each as its own unit
    reads it, `model.aliases.unit_aliases`; `filled`: what the
    task's units put into holders of which label, `holder_init`; `kitchen`: the task's kitchen nodes, which judge what
    the kitchen says, and `plan`: the units of the plan the counts are derived from, `implied_contents`). Also the task's aliases
    (`holder_words.task_aliases`), the labels a node places something in or on, the network's nodes the
    holders the kitchen implies start in, and the notes on where those start (`started_notes`) and of the kitchen
    nodes `implied_contents` reads as placed in a container (the unit that makes, else takes, the node the
    container's list could not start in)."""
    instances = counted_objects(table, counts)
    alias = dict(task_aliases(units, have, [x.start for x in instances]))
    placed = frozenset(alias.get(c, c) for n in nodes for _, c in places(n))
    paired, planned = (frozenset((a, b) for u in us for a in u.inputs for b in u.inputs) for us in (units, plan))
    contents, read = implied_contents(instances, alias, placed, nodes, paired, kitchen, planned)
    instances = named_objects(table, instances, contents)
    missing = sorted(set(named) - {x.label for x in instances})
    instances = named_objects(table, instances, [make_node(c, []) for c in missing])  # `in [muff]`: FOON only
    quiet = silent | frozenset(missing)  # a place only FOON names says nothing it holds
    follows = same_place_steps(units)
    instances, implied = holder_init(instances, alias, quiet, nodes, paired, filled, follows)
    told = started_notes(units, [x.start for x in instances if x.holder is None and place_of(x.start) is not None],
                         implied, follows, kitchen)
    if implied:
        # an added holder that cannot list what it holds (no lists at level 2; a bowl `in [bowl]` is not
        # held by itself) leaves those objects standing free: `_` are the holders a third pass would add
        instances, _ = holder_init(named_objects(table, instances, implied), alias, quiet)
    return instances, alias, placed, frozenset(implied) & nodes, told + placed_notes(read, (*units, *plan))
