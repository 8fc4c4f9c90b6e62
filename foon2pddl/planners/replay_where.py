"""Where a step does its work, read off holders and bindings alone: the physical replay's checks that read no
FOON list (`physical_replay`'s module doc gives the rules), so they hold for the pairs a trace reports
(`PhysicalTrace.gaps`: FOON's nodes contradict each other about a container and a content label, and the encoding
binds the holder late). Stop 60 found level-2 plans the list checks could not see: 0050 mixed the milk in bowl_2
into the egg mixture made in bowl_1.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from ..model.foon import ObjectNode
from ..model.physical import ObjectState, Relation, TraceStep
from .replay_findings import DisagreementKind

__all__ = ["where_done"]


def where_done(step: TraceStep, before: Mapping[str, ObjectState], after: Mapping[str, ObjectState],
               label: Mapping[str, str], kept: Callable[[str, ObjectState], bool],
               named: Callable[[ObjectNode, str], set[str]], said: set[tuple[DisagreementKind, str]],
               add: Callable[[DisagreementKind, tuple[str, ...], str], None]) -> None:
    """Report, through `add`, each object of `step` worked on where the step does not work.

    A consumed object is in the holder of what the step makes, unless the step brings it there (`brought`):
    `CONSUMED_ELSEWHERE`. An object the step changes in place, uses up or moves, in a holder of label C, while
    the step changes objects labelled C it binds as roles or chosen holders (none where anything arrives, nor
    what holds that), is in a C the step binds so: `HOLDER_NOT_BOUND`, `WRONG_SOURCE` for a move, unless `said`
    (kind, object) already. `label`: object -> label; `kept(oid, state)`: still in the undescribed start holder
    (exempt); `named(node, oid)`: the holder labels the node names. O(bindings x (bindings + depth)).
    """
    made = {b.object for b in step.bindings if b.before is None}
    ours: dict[str, set[str]] = {}  # label -> the objects the step binds and changes, there before it
    for b in step.bindings:
        if b.role and b.object not in made and before[b.object].exists and b.after not in (None, b.before):
            ours.setdefault(label[b.object], set()).add(b.object)
    products: dict[str, list[str]] = {}
    for m in sorted(made):
        if after[m].exists and after[m].holder is not None:
            products.setdefault(after[m].holder, []).append(m)
    bound = {b.object for b in step.bindings if b.role}  # the unit's objects and the holders the step chose
    into = set().union(*(chain(after[b.object].holder, after) for b in step.bindings  # where things arrive
                         if after[b.object].exists and after[b.object].holder != before[b.object].holder))
    for b in step.bindings:
        x, was, now = b.object, before[b.object], after[b.object]
        if b.before is None or not was.exists or was.holder is None or kept(x, was):
            continue
        if now.consumed and products:
            h = was.holder
            while h is not None and after[h].consumed and not before[h].consumed:  # on a mixture consumed too
                h = before[h].holder
            kinds = {label[p] for p in products}
            if h is not None and h not in products and not brought(step, was, label[was.holder], kinds,
                                                                   named(b.before, x)):
                where = ", ".join(f"{', '.join(ms)} in {p}" for p, ms in sorted(products.items()))
                add(DisagreementKind.CONSUMED_ELSEWHERE, (x, h, *sorted(products)),
                    f"{x} is consumed in {h}, but the step makes {where}")
            continue
        if now == was:  # only used (the carton a portion is poured from): where is the unit's business
            continue
        moved = now.holder != was.holder and not now.consumed
        others = ours.get(label[was.holder], set()) - {x} - into
        kind = DisagreementKind.WRONG_SOURCE if moved else DisagreementKind.HOLDER_NOT_BOUND
        if others and was.holder not in bound and (kind, x) not in said:
            add(kind, (x, was.holder, *sorted(others)),
                f"the step uses {', '.join(sorted(others))}, but {x} is {was.relation} {was.holder}")


def brought(step: TraceStep, was: ObjectState, kind: str, made_in: set[str], places: set[str]) -> bool:
    """Whether the step itself takes an object from its holder (of label `kind`) to what it makes (in holders
    labelled `made_in`): it rests on its holder (the slice lifted onto the sandwich), or the unit names a `kind`
    besides where it makes its products (the measuring cup of a pour and stir), or the object's node (`places`)
    names its `kind` where the products are in another (the meat scooped from the pan onto the tortilla)."""
    if was.relation is Relation.ON:
        return True
    there = sum(n.label == kind for n in step.unit.inputs) - (kind in made_in)
    return there > 0 or (kind not in made_in and kind in places)


def chain(h: str | None, states: Mapping[str, ObjectState]) -> set[str]:
    """`h` and every holder it is in or on, outward. O(depth)."""
    out: set[str] = set()
    while h is not None and h not in out:
        out.add(h)
        h = states[h].holder
    return out
