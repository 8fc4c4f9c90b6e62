"""Can a kitchen's objects carry out a task tree? Its units scheduled in order with object identity.

FOON's semantics is over nodes: once `bowl (empty)` is available it stays
available, so one bowl serves every unit that needs an empty bowl, even at once.
`schedule` runs the tree's units in order over physical objects instead: every
kitchen node holds `counts[label]` objects (`uncounted` for a label `counts` does
not name, default 1: one object per kitchen item; None: no limit; `per_item` scales
both), each object is in one node at a time, and a unit's
role (`model.pairing.unit_roles`) binds a distinct object in the node the role
needs: the first by id among the objects in that node, else a fresh kitchen
object of that node while the node has one left. A utensil or container is thus
reused only when it is free again, in the state the unit needs (a knife once
dirty is not clean until a wash unit makes it so). Moved objects go to their
output node; new objects are made; a read-only object whose node names a place
goes into the product when the unit makes one in or on a holder of that label (the
lettuce of a salad), as in `instance_physical`.

Verdicts (`Executability.verdict`): `executable`; `short` (the kitchen runs out:
no object of the label is in the node, and its kitchen objects there are all
taken: which label, at which step); `used-up` (the node is no kitchen node and the
object once made in it has moved on or was consumed: in the tree's order the unit
making it would have to fire again; FOON's delete-free order may also turn a mixer
off before a unit that needs it on, which another order would avoid: the schedule
keeps the tree's order, as a cook reading the tree would); `missing` (no object was ever in that node: the tree is not valid). The
schedule stops at the first failing step. `needed` gives the objects per kitchen
node an unlimited kitchen draws (how many more the tree needs; `uncounted=None`
with no counts). Inference units
(`--containment infer`) move no object and are skipped. O(steps x objects).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from enum import StrEnum

from ..model.containment import is_inference
from ..model.foon import ObjectNode
from ..model.pairing import RoleKind, unit_roles
from ..model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, TraceStep
from ..model.places import places
from ..model.tasktree import TaskTree
from .foon_places import step_source

__all__ = ["Executability", "Verdict", "drawn_by_plan", "needed", "schedule", "short_message"]


class Verdict(StrEnum):
    """Whether a tree can be carried out with the kitchen's objects (see the module doc)."""

    EXECUTABLE = "executable"
    SHORT = "short"
    USED_UP = "used-up"
    MISSING = "missing"


@dataclass(frozen=True)
class Executability:
    """The verdict; for a failure the step (0-based), the label and node that ran short, and a message;
    the objects drawn per kitchen node; and the schedule up to the failing step as a trace (no holders)."""

    verdict: Verdict
    step: int | None = None
    label: str = ""
    node: ObjectNode | None = None
    message: str = ""
    drawn: tuple[tuple[ObjectNode, int], ...] = ()
    trace: PhysicalTrace | None = None

    @property
    def ok(self) -> bool:
        return self.verdict is Verdict.EXECUTABLE


