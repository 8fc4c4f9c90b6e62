"""The `foon-compat` encoding: the public foon_to_pddl converter's "FOON" format, with a goal.

As there: domain `universal_foon`, one type `object_node`, every object node a
domain constant, one predicate `(is_available ?obj - object_node)`, one
parameterless action `functional_unit_<i>` per unit (precondition: inputs
available; effect: outputs available), the kitchen as the initial state. Unlike
there, names are sanitized and unique, `:requirements` lists what is used
(`:strips :typing`, not `:adl`), and the problem has a goal: the candidate node
is available, or, with several candidates, the constant `goal_reached` made
available by one auxiliary action per candidate (so the one predicate stays
the only predicate). Semantics are the `tree` encoding's.
"""

from __future__ import annotations

from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .encoding import DEFAULT_OPTIONS, EncodeOptions, at_level, goal_actions, header, select, unit_actions
from .names import NameTable
from .task import Atom, PlanningTask, Predicate

NODE_TYPE = "object_node"
AVAILABLE = "is_available"
GOAL_CONSTANT = "goal_reached"


def encode_compat(
    foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3, options: EncodeOptions = DEFAULT_OPTIONS
) -> PlanningTask:
    """The converter-compatible task of `foon` (see the module doc)."""
    inp = at_level(foon, kitchen, goal, level)
    f, sel = inp.foon, select(inp, options.prune)
    ix = sel.index
    several = len(sel.candidates) > 1
    table = NameTable()
    table.reserve(AVAILABLE, "is available")
    table.reserve(NODE_TYPE, "object node")
    if several:
        table.reserve(GOAL_CONSTANT, "goal reached")
    const = {i: table.name(ix.nodes[i].describe(), key=("node", i)) for i in sel.nodes}
    avail = {i: Atom(AVAILABLE, (name,)) for i, name in const.items()}

    actions = unit_actions(f, sel, avail, lambda i, u: table.name(f"functional_unit_{i}", key=("unit", i)), options)
    constants = [(const[i], NODE_TYPE) for i in sel.nodes]
    if several:
        goal_atom = Atom(AVAILABLE, (GOAL_CONSTANT,))
        constants.append((GOAL_CONSTANT, NODE_TYPE))
        actions.extend(goal_actions(table, [(ix.nodes[c], (avail[c],)) for c in sel.candidates], goal_atom, options))
        goal_atoms: tuple[Atom, ...] = (goal_atom,)
    else:
        goal_atoms = (avail[sel.candidates[0]],)

    return PlanningTask(
        domain="universal_foon",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="foon-compat",
        level=inp.level,
        predicates=(Predicate(AVAILABLE, (("?obj", NODE_TYPE),), "the object node is available"),),
        actions=tuple(actions),
        init=tuple(sorted(avail[i] for i in sel.kitchen)),
        goal=goal_atoms,
        types=((NODE_TYPE, "object"),),
        constants=tuple(constants),
        units=f.units,
        labels=table.labels,
        comments=header("foon-compat", inp, options, len(sel.units)),
    )
