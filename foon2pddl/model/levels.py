"""Hierarchy levels: how much of a node counts as its identity.

Level 1 = object label; level 2 = label + states (state label with its related
object); level 3 = level 2 + ingredient lists. Every algorithm projects the
network, kitchen and goal to one level first and then compares nodes with `==`.
"""

from __future__ import annotations

from ..errors import UsageError
from .bulk import bulk
from .dedupe import deduped
from .foon import Foon, FunctionalUnit, ObjectNode, State

LEVELS = (1, 2, 3)


def check_level(level: int) -> int:
    """Validate a level number."""
    if level not in LEVELS:
        raise UsageError(f"level must be 1, 2 or 3, not {level!r}")
    return level


def project_node(node: ObjectNode, level: int) -> ObjectNode:
    """The node as seen at `level` (attributes kept)."""
    if level == 3:
        return node
    if level == 1:
        states: tuple[State, ...] = ()
    else:
        states = tuple(sorted({State(s.label, s.related) for s in node.states}))
    return ObjectNode(node.label, states, node.motion_flag, node.goal, node.dish)


def project_unit(unit: FunctionalUnit, level: int, node=None) -> FunctionalUnit:
    """A unit with its nodes projected, one per node of `unit`: nodes that become equal stay listed each time.

    A unit's nodes are its objects (`pairing.unit_roles`): the pour from `bowl (contains {egg})` into `bowl
    (contains {flour})` is a pour between two bowls at level 2 too, where both are `bowl (contains)`; kept once,
    it had one bowl, the egg never left it, and the dish was unsolvable for the encodings with objects. A set of
    nodes is unchanged (`tree`: FOON's semantics, the same facts). `node` replaces `project_node(n, level)` (used
    by `project` to memoize).
    """
    if level == 3:
        return unit
    node = node or (lambda n: project_node(n, level))
    return FunctionalUnit(tuple(map(node, unit.inputs)), unit.motion, tuple(map(node, unit.outputs)), unit.sources)


@bulk
def project(foon: Foon, level: int) -> Foon:
    """The network at `level` with units that became identical merged (provenance joined)."""

    check_level(level)
    if level >= foon.level:
        return foon
    # Node instances recur across units: project each instance once (keyed by id, so
    # attributes such as the motion flag stay those of the instance; `foon` keeps them alive).
    memo: dict[int, ObjectNode] = {}

    def node(n: ObjectNode) -> ObjectNode:
        p = memo.get(id(n))
        if p is None:
            p = memo[id(n)] = project_node(n, level)
        return p

    return deduped((project_unit(u, level, node) for u in foon.units), level)
