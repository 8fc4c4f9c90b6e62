"""The `relational` encoding: physical objects as in `instances`, plus which object holds which.

* **Objects and states** as in `encode_instances`: one PDDL object per physical
  object, `(is ?x ?s)` for its FOON node (`not-yet-made` before it exists,
  `consumed` after it became part of a mixture), `(occupied s)` for stable nodes
  (and, kept by a tally, for a role that only checks a node others leave: `tallies`),
  `(precedes ?a ?b)` to bind two roles of one state to two objects. Counts are
  derived as for `instances`, from the roles this encoding gives each unit
  (`relational_plan.count_roles`: a portion poured off is a new object); counted
  small with `EncodeOptions.narrow` (`relational_objects`: what `plan` tries first).
* **Relations** as facts between objects, holder first (the public converter's
  order): `(in ?holder ?obj)`, `(on ?surface ?obj)`. A container's contents are
  the objects in it; every action that puts an object somewhere removes it from
  where it was, so an object is in or on at most one holder.
* **Actions.** One schema per unit, from the unit's reading in the task (`relational_reading.read_units`:
  `relational_plan.plan_unit`, `holders.relational_roles`), written by `relational_action.unit_action` (its doc
  says, per role, what it requires, moves, splits, empties and consumes).
* **Init.** Kitchen objects start in the state of their node; an object whose node
  names a place starts in an object of that label whose node lists it (else one
  silent about its contents); when there is none, a holder of that label is added,
  listing what starts in it (`heavy cream (in [carton])` and no carton in any unit,
  or `egg (in [bowl])` while every bowl of the kitchen is `bowl (empty)`), and a
  kitchen container that lists an item holds one object of it.
* **Stitches** (`input_stitch`): an input no unit makes, read as the node the plan left it in; two nodes of a unit
  that list each other, read as one on the other (`mutual_lists`); a list's item no object of the unit is, taken
  there on the container's path in a node no unit makes, read as arriving with the unit (`list_arrivals`); a node
  a unit takes and leaves listing what it puts in, read before it as the node without that (`list_brought`); a
  container's node and what is in it, taken together and made together by no unit, as at hand (`kitchen_pairs`); a
  product naming no place, read in the one container the unit leaves listing it (`list_placed`).
* **Reports.** Label readings and contradictions (`holder_words.mismatches`, `holder_gaps.list_gaps`), stitches, and
  every object the unit puts where its node does not say what the holder holds (a target the unit does not
  name: `sandwich (on [plate])` with no plate in the unit), once per task with the unit's file:line; the last
  two are the (container, content) pairs the replay does not check.

Requirements: `:strips :typing`, `:conditional-effects` when an action has a
quantified or conditional effect, `:action-costs` with costs.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace

from ..model.aliases import unit_aliases
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.physical import Relation
from ..model.places import describes_contents, place_of, places
from . import relational_touched
from .count_reasons import count_reasons
from .encode_instances import (
    GOAL_OBJECT,
    IS,
    NOT_MADE,
    OCCUPIED,
    PRECEDES,
    ROOT_TYPE,
    STATE_TYPE,
    count_lines,
    goal_actions_over_objects,
    object_types,
    precedes_facts,
)
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, LevelInputs, at_level, header
from .holder_gaps import attached_gaps, list_gaps
from .holder_words import mismatches, reported
from .holders import Fate, on_parts
from .input_stitch import Stitched, with_stitches
from .kitchen_pairs import Pair, read_pairs
from .list_arrivals import read_arrivals
from .list_brought import read_brought
from .list_placed import read_placed
from .live_holders import LIVE, with_live
from .mutual_lists import mutual_notes, read_mutual
from .prune import restoring_units
from .registry import Compiled
from .relational_action import IN, ON, unit_action
from .relational_init import kitchen_implied
from .relational_objects import task_objects
from .relational_stitch import Stitches, stitch_notes, stitched
from .relational_sweep import CONSUMED
from .tallies import tallied
from .task import Atom, PlanningTask, Predicate
from .untouched import set_aside

__all__ = ["CONSUMED", "encode_relational"]

#: The note kinds of a relation FOON states that the encoding does not hold (`holder_gaps.attached_gaps`) and of a
#: pair of nodes no unit makes together, read as the kitchen's (`kitchen_pairs`).
UNHELD, AT_HAND = "relation not modelled", "assumed at hand"


def encode_relational(foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3,
                      options: EncodeOptions = DEFAULT_OPTIONS) -> Compiled:
    """The relational task of `goal` over `foon` (see the module doc), with its reports as notes. With
    `options.memo`, the network's reading (`_read`) and the counts are made once per network, kitchen, goal (the
    same objects), level, pruning and stated counts, however many counts the caller asks for."""
    shared = {} if options.memo is None else options.memo
    key = ("relational", id(foon), id(kitchen), id(goal), level, options.prune, options.instances)
    if key not in shared:  # the inputs are kept with it: while the memo lives, their ids name no other object
        shared[key] = (foon, kitchen, goal), _read(foon, kitchen, goal, level, options.prune), {}
    _, net, counting = shared[key]
    inp, given, st, at_hand, reads = net.inp, net.given, net.st, net.at_hand, net.reads
    mutual, arrived, brought, placed_at = net.mutual, net.arrived, net.brought, net.placed
    f, units, origin, sewn = st.foon, st.units, st.origin, st.found
    scene = kitchen.project(level).scene
    ob = task_objects(inp, st, scene, kitchen.project(level).stated_counts(), dict(options.instances), (
        IS, IN, ON, OCCUPIED, NOT_MADE, CONSUMED, PRECEDES, GOAL_REACHED, GOAL_OBJECT, STATE_TYPE, ROOT_TYPE, LIVE),
        options.narrow, options.through, options.placed, counting, options.own)
    # the objects are one per count (`relational_objects.task_objects`, kept in `counting`): a count equal to one
    # encoded before is that task (FOON's own plan unfolded or makers by holder reach counting as the wide count, the
    # narrow count that is the one through the stitches: `plan` compiles it once)
    done = ("encoded", id(ob), options.costs, id(options.rates), options.categories)
    if done in counting:
        return counting[done][1]
    rd, table, instances, alias, placed, nodes = ob.reading, ob.table, list(ob.instances), ob.alias, ob.placed, set(ob.nodes)
    units, plans, drops, counts = rd.units, rd.plans, rd.drops, rd.counts
    reasons = count_reasons(f, rd.explained or counts, ob.kitchen, rd.roles_of, through=rd.explained is not None,
                            given=kitchen.project(level), instances=dict(options.instances))
    why = tuple(f"objects: {w}" for w in (*reasons, *((ob.narrowed,) if ob.narrowed else ())))
    # labels of objects held where their node names no place (a scene's onion in the fridge): moving one
    # leaves whatever holds it
    loose = frozenset(x.label for x in instances if x.holder is not None and place_of(x.start) is None)
    nodes.update(x.start for x in instances if x.start is not None)
    readings = frozenset(pair for u in units for pair in unit_aliases(f.units[u]))
    ways = {u: relational_touched.flow_ways(plans[u], nodes, alias, readings) for u in units}
    nodes.update(n for w in ways.values() for lst in w.values() for _, _, n in lst if n is not None)
    empties = relational_touched.every_late_empty({u: plans[u] for u in units}, nodes, alias)
    type_of, types = object_types(table, sorted({x.label for x in instances} | {c.label for c in inp.candidates}),
                            dict(options.categories))
    const = {n: table.name(n.describe() if n.states else f"{n.label} plain", key=("node", n)) for n in sorted(nodes)}
    init = [Atom(IS, (x.name, const[x.start] if x.start is not None else NOT_MADE)) for x in instances]
    init.extend(Atom(x.relation.value, (x.holder, x.name)) for x in instances if x.holder is not None)

    inside: dict[str, list[tuple[ObjectNode, Relation]]] = {}  # label -> nodes placed in or on one
    for n in sorted(nodes):
        for rel, c in places(n)[:1]:
            inside.setdefault(alias.get(c, c), []).append((n, rel))
    for n, holder in sorted({x for u in units for x in on_parts(f.units[u])}):  # the bacon `on [bread]`: on the
        inside.setdefault(holder, []).extend((n, rel) for rel, _ in places(n)[:1])  # sandwich (`holders` rule 2)
    dust = relational_touched.dustings(plans[u] for u in units)
    left = relational_touched.left_nodes([(plans[u], ways[u], empties[u]) for u in units], inside, dust)
    stable = {n for n in const if n not in left}
    entered = {n for u in units for k, s in enumerate(plans[u].slots) if s.fate is not Fate.CONSUMED  # an action puts
               for n in (s.portion, plans[u].after_of(k)) if n not in (None, s.rel.role.before)}  # an object there
    init.extend(Atom(OCCUPIED, (const[x.start],)) for x in instances if x.start in stable)

    gaps: list[tuple[str, str, str, object]] = list(drops)  # (container, content, message, unit)
    precede: set[str] = set()
    container_labels = {n.label for n in nodes if describes_contents(n)} & placed
    actions = [replace(unit_action(u, plans[u], table, const, stable, type_of, options, precede, ways[u], gaps,
                                   container_labels, inside, empties[u], loose, dust, entered), unit=origin.get(u, u))
               for u in units]
    live = {origin[u] for u in units if u in origin}  # the stitched units the task has (objects for their labels)
    # what the kitchen implies (its objects where its holders say, the holders its objects are in): the tree
    # check's kitchen too; a candidate an object starts in beyond it is reached only by what units make
    moved = (kitchen_implied((x.start for x in instances), inp.kitchen) | ob.implied | {x.node for x in sewn if x.unit in live}
             | {n for x in at_hand for n in (x.box, x.held)} | {n for u in units for n in f.units[u].inputs if n in net.at})
    early = {c for c in inp.candidates if c not in moved and c not in inp.kitchen
             and any(x.start == c for x in instances)}
    actions.extend(goal_actions_over_objects(inp.candidates, stable, table, const, type_of, options, early))
    init.extend(Atom(GOAL_OBJECT, (x.name,)) for x in instances if any(x.label == c.label and x.start != c
                                                                      for c in early))
    init.extend(precedes_facts(precede, instances))
    hold = (("?h", ROOT_TYPE), ("?x", ROOT_TYPE))
    predicates = [Predicate(IS, (("?x", ROOT_TYPE), ("?s", STATE_TYPE)), "?x is in the state of FOON node ?s"),
                  Predicate(IN, hold, "?x is in ?h"), Predicate(ON, hold, "?x is on ?h"),
                  Predicate(OCCUPIED, (("?s", STATE_TYPE),), "some object is in state ?s, which no action leaves"),
                  Predicate(GOAL_REACHED, comment="a goal candidate was made")]
    if precede:
        predicates.append(Predicate(PRECEDES, hold, "static order of the objects of a label"))
    if early:
        predicates.append(Predicate(GOAL_OBJECT, (("?x", ROOT_TYPE),), "?x may reach the goal: no kitchen object"))
    unheld = [(f.units[u], g) for u in units for _, _, g in attached_gaps(f.units[u])]  # FOON's labels agree there
    found = [(f.units[u], m) for u in units for m in (*mismatches(f.units[u]), *(g for _, _, g in list_gaps(f.units[u])))
             if (f.units[u], m) not in unheld]
    found += [(unit, msg) for _, _, msg, unit in gaps] + stitch_notes(reads) + mutual_notes(
        mutual, {n for u in units for n in (*f.units[u].inputs, *f.units[u].outputs)})
    found += [(x.taker, x.describe()) for x in sewn if x.unit in live] + [x[u] for x in (arrived, brought, placed_at) for u in units if u in x]
    found += rd.renamed + rd.portions + ob.init_notes
    told = [(kind, reported(x)) for kind, x in (("label mismatch", found), (UNHELD, unheld),
                                                (AT_HAND, [(x.taker, x.describe()) for x in at_hand]))]
    notes, commented = ([f"{kind}: {m}" for kind, both in told for m in both[i]] for i in (0, 1))
    pairs = {(c, x) for u in (*units, *ob.beside) for c, x, _ in list_gaps(f.units[u])} | {(c, x) for c, x, _, _ in gaps}
    task = PlanningTask(
        domain="foon-relational", problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="relational", level=inp.level, predicates=tuple(predicates), actions=tuple(actions),
        init=tuple(sorted(set(init))), goal=(Atom(GOAL_REACHED),), types=tuple(types),
        constants=tuple((name, STATE_TYPE) for name in (NOT_MADE, CONSUMED, *const.values())),
        objects=tuple((x.name, type_of[x.label]) for x in instances), units=given, labels=table.labels,
        comments=header("relational", inp, options, len(units) - len(live)) + count_lines(counts) + why
        + tuple(commented),
        instances=tuple(instances), nodes=tuple(sorted((name, n) for n, name in const.items())),
        gaps=tuple(sorted(pairs)))
    task = with_live(task)  # late-bound targets exist: (live x), made to consumed
    task = set_aside(task) if options.prune else task  # untouched objects: out of the problem, not the replay
    task = tallied(task)  # a role that only checks a state other actions leave: (occupied s), kept by a tally
    out = Compiled(task, every_step=True, placed=moved, notes=tuple(notes) + why, narrowed=ob.narrowed,
                   counted=frozenset(origin.get(u, u) for u, _ in rd.counts.firings))  # the units of the plan counted from
    counting[done] = options, out  # the options kept: their rates' id names no other while the memo lives
    return out


@dataclass(frozen=True)
class _Network:
    """The network as the task reads it, before any count (`_read`; module doc, "Stitches")."""

    inp: LevelInputs  # the inputs at the task's level, read
    given: tuple[FunctionalUnit, ...]  # FOON's own units: the plan's tree is made of them
    mutual: Mapping[ObjectNode, tuple[ObjectNode, FunctionalUnit]]  # two nodes listing each other (`mutual_lists`)
    arrived: Mapping[int, tuple[FunctionalUnit, str]]  # a list's item arriving with the unit (`list_arrivals`)
    brought: Mapping[int, tuple]  # a node read before what the unit puts in (`list_brought`)
    reads: Stitches  # the stitches' readings (`relational_stitch`)
    at_hand: tuple[Pair, ...]  # the pairs read as at hand (`kitchen_pairs`)
    st: Stitched  # the network with its stitches (`input_stitch.with_stitches`)
    placed: Mapping[int, tuple]  # a product naming no place, read in the container listing it (`list_placed`)
    at: frozenset[ObjectNode]  # the nodes so read (the tree's check takes them as given)


def _read(foon: Foon, kitchen: Kitchen, goal: Goal, level: int, prune: bool) -> _Network:
    """`foon` read for the task of `goal` from `kitchen` at `level` (its relevant units: `prune`'s)."""
    inp = at_level(foon, kitchen, goal, level)
    given = inp.foon.units
    inp, placed, at = read_placed(inp)  # a product naming no place: in the one container listing it
    inp, mutual = read_mutual(inp)  # two nodes listing each other: one is on the other
    inp, arrived = read_arrivals(inp)  # a list's item no object of the unit is, taken there later: put in too
    inp, brought = read_brought(inp)  # a node a unit takes and leaves, listing what it puts in: before it, less that
    inp, reads, units = stitched(inp, lambda i: restoring_units(i.foon, i.kitchen, i.candidates) if prune
                                 else tuple(range(len(given))))
    inp, at_hand = read_pairs(inp, units)  # a container's node and what is in it that no unit makes together: the kitchen's

    def relevant(net: Foon) -> tuple[int, ...]:
        return restoring_units(net, inp.kitchen, inp.candidates) if prune else tuple(range(len(net.units)))
    st = with_stitches(inp.foon, relevant)  # inputs no unit makes, read as the node the plan left that object in
    return _Network(inp, given, mutual, arrived, brought, reads, at_hand, st, placed, at)
