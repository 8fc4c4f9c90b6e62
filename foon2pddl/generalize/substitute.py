"""Renaming objects inside nodes and units: the one substitution FOON-EXP and lifted GEN share.

A substitution maps whole object labels to labels. It applies to a node's label,
to the related object of each state (`in [bowl]`) and to each item of its
ingredient lists, never to parts of other labels: replacing `lemon` leaves
`lemon juice` alone. Nodes are rebuilt with `make_state`/`make_node`, so
ingredient lists stay sorted and duplicate-free when two items become one.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.constraints import node_labels
from ..model.foon import FunctionalUnit, ObjectNode, Source, make_node, make_state


def substitute_node(node: ObjectNode, mapping: Mapping[str, str]) -> ObjectNode:
    """`node` with every label in `mapping` replaced (attributes other than identity kept)."""
    get = mapping.get
    states = [make_state(s.label, get(s.related, s.related) if s.related else "",
                         (get(i, i) for i in s.ingredients)) for s in node.states]
    return make_node(get(node.label, node.label), states,
                     motion_flag=node.motion_flag, goal=node.goal, dish=node.dish)


def unit_labels(unit: FunctionalUnit) -> frozenset[str]:
    """Every object label a unit mentions: node labels, related objects and ingredients."""
    return frozenset().union(*(node_labels(n) for n in (*unit.inputs, *unit.outputs)))


def substitute_unit(unit: FunctionalUnit, mapping: Mapping[str, str], note: str | None = None) -> FunctionalUnit:
    """`unit` with labels replaced in every node; `note` marks its sources `expanded_from`."""
    ins = tuple(dict.fromkeys(substitute_node(n, mapping) for n in unit.inputs))
    outs = tuple(dict.fromkeys(substitute_node(n, mapping) for n in unit.outputs))
    sources = unit.sources
    if note is not None:
        sources = tuple(Source(s.path, s.line, s.url, note) for s in unit.sources) or (Source("", 0, None, note),)
    return FunctionalUnit(ins, unit.motion, outs, sources)