def schedule(tree: TaskTree, kitchen_nodes: Iterable[ObjectNode], counts: Mapping[str, int] | None = None,
             per_item: int = 1, *, uncounted: int | None = 1,
             stated: Mapping[ObjectNode, int] | None = None) -> Executability:
    """Run `tree`'s units in order over the kitchen's objects (see the module doc); `stated`: objects per
    kitchen node where the kitchen says how many (a scene's), before `counts` per label, before `uncounted`
    (objects per node of any other label; None: as many as the tree draws, so only what is counted limits)."""
    kitchen = frozenset(kitchen_nodes)
    counts = counts or {}
    stated = stated or {}
    objects: list[PhysicalObject] = []
    start: dict[str, ObjectNode | None] = {}
    now: dict[str, ObjectState] = {}
    drawn: dict[ObjectNode, int] = {}
    per_label: dict[str, int] = {}
    made: set[ObjectNode] = set()
    left: dict[ObjectNode, int] = {}  # node -> the last step that moved an object out of it
    steps: list[TraceStep] = []

    def new_object(label: str, node: ObjectNode | None) -> str:
        per_label[label] = per_label.get(label, 0) + 1
        oid = f"{label.replace(' ', '_')}_{per_label[label]}"
        objects.append(PhysicalObject(oid, label))
        start[oid] = node
        now[oid] = ObjectState(oid, node)
        return oid

    def result(verdict: Verdict, k: int | None = None, label: str = "", node: ObjectNode | None = None,
               message: str = "") -> Executability:
        trace = PhysicalTrace(tuple(objects), tuple(ObjectState(o.id, start[o.id]) for o in objects), tuple(steps))
        return Executability(verdict, k, label, node, message, tuple(sorted(drawn.items())), trace)

    for unit in (u for u in tree.units if not is_inference(u)):
        k = len(steps)
        roles = unit_roles(unit)
        names: list[str] = []
        for role in roles:
            if role.before is None:
                names.append("")
                continue
            free = sorted(o for o, s in now.items() if s.exists and s.node == role.before and o not in names)
            if free:
                names.append(free[0])
                continue
            what = role.before.describe()
            if role.before in kitchen:
                each = counts.get(role.label, uncounted)  # objects per kitchen node of the label; None: no limit
                limit = stated[role.before] if role.before in stated else None if each is None else each * per_item
                if limit is None or drawn.get(role.before, 0) < limit:
                    drawn[role.before] = drawn.get(role.before, 0) + 1
                    names.append(new_object(role.label, role.before))
                    continue
                return result(Verdict.SHORT, k, role.label, role.before,
                              short_message(k, unit.motion.label, role.label, role.before, limit))
            if role.before in made:
                return result(Verdict.USED_UP, k, role.label, role.before,
                              f"step {k + 1} ({unit.motion.label}) needs {what!r} again, but step "
                              f"{left[role.before] + 1} moved the {role.label} on (in this order of the units "
                              "the unit making it must fire again)")
            return result(Verdict.MISSING, k, role.label, role.before,
                          f"step {k + 1} ({unit.motion.label}) needs {what!r}, which no earlier step makes")
        names = [n or new_object(r.label, None) for r, n in zip(roles, names, strict=True)]
        landed = {p for r in roles if r.kind is RoleKind.NEW for p in places(r.after)}
        changes = []
        for oid, role in zip(names, roles, strict=True):
            if role.changes:
                changes.append(ObjectState(oid, role.after))
                made.add(role.after)
            elif role.kind is RoleKind.READ_ONLY and set(places(role.before)) & landed:
                changes.append(ObjectState(oid, role.before, consumed=True))
            else:
                continue
            if role.before is not None:
                left[role.before] = k
        bindings = tuple(Binding(o, r.before, r.after if r.changes else None) for o, r in zip(names, roles, strict=True))
        steps.append(TraceStep(k, unit, bindings, tuple(changes), step_source(TraceStep(k, unit, (), ()))))
        now.update((c.id, c) for c in changes)
    return result(Verdict.EXECUTABLE)


def drawn_by_plan(trace: PhysicalTrace, kitchen_nodes: Iterable[ObjectNode], per_item: int = 1, *,
                  stated: Mapping[ObjectNode, int] | None = None) -> Executability:
    """Whether a physical plan (a planner's `trace`, already replayed) fits a kitchen of `per_item` objects per
    kitchen node (`stated`: per node where the kitchen says, as in `schedule`): the objects it draws per
    kitchen node are those starting in that node that some step binds.
    `short` at the first step binding one object more than the kitchen has there (its label and node, in
    `schedule`'s words), with `drawn` over the whole plan (the objects it needs; beyond `per_item`, more).
    A planner given derived counts (`instances`) may use a second bowl where the kitchen has one. O(steps)."""
    kitchen = frozenset(kitchen_nodes)
    start = {s.id: s.node for s in trace.initial}
    labels = trace.by_id
    stated = stated or {}

    def limit(node: ObjectNode) -> int:
        return stated.get(node, per_item)

    drawn: dict[ObjectNode, set[str]] = {}
    first: tuple[int, str, ObjectNode, str] | None = None
    for step in trace.steps:
        for b in step.bindings:
            node = start.get(b.object)
            if node is None or node not in kitchen or b.object in drawn.get(node, ()):
                continue
            drawn.setdefault(node, set()).add(b.object)
            if first is None and len(drawn[node]) > limit(node):
                first = (step.index, labels[b.object].label, node, step.unit.motion.label)
    counts = tuple(sorted((n, len(o)) for n, o in drawn.items()))
    if first is None:
        return Executability(Verdict.EXECUTABLE, drawn=counts, trace=trace)
    k, label, node, motion = first
    return Executability(Verdict.SHORT, k, label, node, short_message(k, motion, label, node, limit(node)), counts,
                         trace)


def short_message(step: int, motion: str, label: str, node: ObjectNode, limit: int) -> str:
    """The words of a `SHORT` verdict (one sentence for trees and plans; `experiment.physical` reads them)."""
    return f"step {step + 1} ({motion}) needs one more {label} in {node.describe()!r}: the kitchen has {limit} there, none free"


def needed(tree: TaskTree, kitchen_nodes: Iterable[ObjectNode]) -> Executability:
    """The schedule with an unlimited kitchen: `drawn` says how many objects each kitchen node must hold."""
    return schedule(tree, kitchen_nodes, uncounted=None)

