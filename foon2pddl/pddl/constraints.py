"""Constraints in PDDL, for every encoding alike: filter before encoding, must-use after.

- Bans: the network is filtered before it is encoded (`analysis.constraints`): a unit a
  ban removes has no action, the kitchen loses its banned objects and the goal its
  banned candidates, exactly as native retrieval sees them.
- Must-use X: a 0-ary predicate `(used-X)` is added by every action whose unit uses X
  and joins the goal, `(and <goal> (used-X))`; the plan must run a unit using X.
- Rates from the constraints become action costs through the existing `success-rate`
  cost mode (the caller merges them into the rates, `io.constraints_file.with_rates`).
In the `tree` encoding a plan exists iff `Removal.solvable`, the solvable set of
native `complete` retrieval under the same constraints.
"""

from __future__ import annotations

from dataclasses import replace

from ..analysis.constraints import Filtered, removal
from ..model.constraints import Constraints, describe_all, unit_uses
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .names import NameTable
from .prune import relevant_units
from .task import Action, Atom, PlanningTask, Predicate


class GoalExcluded(ValueError):
    """No candidate of the goal remains under the constraints: nothing to encode (the goal is unsolvable)."""


def constrained_inputs(foon: Foon, kitchen: Kitchen, goal: Goal, constraints: Constraints) -> tuple[Foon, Kitchen, Goal]:
    """The network, kitchen and goal with the bans applied; GoalExcluded when no candidate remains
    a node of the filtered network."""
    f: Filtered = removal(foon, constraints).filtered(kitchen.nodes, goal)
    present = f.foon.producers
    cands = tuple(c for c in f.candidates if c in present)
    if not cands:
        raise GoalExcluded(f"no way to make {goal.describe()!r} is left by the constraints "
                           f"({', '.join(describe_all(constraints.bans)) or 'none'})")
    return f.foon, Kitchen(f.kitchen, kitchen.level, kitchen.source), Goal(goal.spec, cands, goal.level)


def must_use_cone(foon: Foon, kitchen: Kitchen, goal: Goal, must_use: tuple[str, ...]) -> Foon:
    """Relevance pruning that keeps must-use objects possible: the units that can contribute to a goal
    candidate or to the inputs of a unit using a must-use object, and those units (original order).
    Encode the result unpruned: goal-directed pruning alone would drop the units using the objects."""
    users = [i for i, u in enumerate(foon.units) if any(unit_uses(u, x) for x in must_use)]
    targets = set(goal.candidates).union(*(foon.units[i].inputs for i in users))
    makers = {i for c in goal.candidates for i in foon.producers.get(c, ())}  # keeps the candidates nodes
    keep = set(relevant_units(foon, kitchen.nodes, targets)) | set(users) | makers
    return Foon(tuple(u for i, u in enumerate(foon.units) if i in keep), foon.level)


def add_must_use(task: PlanningTask, must_use: tuple[str, ...]) -> PlanningTask:
    """`task` with a `(used-X)` effect on the actions whose unit uses X and `(used-X)` in the goal."""
    if not must_use:
        return task
    table = NameTable(set(task.labels) | {p.name for p in task.predicates} | {a.name for a in task.actions})
    atoms = {x: Atom(table.name(f"used {x}", key=("used", x))) for x in must_use}
    actions: list[Action] = []
    for a in task.actions:
        extra = () if a.unit is None else tuple(atoms[x] for x in must_use if unit_uses(task.units[a.unit], x))
        actions.append(replace(a, add=a.add + extra) if extra else a)
    predicates = task.predicates + tuple(Predicate(atoms[x].predicate, comment=f"a unit using {x} ran")
                                         for x in must_use)
    return replace(task, predicates=predicates, actions=tuple(actions), goal=task.goal + tuple(atoms.values()),
                   labels={**task.labels, **table.labels},
                   comments=task.comments + (f"must use: {', '.join(must_use)}",))
