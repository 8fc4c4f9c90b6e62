"""The registry of encodings, and one entry point from (network, kitchen, goal) to a task in any of them.

`ENCODINGS` maps each encoding's name to its `registry.Encoding` (the first is
the default); `compile_goal` returns a `registry.Compiled` (the task and how plan
steps map back to units), `compile_task` just its `PlanningTask`. To add an
encoding, write its encoder (and, over physical objects, its replay and view
hooks) and list it here (docs/extending.md).
"""

from __future__ import annotations

from dataclasses import replace

from ..errors import UsageError
from ..generalize.categories import CategoryIndex
from ..io.rates import Rates
from ..model.constraints import Constraints
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .constraints import add_must_use, constrained_inputs, must_use_cone
from .encode_compat import encode_compat
from .encode_instances import encode_instances
from .encode_ocp import encode_ocp
from .encode_relational import encode_relational
from .encode_state import encode_state
from .encode_tree import encode_tree
from .encoding import EncodeOptions
from .instance_replay import INSTANCE_VIEW, instance_trace
from .lifted_plans import compile_lifted
from .registry import Compiled, Encoding
from .relational_replay import RELATIONAL_VIEW, relational_trace
from .task import PlanningTask, settle_goal

__all__ = ["DEFAULT_ENCODING", "ENCODINGS", "GROUND_ENCODINGS", "PLAN_ENCODING", "as_compiled", "compile_goal", "compile_task",
           "encoding_named", "register"]


def _registry(*encodings: Encoding) -> dict[str, Encoding]:
    return {e.name: e for e in encodings}


#: Encoding name -> encoding, the default first.
ENCODINGS: dict[str, Encoding] = _registry(
    Encoding("tree", encode_tree, "FOON's semantics, delete-free: one proposition per node, one action per unit",
             kitchen_init=True),
    Encoding("instances", encode_instances, "physical object instances whose states change", every_step=True,
             replay=instance_trace, view=INSTANCE_VIEW),
    Encoding("relational", encode_relational, "physical objects and which object holds which: (in ?holder ?obj)",
             every_step=True, replay=relational_trace, view=RELATIONAL_VIEW, holders=True, complete=False),
    Encoding("state", encode_state, "object-centred STRIPS: facts per object and state, with deletes",
             foon_semantics=False, every_step=True, complete=False),
    Encoding("foon-compat", encode_compat, "the public foon_to_pddl converter's format, with a goal"),
    Encoding("ocp", encode_ocp, "the public foon_to_pddl converter's object-centred format: (in cup water), air, table",
             foon_semantics=False, every_step=True, complete=False),
    Encoding("gen-lifted", compile_lifted,
             "FOON-GEN: categories as types, the planner grounds them to kitchen objects", lifted=True),
)

DEFAULT_ENCODING = next(iter(ENCODINGS))
#: The encoding `foon2pddl plan` uses when none is asked for: physical objects and which holds which, whose plans a
#: robot could carry out (`compile` and the API keep `DEFAULT_ENCODING`, FOON's own semantics; docs/planning.md).
PLAN_ENCODING = "relational"

#: The encodings whose plan steps map back through `Action.unit` alone (the lifted one grounds categories).
GROUND_ENCODINGS = tuple(name for name, e in ENCODINGS.items() if not e.lifted)


def register(encoding: Encoding) -> Encoding:
    """Add (or replace) an encoding; returns it (docs/extending.md)."""
    ENCODINGS[encoding.name] = encoding
    return encoding


def encoding_named(name: str) -> Encoding:
    """The registered encoding `name` (UsageError listing the known ones)."""
    try:
        return ENCODINGS[name]
    except KeyError:
        raise UsageError(f"encoding must be one of {', '.join(ENCODINGS)}, not {name!r}") from None


