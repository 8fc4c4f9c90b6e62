"""An `instances` plan as a `PhysicalTrace` with holders, inferred by tracking (for the physical replay).

The `instances` encoding does not model which object holds which: `onion (in
[bowl])` is part of the onion's state, and its plan's trace
(`pddl.instance_replay.instance_trace`) has no holders. `physical_trace` rebuilds it with holders
from FOON's own evidence, step by step, so `physical_replay.replay` can judge the
plan object by object. It shares no logic with an encoding that models holders.

Holder of an object whose new node says `in [C]` / `on [C]` (`HolderEvidence`):

1. **tracked**: it is already in or on an object labelled C (same relation) and
   stays there, unless that holder is bound in the step and its new node no longer
   lists the object's label while another bound C's list does (a pour between two
   bowls, where the poured node does not change);
2. **single**: the step binds exactly one other object labelled C;
3. **listed**: the bound C whose new ingredient list names the object's label (one
   that did not list it before first; then the first in role order);
4. **only**: the step binds no C, and exactly one object labelled C exists (the
   oven a unit never lists: the replay then reports that the step does not use it);
5. **unresolved**: none of these: no holder (the replay then reports it misplaced).

A node naming several places (`in [bowl]`, `in [microwave]`) is resolved for the
place whose candidates name another of its places first (the bowl in the
microwave holds the salmon). Objects used unchanged move only by rule 1's
exception. Start states: the only object labelled C at the start, else the first
(by name) whose start node lists the object's label and holds no object of that
label yet, else the first that lists it, else unresolved. A holder that would
make a loop is unresolved.

What becomes of things: a read-only role (no output of its label) whose node names
a place goes into the bound container whose list newly names its label (the cream
a `pour*` lists in the mixing bowl; its node stays the input's, as in the plan,
which the replay reports), else it is *consumed* when the step makes an object
in or on a holder of the label it was in or on (it went into that product: the
lettuce of a salad, the bread of a garlic bread); else it stays as it was (a
baking tray FOON leaves out of a unit's outputs). A read-only role that is no parameter of
the action (the encoding checks "some instance is there") gets, among the
instances in the required state, the one holding another object of the step when
there is one (the encoding leaves the choice open), else the trace's choice.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, replace
from enum import StrEnum

from ..model.foon import ObjectNode
from ..model.pairing import Role, RoleKind
from ..model.physical import Binding, ObjectState, PhysicalTrace, Relation, TraceError, TraceStep
from ..model.places import listed, places
from ..model.where import short_path
from ..model.words import count
from ..pddl.task import PlanningTask
from .physical_replay import replay

__all__ = ["HolderEvidence", "InferredTrace", "physical_trace", "replay_note"]


class HolderEvidence(StrEnum):
    """Which rule placed an object (see the module doc)."""

    TRACKED = "tracked"
    SINGLE = "single"
    LISTED = "listed"
    ONLY = "only"
    UNRESOLVED = "unresolved"


@dataclass(frozen=True)
class InferredTrace:
    """The trace, and how often each rule placed an object (start states and steps together)."""

    trace: PhysicalTrace
    evidence: Counter


class _Builder:
    def __init__(self, task: PlanningTask) -> None:
        self.label = {x.name: x.label for x in task.instances}
        self.now: dict[str, ObjectState] = {}
        self.evidence: Counter = Counter()

    def loops(self, obj: str, holder: str) -> bool:
        at: str | None = holder
        while at is not None:
            if at == obj:
                return True
            at = self.now[at].holder if at in self.now else None
        return False

    def start(self, initial: Sequence[ObjectState]) -> tuple[ObjectState, ...]:
        self.now = {s.id: ObjectState(s.id, s.node) for s in initial}
        made = {s.id: s.node for s in initial if s.node is not None}
        holds: dict[str, set[str]] = {}
        for name, node in ((s.id, s.node) for s in initial):
            label = self.label[name]
            for rel, c in places(node):
                cands = sorted(h for h, n in made.items() if self.label[h] == c and h != name)
                lists = [h for h in cands if label in listed(made[h])]
                pick = (cands[0] if len(cands) == 1 else
                        next((h for h in lists if label not in holds.get(h, set())), lists[0] if lists else None))
                if pick is not None and not self.loops(name, pick):
                    self.evidence[HolderEvidence.SINGLE if len(cands) == 1 else HolderEvidence.LISTED] += 1
                    holds.setdefault(pick, set()).add(label)
                    self.now[name] = ObjectState(name, node, pick, rel)
                    break
            else:
                if places(node):
                    self.evidence[HolderEvidence.UNRESOLVED] += 1
        return tuple(self.now[s.id] for s in initial)

    def holder(self, obj: str, node: ObjectNode, roles: Sequence[tuple[Role, str]],
               unchanged: bool = False) -> tuple[str | None, Relation | None]:
        """Where `obj`, now in `node`, is after a step with `roles` (module doc, rules 1-5; only rule 1's
        exception for an object the step leaves `unchanged`)."""
        named = places(node)
        cur = self.now[obj]
        if unchanged and not named:
            return cur.holder, cur.relation
        if not named:
            return None, None
        after = {n: (r.after if r.changes else r.before) for r, n in roles}
        before = {n: r.before for r, n in roles}
        mine = self.label[obj]

        def more_direct(place: tuple[Relation, str]) -> int:
            others = {c for _, c in named} - {place[1]}
            return -any(c in others for n, nd in after.items() if self.label[n] == place[1] for _, c in places(nd))

        for rel, c in sorted(named, key=more_direct):
            bound = [n for _, n in roles if self.label[n] == c and n != obj]
            lists = [n for n in bound if mine in listed(after[n])]
            fresh = [n for n in lists if mine not in listed(before[n])]
            if cur.holder is not None and self.label[cur.holder] == c and cur.relation == rel:
                left = cur.holder in after and mine not in listed(after[cur.holder])
                moved = [n for n in (fresh or lists) if n != cur.holder]
                if not (left and moved):
                    self.evidence[HolderEvidence.TRACKED] += not unchanged
                    return cur.holder, rel
                pick, why = moved[0], HolderEvidence.LISTED
            elif unchanged:
                continue
            elif len(bound) == 1:
                pick, why = bound[0], HolderEvidence.SINGLE
            elif lists:
                pick, why = (fresh or lists)[0], HolderEvidence.LISTED
            elif not bound and len(only := [n for n, s in self.now.items() if self.label[n] == c and s.exists]) == 1:
                pick, why = only[0], HolderEvidence.ONLY
            else:
                continue
            if not self.loops(obj, pick):
                self.evidence[why] += 1
                return pick, rel
        if unchanged:
            return cur.holder, cur.relation
        self.evidence[HolderEvidence.UNRESOLVED] += 1
        return None, None

    def receiver(self, obj: str, roles: Sequence[tuple[Role, str]]) -> str | None:
        """The bound container whose list newly names `obj`'s label (the first in role order), if any."""
        mine = self.label[obj]
        for r, n in roles:
            if r.changes and r.before is not None and mine in listed(r.after) - listed(r.before) and n != obj:
                if not self.loops(obj, n):
                    self.evidence[HolderEvidence.LISTED] += 1
                    return n
        return None

    def rebind(self, roles: list[tuple[Role, str]], free: Sequence[bool]) -> list[tuple[Role, str]]:
        """Unbound read-only roles: prefer an instance in the required state that holds another of the step's objects."""
        holders = {self.now[n].holder for _, n in roles if n in self.now}
        out = []
        for k, ((role, name), is_free) in enumerate(zip(roles, free, strict=True)):
            if is_free and role.before is not None:
                taken = {n for _, n in out} | {n for _, n in roles[k + 1:]}
                cands = sorted(n for n, s in self.now.items() if self.label[n] == role.label and s.exists
                               and s.node == role.before and n not in taken)
                name = next((n for n in cands if n in holders), name if name in cands else (cands or [name])[0])
            out.append((role, name))
        return out

    def step(self, step: TraceStep, free: Sequence[bool]) -> TraceStep:
        given = [(Role(self.label[b.object], b.before, b.after), b.object) for b in step.bindings]
        roles = self.rebind(given, free)
        roles = [(r, n) for r, n in roles if n in self.now]
        landed = {p for r, _ in roles if r.kind is RoleKind.NEW for p in places(r.after)}
        changes = []
        for role, name in roles:
            cur = self.now[name]
            if role.kind is RoleKind.READ_ONLY and places(role.before):
                into = self.receiver(name, roles)
                if into is not None:
                    new = ObjectState(name, role.before, into, cur.relation or Relation.IN)
                elif set(places(role.before)) & landed:
                    new = ObjectState(name, role.before, cur.holder, cur.relation, consumed=True)
                else:
                    continue
            else:
                node = role.after if role.changes else role.before
                if not role.changes and cur.holder is None:
                    continue
                new = ObjectState(name, node, *self.holder(name, node, roles, unchanged=not role.changes))
            if new != cur:
                changes.append(new)
        self.now.update((c.id, c) for c in changes)
        bindings = tuple(Binding(n, r.before, r.after if r.changes else None) for r, n in roles)
        return TraceStep(step.index, step.unit, bindings, tuple(changes), step.source)


