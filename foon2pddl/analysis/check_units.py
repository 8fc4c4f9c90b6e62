"""Structural defects of a network: self-supporting producers, cycles with no entry, units that
change nothing, contents lists that disagree with `in [c]` nodes, mentions of unknown objects."""

from __future__ import annotations

from collections import defaultdict

import networkx as nx

from ..model.foon import Foon, ObjectNode
from ..model.kitchen import default_kitchen, is_base_node
from ..model.words import count, first_of, plural
from .defects import Defect, DefectKind, defect, mentions
from .index import index_of
from .reachability import UNREACHED, reachable

#: Nodes named in one defect's message.
SHOW = 4


def _names(nodes: list[ObjectNode]) -> str:
    return first_of(nodes, SHOW, ObjectNode.describe)


def self_supporting(foon: Foon) -> list[Defect]:
    """Nodes (not in base state) that units output, but only units that also consume them."""
    ix = index_of(foon)
    outputting: dict[int, list[int]] = defaultdict(list)
    for u, outs in enumerate(ix.outputs):
        for n in outs:
            if not ix.makers[n]:
                outputting[n].append(u)
    out = []
    for n, units in sorted(outputting.items()):
        node = ix.nodes[n]
        if is_base_node(node):
            continue
        out.append(defect(DefectKind.SELF_SUPPORTING,
                          f"{node.describe()} is output only by units that also take it as input: "
                          "no unit makes it, so a kitchen must already hold it",
                          (s for u in units for s in foon.units[u].sources), [node.describe()]))
    return out


def no_entry_cycles(foon: Foon) -> list[Defect]:
    """Groups of nodes every way of making which needs another node of the group (and nothing enters).

    Entry: every node no unit makes plus the default kitchen's base-state nodes. The nodes
    still unmakeable that have makers form a "needs" graph (n -> an unmakeable input of a maker
    of n); its strongly connected components with no way out are the cycles; everything that
    needs them is blocked, and counted in the cycle's message. Linear in the network size.
    """
    ix = index_of(foon)
    entry = {ix.nodes[n] for n in range(len(ix.nodes)) if not ix.makers[n]} | default_kitchen(foon).nodes
    reach = reachable(foon, entry)
    stuck = [n for n in range(len(ix.nodes)) if ix.makers[n] and reach.node_round[n] == UNREACHED]
    g = nx.DiGraph()
    g.add_nodes_from(stuck)
    for n in stuck:
        for u in ix.makers[n]:
            g.add_edges_from((n, m) for m in ix.inputs[u] if reach.node_round[m] == UNREACHED and ix.makers[m])
    cond = nx.condensation(g)
    out = []
    for c in sorted(cond.nodes, key=lambda c: min(cond.nodes[c]["members"])):
        members = sorted(cond.nodes[c]["members"])
        if cond.out_degree(c) or (len(members) == 1 and not g.has_edge(members[0], members[0])):
            continue
        inside = set(members)
        units = sorted({u for n in members for u in ix.makers[n] if inside.intersection(ix.inputs[u])})
        blocked = len(nx.ancestors(cond, c)) and sum(len(cond.nodes[a]["members"]) for a in nx.ancestors(cond, c))
        nodes = [ix.nodes[n] for n in members]
        out.append(defect(DefectKind.NO_ENTRY_CYCLE,
                          f"{count(len(nodes), 'node')} can only be made from each other: {_names(nodes)}; "
                          f"{blocked} more {plural(blocked, 'node')} {'needs' if blocked == 1 else 'need'} them",
                          (s for u in units for s in foon.units[u].sources), [n.describe() for n in nodes]))
    return out


def identity_units(foon: Foon) -> list[Defect]:
    """Units whose outputs are exactly their inputs."""
    return [defect(DefectKind.IDENTITY_UNIT, f"unit changes nothing ({u.motion.label}: outputs equal inputs): "
                   + _names(list(u.inputs)), u.sources, [u.describe()])
            for u in foon.units if set(u.inputs) == set(u.outputs)]


def ingredient_mismatches(foon: Foon) -> list[Defect]:
    """Units where a node `x (in [c])` sits beside `c (contains {...})` whose list does not name x."""
    found: dict[tuple, list] = defaultdict(list)
    for unit in foon.units:
        for side in (unit.inputs, unit.outputs):
            for c in side:
                lists = [s for s in c.states if s.label == "contains" and s.ingredients]
                if not lists:
                    continue
                listed = {i for s in lists for i in s.ingredients}
                inside = sorted({n.label for n in side if n is not c
                                 and any(s.label == "in" and s.related == c.label for s in n.states)} - listed)
                if inside:
                    found[(c.describe(), tuple(inside))].extend(unit.sources)
    return [defect(DefectKind.INGREDIENT_MISMATCH,
                   f"{', '.join(inside)} in [{what.split(' (')[0]}] beside {what}, whose contents list lacks "
                   f"{'it' if len(inside) == 1 else 'them'}", sources, [what])
            for (what, inside), sources in sorted(found.items())]


def unknown_objects(foon: Foon) -> list[Defect]:
    """Related objects (`in [x]`) and ingredients (`{x}`) that are no object of the network."""
    labels = {n.label for n in foon.nodes}
    found = {name: sources for name, sources in mentions(foon).items() if name not in labels}
    return [defect(DefectKind.UNKNOWN_OBJECT, f"{name!r} is mentioned (as a related object or ingredient) but no "
                   "unit produces it and no starting node is one", sources, [name])
            for name, sources in sorted(found.items())]