def compile_goal(foon: Foon, kitchen: Kitchen, goal: Goal, encoding: str = DEFAULT_ENCODING, level: int = 3, *,
                 prune: bool = True, costs: str | None = None, rates: Rates | None = None,
                 instances: tuple[tuple[str, int], ...] = (), categories: tuple[tuple[str, tuple[str, ...]], ...] = (),
                 category_index: CategoryIndex | None = None, policy: str = "absent",
                 constraints: Constraints | None = None, narrow: bool = False, through: bool = False,
                 placed: bool = False, memo: dict | None = None, own: bool = False) -> Compiled:
    """Encode `goal` from `kitchen` over `foon` at `level` (UsageError on an unknown encoding or bad options).

    `instances` and `categories` (category chains) are read by the `instances` encoding,
    `category_index` and `policy` by lifted ones (default: the shipped category index), `narrow` (objects
    counted small, `Compiled.narrowed`; from the plan through the stitches alone with `through`, with makers by
    holder reach with `placed`, or without `narrow` counted wide with those makers; `own`: counted wide from FOON's
    own plan unfolded) by the `relational` one; `memo`:
    a dict the caller passes to every compile of one goal (the same network, kitchen and goal objects), in which the
    `relational` encoding keeps the network's reading and its counts, each derived once across them
    (`planners.solve.plan`'s counts; `EncodeOptions.memo`).
    With `constraints`, the one place they apply to every encoding (`constraints.py`): the network,
    kitchen and goal are filtered before encoding (GoalExcluded when no candidate remains) and
    must-use objects join the goal after. A goal the kitchen already holds is put in the initial
    state (`task.settle_goal`), so that every encoding's plan for it is empty.

    >>> from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
    >>> from foon2pddl.model.goal import Goal, GoalSpec
    >>> from foon2pddl.model.kitchen import Kitchen
    >>> whole, chopped = make_node("onion", [make_state("whole")]), make_node("onion", [make_state("chopped")])
    >>> knife = make_node("knife")
    >>> foon = Foon((FunctionalUnit((whole, knife), Motion("chop"), (chopped, knife)),), 3)
    >>> compiled = compile_goal(foon, Kitchen(frozenset({whole, knife}), 3), Goal(GoalSpec("onion"), (chopped,), 3))
    >>> [a.name for a in compiled.task.actions], compiled.task.goal[0].predicate
    (['chop_u0'], 'onion_chopped')
    >>> compiled.unit_of(compiled.task.actions[0]).motion.label
    'chop'
    """
    enc = encoding_named(encoding)
    if costs is not None and not enc.costs:
        raise UsageError(f"the {enc.name} encoding does not support action costs")
    if constraints:
        foon, kitchen, goal = constrained_inputs(foon, kitchen, goal, constraints)
        if constraints.must_use and prune:
            foon, prune = must_use_cone(foon, kitchen, goal, constraints.must_use), False
    options = EncodeOptions(prune=prune, costs=costs, rates=rates, instances=instances, categories=categories,
                            category_index=category_index, policy=policy, narrow=narrow, through=through,
                            placed=placed, memo=memo, own=own)
    compiled = enc.compile(foon, kitchen, goal, level, options)
    if constraints:
        compiled = replace(compiled, task=add_must_use(compiled.task, constraints.must_use))
    settled = settle_goal(compiled.task)
    return compiled if settled is compiled.task else replace(compiled, task=settled)


def as_compiled(task: PlanningTask | Compiled) -> Compiled:
    """`task` with what its registered encoding promises (a lifted task needs its `Compiled` to map plans back)."""
    if isinstance(task, Compiled):
        return task
    enc = encoding_named(task.encoding)
    if enc.lifted:
        raise UsageError(f"plans of the {enc.name} encoding map back through its Compiled task (compile_goal)")
    return enc.wrap(task)


def compile_task(foon: Foon, kitchen: Kitchen, goal: Goal, encoding: str = DEFAULT_ENCODING, level: int = 3,
                 prune: bool = True, costs: str | None = None, rates: Rates | None = None,
                 constraints: Constraints | None = None, *, instances: tuple[tuple[str, int], ...] = (),
                 categories: tuple[tuple[str, tuple[str, ...]], ...] = ()) -> PlanningTask:
    """The `PlanningTask` of `compile_goal` (for callers that do not map plans back)."""
    return compile_goal(foon, kitchen, goal, encoding, level, prune=prune, costs=costs, rates=rates,
                        instances=instances, categories=categories, constraints=constraints).task
