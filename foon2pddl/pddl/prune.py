"""Relevance pruning: compile only what can help reach the goal.

Two analyses, one per semantics, both solvability-preserving:

* `relevant_units` (FOON semantics, used by `tree` and `foon-compat`): the units
  that fire in the kitchen's fixpoint (forward) *and* make, without consuming
  it, a node needed for a goal candidate (backward: candidates, then the inputs
  of every kept unit that fires, stopping at kitchen nodes; tighter than
  `analysis.reachability.relevant_units`, which does not know what fires). Any sequence of units that
  reaches a candidate has a sub-sequence made of such units only, and removing
  units never makes an unsolvable goal solvable, so the goal's solvability is
  unchanged.
* `prune_task` (STRIPS semantics, used by `state`, whose atoms combine across
  nodes so FOON reachability does not bound it): the ground actions reachable
  in the delete relaxation from the initial state and relevant backwards from
  the goal atoms over achievers (adders that do not require what they add). Sound for STRIPS with
  positive preconditions;
  init atoms, predicates and constants no kept part mentions are dropped too.

And one for lifted tasks, exact whatever the semantics: `drop_unbindable` drops the actions whose static
preconditions no binding of their parameters satisfies (the `instances` encoding's lanes leave most
unit schemas of a large goal so), which Fast Downward's translator would ground to nothing anyway.

`feeding_units` prunes nothing: the units of a task that make a target or a node such a unit takes, by FOON's
nodes; the `relational` count adds no holder only the others name (`relational_objects`).

`counted_only` does not preserve solvability: the task's actions of the units a plan fires (the `relational`
plan the objects are counted from), which `planners.solve.plan` tries before the whole task.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable
from dataclasses import replace
from itertools import chain

from ..analysis.fixpoint import fire
from ..analysis.reachability import UNREACHED, reachable
from ..model.foon import Foon, ObjectNode
from ..model.memo import per_network
from ..model.pairing import unit_roles
from .task import Atom, PlanningTask


def relevant_units(foon: Foon, kitchen: Iterable[ObjectNode], targets: Iterable[ObjectNode]) -> tuple[int, ...]:
    """Sorted indexes of the units of `foon` that can contribute to making any of `targets` from `kitchen`."""
    targets = tuple(targets)
    reach = reachable(foon, kitchen, targets)  # the fixpoint over the units that can contribute to targets
    ix, node_round, unit_round = reach.index, reach.node_round, reach.unit_round
    keep: set[int] = set()
    seen: set[int] = set()
    stack = [i for i in ix.ids(targets) if node_round[i] != 0]
    while stack:
        n = stack.pop()
        if n in seen:
            continue
        seen.add(n)
        for u in ix.makers[n]:
            if unit_round[u] != UNREACHED and u not in keep:
                keep.add(u)
                stack.extend(i for i in ix.inputs[u] if node_round[i] != 0 and i not in seen)
    return tuple(sorted(keep))


def feeding_units(foon: Foon, units: Iterable[int], targets: Iterable[ObjectNode]) -> frozenset[int]:
    """The `units` of `foon` that feed a target: each makes one of `targets`, or a node a unit so kept takes, to a
    fixpoint (backward from the targets over the makers among `units`). A unit outside it makes only nodes no unit
    of `units` takes and no target: the pizza's pick-and-place of an empty bowl onto a surface
    (`0085-mini_bacon_egg_breakfast_pizza.txt:104`) in a task whose units take no bowl on a surface. O(units x
    nodes per unit); order does not matter."""
    units = tuple(units)
    makers: dict[ObjectNode, list[int]] = {}
    for u in units:
        for n in foon.units[u].outputs:
            makers.setdefault(n, []).append(u)
    keep: set[int] = set()
    wanted = set(targets)
    while wanted:  # each round keeps new units only: at most |units| rounds
        new = {u for x in wanted for u in makers.get(x, ()) if u not in keep}
        keep |= new
        wanted = {x for u in new for x in foon.units[u].inputs}
    return frozenset(keep)


@per_network
def _changed_ids(foon: Foon) -> dict[int, tuple[int, ...]]:
    """Unit index -> the ids (`analysis.index.index_of(foon)`) of the nodes it moves an object out of, filled as
    `restoring_units` meets units. Sound: a unit's roles and the network's node ids are fixed for a network object,
    which this is kept per; a trial's goals meet most of one network's units again (FOON-GEN: 530-880 a goal)."""
    return {}


def restoring_units(foon: Foon, kitchen: Iterable[ObjectNode], targets: Iterable[ObjectNode]) -> tuple[int, ...]:
    """Units that can help make `targets` when a kitchen state can be used up, sorted.

    With object instances, a unit that moves an object out of a kitchen state (a clean
    knife gets dirty, a mixer turned on is no longer off) uses that state up, and a unit
    that restores it (washing, turning off) can help although FOON's semantics never
    needs one. Backward from the targets over the makers that fire in the kitchen's
    fixpoint, like `relevant_units`, but a kitchen node is expanded too once some kept
    unit moves an object out of it (`pairing.unit_roles`). Sound: every unit of a plan
    fires in the fixpoint and makes something a kept unit needs or uses up.
    """
    kitchen = frozenset(kitchen)
    reach = reachable(foon, kitchen)
    ix = reach.index
    changed = _changed_ids(foon)
    keep: set[int] = set()
    used_up: set[int] = set()
    parked: set[int] = set()  # kitchen nodes met but not (yet) used up
    seen: set[int] = set()
    stack = list(ix.ids(targets))
    while stack:
        n = stack.pop()
        if n in seen:
            continue
        seen.add(n)
        if reach.node_round[n] == 0 and n not in used_up:
            parked.add(n)
            continue
        for u in ix.makers[n]:
            if reach.unit_round[u] == UNREACHED or u in keep:
                continue
            keep.add(u)
            stack.extend(ix.inputs[u])
            if u not in changed:
                changed[u] = tuple(ix.node_id[r.before] for r in unit_roles(foon.units[u])
                                   if r.changes and r.before is not None)
            for k in changed[u]:
                if reach.node_round[k] == 0 and k not in used_up:
                    used_up.add(k)
                    if k in parked:
                        parked.discard(k)
                        seen.discard(k)
                        stack.append(k)
    return tuple(sorted(keep))


def prune_task(task: PlanningTask) -> PlanningTask:
    """The task restricted to relevant, relaxed-reachable ground actions (lifted tasks are returned as is)."""
    if any(a.params for a in task.actions):
        return task
    actions = task.actions
    # Forward: delete-relaxed reachability, the counter fixpoint (`fixpoint.fire`) over dense atom ids
    # (an atom is hashed once per occurrence; the fixpoint then indexes lists).
    ids: dict[Atom, int] = {}
    number = ids.setdefault
    init = {number(a, len(ids)) for a in task.init}
    pres = [{number(p, len(ids)) for p in a.pre} for a in actions]
    adds = [[number(x, len(ids)) for x in a.add] for a in actions]
    consumers: list[list[int]] = [[] for _ in range(len(ids))]
    missing: list[int] = []
    for i, pre in enumerate(pres):
        left = 0
        for p in pre:
            if p not in init:
                consumers[p].append(i)
                left += 1
        missing.append(left)
    ready = [i for i, m in enumerate(missing) if not m]
    node_round = [UNREACHED] * len(ids)
    for i in init:
        node_round[i] = 0
    rounds = fire(ready, missing, adds, consumers, node_round, [-1] * len(ids))
    applicable = set(chain.from_iterable(rounds))
    # Backward: atoms needed for the goal, over the applicable actions that make them true. An action that
    # requires the atom it adds (the `state` and `ocp` encodings re-add what a unit leaves as it was) never
    # makes it true, so it is not one of its achievers: every action of a plan with no useless step adds an
    # atom that was false before it.
    adders: dict[Atom, list[int]] = {}
    for i in applicable:
        pre = actions[i].pre
        for atom in actions[i].add:
            if atom not in pre:
                adders.setdefault(atom, []).append(i)
    needed: set[Atom] = set()
    keep: set[int] = set()
    stack = list(task.goal)
    while stack:
        atom = stack.pop()
        if atom in needed:
            continue
        needed.add(atom)
        for i in adders.get(atom, ()):
            if i not in keep:
                keep.add(i)
                stack.extend(p for p in actions[i].pre if p not in needed)
    kept = tuple(a for i, a in enumerate(actions) if i in keep)
    init = tuple(a for a in task.init if a in needed)
    used_atoms = [*init, *task.goal, *(x for a in kept for x in (*a.pre, *a.add, *a.delete)),
                  *(x for a in kept for c in a.conditional for x in c.atoms())]
    used_preds = {a.predicate for a in used_atoms}
    used_args = {arg for a in used_atoms for arg in a.args}
    return replace(
        task,
        actions=kept,
        init=init,
        predicates=tuple(p for p in task.predicates if p.name in used_preds),
        constants=tuple(c for c in task.constants if c[0] in used_args),
        objects=tuple(o for o in task.objects if o[0] in used_args),
    )


def static_facts(task: PlanningTask) -> dict[str, list[tuple[str, ...]]]:
    """The arguments of each init atom whose predicate no action changes (adds or deletes, conditionally or
    not), by predicate, in init's order: facts true in every state a plan reaches. O(actions' effects + init)."""
    changing = changed_predicates(task)
    static: dict[str, list[tuple[str, ...]]] = {}
    for a in task.init:
        if a.predicate not in changing:
            static.setdefault(a.predicate, []).append(a.args)
    return static


def changed_predicates(task: PlanningTask) -> set[str]:
    """The predicates some action adds or deletes, conditionally or not."""
    return {x.predicate for a in task.actions
            for x in (*a.add, *a.delete, *(y for c in a.conditional for y in (*c.add, *c.delete)))}


def drop_unbindable(task: PlanningTask) -> PlanningTask:
    """The task without the actions that have no ground instance: some static precondition (of a predicate
    no action adds or deletes, so true exactly in `init`) that no binding of the parameters can satisfy.

    The check is generalized arc consistency over the static preconditions: each parameter's candidate
    values are narrowed to those some matching init atom supports, until nothing changes; an action goes
    when an atom has no matching init atom left. A binding that satisfies every static precondition survives
    the narrowing, so a dropped action has no ground instance a planner could apply in any state: plans,
    and what a translator grounds, are unchanged (fluent preconditions and types are not read; the check
    is partial there and never drops wrongly). Returns `task` itself when nothing is dropped.
    O(narrowing rounds x static atoms x matching init atoms) per action; matches are looked up by an
    atom's constant arguments.
    """
    changing = changed_predicates(task)
    static = static_facts(task)
    memo: dict[tuple, list[tuple[str, ...]]] = {}

    def matching(atom: Atom) -> list[tuple[str, ...]]:
        """Init atoms of `atom`'s predicate and arity equal to it in its constant arguments."""
        fixed = tuple((i, x) for i, x in enumerate(atom.args) if not x.startswith("?"))
        key = (atom.predicate, len(atom.args), fixed)
        if key not in memo:
            memo[key] = [f for f in static.get(atom.predicate, ()) if len(f) == len(atom.args)
                         and all(f[i] == x for i, x in fixed)]
        return memo[key]

    def bindable(pre: list[Atom]) -> bool:
        atoms = [(matching(p), [(i, x) for i, x in enumerate(p.args) if x.startswith("?")]) for p in pre]
        if any(not facts for facts, _ in atoms):
            return False
        domain: dict[str, set[str]] = {}
        todo = [k for k, (_, at) in enumerate(atoms) if at]  # AC-3: the atoms whose variables narrowed
        users: dict[str, list[int]] = {}
        for k in todo:
            for _, x in atoms[k][1]:
                users.setdefault(x, []).append(k)
        while todo:
            facts, at = atoms[todo.pop()]
            live = [(i, domain[x]) for i, x in at if x in domain]
            fits = [r for r in facts if all(r[i] in d for i, d in live)] if live else facts
            if len(at) > 1 and len({x for _, x in at}) < len(at):
                fits = [r for r in fits if _same_var_same_value(at, r)]
            if not fits:
                return False
            for i, x in at:
                values = {r[i] for r in fits}
                if x not in domain or len(values) < len(domain[x]):  # `fits` kept only values in domain[x]
                    domain[x] = values
                    todo.extend(k for k in users[x] if k not in todo)
        return True

    kept = tuple(a for a in task.actions
                 if bindable([p for p in a.pre if p.predicate not in changing]))
    return task if len(kept) == len(task.actions) else replace(task, actions=kept)


def _same_var_same_value(at: list[tuple[int, str]], row: tuple[str, ...]) -> bool:
    """Whether `row` gives a variable that occurs twice in an atom (its `(position, variable)`s) one value."""
    seen: dict[str, str] = {}
    return all(seen.setdefault(x, row[i]) == row[i] for i, x in at)


def counted_only(task: PlanningTask, units: Collection[int]) -> PlanningTask | None:
    """`task` with only the actions of `units` (and those of no unit: the goal's), or None when that leaves out
    none of its actions (or `units` is empty: not known). Every plan of it is a plan of `task`, not the other way
    round: the task may need a unit the counted plan does not fire (one that restores what it reads twice)."""
    kept = tuple(a for a in task.actions if a.unit is None or a.unit in units)
    return replace(task, actions=kept) if units and len(kept) < len(task.actions) else None
