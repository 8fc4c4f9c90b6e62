"""The physical view of a plan: which object is where, in which state, after every step.

A task tree is FOON's view of a plan (nodes, not objects). Encodings over physical
objects (`instances`, `relational`) and the layers below them (robot skills, a
cook's text, the experiment's "physically executable" question) need the other
view: every physical object (`bowl_2`), the FOON node whose state it is in, what
it is in or on (`holder`, an object id, or None when it stands free: on the
counter), and whether it is consumed (became part of a mixture, or was used up).

`PhysicalTrace` is that view, encoding-independent: the objects, their states
before the first step, and per unit step the functional unit, which object each
of its roles was bound to, and the new state of every object the step changed.
Invariants checked at construction (as `retrieval.result` does): object ids are
unique, every state names a known object, a holder is a known object other than
the object itself, and no holder chain loops. Whether the states agree with FOON
(a container holds exactly what its node lists, a pour starts where the poured
object is) is not an invariant of the type: that is what an independent replay
checks (`planners.physical_replay`), so a wrong encoding cannot hide behind it.

>>> bowl, salt = PhysicalObject("bowl_1", "bowl"), PhysicalObject("salt_1", "salt")
>>> t = PhysicalTrace((bowl, salt), (ObjectState("bowl_1"), ObjectState("salt_1")), ())
>>> t.holder_of("salt_1") is None and t.contents("bowl_1") == ()
True
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from enum import StrEnum
from functools import cached_property

from .foon import FunctionalUnit, ObjectNode

__all__ = ["Binding", "ObjectState", "PhysicalObject", "PhysicalTrace", "Relation", "TraceError", "TraceStep", "renamed"]


class TraceError(ValueError):
    """A trace that breaks its own invariants (a bug in whoever built it, never bad user input)."""


class Relation(StrEnum):
    """How an object rests on its holder: inside it (`in [bowl]`) or on top of it (`on [cutting board]`)."""

    IN = "in"
    ON = "on"


@dataclass(frozen=True, order=True)
class PhysicalObject:
    """One physical object: its id (a scene id or `bowl_2`, also its PDDL name) and its FOON label."""

    id: str
    label: str


@dataclass(frozen=True)
class ObjectState:
    """Where one object is and in which state.

    `node`: the FOON node whose state the object is in (None: not yet made, or no
    FOON node describes it any more); `holder`/`relation`: what it is in or on
    (None: it stands free); `consumed`: it no longer exists as itself (it became
    part of a mixture, or was eaten up by a unit).
    """

    id: str
    node: ObjectNode | None = None
    holder: str | None = None
    relation: Relation | None = None
    consumed: bool = False

    def __post_init__(self) -> None:
        if (self.holder is None) != (self.relation is None):
            raise TraceError(f"{self.id}: a holder needs a relation and a relation a holder")
        if self.relation is not None:
            object.__setattr__(self, "relation", Relation(self.relation))

    @property
    def exists(self) -> bool:
        """Made and not consumed."""
        return self.node is not None and not self.consumed


@dataclass(frozen=True)
class Binding:
    """One role of a unit bound to an object: the object's node before the step (None: it is made by the
    step) and after it (None: the unit leaves it as it was)."""

    object: str
    before: ObjectNode | None
    after: ObjectNode | None
    #: False for an object the step touches that is no role of the unit (a holder an effect emptied)
    role: bool = True


@dataclass(frozen=True)
class TraceStep:
    """One firing of a unit: `index` in the plan's unit steps (0-based), the unit, its bindings, the new
    state of every object the step changed, and where the step came from (`source`, e.g. `file.txt:12`)."""

    index: int
    unit: FunctionalUnit
    bindings: tuple[Binding, ...]
    changes: tuple[ObjectState, ...]
    source: str = ""
    #: (name, label): names this unit's own words use for one of its objects (`sandwich` for the step's
    #: `club sandwich`), as the builder read them; a replay reads the nodes this step sets through them,
    #: also where the name is another object's label elsewhere in the task
    aliases: tuple[tuple[str, str], ...] = ()

    @property
    def objects(self) -> tuple[str, ...]:
        """The ids of the objects the step binds, in role order."""
        return tuple(b.object for b in self.bindings)


@dataclass(frozen=True)
class PhysicalTrace:
    """Every object, its state before the plan, and the plan's unit steps (see the module doc)."""

    objects: tuple[PhysicalObject, ...]
    initial: tuple[ObjectState, ...]
    steps: tuple[TraceStep, ...]
    #: (name, label): names FOON's lists and places use for an object label, as the trace's builder read
    #: them and reported them (`salad` for `carrot salad`); a replay reads FOON's words through them
    aliases: tuple[tuple[str, str], ...] = ()
    #: (container label, content label): pairs FOON's own nodes contradict each other about (a product
    #: placed in a container whose node does not list it), as the builder reported them: not checked
    gaps: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        ids = [o.id for o in self.objects]
        if len(set(ids)) != len(ids):
            raise TraceError("duplicate object ids: " + ", ".join(sorted({i for i in ids if ids.count(i) > 1})))
        known = set(ids)
        if {s.id for s in self.initial} != known or len(self.initial) != len(known):
            raise TraceError("the initial states must name every object exactly once")
        for n, step in enumerate(self.steps):
            if step.index != n:
                raise TraceError(f"step {n} is numbered {step.index}")
            for name in (*step.objects, *(c.id for c in step.changes)):
                if name not in known:
                    raise TraceError(f"step {n} names an unknown object {name!r}")
        for n, states in enumerate(self.states()):
            _check_holders(states, known, f"before step {n}" if n < len(self.steps) else "after the plan")

    @cached_property
    def by_id(self) -> Mapping[str, PhysicalObject]:
        return {o.id: o for o in self.objects}

    def states(self) -> Iterable[Mapping[str, ObjectState]]:
        """Every object's state before the first step, then after each step (len(steps) + 1 snapshots)."""
        current = {s.id: s for s in self.initial}
        yield dict(current)
        for step in self.steps:
            current.update((c.id, c) for c in step.changes)
            yield dict(current)

    @cached_property
    def final(self) -> Mapping[str, ObjectState]:
        """Every object's state after the plan."""
        *_, last = self.states()
        return last

    def after(self, index: int) -> Mapping[str, ObjectState]:
        """Every object's state after step `index` (-1: before the first step)."""
        for n, states in enumerate(self.states()):
            if n == index + 1:
                return states
        raise IndexError(index)

    def holder_of(self, object_id: str, index: int | None = None) -> str | None:
        """What `object_id` is in or on after step `index` (default: after the plan)."""
        states = self.final if index is None else self.after(index)
        return states[object_id].holder

    def contents(self, holder: str, index: int | None = None) -> tuple[str, ...]:
        """The ids of the existing objects in or on `holder` after step `index` (default: after the plan), sorted."""
        states = self.final if index is None else self.after(index)
        return tuple(sorted(s.id for s in states.values() if s.holder == holder and s.exists))


def _check_holders(states: Mapping[str, ObjectState], known: set[str], when: str) -> None:
    for s in states.values():
        if s.holder is not None and (s.holder not in known or s.holder == s.id):
            raise TraceError(f"{when}: {s.id} is held by {s.holder!r}, which is not another object")
    for start in states:
        seen, at = {start}, states[start].holder
        while at is not None:
            if at in seen:
                raise TraceError(f"{when}: the holders of {start} loop through {at}")
            seen.add(at)
            at = states[at].holder


def renamed(trace: PhysicalTrace, names: Mapping[str, str]) -> PhysicalTrace:
    """`trace` with object ids renamed (`names`: old -> new, others kept): PDDL names back to a scene's ids."""
    def new(x: str | None) -> str | None:
        return names.get(x, x) if x is not None else None

    def state(s: ObjectState) -> ObjectState:
        return replace(s, id=new(s.id), holder=new(s.holder))

    steps = tuple(replace(k, bindings=tuple(replace(b, object=new(b.object)) for b in k.bindings),
                          changes=tuple(map(state, k.changes))) for k in trace.steps)
    return replace(trace, objects=tuple(replace(o, id=new(o.id)) for o in trace.objects),
                   initial=tuple(map(state, trace.initial)), steps=steps)
