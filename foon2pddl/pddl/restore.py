"""Generic restoring units (`plan`'s restore option) a cook may accept beyond FOON (wash, empty, switch off), and the
object counts they allow.

FOON has a unit for what its videos show; it rarely washes the knife or empties the bowl, so a plan over
physical objects takes a fresh clean knife for every cut (`instance_counts`: one object per use). With
the restore option, an assumption beyond FOON, the network gains restoring units: per label whose kitchen state
`S` is a *ready* state (no place, every state one of `READY`: `knife (clean)`, `bowl (clean, empty)`,
`stove (off)`), one unit per node `N` a unit of the network leaves an object of that label in (no place,
not a kitchen node, not `S`), turning `N` back into `S`. Its motion says what it does (`restore_motion`):
`wash` a node with `dirty`, `empty` a node that lists contents (they are thrown away), `turn off` a node
that is `on`, else `restore`. Its source is `assumed-restore:K` (K numbers them), so every note and plan step
says it is an assumption.

The counts: the plan `instance_counts.derive_counts` unfolds is replayed object by object in firing
order (`restore_counts`); a unit that needs an object in a ready kitchen state takes one there, else
restores one of that label that sits in a node it can restore and that no later firing needs, else the
kitchen needs one more. Each ready kitchen state gets that peak as its stated count (`2 x knife (clean)`;
the kitchen's own stated counts, and the caller's instance overrides, win). O(firings x roles x nodes of the label).
A plan at those counts may still use them one after another where the counts had two in use at once (the
planner takes the second clean board rather than wash the first): `fewer` lowers each count this module stated
to the most the plan had busy at once (`planners.copies.busy`), for `planners.solve.plan_restoring` to plan again.

>>> from foon2pddl.model.foon import make_node, make_state
>>> restore_motion(make_node("knife", [make_state("dirty")]))
'wash'
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, Source
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.pairing import RoleKind, unit_roles
from ..model.places import listed, places
from .encoding import at_level
from .instance_counts import InstanceCounts, derive_counts
from .prune import restoring_units

__all__ = ["READY", "RESTORE_SOURCE", "discards", "fewer", "is_restoring", "ready_states", "restore_counts", "restore_motion",
           "restoring_network", "returns", "with_restore"]

#: States a ready kitchen state may have (and nothing else).
READY = frozenset({"clean", "empty", "off", "washed", "dry", "closed"})
#: The source path of every restoring unit (`assumed-restore:K`).
RESTORE_SOURCE = "assumed-restore"


def ready_states(kitchen: Iterable[ObjectNode]) -> dict[str, ObjectNode]:
    """Label -> its one ready kitchen state (labels with none, or several, are left out)."""
    found: dict[str, list[ObjectNode]] = {}
    for n in kitchen:
        if not places(n) and n.states and all(s.label in READY for s in n.states):
            found.setdefault(n.label, []).append(n)
    return {label: ns[0] for label, ns in sorted(found.items()) if len(ns) == 1}


def restore_motion(node: ObjectNode) -> str:
    """What turns `node` back into a ready state: `wash`, `empty`, `turn off`, or `restore`."""
    labels = {s.label for s in node.states}
    if "dirty" in labels:
        return "wash"
    if listed(node):
        return "empty"
    return "turn off" if "on" in labels else "restore"


def discards(unit: FunctionalUnit) -> bool:
    """Whether `unit` is a restoring unit that empties a container: what is in or on it is thrown away."""
    return is_restoring(unit) and unit.motion.label == "empty"


def is_restoring(unit: FunctionalUnit) -> bool:
    """Whether `unit` is one of the restoring units (`restoring_network`), by its source."""
    return bool(unit.sources) and unit.sources[0].path == RESTORE_SOURCE


def restoring_network(foon: Foon, kitchen: Iterable[ObjectNode],
                      among: Iterable[int] | None = None) -> tuple[Foon, dict[str, ObjectNode]]:
    """`foon` with the restoring units (module doc) appended, for the nodes the units `among` (default: all)
    leave objects in, and the ready state of each label they restore."""
    kitchen = frozenset(kitchen)
    ready = ready_states(kitchen)
    units = foon.units if among is None else [foon.units[u] for u in among]
    targets = sorted({n for u in units for n in u.outputs
                      if n.label in ready and n not in kitchen and n != ready[n.label] and not places(n)})
    units = tuple(FunctionalUnit((n,), Motion(restore_motion(n)), (ready[n.label],), (Source(RESTORE_SOURCE, k),))
                  for k, n in enumerate(targets, start=1))
    return Foon(foon.units + units), {label: ready[label] for label in sorted({n.label for n in targets})}


def returns(foon: Foon) -> dict[ObjectNode, ObjectNode]:
    """Node -> the ready state a restoring unit of `foon` turns it back into (`knife (dirty)` -> `knife (clean)`)."""
    return {u.inputs[0]: u.outputs[0] for u in foon.units if is_restoring(u)}


def fewer(counted: Kitchen, given: Kitchen, back: Mapping[ObjectNode, ObjectNode], have: Mapping[ObjectNode, int],
          peak: Mapping[ObjectNode, int]) -> Kitchen | None:
    """`counted` stating, for each ready state the restoring units `back` (`returns`) turn objects back into and
    whose count `given` (the kitchen as given) does not state, `peak` objects (the most a plan had busy at once,
    at least one) where the plan had more (`have`); None when no count is lower."""
    own = dict(given.counts)
    low = {n: max(1, peak.get(n, 0)) for n in sorted(set(back.values()))
           if n not in own and max(1, peak.get(n, 0)) < have.get(n, 0)}
    return replace(counted, counts=tuple(sorted({**dict(counted.counts), **low}.items()))) if low else None


def restore_counts(foon: Foon, counts: InstanceCounts, ready: Mapping[str, ObjectNode]) -> dict[ObjectNode, int]:
    """Ready kitchen node -> objects the unfolded plan of `counts` needs in it when restoring units reuse them
    (module doc); only the nodes of `ready` the counts place objects in, and only when `counts` has the
    unfolded plan ({} otherwise)."""
    if not counts.unfolded:
        return {}
    firings = dict(counts.firings)
    order = [u for u in counts.unfolded for _ in range(firings.get(u, 1))]
    restorable = {n for n, r in returns(foon).items() if r == ready.get(n.label)}
    ahead: Counter[ObjectNode] = Counter(r.before for u in order for r in unit_roles(foon.units[u]) if r.before)
    at: Counter[ObjectNode] = Counter()
    need: Counter[ObjectNode] = Counter()
    for u in order:
        roles = unit_roles(foon.units[u])
        ahead.subtract(r.before for r in roles if r.before)
        for r in roles:
            if r.before is None:
                at[r.after] += 1
                continue
            if at[r.before] == 0:
                free = [n for n in sorted(restorable) if n.label == r.label and at[n] > max(ahead[n], 0)]
                if free and ready.get(r.label) == r.before:
                    at[free[0]] -= 1  # restored: washed, emptied or switched off
                else:
                    need[r.before] += 1
                at[r.before] += 1
            if r.kind is RoleKind.MOVED:
                at[r.before] -= 1
                at[r.after] += 1
    wanted = set(ready.values())
    return {n: max(need[n], 1) for n, _ in counts.at_node if n in wanted}


def with_restore(foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3) -> tuple[Foon, Kitchen]:
    """`foon` with its restoring units, and `kitchen` stating the counts they allow in its ready states
    (`restore_counts`, at `level`; the kitchen's own stated counts win): what `plan` and `compile_goal` take."""
    if level != foon.level:  # unit indexes below are the network's own: project it first (`model.levels`)
        raise ValueError(f"restoring units are built at the network's level ({foon.level}), not {level}")
    plain = at_level(foon, kitchen, goal, level)  # restoring units only for what the goal's units leave
    augmented, ready = restoring_network(foon, kitchen.nodes, restoring_units(plain.foon, plain.kitchen,
                                                                              plain.candidates))
    if level < kitchen.level:  # counts are stated at the kitchen's own level
        return augmented, kitchen
    inp = at_level(augmented, kitchen, goal, level)
    counts = derive_counts(inp.foon, tuple(range(len(foon.units))), inp.kitchen, inp.candidates,
                           stated=kitchen.project(level).stated_counts())
    mine = restore_counts(inp.foon, counts, ready)  # the kitchen as given: its ready states are `ready`'s
    own = dict(kitchen.counts)
    return augmented, replace(kitchen, counts=tuple(sorted({**mine, **own}.items())),
                              restored=frozenset(n for n in mine if n not in own))
