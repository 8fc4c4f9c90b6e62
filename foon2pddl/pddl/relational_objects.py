"""The `relational` task's objects: counted from its units' reading, or the scene's, with the kitchen completed
(`relational_init`); counted small first when asked (`task_objects`).

Counted wide (`compile`'s): for FOON's plan unfolded, and for the plan through the stitched units beside it
(`relational_reading.read_units`). That plan makes every node FOON's semantics needs, also one the completed
kitchen holds: the brownie's cut (`ACT-0010-choco_brownie.txt:384`) takes the kitchen's `brownie (baked, on
[cutting board])` with `cutting board (contains {brownie})`, a node only the whole recipe makes, while the init
puts the kitchen's brownie on a board of its own, in that node: 56 objects for a plan that is the cut. Counted
small (`narrow`, what `planners.solve.plan` tries first): from FOON's own plan alone (no stitched plan beside
it; a unit taking a made node as it was before a later unit moved the object on takes it as that unit left it, when
that counts fewer, `relational_reading._as_now`), in the kitchen with the network's nodes the objects the completion adds start in (the holders its nodes imply,
and what kitchen containers list: the kofta's pour takes the water of the kitchen's cup below the faucet, not
another cup filled again): the cut, 4 objects. Those nodes are read from the wide count, and also from the wide
count without a container a unit fills in a kitchen node taken again (`count_reuse._refilled_with`) when that lowered it:
the kitchen bowl of flour it stands for goes, and with it `flour (in [bowl], powder)`, where the small count takes
the flour from the kitchen (the blueberry muffin on the universal FOON of 70 subgraphs drawn with seed 56: 41
objects in the problem, 44 when read from the wide count alone); the small count of fewer objects is kept. A node
of those that a unit the small plan fires makes anyway gets no kitchen object when the count without it has fewer
objects and fires the same units (`_made_anyway`: the `same` set's 0050 omelette, 21 -> 20 objects in the problem;
without the second condition its cheesy garlic bread, whose count then fired another recipe's chain twice, 44 ->
47). Kept
when it has fewer objects, with a note that says so (`Compiled.narrowed`). Every count takes the plans with a needed
node made by another of its makers too, when they count fewer (`instance_counts.derive_counts`' `other_makers`), but
counted wide with `own`: FOON's own plan unfolded, what `plan` falls back on last when the wide task took such a plan
and has no valid plan (the experiment's REG trial 6 macaroni in the pot: 9 objects with the linguine's pour of water,
unsolvable, 14 for FOON's own plan, solved). It may have no plan where the wide
task has one (0050's own plan takes the finished omelette from the kitchen, out of holder reach: the plan needs the bacon
the stitched one sprinkles). Counted small `through` the stitches: from the plan through them alone (no FOON plan
beside it; 0050's, with the bacon, 24 objects where wide counts 25): what `plan` tries next when the task of FOON's
own plan is out of holder reach, then (`placed`) counted as wide with makers chosen by holder reach
(`count_together._placed_back`: the even universal half's kofta mix, 14 objects where wide counts 19), then the wide
task; last, when that is out of holder reach too, counted wide with makers by holder reach (`placed` without
`narrow`: FOON's plan with those makers and the stitched plan beside it, whatever the count). A small count of no
objects is none (FOON's own plan is none from this kitchen: no plan was counted): with stitches, the count from the
plan through them alone is the small count (the universal ramen in its base kitchen: 65 objects, where wide counts 73),
else the wide task is the one. A scene's objects are the scene's: never counted small.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace

from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.places import places
from ..model.scene import SceneObject
from ..model.words import count
from .encoding import LevelInputs
from .holder_words import task_aliases
from .input_stitch import Stitched
from .instance_names import scene_instances
from .names import NameTable
from .prune import feeding_units
from .relational_init import completed_kitchen
from .relational_reading import Reading, read_units
from .task import Instance

__all__ = ["TaskObjects", "task_objects"]


@dataclass(frozen=True)
class TaskObjects:
    """A relational task's objects (`task_objects`): the units' `reading` (its counts), the names `table`, the
    `instances`, the task's aliases (`alias`), the labels a node places something in or on (`placed`), the
    network's nodes the kitchen implies objects start in (`implied`: the completion's holders, the nodes counted
    small from), the task's `nodes`, the `kitchen` the counts are derived in, the note when counted small, and
    the notes on the kitchen's reading in `:init` (`init_notes`: where the completion's holders start,
    `relational_init.started_notes`, and kitchen nodes read as placed in a kitchen container); counted small, the
    units the wide count reads that this one does not (`beside`): the small task starts where they lead, so the pairs
    FOON contradicts itself about in them (`holder_gaps.list_gaps`) are its own too (0086's pie starts with the filling
    the fold at `0086-apple_turnover.txt:418` puts in it, which the dish's list drops)."""

    reading: Reading
    table: NameTable
    instances: tuple[Instance, ...]
    alias: Mapping[str, str]
    placed: frozenset[str]
    implied: frozenset[ObjectNode]
    nodes: frozenset[ObjectNode]
    kitchen: frozenset[ObjectNode]
    narrowed: str = ""
    init_notes: tuple[tuple[FunctionalUnit, str], ...] = ()  # (unit, note) on the kitchen's reading in :init
    beside: tuple[int, ...] = ()


def task_objects(inp: LevelInputs, st: Stitched, scene: Sequence[SceneObject], stated: Mapping[ObjectNode, int],
                 overrides: Mapping[str, int], reserved: Iterable[str], narrow: bool = False,
                 through: bool = False, placed: bool = False, memo: dict | None = None,
                 own: bool = False) -> TaskObjects:
    """The objects of the task of `st`'s units (module doc): `scene` the kitchen's scene objects (none: counted),
    `stated` and `overrides` the counts the kitchen and options give, `reserved` the names the encoding keeps;
    `narrow`: counted small when that gives fewer objects, `through` the stitches (a task with none: counted wide),
    `placed`: counted as wide, with makers by holder reach (`count_together._placed_back`), kept when fewer;
    without `narrow`, the wide count with those makers; `own` (without `narrow`): counted wide from FOON's own plan
    unfolded, no other makers' plans (module doc).
    Counting small reuses the readings counting wide made (`read_units`' memo: units are read again only with other
    holders silent) and derives its own counts; `memo`, when given, is that memo shared with the other countings of
    the same `inp`, `st`, `stated` and `overrides` (`encode_relational`'s, across `planners.solve.plan`'s counts: the
    wide count, which each of them starts from, is derived once). Counted small, the kitchen is read from the wide
    count, and from it without a filled container taken again when that lowered it (module doc): at most two small
    counts, the one of fewer objects kept. Each count is made once per `memo` (the same object each time it is asked
    for: `encode_relational` encodes it once, by its id, while the memo lives), so a narrow count that is the one
    through the stitches is that count (reread60's F12)."""
    memo = {} if memo is None else memo  # the units' readings and counts the countings share (`read_units`)
    key = ("task objects", narrow, through, placed, own)
    if key not in memo:
        memo[key] = _task_objects(inp, st, scene, stated, overrides, tuple(reserved), narrow, through, placed, memo, own)
    return memo[key]


def _task_objects(inp: LevelInputs, st: Stitched, scene: Sequence[SceneObject], stated: Mapping[ObjectNode, int],
                  overrides: Mapping[str, int], reserved: tuple[str, ...], narrow: bool, through: bool, placed: bool,
                  memo: dict, own: bool) -> TaskObjects:
    """`task_objects`, made: O(the counts it derives)."""
    wide = _objects(inp, st, scene, stated, overrides, reserved, None, memo, placed=placed and not narrow,
                    other_makers=not own)
    if not narrow or scene or (through and not st.origin):
        return wide
    # where the wide task's objects start, also without a filled container taken again when that lowered its
    # count (its contents' node is one the small count may take from the kitchen): the small count of fewer objects
    bases = [wide] if placed or not wide.reading.counts.refilled else [
        wide, _objects(inp, st, scene, stated, overrides, reserved, None, memo, refill=False)]
    starts = dict.fromkeys(frozenset() if placed else base.implied | {
        x.start for x in base.instances if x.start is not None and x.start not in inp.kitchen} for base in bases)
    smalls = [(_objects(inp, st, scene, stated, overrides, reserved, None if placed else started, memo,
                        through, placed), started) for started in starts]
    small, started = min(smalls, key=lambda s: len(s[0].instances))  # the first of equals
    if not placed and (made := _made_anyway(st, small, started)):  # the plan makes them: no kitchen objects for them
        fewer = _objects(inp, st, scene, stated, overrides, reserved, started - made, memo, through)
        if len(fewer.instances) < len(small.instances) and _same_plan(fewer, small):
            small, started = fewer, started - made
    if not small.instances and not through and not placed and st.origin:  # FOON's own plan is none: its small count
        return task_objects(inp, st, scene, stated, overrides, reserved, True, True, False, memo)  # the stitches'
    if not small.instances or len(small.instances) >= len(wide.instances):  # no objects: no count (no plan counted)
        return wide
    more = ", ".join(n.describe() for n in sorted(started))
    beside = tuple(u for u in wide.reading.units if u not in small.reading.units)
    source = "the plan through the stitches alone" if through else "FOON's own plan alone"
    how = "counted with makers chosen by holder reach" if placed else f"counted small, from {source}"
    return replace(small, init_notes=tuple(dict.fromkeys(wide.init_notes + small.init_notes)), beside=beside, narrowed=(
        how + (f" in the kitchen with {more}, where the objects its nodes imply start" if more else "")
        + f": {count(len(small.instances), 'object')}, where FOON's plan unfolded counts {len(wide.instances)}"))


def _made_anyway(st: Stitched, small: TaskObjects, started: frozenset[ObjectNode]) -> frozenset[ObjectNode]:
    """The nodes of `started` the small count starts objects in that a unit its plan fires makes too: beside the
    plain omelette, whose kitchen pan `cooking pan (empty, on [stove])` (`0063-plain_omelette_mahalo.txt:94`) starts
    on a stove in `stove (on, with [pan])`, the 0050 omelette's cooks take that node from the kitchen, and the
    pick-and-place at `0050-scrambled_eggs_with_bacon-cheese.txt:123`, fired for the pans, makes it. Left out only
    when the count then fires the same units (`_same_plan`): a node the plan makes only by firing more is no node it
    makes anyway. O(firings x outputs)."""
    counts = small.reading.counts
    made = {o for u, _ in counts.firings for o in st.foon.units[u].outputs}
    return frozenset(n for n, k in counts.at_node if k > 0 and n in started and n in made)


def _same_plan(a: TaskObjects, b: TaskObjects) -> bool:
    """Whether two counts fire the same units as often (their plans differ only in where objects start)."""
    return sorted(a.reading.counts.firings) == sorted(b.reading.counts.firings)


def _objects(inp: LevelInputs, st: Stitched, scene: Sequence[SceneObject], stated: Mapping[ObjectNode, int],
             overrides: Mapping[str, int], reserved: tuple[str, ...], more: frozenset[ObjectNode] | None,
             memo: dict, through: bool = False, placed: bool = False, other_makers: bool = True,
             refill: bool = True) -> TaskObjects:
    """The objects counted from the reading of the units (`read_units`, small with `more`, `through` the stitches,
    with makers by holder reach when `placed`, with other makers' plans when `other_makers`, a filled container taken
    again when `refill`, sharing `memo`), or the scene's. Counted wide (no `more`), one object per reading in
    `memo`: a reading is its units' readings (`read_units`' memo, by silent holders, `sole` and the units read as
    taking a portion, which its `roles_of` names: one per such reading while the memo holds it) and its counts, so
    counts equal to ones read before (FOON's own plan unfolded that took no other maker's plan, makers by holder
    reach that chose the first makers) give the objects made then, which `encode_relational` encodes once."""
    rd = read_units(inp, st, scene, stated, overrides, more, memo, through, placed, other_makers, refill)
    key = ("objects", rd.silent, rd.sole, id(rd.roles_of), rd.counts) if more is None else None
    if key is not None and key in memo:
        return memo[key]
    f, units, plans, counts = st.foon, rd.units, rd.plans, rd.counts
    table = NameTable()
    for name in reserved:
        table.reserve(name)
    nodes = set(inp.candidates) | {n for n, _ in counts.at_node}
    for u in units:
        p = plans[u]
        nodes.update(x for s in p.slots for x in (s.rel.role.before, s.after, s.portion) if x is not None)
        nodes.update(n for _, n in p.emptied)
    held_by: frozenset[ObjectNode] = frozenset()  # network nodes the holders the kitchen implies start in
    init_notes: tuple = ()
    if scene:  # the scene is the init: its objects, where they are, and the objects units make
        instances = scene_instances(table, scene, counts.unmade)
        alias = dict(task_aliases([f.units[u] for u in units], rd.have, [x.start for x in instances]))
        placed = frozenset(alias.get(c, c) for n in nodes for _, c in places(n))
    else:
        aliases = {u: dict(unit_aliases(f.units[u])) for u in units}  # once per unit, not per place
        # a place only a unit feeding nothing names gets no holder (that unit's action then binds none)
        feeding = feeding_units(f, units, inp.candidates) | {u for u, _ in counts.firings}
        named = {aliases[u].get(c, c) for u in units if u in feeding
                 for s in plans[u].slots for n in (s.after, s.portion) for _, c in places(n)}
        instances, alias, placed, held_by, init_notes = completed_kitchen(
            table, counts, [f.units[u] for u in units], rd.have, nodes, named, rd.silent, rd.filled, inp.kitchen,
            [f.units[u] for u, _ in counts.firings])
    out = TaskObjects(rd, table, tuple(instances), alias, placed, held_by | (more or frozenset()), frozenset(nodes),
                      inp.kitchen | (more or frozenset()), init_notes=init_notes)
    if key is not None:
        memo[key] = out
    return out
