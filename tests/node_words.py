"""Short builders for FOON nodes in tests: `n("bowl", contains("salt"))`, `n("salt", inside("bowl"))`."""

from __future__ import annotations

from foon2pddl.model.foon import ObjectNode, State, make_node, make_state


def n(label: str, *states: State | str) -> ObjectNode:
    """A node of `label`; a plain string is a state with no related object (`"chopped"`)."""
    return make_node(label, [s if not isinstance(s, str) else make_state(s) for s in states])


def contains(*items: str) -> State:
    return make_state("contains", "", items)


def inside(holder: str) -> State:
    return make_state("in", holder)
