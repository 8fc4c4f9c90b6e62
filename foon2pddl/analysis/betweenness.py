"""Betweenness centrality of an undirected, unweighted graph: Brandes's algorithm, many sources at once.

networkx's `betweenness_centrality` runs one breadth-first search per source node in Python: on
the level-3 object projection of the shared subgraphs (3,329 nodes, 18,193 edges) `analyze --level 3`
took 68.5 CPU s with one line on stderr for minutes (14.6 CPU s now; docs/datasets.md). Here `BATCH`
sources are searched together with numpy: each BFS level is one sparse product (edges x batch); path
counts go forward level by level, dependencies back (Brandes 2001). The work is the same, O(k (V + E))
for k sources, but in array operations, in steps of about `STEP_WORK` edge visits, each wrapped in the
caller's `Step`, so that a command says how far it is (`betweenness of 3,329 objects: source nodes
1-32 of 3,329 ...`).

Values are networkx's (`normalized=True`; with `k`, the same seeded sample of source nodes
and networkx's rescaling of sampled and other nodes) up to float rounding, rounded to
`DIGITS` decimals so that equal values stay equal whatever order the sums ran in (rankings
then break ties by name).
"""

from __future__ import annotations

import random

import networkx as nx
import numpy as np

from ..io.steps import Step, silent_step

#: Source nodes searched together: 16 was fastest on the projection above (arrays of edges x 16 floats
#: stay in cache; 256 took 3.5x the CPU).
BATCH = 16
#: Edge visits (sources x (nodes + edges)) of one step: about 0.15 CPU s.
STEP_WORK = 1_000_000
#: Decimals kept: far below what any report shows (6), far above float noise (1e-15).
DIGITS = 12


class _Edges:
    """Both directions of every edge, sorted by head: `spread` sums over each node's neighbours."""

    def __init__(self, g: nx.Graph, index: dict) -> None:
        pairs = np.array([(index[a], index[b]) for a, b in g.edges if a != b], dtype=np.int64).reshape(-1, 2)
        tail = np.concatenate([pairs[:, 0], pairs[:, 1]])
        head = np.concatenate([pairs[:, 1], pairs[:, 0]])
        order = np.argsort(head, kind="stable")
        self.tail = tail[order]
        self.heads, self.starts = np.unique(head[order], return_index=True)
        self.n = len(index)

    def spread(self, x: np.ndarray) -> np.ndarray:
        """y[v] = the sum of x[u] over v's neighbours u (one row per node, one column per source)."""
        y = np.zeros((self.n, x.shape[1]))
        if len(self.tail):
            y[self.heads] = np.add.reduceat(x[self.tail], self.starts, axis=0)
        return y


def _dependencies(edges: _Edges, batch: np.ndarray) -> np.ndarray:
    """Brandes's dependency of every node (rows) on each source of `batch` (columns); 0 for the source."""
    cols = np.arange(len(batch))
    dist = np.full((edges.n, len(batch)), -1, dtype=np.int32)
    sigma = np.zeros((edges.n, len(batch)))
    dist[batch, cols], sigma[batch, cols] = 0, 1.0
    frontier, depth = sigma.copy(), 0
    while True:  # forward: shortest-path counts, one BFS level of every source at a time
        reached = edges.spread(frontier)
        new = (dist < 0) & (reached > 0)
        if not new.any():
            break
        depth += 1
        dist[new], sigma[new] = depth, reached[new]
        frontier = np.where(new, sigma, 0.0)
    delta = np.zeros_like(sigma)
    for level in range(depth, 0, -1):  # back: dependencies, from the deepest level up
        at = dist == level
        share = np.where(at, (1.0 + delta) / np.where(at, sigma, 1.0), 0.0)
        delta += np.where(dist == level - 1, sigma * edges.spread(share), 0.0)
    delta[batch, cols] = 0.0
    return delta


def betweenness(g: nx.Graph, k: int | None = None, seed: int = 0, step: Step = silent_step,
                what: str = "nodes") -> dict:
    """Normalized betweenness of every node of `g` (undirected, unweighted), as networkx's
    `betweenness_centrality(g, k, normalized=True, seed=seed)` gives it; each share of the sources
    (`STEP_WORK`) runs in `step("betweenness of N WHAT: source nodes A-B of K")`, a series (one redrawn
    line on a terminal). O(k (V + E))."""
    nodes = list(g.nodes)
    n = len(nodes)
    index = {v: i for i, v in enumerate(nodes)}
    sampled = k is not None and k < n
    picked = [index[s] for s in random.Random(seed).sample(nodes, k)] if sampled else list(range(n))
    edges = _Edges(g, index)
    total = np.zeros(n)
    share = max(BATCH, STEP_WORK // max(1, n + g.number_of_edges()) // BATCH * BATCH)
    for first in range(0, len(picked), share):
        last = min(first + share, len(picked))
        with step(f"betweenness of {n:,} {what}: source nodes {first + 1:,}-{last:,} of {len(picked):,}",
                  series=f"betweenness of {n:,} {what}"):
            for at in range(first, last, BATCH):
                total += _dependencies(edges, np.array(picked[at:min(at + BATCH, last)])).sum(axis=1)
    if n <= 2:
        return dict.fromkeys(nodes, 0.0)
    scale = np.full(n, 1.0 / ((n - 1) * (n - 2)))
    if sampled:  # networkx's rescaling: a sampled node is no source of its own paths
        scale[:] = 1.0 / (len(picked) * (n - 2))
        scale[picked] = 1.0 / ((len(picked) - 1) * (n - 2)) if len(picked) > 1 else np.nan
    return {v: round(float(total[i] * scale[i]), DIGITS) for i, v in enumerate(nodes)}
