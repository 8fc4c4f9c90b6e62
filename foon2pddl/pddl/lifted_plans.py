"""A `gen-lifted` plan read back as FOON (`encode_lifted` builds the task): each step's lifted unit grounded on the
objects the plan bound (`ground_unit`), and what the plan made from a substituted object renamed with it
(`rename_made`); `compile_lifted`, the registered encoder, pairs them with the task.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..generalize.categories import load_index
from ..generalize.substitute import rename_derived, substitute_node, substitute_unit
from ..model.constraints import node_labels
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree, validate
from .encode_lifted import LiftedTask, encode_lifted
from .encoding import EncodeOptions
from .registry import Compiled, PlanDecodeError

__all__ = ["compile_lifted", "ground_unit", "plan_bindings", "rename_made"]


def ground_unit(lt: LiftedTask, action_index: int, args: tuple[str, ...]) -> FunctionalUnit:
    """The concrete unit of lifted unit `action_index` with its parameters bound to the objects `args` (PDDL names).

    Raises PlanDecodeError when `args` do not fit the action (count, unknown object).
    """
    lu = lt.lifted[action_index]
    if len(args) != len(lu.params):
        raise PlanDecodeError(f"action of unit {action_index} takes {len(lu.params)} arguments, got {len(args)}")
    unknown = [a for a in args if a not in lt.objects]
    if unknown:
        raise PlanDecodeError(f"unknown object {unknown[0]!r}")
    binding = {label: lt.objects[a] for (label, _), a in zip(lu.params, args, strict=True)}
    changed = {k: v for k, v in binding.items() if k != v}
    if not changed:
        return lu.unit
    note = "gen: " + ", ".join(f"{k} -> {v}" for k, v in sorted(changed.items()))
    return substitute_unit(lu.unit, binding, note=note)


def plan_bindings(lt: LiftedTask, steps: Sequence[str]) -> dict[str, str]:
    """Recipe object -> kitchen object, for every parameter a plan bound to another object."""
    out: dict[str, str] = {}
    for step in steps:
        name, *args = step.split()
        action = lt.task.action_for(name)
        if action is None or action.unit is None or len(args) != len(lt.lifted[action.unit].params):
            continue
        for (label, _), a in zip(lt.lifted[action.unit].params, args, strict=True):
            if lt.objects.get(a, label) != label:
                out.setdefault(label, lt.objects[a])
    return out


def rename_made(lt: LiftedTask, tree: TaskTree, steps: Sequence[str], kitchen_nodes: frozenset[ObjectNode]) -> TaskTree:
    """The tree with what the plan made from a substituted object renamed with it, as FOON-EXP names it.

    `substitute.rename_derived`: a lime squeezed where the recipe squeezed a lemon gives `lime juice`,
    in every unit and in the goal node; when the renamed tree would not validate (a new name colliding
    with another object), the recipe's names are kept.
    """
    fixed = frozenset().union(*(node_labels(n) for n in kitchen_nodes)) - {""}
    renames = rename_derived(tree.units, plan_bindings(lt, steps), fixed)
    if not renames:
        return tree
    renamed = TaskTree(tuple(substitute_unit(u, renames) for u in tree.units), substitute_node(tree.goal, renames),
                       tree.level)
    return renamed if validate(renamed, kitchen_nodes).ok else tree


def compile_lifted(foon: Foon, kitchen: Kitchen, goal: Goal, level: int, options: EncodeOptions) -> Compiled:
    """The registered `gen-lifted` encoder: `encode_lifted` with the options' category index (default: shipped)."""
    index = options.category_index if options.category_index is not None else load_index()
    lt = encode_lifted(foon, kitchen, goal, index, level, prune=options.prune, policy=options.policy, options=options)
    return Compiled(lt.task, True, lambda unit, args: ground_unit(lt, unit, args),
                    lambda tree, steps, kitchen_nodes: rename_made(lt, tree, steps, kitchen_nodes))
