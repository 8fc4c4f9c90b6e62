"""Container/content duality: `--containment strict|infer` (definition in docs/format.md).

FOON describes "cornmeal is in the bowl" from two sides: the content node
`cornmeal (ground, in [bowl])` and the container node `bowl (contains {cornmeal})`.
Under `strict` (the default) they are unrelated nodes. Under `infer`, one rule
(the *containment rule*) makes a container node available from its contents:

level 3: `c (contains {x1, ..., xk}, R...)` (k >= 1; R = its other states, possibly
none) is available when, for every xi, some available node labelled xi has the state
`in [c]` (whatever its other states), and, when R is not empty, the node `c (R...)`
(the container in exactly its other states) is available. Level 2 forgets the lists:
`c (contains, R...)` needs one available node of any label in state `in [c]`, plus
`c (R...)` as above. Level 1 has no states: nothing is inferred. The reverse (a
content from its container) is not inferred: the container does not say which
states its contents are in.

The rule is applied in one way everywhere: `with_containment` adds *inference
units* (motion `INFER_MOTION`) that encode it, so every search, the PDDL
encodings (as derived actions) and the experiment use it unchanged; `rule_holds`
is the rule itself, used by the validator to check inference steps and to infer
a missing container input (an oracle independent of the inference units).
For k >= 2 (or a container with other states), auxiliary nodes
`x (inferred in [c])` stand for "some x is in c" (an OR over the witnesses).
"""

from __future__ import annotations

from collections.abc import Iterable
from enum import StrEnum

from .foon import Foon, FunctionalUnit, Motion, ObjectNode, Source, State

#: Motion label of inference units; `SOURCE` marks them (a recipe cannot produce it).
INFER_MOTION = "infer containment"
SOURCE = "<containment rule>"
#: State label of the auxiliary "some x is in c" nodes.
INFERRED_IN = "inferred in"
#: Content wildcard at level 2 (lists are not part of identity there).
ANY = "*"


class Containment(StrEnum):
    """How container and content nodes relate (see the module doc)."""

    STRICT = "strict"
    INFER = "infer"


def is_inference(unit: FunctionalUnit) -> bool:
    """Whether `unit` is an inference unit added by `with_containment`."""
    return unit.motion.label == INFER_MOTION and bool(unit.sources) and unit.sources[0].path == SOURCE


def is_auxiliary(node: ObjectNode) -> bool:
    """Whether `node` is an auxiliary `x (inferred in [c])` node."""
    return len(node.states) == 1 and node.states[0].label == INFERRED_IN


def container_parts(node: ObjectNode, level: int) -> tuple[frozenset[str], tuple[State, ...]] | None:
    """(contents, other states) of a container node at `level`, or None when it holds no `contains` state.

    Contents: the ingredient lists of its `contains` states and their related objects (`contains [x]`);
    at level 2 the wildcard `ANY`.
    """
    if level < 2:
        return None
    holds = [s for s in node.states if s.label == "contains"]
    if not holds:
        return None
    other = tuple(s for s in node.states if s.label != "contains")
    if level == 2:
        return frozenset({ANY}), other
    contents = frozenset(i for s in holds for i in s.ingredients) | {s.related for s in holds if s.related}
    contents -= {node.label}
    return (contents, other) if contents else None


def _inside(node: ObjectNode, container: str) -> bool:
    return any(s.label == "in" and s.related == container for s in node.states)


def _witness_key(node: ObjectNode, container: str, content: str) -> bool:
    return _inside(node, container) and (content == ANY or node.label == content)


def rule_holds(node: ObjectNode, available: Iterable[ObjectNode], level: int) -> bool:
    """The containment rule applied directly: is `node` (a container or auxiliary node) inferable from `available`?"""
    pool = available if isinstance(available, (set, frozenset)) else set(available)
    if is_auxiliary(node):
        c = node.states[0].related
        return any(_witness_key(n, c, node.label) for n in pool)
    parts = container_parts(node, level)
    if parts is None:
        return False
    contents, other = parts
    if other and ObjectNode(node.label, other) not in pool:
        return False
    return all(any(_witness_key(n, node.label, x) for n in pool) for x in contents)


def _unit(inputs: Iterable[ObjectNode], output: ObjectNode) -> FunctionalUnit:
    return FunctionalUnit(tuple(inputs), Motion(INFER_MOTION), (output,), (Source(SOURCE),))


def inference_units(nodes: Iterable[ObjectNode], pool: Iterable[ObjectNode], level: int) -> tuple[FunctionalUnit, ...]:
    """Inference units making each container among `nodes` from the witnesses in `pool` (sorted, deterministic).

    Time: O(|pool| + sum over containers of their witnesses).
    """
    pool = sorted(set(pool))
    present = set(pool)
    inside: dict[str, list[ObjectNode]] = {}
    for n in pool:
        for s in n.states:
            if s.label == "in" and s.related:
                inside.setdefault(s.related, []).append(n)
    units: dict[tuple, FunctionalUnit] = {}
    for c in sorted(set(nodes)):
        parts = container_parts(c, level)
        if parts is None:
            continue
        contents, other = parts
        base = ObjectNode(c.label, other) if other else None
        if base is not None and base not in present:
            continue
        witnesses = {x: [n for n in dict.fromkeys(inside.get(c.label, ())) if x == ANY or n.label == x]
                     for x in sorted(contents)}
        if not all(witnesses.values()):
            continue
        extra = (base,) if base is not None else ()
        if len(contents) == 1:
            (ws,) = witnesses.values()
            for w in ws:
                u = _unit((w, *extra), c)
                units.setdefault(u.key, u)
            continue
        aux_nodes = []
        for x, ws in witnesses.items():
            aux = ObjectNode(x, (State(INFERRED_IN, c.label),))
            aux_nodes.append(aux)
            for w in ws:
                u = _unit((w,), aux)
                units.setdefault(u.key, u)
        u = _unit((*aux_nodes, *extra), c)
        units.setdefault(u.key, u)
    return tuple(units[k] for k in sorted(units, key=lambda k: (sorted(k[2]), sorted(k[1]))))


def with_containment(foon: Foon, kitchen_nodes: Iterable[ObjectNode], mode: Containment | str) -> Foon:
    """`foon` itself under strict; under infer, `foon` plus the inference units for its container nodes
    (witnesses taken from its nodes and the kitchen's)."""
    if Containment(mode) is Containment.STRICT or foon.level < 2:
        return foon
    kitchen = frozenset(kitchen_nodes)
    containers = [n for n in foon.nodes if n not in kitchen]
    extra = inference_units(containers, (*foon.nodes, *kitchen), foon.level)
    if not extra:
        return foon
    return Foon(foon.units + extra, foon.level)


def inferred_nodes(units: Iterable[FunctionalUnit]) -> tuple[ObjectNode, ...]:
    """The container nodes that inference units among `units` make (auxiliary nodes left out), in order."""
    return tuple(dict.fromkeys(o for u in units if is_inference(u) for o in u.outputs if not is_auxiliary(o)))


def containment_of(units: Iterable[FunctionalUnit]) -> Containment:
    """INFER when any of `units` is an inference unit (a network or task built under infer), else STRICT."""
    return Containment.INFER if any(is_inference(u) for u in units) else Containment.STRICT


def count_inference(units: Iterable[FunctionalUnit]) -> int:
    """How many of `units` are inference units."""
    return sum(map(is_inference, units))
