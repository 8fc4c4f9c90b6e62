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
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from itertools import chain

from ..analysis.fixpoint import fire
from ..analysis.reachability import UNREACHED, reachable
from ..model.foon import Foon, ObjectNode
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
    from .pairing import unit_roles

    kitchen = frozenset(kitchen)
    reach = reachable(foon, kitchen)
    ix = reach.index
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
            for r in unit_roles(foon.units[u]):
                k = ix.node_id[r.before] if r.changes and r.before is not None else -1
                if k >= 0 and reach.node_round[k] == 0 and k not in used_up:
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
