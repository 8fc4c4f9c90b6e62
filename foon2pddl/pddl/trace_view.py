"""How an encoding over physical objects shows its plans: the `TraceView` hook, and shared text pieces.

An encoding whose plans name physical objects registers a replay hook (plan steps ->
`model.physical.PhysicalTrace`, `registry.Encoding.replay`) and a `TraceView`: the text
printed after the task tree (`plan --format steps`) and the JSON keys of `plan --format
json`. The CLI and `planners.decode` only call these hooks, so adding such an encoding
needs no branch on its name.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from ..model.foon import ObjectNode
from ..model.pairing import RoleKind, transfer
from ..model.physical import Binding, PhysicalTrace, TraceStep
from ..model.places import contents
from .task import PlanningTask

__all__ = ["TraceView", "binding_kind", "changed", "show_node", "step_text"]


@dataclass(frozen=True)
class TraceView:
    """`key`: the JSON key of the trace (and of its check under `validation`); `text(task, trace)`: lines
    printed after the task tree; `json(task, trace)`: the JSON value under `key`."""

    key: str
    text: Callable[[PlanningTask, PhysicalTrace], str]
    json: Callable[[PlanningTask, PhysicalTrace], object]


def changed(binding: Binding) -> bool:
    """Whether the step changes (or makes) the bound object."""
    return binding.after is not None and binding.after != binding.before


def binding_kind(binding: Binding) -> RoleKind:
    """The role a binding plays (`after` None: read-only; equal to `before`: kept)."""
    if binding.before is None:
        return RoleKind.NEW
    if binding.after is None:
        return RoleKind.READ_ONLY
    return RoleKind.KEPT if binding.before == binding.after else RoleKind.MOVED


def step_text(step: TraceStep) -> str:
    """`cut lime_1 on cutting_board_1 with knife_1`: the motion, the objects it changes, then `with` the others;
    between two containers of one label (`model.pairing.transfer`), what moves from which into which, as the
    tree's cook's words say it: `pour lettuce_1 from bowl_1 into bowl_2` (what sits in the second is no tool)."""
    found = transfer([(b.before, b.after) for b in step.bindings])
    if found is not None:
        src, dst, moved = step.bindings[found[0]], step.bindings[found[1]], found[2]
        there = contents(dst.before) if dst.before is not None else frozenset()
        what = [b.object for b in step.bindings if b.before is not None and b.before.label in moved]
        others = [b.object for b in step.bindings if b not in (src, dst) and b.object not in what
                  and not (b.before is not None and b.before.label in there)]
        text = f"{step.unit.motion.label} {', '.join(what)} from {src.object} into {dst.object}"
        return text + (f" with {', '.join(others)}" if others else "")
    moved = [b.object for b in step.bindings if changed(b)]
    others = [b.object for b in step.bindings if not changed(b)]
    text = " ".join([step.unit.motion.label, ", ".join(moved)]).strip()
    return text + (f" with {', '.join(others)}" if others else "")


def show_node(node: ObjectNode | None) -> str:
    """A node's description, or `not yet made`."""
    return "not yet made" if node is None else node.describe()
