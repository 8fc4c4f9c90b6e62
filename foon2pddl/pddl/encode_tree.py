"""The `tree` encoding (default): FOON's own semantics, delete-free.

One 0-ary proposition per object node at the level, one parameterless action
per functional unit (precondition: its input nodes; effect: its output nodes).
Nothing is ever deleted, so a plan exists exactly when the kitchen's fixpoint
reaches a goal candidate, the solvable set of native complete retrieval. A
goal with one candidate is that proposition; with several, one auxiliary
action per candidate adds `(goal-reached)` (no disjunctive goal, so planners
such as pyperplan accept it).
"""

from __future__ import annotations

from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, goal_actions, header, select, unit_actions
from .names import NameTable
from .task import Atom, PlanningTask, Predicate


def encode_tree(
    foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3, options: EncodeOptions = DEFAULT_OPTIONS
) -> PlanningTask:
    """The delete-free node-proposition task of `foon` (see the module doc)."""
    inp = at_level(foon, kitchen, goal, level)
    f, sel = inp.foon, select(inp, options.prune)
    ix = sel.index
    table = NameTable()
    several = len(sel.candidates) > 1
    if several:
        table.reserve(GOAL_REACHED, "goal reached")
    # Names are allocated in the sorted node order, so they do not depend on unit order.
    described = [(i, ix.nodes[i].describe()) for i in sel.nodes]
    prop = {i: table.name(text, key=("node", i)) for i, text in described}
    predicates = [Predicate(prop[i], comment=text) for i, text in described]
    atom = {i: Atom(prop[i]) for i in sel.nodes}

    actions = unit_actions(f, sel, atom, lambda i, u: table.name(f"{u.motion.label} u{i}", key=("unit", i)), options)
    if several:
        goal_atom = Atom(GOAL_REACHED)
        predicates.insert(0, Predicate(GOAL_REACHED, comment="a goal candidate was made"))
        actions.extend(goal_actions(table, [(ix.nodes[c], (atom[c],)) for c in sel.candidates], goal_atom, options))
        goal_atoms: tuple[Atom, ...] = (goal_atom,)
    else:
        goal_atoms = (atom[sel.candidates[0]],)

    init = tuple(sorted(atom[i] for i in sel.kitchen))
    return PlanningTask(
        domain="foon-tree",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="tree",
        level=inp.level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=init,
        goal=goal_atoms,
        units=f.units,
        labels=table.labels,
        comments=header("tree", inp, options, len(sel.units)),
    )
