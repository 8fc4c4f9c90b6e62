"""A `PhysicalTrace` from an `instances` plan, holders inferred the simplest way.

The `instances` encoding names every object but not what holds it. This reads
holders off FOON's own relational states (`in [bowl]`, `on [cutting board]`):
an object whose new node is `in [X]` is in the object of label X that the same
step binds (first in role order), else in its current holder when that one is
an X, else in the first existing X by id, else it stands free (None). A node
that names no holder keeps the current one (FOON often drops `on [board]` once
a lime is squeezed). An object read by a unit and listed in the ingredient list
of a product the unit makes (`guacamole (contains {avocado, ...})`) is consumed.
Holders that would make a loop are dropped (the object stands free). The relational
encoding gives real holders; this is what the skill layer falls back on without it.
Linear in the plan's bindings times the objects per label.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from ..model.foon import ObjectNode
from ..model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, Relation, TraceStep
from ..pddl.pairing import RoleKind

__all__ = ["node_holder", "trace_of_instances"]


def node_holder(node: ObjectNode | None) -> tuple[str, Relation] | None:
    """(holder label, relation) that `node` names (`in [bowl]` -> ('bowl', in)), or None."""
    for s in node.states if node is not None else ():
        if s.related and s.label in (Relation.IN, Relation.ON):
            return s.related, Relation(s.label)
    return None


def _loops(states: Mapping[str, ObjectState], obj: str, holder: str) -> bool:
    at: str | None = holder
    seen = set()
    while at is not None and at not in seen:
        if at == obj:
            return True
        seen.add(at)
        at = states[at].holder if at in states else None
    return False


def _pick_holder(obj: str, wanted: str, states: Mapping[str, ObjectState], labels: Mapping[str, str],
                 bound: Sequence[str]) -> str | None:
    current = states[obj].holder
    choices = [b for b in bound if b != obj and labels.get(b) == wanted and states[b].exists]
    if current is not None and labels[current] == wanted:
        choices.append(current)
    choices += [x for x in sorted(states) if x != obj and labels[x] == wanted and states[x].exists]
    return next((c for c in choices if not _loops(states, obj, c)), None)


def _placed(obj: str, node: ObjectNode, states: Mapping[str, ObjectState], labels: Mapping[str, str],
            bound: Sequence[str]) -> ObjectState:
    named = node_holder(node)
    if named is None:
        cur = states[obj]
        return ObjectState(obj, node, cur.holder, cur.relation)
    holder = _pick_holder(obj, named[0], states, labels, bound)
    return ObjectState(obj, node, holder, named[1] if holder is not None else None)


def trace_of_instances(instances: Sequence[tuple[str, str, ObjectNode | None]], steps: Sequence) -> PhysicalTrace:
    """The trace of `instance_plan.InstanceStep`s over the task's `instances` (name, label, start node)."""
    labels = {name: label for name, label, _ in instances}
    states: dict[str, ObjectState] = {name: ObjectState(name, start) for name, _, start in instances}
    for name, _, start in instances:
        if start is not None:
            states[name] = _placed(name, start, states, labels, ())
    initial = tuple(states[name] for name, _, _ in instances)
    out = []
    for index, step in enumerate(steps):
        bound = [name for _, name in step.bindings if name in states]
        products = [role.after for role, _ in step.bindings if role.kind is RoleKind.NEW]
        eaten = {i for p in products for i in p.ingredients}
        changes: dict[str, ObjectState] = {}
        for role, name in step.bindings:
            if name not in states:
                continue
            if role.changes:
                changes[name] = _placed(name, role.after, states, labels, bound)
            elif role.kind is RoleKind.READ_ONLY and role.label in eaten:
                changes[name] = ObjectState(name, states[name].node, consumed=True)
            states.update({name: changes[name]} if name in changes else {})
        bindings = tuple(Binding(name, role.before, role.after if role.changes else None)
                         for role, name in step.bindings if name in labels)
        src = step.unit.source
        where = f"{src.path}:{src.line}" if src is not None else ""
        out.append(TraceStep(index, step.unit, bindings, tuple(changes[k] for k in sorted(changes)), where))
    objects = tuple(PhysicalObject(name, label) for name, label, _ in instances)
    return PhysicalTrace(objects, initial, tuple(out))
