"""How the `relational` encoding reads a task's units, and the objects that reading needs.

Each unit of the task is read by `relational_plan.plan_unit`, given the holders that say nothing of what they
hold (`relational_plan.quiet_places`), the (holder, content) pairs the task's units fill (`holder_flows.gained`), the
task's labels and the labels that hold something (`relational_plan.holding_labels`); flows a later unit's input
says did not happen are dropped (`list_drops.kept_in_place`). The objects come from those readings
(`instance_counts.derive_counts` with `relational_plan.count_roles`; with stitches, enough for FOON's own plan and
for the stitched one; counted small, for FOON's own plan alone, `relational_objects`, or for that plan with each unit
taking a made node as a later unit left the object, when that counts fewer, `_as_now`, or for the plan through the
stitches alone, `through`; with makers by holder reach, `placed`), or from the scene. A unit
with a role of a label the task has no object of is left out; when that changes which places the task's units
name, the units are read again with only the kept ones as speakers (a unit with no objects names no place).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode, make_node, make_state
from ..model.memo import per_network
from ..model.places import listed, places
from ..model.scene import SceneObject
from ..model.where import short_path, unit_where
from .encoding import LevelInputs
from .holder_flows import gained
from .holder_words import task_aliases
from .input_stitch import Stitched
from .instance_counts import InstanceCounts, RolesOf, delete_free_plan, derive_counts
from .list_drops import kept_in_place, taken_again
from .relational_init import placed_since_start
from .relational_plan import (
    UnitPlan,
    called_fills,
    count_roles,
    filled_by_task,
    holding_labels,
    listings,
    plan_unit,
    quiet_places,
    taken_with,
)

__all__ = ["Reading", "read_units"]


@dataclass(frozen=True)
class Reading:
    """A task's units as the relational encoding reads them (`read_units`).

    `units`: the task's units with an object for every role; `silent`: the holders that say nothing of what they
    hold; `plans`: each unit's reading; `drops`: the flows read as not happening, as (container, content,
    message, unit), of the units in `units` only (another unit's reading is no part of the task); `roles_of`: a unit's roles for counting; `counts`, `have`: the objects (label -> how many);
    `filled`: the (holder, content) label pairs the units fill; `renamed`: (unit, note) per kept unit whose
    implied node is read as before the goal's maker (`_short_of_goal`)."""

    units: tuple[int, ...]
    silent: frozenset[str]
    plans: Mapping[int, UnitPlan]
    drops: tuple[tuple[str, str, str, FunctionalUnit], ...]
    roles_of: RolesOf
    counts: InstanceCounts
    have: Mapping[str, int]
    filled: frozenset[tuple[str, str]]
    renamed: tuple[tuple[FunctionalUnit, str], ...] = ()
    #: (unit, note) per kept unit read as taking a portion out of a container FOON takes again (`taken_again`)
    portions: tuple[tuple[FunctionalUnit, str], ...] = ()
    #: the kitchen nodes one unit of the task takes, fired once: poured or sprinkled out whole (`plan_unit`'s `sole`)
    sole: frozenset[ObjectNode] = frozenset()
    #: where the plan through the stitches was counted alone, or FOON's own plan was none (no firings) and that plan
    #: was counted beside it: `counts` with that plan's firings, named by the task's units, to say why the counts are
    #: what they are (`count_reasons`); None where FOON's own plan says it. For the notes only, no part of the task
    explained: InstanceCounts | None = None
    #: the (object node, container node) pairs a unit of the task the plan as counted fires fills, in a node the plan
    #: starts no kitchen object in: the whole leaves it (`plan_unit`'s `task_filled`, `_moved_whole`)
    task_filled: frozenset[tuple[ObjectNode, ObjectNode]] = frozenset()


@dataclass(frozen=True)
class _CountsKey:
    """The memo key of one counting in `read_units`: the network by identity (the memo holds it, so its id names no
    other object while it lives), the plan's units, and the switches it was counted with; the roles each count
    derived under it asked for are kept beside it (`_asking`)."""

    net: int
    need: tuple[int, ...]
    narrow: frozenset[ObjectNode] | None
    placed: bool
    other_makers: bool
    refill: bool


def _short_of_goal(plans: dict[int, UnitPlan], makers: Mapping[ObjectNode, FunctionalUnit]
                   ) -> tuple[dict[int, UnitPlan], dict[int, tuple[FunctionalUnit, str]]]:
    """`plans` with every node a unit only implies for an object (its `after` or `portion` node, not one of the
    unit's outputs) that is a goal candidate a unit of the task makes (`makers`: candidate -> that unit) read as
    the object before that unit: the candidate's states and `before <motion>`. The pour that gives no node of
    the cream it pours into the bowl implies `cream (in [bowl])`, the node the mix makes (GEN's whipped cream):
    only the mix's cream reaches the goal, the poured one is the cream the mix has not yet whipped. Also unit
    index -> (unit, note) per unit so read."""
    said: dict[int, tuple[FunctionalUnit, str]] = {}

    def apart(u: int, node: ObjectNode | None, unit: FunctionalUnit) -> ObjectNode | None:
        if node is None or node not in makers or node in unit.outputs:
            return node
        maker = makers[node]
        said[u] = (unit, f"{unit.motion.label} implies {node.describe()}, the goal's node {maker.motion.label} at "
                         f"{unit_where(maker, short_path)} makes: read as the {node.label} before {maker.motion.label}")
        return make_node(node.label, (*node.states, make_state(f"before {maker.motion.label}")),
                         motion_flag=node.motion_flag)

    def read(u: int, s, unit: FunctionalUnit):  # a slot is copied only when one of its nodes is read apart
        after, portion = apart(u, s.after, unit), apart(u, s.portion, unit)
        return s if after is s.after and portion is s.portion else replace(s, after=after, portion=portion)

    out = {}
    for u, p in plans.items():
        slots = tuple(read(u, s, p.unit) for s in p.slots)
        out[u] = p if slots == p.slots else replace(p, slots=slots)
    return out, said


def _taken_once(f: Foon, units: Sequence[int], kitchen: frozenset[ObjectNode],
                filled: frozenset[tuple[str, str]]) -> frozenset[ObjectNode]:
    """The kitchen containers exactly one of the task's `units` takes, listing something the units put into
    containers of their label (`filled`): those `plan_unit` may read as poured out whole. O(units x inputs)."""
    takers: dict[ObjectNode, int] = {}
    for u in units:
        for n in f.units[u].inputs:
            if n in kitchen and any((n.label, x) in filled for x in listed(n)):
                takers[n] = takers.get(n, 0) + 1
    return frozenset(n for n, k in takers.items() if k == 1)


def _rest_stays(sole: frozenset[ObjectNode], counted: Sequence[tuple[Foon, InstanceCounts]]) -> frozenset[ObjectNode]:
    """The nodes of `sole` a unit of FOON's plan as counted fires again, or that start holding more objects of
    what they list than there are of them (a unit that does not name its holder takes from it too: the chocolate
    cake's sprinkle at `0058-chocolate_cake.txt:17`, beside the pour at `:49`): poured out whole, they would be
    read empty with something in them. O(sole x kitchen nodes counted + firings x inputs)."""
    out = {n for net, c in counted for u, k in c.firings if k > 1 for n in net.units[u].inputs} & sole
    for _, c in counted:
        at = dict(c.at_node)
        out |= {n for n in sole for x, k in c.at_node
                if x.label in listed(n) and any(p[1] == n.label for p in places(x)) and k > at.get(n, 0)}
    return frozenset(out)


def _moved_whole(fills: frozenset[tuple[ObjectNode, ObjectNode]], counted: Sequence[tuple[Foon, InstanceCounts]]
                 ) -> frozenset[tuple[ObjectNode, ObjectNode]]:
    """The pairs of `fills` (`relational_plan.filled_by_task`) that FOON's plan as counted fills: a unit it fires
    makes both nodes, and it starts no object in the container's node, nor one of the pair's label in a holder of the
    container's label (else the plan takes the kitchen's stock, which keeps what it lists: the egg noodle's plan
    pours flour out of the kitchen's spoon of flour at `0030-5_easy_microwave_desserts-chocolate_chip_cookie.txt:45`;
    read as emptied by the noodles' own pour at `0044-egg_noodles_from_scratch.txt:148`, which the plan does not
    fire, that spoon is one an action can touch: two objects more in the problem, the plan the same). A pair no unit
    of the plan fills is left as it was read: of GEN trial 10 goal 57's 626 pairs, 30 (each moved whole, the counts
    of many units' new roles cost its encoding 4x). O(fills + firings x outputs^2 + fills x kitchen nodes counted)."""
    made = {(a, h) for net, c in counted for u, k in c.firings if k > 0
            for a in net.units[u].outputs for h in net.units[u].outputs} & fills
    for _, c in counted:
        start = [x for x, k in c.at_node if k > 0]
        made -= {(a, h) for a, h in made if h in start or any(
            x.label == a.label and any(p[1] == h.label for p in places(x)) for x in start)}
    return frozenset(made)


def _fired_again(counted: Sequence[tuple[Foon, InstanceCounts]]) -> frozenset[FunctionalUnit]:
    """The units FOON's plan as counted fires more than once. A made object such a unit takes whole from a holder
    no node lists it in (`relational_plan.listings`) is read as a portion again: the second firing takes what the
    first left (the pigs in a blanket's pick-and-place onto the tray, `0052-pigs_in_a_blanket.txt:89`, fired twice
    by the plan unfolded, whose bake and last pick-and-place take trays its output node names; whole, the roll and
    what it takes fired twice too, 15 -> 16 objects on the odd half). O(firings)."""
    return frozenset(net.units[u] for net, c in counted for u, k in c.firings if k > 1)


def _as_now(foon: Foon, st: Stitched) -> Foon | None:
    """`foon` (FOON's own network) with each unit of a stitch of a made node (`input_stitch._left_by`,
    `_held_before`: the object as a unit moving it on left it) in the stitched unit's place, indexes unchanged; None
    when there is none. The muffins' bake takes the pan as the scoop filled it, with the oven the put inside left
    holding it: FOON's plan unfolded fires every unit making the batter twice, this one once."""
    sewn = {u: st.foon.units[k] for k, u in sorted(st.origin.items())
            if any(s.unit == u and s.left_by is not None for s in st.found)}
    if not sewn:
        return None
    made, key = _nows(foon), tuple(sewn)  # one network per set of units: its index is built once (an experiment's goals)
    if key not in made:
        while len(made) >= NOWS_KEPT:
            made.pop(next(iter(made)))
        made[key] = Foon(tuple(sewn.get(u, x) for u, x in enumerate(foon.units)), foon.level)
    return made[key]


def _asking(roles_of: RolesOf, asked: dict[FunctionalUnit, tuple]) -> RolesOf:
    """`roles_of`, keeping in `asked` each unit it is asked about with its answer: `read_units`' counts are derived
    again only when some unit a count asked about has other roles now (its readings of the units differ elsewhere:
    `derive_counts` is a pure function of those answers, so the same answers give the same counts: the GEN
    experiment's trial 10 goal 83 derived 30 counts, 20 of them again from the same roles of every unit)."""

    def recorded(unit: FunctionalUnit) -> tuple:
        asked[unit] = roles = roles_of(unit)
        return roles
    return recorded


#: Networks `_as_now` keeps per network object.
NOWS_KEPT = 8


@per_network
def _nows(foon: Foon) -> dict[tuple[int, ...], Foon]:
    """The networks `_as_now` made of `foon`, by the units it puts a stitched unit in the place of."""
    return {}


def read_units(inp: LevelInputs, st: Stitched, scene: Sequence[SceneObject], stated: Mapping[ObjectNode, int],
               overrides: Mapping[str, int], narrow: frozenset[ObjectNode] | None = None,
               memo: dict | None = None, through: bool = False, placed: bool = False,
               other_makers: bool = True, refill: bool = True) -> Reading:
    """The reading of `st`'s units (module doc); `inp.foon` is the network FOON's own plan runs in, `scene` the
    kitchen's scene objects (none: counts derived), `stated` and `overrides` the counts the kitchen and options
    give; `narrow`: count small, from FOON's own plan alone (no stitched one beside it) in the kitchen with these
    nodes too (`relational_objects`), from the plan through the stitches alone with `through`, with makers by holder
    reach with `placed` (`count_together.makers_together`), and the plans with a needed node made by another of its
    makers counted too with `other_makers` (`instance_counts.derive_counts`; without: FOON's own plan unfolded), and a
    container a unit fills in a kitchen node taken again with `refill` (`count_reuse._refilled_with`; another idea
    than `Reading.filled`, the (holder, content) label pairs the units fill). A container a unit of the task fills,
    in a node the kitchen has too, is emptied whole by a unit taking what it holds when the wide count's plan (no
    `narrow`, `placed` or other switch) fills it (`_moved_whole`; `Reading.task_filled`): every other count takes
    that count's pairs as they are, so its counts of the units' other readings stay the ones already derived, and a
    small count is read as the wide one. `memo`: a dict shared by the calls with
    the same `inp`, `st`, `stated` and `overrides` (counted wide, then small): the units' readings by speakers and
    the counts by plan and kitchen are made once (the same values: read twice, they cost a GEN trial's encoding a
    third more)."""
    memo = {} if memo is None else memo
    f, units = st.foon, st.units
    if "task" not in memo:
        task_nodes = set(inp.kitchen) | {n for u in units for n in (*f.units[u].inputs, *f.units[u].outputs)}
        gains = frozenset().union(*(gained(f.units[u]) for u in units))
        alias = dict(task_aliases([f.units[u] for u in units], {n.label for n in task_nodes}))
        memo["task"] = (task_nodes, gains, frozenset(n.label for n in task_nodes),
                        holding_labels(f.units[u] for u in units),
                        called_fills(f.units[u] for u in units),  # FOON-GEN's `pan`: the cookware
                        _taken_once(f, units, inp.kitchen, gains), listings(task_nodes, alias), alias,
                        filled_by_task([f.units[u] for u in units], inp.kitchen))
    task_nodes, filled, labels, holding, called, once, lists, alias, task_filled = memo["task"]
    home = inp.kitchen | narrow if narrow else inp.kitchen  # the kitchen the counts are derived in

    def quiet(speakers: Sequence[int]) -> frozenset[str]:
        key = ("silent", tuple(speakers))
        if key not in memo:
            memo[key] = quiet_places(task_nodes, [f.units[u] for u in units], [f.units[u] for u in speakers])
        return memo[key]

    def plan_of(u: int, silent: frozenset[str], sole: frozenset[ObjectNode], split: frozenset[int],
                fills: frozenset[tuple[ObjectNode, ObjectNode]]) -> UnitPlan:
        key = ("plan", u, silent, sole, u in split, fills)  # `split` matters only by whether it holds `u`: read once
        if key not in memo:
            memo[key] = plan_unit(f.units[u], inp.kitchen, silent, filled, labels, holding, called, sole,
                                  None if u in split else lists, alias, fills)
        return memo[key]

    def plans_of(silent: frozenset[str], sole: frozenset[ObjectNode], split: frozenset[int],
                 fills: frozenset[tuple[ObjectNode, ObjectNode]]) -> tuple:  # made once
        key = ("plans", silent, sole, split, fills)
        if key not in memo:
            plans, drops = kept_in_place(f, units, {u: plan_of(u, silent, sole, split, fills) for u in units})
            if "fired" not in memo:  # FOON's own plan as counted, in firing order: the taker it fires first is named
                found = delete_free_plan(inp.foon, inp.kitchen, inp.candidates, together=True)
                memo["fired"] = found[0] if found is not None else ()
            plans, portions = taken_again(f, units, plans, memo["fired"])
            plans, said = _short_of_goal(plans, {c: f.units[u] for u in units for c in f.units[u].outputs
                                                 if c in inp.candidates})
            memo[key] = plans, drops, said, portions, {f.units[u]: p for u, p in plans.items()}
        return memo[key]

    def roles_in(silent: frozenset[str], sole: frozenset[ObjectNode], split: frozenset[int],
                 fills: frozenset[tuple[ObjectNode, ObjectNode]]) -> RolesOf:
        key = ("roles", silent, sole, split, fills, home)  # counted in `home`: read once per unit
        if key not in memo:
            by_unit, roles = plans_of(silent, sole, split, fills)[4], {}
            if ("started", home) not in memo:  # where the kitchen's objects still are: once per counting kitchen
                memo["started", home] = placed_since_start([f.units[u] for u in units], home, alias)
            if "taken" not in memo:  # (object, holder) node pairs the task's units take together
                memo["taken"] = taken_with((f.units[u] for u in units), alias)
            started, taken = memo["started", home], memo["taken"]

            def roles_of(unit):  # asked once per unit and plan position by the counts: read once
                if unit not in roles:
                    roles[unit] = count_roles(by_unit[unit], alias, home, started, taken) if unit in by_unit else ()
                return roles[unit]
            memo[key] = roles_of
        return memo[key]

    def count(net: Foon, need: tuple[int, ...], roles_of: RolesOf) -> InstanceCounts:  # objects for a plan in `net`
        # `net`: `inp.foon`, `st.through` or `_as_now`'s (a cache of `NOWS_KEPT`); the memo holds it, so its id
        # names no other network while the memo lives
        key = _CountsKey(id(net), need, narrow or None, placed, other_makers, refill)
        _, derived = memo.setdefault(key, (net, []))
        for asked, counts in derived:  # `_asking`: the same roles where a count read them
            if all(roles_of(unit) == roles for unit, roles in asked):
                return counts
        asked: dict[FunctionalUnit, tuple] = {}
        unfilled: list[InstanceCounts] = []  # with `refill`, the counts without it too: derived once for both
        counts = derive_counts(net, need, home, inp.candidates,
                               stated=stated, overrides=overrides, roles_of=_asking(roles_of, asked), together=True,
                               stitched=True, reuse=True, placed=placed, other_makers=other_makers, refill=refill,
                               unfilled=unfilled if refill else None)
        asked_once = tuple(asked.items())  # without `refill` the derivation asks no more (one step less)
        for fill, made in ((refill, counts), *((False, c) for c in unfilled)):
            memo.setdefault(replace(key, refill=fill), (net, []))[1].append((asked_once, made))
            if other_makers and not made.other_maker:  # the same counts without other makers' plans: FOON's own
                memo.setdefault(replace(key, other_makers=False, refill=fill), (net, []))[1].append((asked_once, made))  # plan unfolded counts them again no more
        return counts

    def counted_by(roles_of: RolesOf) -> list[tuple[Foon, InstanceCounts]]:  # FOON's own plan's, the stitched one's beside
        if narrow is not None and through:  # small, the stitched plan alone: FOON's own is out of holder reach
            return [(st.through, count(st.through, st.needed, roles_of))]
        counted = [(inp.foon, count(inp.foon, st.own, roles_of))]
        if st.origin and narrow is None:
            counted.append((st.through, count(st.through, st.needed, roles_of)))
        elif narrow is not None and (now := _as_now(inp.foon, st)) is not None:
            other = count(now, st.own, roles_of)  # small: each unit taking an object as a later unit left it, when fewer
            counted = [(now, other)] if other.total < counted[0][1].total else counted
        return counted

    def read(speakers: Sequence[int], sole: frozenset[ObjectNode],
             fills: frozenset[tuple[ObjectNode, ObjectNode]] | None = None, fixed: bool = False) -> Reading:
        silent, split, opened, fills = quiet(speakers), frozenset(), fills is not None, fills or frozenset()
        while True:  # three fixpoints at once: a kitchen container a unit the plan fires again takes, or another
            # takes from, leaves the rest where it stays (`sole` shrinks); a made object a unit fired again takes whole
            # from a holder no node lists it in is a portion (`split` grows); a container a unit of the task fills
            # is emptied whole only while the plan as counted fires that unit and starts no kitchen object in its node
            # (`fills` shrinks, `_moved_whole`; not when `fixed`: the wide count's pairs)
            plans, drops, said, portions, _ = plans_of(silent, sole, split, fills)
            roles_of = roles_in(silent, sole, split, fills)
            counted = counted_by(roles_of)
            again, stocked = _rest_stays(sole, counted), frozenset() if fixed else fills - _moved_whole(fills, counted)
            fired = _fired_again(counted)  # a made object it takes whole from a holder no node lists it in: a portion
            more = frozenset(u for u in units if u not in split and f.units[u] in fired
                             and plan_of(u, silent, sole, split, fills) != plan_of(u, silent, sole, split | {u}, fills))
            if not again and not more and not stocked:
                if opened:
                    break
                # read first with no pair moved whole, then only the pairs the plan so counted fills: GEN trial 10
                # goal 57 has 626 pairs, 30 of them filled by its plan; all of them whole at first, then shrinking,
                # derived 49 counts for its 6 compiles where 30 were derived before (each whole pair changes the
                # roles of many units); so 32
                opened, fills = True, _moved_whole(task_filled, counted)
                continue  # read with them: where they change no unit's roles, the counts are memo hits (`_asking`)
            sole, split, fills = sole - again, split | more, fills - stocked  # at most |sole| + |units| + |fills| rounds
        counts = counted[0][1].widest(counted[1][1]) if len(counted) > 1 else counted[0][1]
        if narrow is not None and through:  # counted in `st.through`: its plan named by the task's unit indexes
            counts = counts.renumbered(st.in_task)
        explained = counts if narrow is not None and through else (  # the plan through the stitches says why
            replace(counts, firings=counted[1][1].renumbered(st.in_task).firings)  # FOON's own plan none
            if len(counted) > 1 and not counts.firings and counted[1][1].firings else None)
        have = counts.labels() if not scene else {**dict.fromkeys((o.label for o in scene), 1), **dict(counts.unmade)}
        kept = tuple(u for u in units if all(s.rel.role.label in have for s in plans[u].slots))
        acting = {f.units[u] for u in kept}
        return Reading(kept, silent, plans, tuple(d for d in drops if d[3] in acting), roles_of, counts, have, filled,
                       tuple(said[u] for u in kept if u in said), tuple(portions[u] for u in kept if u in portions),
                       sole, explained, fills)

    standard = narrow is None and not placed and other_makers and refill  # the wide count every other one follows
    if not standard and "fills" not in memo:  # the pairs the wide count's plan fills: read once per memo, whichever
        read_units(inp, st, scene, stated, overrides, memo=memo)  # count is asked first (the same pairs each time)
    first = read(units, once, None if standard else memo["fills"], not standard)
    if quiet(first.units) != first.silent:
        first = read(first.units, first.sole, first.task_filled, not standard)
    if standard:
        memo["fills"] = first.task_filled
    return first
