"""Wu-Palmer similarity of noun synsets, computed from cached hypernym data.

NLTK's `Synset.wup_similarity` recomputes hypernym closures and depths on every
call (about 3.5 ms a pair); a similarity matrix over ~500 labels needs a million
sense pairs. `WupTable` keeps, per synset, its ancestors with their BFS distances
and the ancestors ordered by NLTK's tie-breaking, and then follows NLTK's
definition exactly (nouns of WordNet >= 2.0, which need no simulated root):

- subsumers: common hypernyms (each synset counts as its own) of greatest
  `min_depth`; the LCS is `self` if it is one of them, else the first by name;
- depth = LCS `max_depth` + 1; len_i = `shortest_path_distance(synset_i, LCS)`;
- wup = 2 depth / (len_1 + len_2 + 2 depth).

NLTK's tie-breaking makes wup(a, b) and wup(b, a) differ in rare cases; callers
wanting a symmetric value pass the pair in a canonical order.

`deepest` is the variant the cook's similarity uses (`cook.py`): the LCS is the
common hypernym of greatest `max_depth` (ties: name), not of greatest `min_depth`.
The two differ when a synset has two hypernym paths of different lengths: `lemon.n.01`
(the food) reaches `citrus.n.01` through `edible_fruit.n.01`, which is both a
`produce.n.01` (a food, min_depth 6) and a `fruit.n.01` (a plant part, max_depth 9).
NLTK compares common hypernyms by their shortest path to the root, so a shallow
subsumer reached by a short path can win over a deeper one; with the deepest common
ancestor, two synsets one link below `citrus.n.01` always score as siblings there.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass


@dataclass(frozen=True)
class _Info:
    dist: dict[str, int]  # ancestor name (self included) -> shortest number of hypernym links
    order: tuple[str, ...]  # ancestors by descending min_depth, then name (NLTK's LCS preference)
    min_depth: int
    max_depth: int


class WupTable:
    """Wu-Palmer over NLTK synsets, with per-synset data computed once."""

    def __init__(self, reader) -> None:
        self._wn = reader
        self._info: dict[str, _Info] = {}
        self._spd: dict[tuple[str, str], int] = {}
        self._pairs: dict[tuple[str, str], tuple[int, int, int] | None] = {}

    def info(self, name: str) -> _Info:
        """Hypernym data of the synset called `name` (e.g. `onion.n.03`)."""
        found = self._info.get(name)
        if found is None:
            found = self._info[name] = self._build(self._wn.synset(name))
        return found

    def _build(self, synset) -> _Info:
        dist: dict[str, int] = {}
        objs = {}
        queue = deque([(synset, 0)])
        while queue:  # breadth first, as NLTK's `_shortest_hypernym_paths`
            s, d = queue.popleft()
            if s.name() in dist:
                continue
            dist[s.name()] = d
            objs[s.name()] = s
            for h in s.hypernyms() + s.instance_hypernyms():
                queue.append((h, d + 1))
        mind = {n: s.min_depth() for n, s in objs.items()}
        order = tuple(sorted(dist, key=lambda n: (-mind[n], n)))
        return _Info(dist, order, synset.min_depth(), synset.max_depth())

    def _distance(self, name: str, ancestor: str) -> int:
        """NLTK's `shortest_path_distance(name, ancestor)` for an ancestor of `name`."""
        if name == ancestor:
            return 0
        key = (name, ancestor)
        found = self._spd.get(key)
        if found is None:
            mine, theirs = self.info(name).dist, self.info(ancestor).dist
            found = self._spd[key] = min(mine[x] + d for x, d in theirs.items())
        return found

    def components(self, a: str, b: str) -> tuple[int, int, int] | None:
        """(depth, len_a, len_b) of NLTK's wup(a, b), or None when a and b share no hypernym."""
        key = (a, b)
        if key in self._pairs:
            return self._pairs[key]
        ia, ib = self.info(a), self.info(b)
        first = next((x for x in ia.order if x in ib.dist), None)
        if first is None:
            result = None
        else:
            best = self.info(first).min_depth
            lcs = a if (a in ib.dist and ia.min_depth == best) else first
            result = (self.info(lcs).max_depth + 1, self._distance(a, lcs), self._distance(b, lcs))
        self._pairs[key] = result
        return result

    def subsumer(self, a: str, b: str) -> str | None:
        """The LCS NLTK's wup(a, b) uses (see the module doc), or None."""
        ia, ib = self.info(a), self.info(b)
        first = next((x for x in ia.order if x in ib.dist), None)
        if first is None:
            return None
        return a if (a in ib.dist and ia.min_depth == self.info(first).min_depth) else first

    def deepest(self, a: str, b: str) -> tuple[str, int, int, int] | None:
        """(LCS, depth, len_a, len_b) with the deepest common hypernym as LCS (greatest max_depth, then name).

        depth = LCS max_depth + 1 and len_i = shortest hypernym distance to the LCS, as in
        `components`; symmetric by construction. O(ancestors of a) set lookups.
        """
        ia, ib = self.info(a), self.info(b)
        common = [x for x in ia.dist if x in ib.dist]
        if not common:
            return None
        lcs = min(common, key=lambda x: (-self.info(x).max_depth, x))
        return lcs, self.info(lcs).max_depth + 1, self._distance(a, lcs), self._distance(b, lcs)

    def ancestors(self, name: str) -> frozenset[str]:
        """Every hypernym of synset `name`, itself included."""
        return frozenset(self.info(name).dist)

    def wup(self, a: str, b: str) -> float | None:
        """Wu-Palmer similarity of synsets `a` and `b` exactly as NLTK computes `a.wup_similarity(b)`."""
        c = self.components(a, b)
        if c is None:
            return None
        depth, la, lb = c
        return 2.0 * depth / (la + lb + 2 * depth)
