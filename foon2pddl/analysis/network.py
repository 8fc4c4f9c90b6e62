"""Network analysis of a FOON in the style of Paulius et al. (IROS 2016), via networkx.

The FOON is a bipartite graph of object nodes and motion nodes (one motion node
per functional unit; edges input -> motion -> output). Objects are compared by
label (level 1, as the paper ranks objects) unless `level` 3 keeps whole nodes.
- object-object projection: two objects are linked when they take part in one
  functional unit (weight: how many units they share);
- motion-motion projection: two motion labels are linked when a unit of one makes
  an object node (level 3) that a unit of the other takes (weight: such unit pairs);
- degree centrality (networkx: degree / (n - 1)) and betweenness centrality
  (shortest paths, unweighted, normalized) of every node of each projection;
- connected components of the bipartite graph (undirected).
Betweenness (`betweenness.py`: Brandes, batched breadth-first searches, networkx's values) is
exact while its work, O(V (V + E)), is at most `BETWEENNESS_WORK` (7.2e7 on the universal
FOON of the shared subgraphs at level 3: exact, `analyze` 14.6 CPU s, 68.5 with networkx); beyond
it, it is estimated from k = max(`MIN_SOURCES`, BETWEENNESS_WORK / (V + E)) source nodes
drawn with a fixed seed (networkx's `k` sampling, deterministic), so its cost stays bounded
on any network, and the outputs say so (`Analysis.sampled`). Slow parts run in the caller's
`Step` (a command says what it does and how far it is). Ties in rankings break by label.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from itertools import combinations

import networkx as nx

from ..io.steps import Step, silent_step
from ..model.foon import Foon, ObjectNode
from ..model.words import count
from .betweenness import betweenness

#: Most edge visits (V (V + E) for exact betweenness) spent on one projection's betweenness.
BETWEENNESS_WORK = 100_000_000
#: Fewest source nodes of a sampled estimate, and the seed that draws them.
MIN_SOURCES = 10
SAMPLE_SEED = 0


def _object_key(node: ObjectNode, level: int) -> str:
    return node.label if level == 1 else node.describe()


def bipartite(foon: Foon, level: int = 1) -> nx.DiGraph:
    """Object nodes (`kind=object`) and one motion node per unit (`kind=motion`, `motion=label`)."""
    g = nx.DiGraph()
    for i, unit in enumerate(foon.units):
        m = f"unit {i}: {unit.motion.label}"
        src = unit.source
        g.add_node(m, kind="motion", motion=unit.motion.label,
                   source=f"{src.path}:{src.line}" if src else "")
        for n in unit.inputs:
            g.add_node(_object_key(n, level), kind="object")
            g.add_edge(_object_key(n, level), m)
        for n in unit.outputs:
            g.add_node(_object_key(n, level), kind="object")
            g.add_edge(m, _object_key(n, level))
    return g


def object_projection(foon: Foon, level: int = 1) -> nx.Graph:
    """Objects linked when they take part in one unit; `weight` = units shared."""
    weights: Counter = Counter()
    g = nx.Graph()
    for unit in foon.units:
        objs = sorted({_object_key(n, level) for n in (*unit.inputs, *unit.outputs)})
        g.add_nodes_from(objs, kind="object")
        weights.update(combinations(objs, 2))
    g.add_weighted_edges_from((a, b, w) for (a, b), w in sorted(weights.items()))
    return g


def motion_projection(foon: Foon) -> nx.Graph:
    """Motion labels linked when a unit of one makes a node (level 3) a unit of the other takes:
    one follows the other in some recipe. `weight` = such unit pairs. Self-links are left out."""
    weights: Counter = Counter()
    for n, makers in foon.producers.items():
        for c in foon.consumers.get(n, ()):
            for m in makers:
                a, b = foon.units[m].motion.label, foon.units[c].motion.label
                if a != b and m != c:
                    weights[tuple(sorted((a, b)))] += 1
    g = nx.Graph()
    g.add_nodes_from(sorted({u.motion.label for u in foon.units}), kind="motion")
    g.add_weighted_edges_from((a, b, w) for (a, b), w in sorted(weights.items()))
    return g


@dataclass(frozen=True)
class Ranked:
    """One node of a projection with its centralities."""

    name: str
    degree: int
    degree_centrality: float
    betweenness: float

    def as_dict(self) -> dict:
        return {"name": self.name, "degree": self.degree, "degree_centrality": round(self.degree_centrality, 6),
                "betweenness": round(self.betweenness, 6)}


@dataclass(frozen=True)
class Analysis:
    """Centralities of both projections, and the components of the bipartite graph."""

    objects: tuple[Ranked, ...]     # sorted by degree centrality, then betweenness, then name
    motions: tuple[Ranked, ...]
    components: tuple[int, ...]     # sizes (objects + motion nodes), largest first
    object_count: int
    unit_count: int
    level: int
    sampled: tuple[tuple[str, int], ...] = ()  # (projection, source nodes) of betweenness estimated by sampling

    def top(self, which: str, key: str, n: int) -> list[Ranked]:
        """The `n` highest of `which` (objects or motions) by `key` (degree_centrality or betweenness)."""
        items = self.objects if which == "objects" else self.motions
        return sorted(items, key=lambda r: (-getattr(r, key), r.name))[:n]


def sources(g: nx.Graph) -> int | None:
    """Source nodes `rank` samples for the betweenness of `g`; None when it is exact (within BETWEENNESS_WORK)."""
    v, size = g.number_of_nodes(), g.number_of_nodes() + g.number_of_edges()
    if v * size <= BETWEENNESS_WORK:
        return None
    return min(v, max(MIN_SOURCES, BETWEENNESS_WORK // size))


def rank(g: nx.Graph, what: str = "nodes", step: Step = silent_step) -> tuple[Ranked, ...]:
    """Degree and betweenness centrality of every node of `g` (betweenness sampled when `sources(g)` says so,
    in steps of `step` naming `what` the nodes are)."""
    if g.number_of_nodes() == 0:
        return ()
    deg = nx.degree_centrality(g)
    btw = betweenness(g, k=sources(g), seed=SAMPLE_SEED, step=step, what=what)
    out = [Ranked(n, g.degree(n), deg[n], btw[n]) for n in g.nodes]
    return tuple(sorted(out, key=lambda r: (-r.degree_centrality, -r.betweenness, r.name)))


def analyze(foon: Foon, level: int = 1, step: Step = silent_step) -> Analysis:
    """Both projections ranked, and the connected components of the bipartite graph (slow parts in `step`)."""
    with step(f"projecting {count(len(foon.units), 'unit', grouped=True)} (objects, motions, components)"):
        b = bipartite(foon, level)
        sizes = tuple(sorted((len(c) for c in nx.weakly_connected_components(b)), reverse=True))
        og, mg = object_projection(foon, level), motion_projection(foon)
    objects = rank(og, "objects", step)
    estimated = tuple((name, k) for name, g in (("objects", og), ("motions", mg)) if (k := sources(g)) is not None)
    return Analysis(objects, rank(mg, "motions", step), sizes, len(objects), len(foon.units), level, estimated)


def graphml_graphs(foon: Foon, result: Analysis) -> dict[str, nx.Graph]:
    """The bipartite graph and both projections with centralities as node attributes (for GraphML)."""
    b = bipartite(foon, result.level)
    objects = object_projection(foon, result.level)
    motions = motion_projection(foon)
    for g, ranked in ((objects, result.objects), (motions, result.motions)):
        for r in ranked:
            g.nodes[r.name].update(degree_centrality=r.degree_centrality, betweenness=r.betweenness)
    for r in result.objects:
        b.nodes[r.name].update(degree_centrality=r.degree_centrality, betweenness=r.betweenness)
    return {"foon": b, "objects": objects, "motions": motions}