def physical_trace(task: PlanningTask, trace: PhysicalTrace) -> InferredTrace:
    """`trace` (an `instances` plan over `task`'s instances) with holders inferred (see the module doc).

    O(steps x instances)."""
    b = _Builder(task)
    initial = b.start(trace.initial)
    flags = {id(task.units[a.unit]): a.roles for a in task.actions if a.unit is not None}
    out = []
    for s in trace.steps:
        roles = flags.get(id(s.unit), ())
        free = [not bound for _, bound in roles] if len(roles) == len(s.bindings) else [False] * len(s.bindings)
        out.append(b.step(s, free))
    return InferredTrace(PhysicalTrace(trace.objects, initial, tuple(out)), b.evidence)


def replay_note(task: PlanningTask, trace: PhysicalTrace) -> tuple[str, ...]:
    """A note for a plan whose encoding models no holders: what the physical replay finds with inferred ones
    (empty when it finds nothing)."""
    try:
        report = replay(physical_trace(task, trace).trace)
    except TraceError as exc:  # an inference bug must not cost the user the plan
        return (f"not checked physically by the encoding, and its holders could not be inferred: {exc}",)
    if report.ok:
        return ()
    n, steps, first = len(report.disagreements), len(trace.steps), report.disagreements[0]
    return (f"not checked physically by the encoding: with holders inferred by tracking, the physical replay "
            f"finds {count(n, 'disagreement')} ({len(report.affected_steps)} of {steps} steps "
            f"affected); first: {replace(first, source=short_path(first.source))}",)
