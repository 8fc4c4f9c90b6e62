"""Similarity of object labels (Wu-Palmer over WordNet), and the cached similarity matrix.

Rule, for two different labels `a` and `b` (a label is 1.0 similar to itself):
- a pair fixed in the overrides file has that value;
- a label with no kitchen-relevant sense (see `senses.resolve`) is similar to nothing (0.0);
- both found as whole terms: the greatest Wu-Palmer similarity over their sense pairs;
- both found only by their head nouns (`blueberry muffin`, `bran muffin`): the heads'
  similarity times the similarity of the modifiers (`blueberry` vs `bran`), so that
  `egg mixture` and `flour mixture` are not taken for the same thing;
- one found only by its head (`sea salt` vs `salt`): Wu-Palmer with the compound
  placed one level below its head (a sea salt is a kind of salt).
Each sense pair is evaluated in name order, so the value is symmetric.

The matrix over a vocabulary is cached in `<cache>/similarity/<key>.npz`, the key
hashing the sorted vocabulary, the WordNet version, `CODE_VERSION` and the
overrides; a cache hit does not import NLTK.
"""

from __future__ import annotations

import io
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from ..io.atomic import atomic_write
from ..io.steps import Step, silent_step
from ..model.foon import normalize_label
from ..model.words import count
from . import wordnet
from .cache import cache_dir, digest
from .senses import Overrides, Resolution, resolve, shipped_overrides

#: Bump when the similarity rule changes, so cached matrices are recomputed.
CODE_VERSION = "1"
#: Label pairs compared in one step of `compute_matrix` (a few seconds at most under load).
SHARE_PAIRS = 4096


@dataclass(frozen=True)
class Evidence:
    """Why two labels have their similarity: the sense pair, its common ancestor and that ancestor's breadth.

    `rejected`: "" (accepted), "broad" (the best sense pair's ancestor is too broad, `cook.py`),
    "forbidden" (in the overrides), "fixed" (value from the overrides), "unknown" (a label
    without sense), "same" (a label and itself), "variant" (a dish compound and a label, `cook.py`
    rule 4), "dishes" (two senses under a dish, rule 4), "category" (two labels FOON-GEN's categories do not group, rule 5), "sibling" (a label filed
    through one member with a label that is not its kind, rule 6), "purpose" (such a label and a kind of tool
    whose name or gloss names a food the other's does not, rule 7), "class" (such a label with many WordNet
    kinds and one of its kinds, rule 8), "food class" (a food class whose kinds are classes with a kind, rule 9).
    """

    similarity: float
    ancestor: str = ""
    sense_a: str = ""
    sense_b: str = ""
    breadth: float = 0.0
    rejected: str = ""


class LabelSimilarity:
    """Label similarity with per-label senses and per-pair values cached in memory (mode `paper`)."""

    mode = "paper"
    tag = ""  # nothing beyond labels and overrides changes a value

    def __init__(self, reader=None, overrides: Overrides | None = None) -> None:
        from .wup import WupTable

        self.reader = reader if reader is not None else wordnet.reader()
        self.overrides = overrides if overrides is not None else shipped_overrides()
        self._wup = WupTable(self.reader)
        self._resolved: dict[str, Resolution] = {}
        self._values: dict[tuple[str, str], float] = {}

    def resolution(self, label: str) -> Resolution:
        """The senses `label` stands for."""
        label = normalize_label(label)
        found = self._resolved.get(label)
        if found is None:
            found = self._resolved[label] = resolve(self.reader, label, self.overrides)
        return found

    def __call__(self, a: str, b: str) -> float:
        """Similarity of labels `a` and `b` in [0, 1] (symmetric)."""
        a, b = sorted((normalize_label(a), normalize_label(b)))
        if a == b:
            return 1.0
        key = (a, b)
        found = self._values.get(key)
        if found is None:
            found = self._values[key] = self._compute(a, b)
        return found

    def _compute(self, a: str, b: str) -> float:
        fixed = self.overrides.pair(a, b)
        if fixed is not None:
            return fixed
        ra, rb = self.resolution(a), self.resolution(b)
        if not ra.senses or not rb.senses:
            return 0.0
        sa, sb = ra.senses, rb.senses
        if ra.modifier is None and rb.modifier is None:
            return self._best(sa, sb, 0)
        if ra.modifier is not None and rb.modifier is not None:
            return self._best(sa, sb, 0) * self(ra.modifier, rb.modifier)
        return self._best(sa, sb, 1)

    def explain(self, a: str, b: str) -> Evidence:
        """The similarity of `a` and `b` (as `__call__`) with the head senses and NLTK subsumer it comes from.

        For two compounds the value multiplies the heads' and the modifiers' values; the
        evidence names the heads' sense pair (the first in WordNet order with the best value).
        """
        a, b = sorted((normalize_label(a), normalize_label(b)))
        value = self(a, b)
        if a == b:
            return Evidence(1.0, rejected="same")
        if self.overrides.pair(a, b) is not None:
            return Evidence(value, rejected="fixed")
        ra, rb = self.resolution(a), self.resolution(b)
        if not ra.senses or not rb.senses:
            return Evidence(0.0, rejected="unknown")
        extra = 1 if (ra.modifier is None) != (rb.modifier is None) else 0
        best = None
        for s in ra.senses:
            for t in rb.senses:
                x, y = (s, t) if s <= t else (t, s)
                c = self._wup.components(x, y)
                if c is not None:
                    v = 2.0 * c[0] / (c[1] + c[2] + 2 * c[0] + extra)
                    if best is None or v > best[0]:
                        best = (v, self._wup.subsumer(x, y), s, t)
        return Evidence(value, *best[1:]) if best else Evidence(value)

    def _best(self, senses_a: tuple[str, ...], senses_b: tuple[str, ...], extra: int) -> float:
        """Greatest Wu-Palmer value over sense pairs; `extra` links added below one side."""
        best = 0.0
        for s in senses_a:
            for t in senses_b:
                c = self._wup.components(s, t) if s <= t else self._wup.components(t, s)
                if c is not None:
                    depth, la, lb = c
                    best = max(best, 2.0 * depth / (la + lb + 2 * depth + extra))
        return best


@dataclass(frozen=True)
class SimilarityMatrix:
    """Symmetric label similarities over a sorted vocabulary (`values[i][j]`, 1.0 on the diagonal)."""

    labels: tuple[str, ...]
    values: object  # numpy.ndarray of float64, shape (n, n)
    key: str = ""

    def index(self, label: str) -> int:
        import bisect

        i = bisect.bisect_left(self.labels, label)
        if i == len(self.labels) or self.labels[i] != label:
            raise KeyError(label)
        return i

    def __call__(self, a: str, b: str) -> float:
        return float(self.values[self.index(a), self.index(b)])

    def or_else(self, make_sim: Callable[[], Callable[[str, str], float]]) -> Callable[[str, str], float]:
        """This matrix's value for two of its labels (normalized first), else that of the similarity `make_sim()`
        builds at the first pair the matrix lacks: pairs it holds open no WordNet (FOON-EXP's copies compare labels
        of the matrix it was built by)."""
        made: list[Callable[[str, str], float]] = []

        def value(a: str, b: str) -> float:
            try:
                return self(normalize_label(a), normalize_label(b))
            except KeyError:
                made[:] = made or [make_sim()]
                return made[0](a, b)
        return value

    def similar(self, label: str, threshold: float) -> tuple[tuple[str, float], ...]:
        """Other labels at least `threshold` similar to `label`, most similar first (then by label)."""
        row = self.values[self.index(label)]
        found = [(self.labels[j], float(row[j])) for j in range(len(self.labels))
                 if row[j] >= threshold and self.labels[j] != label]
        return tuple(sorted(found, key=lambda x: (-x[1], x[0])))


def matrix_key(labels: tuple[str, ...], overrides_text: str, tag: str = "") -> str:
    """Cache key: sorted vocabulary, WordNet version, code version, overrides, and the similarity's
    own tag (what else its values depend on; none for this rule)."""
    parts = ("\n".join(labels), wordnet.version(), CODE_VERSION, overrides_text)
    return digest(*parts, tag) if tag else digest(*parts)


def compute_matrix(labels: tuple[str, ...], sim: LabelSimilarity, key: str = "",
                   step: Step = silent_step) -> SimilarityMatrix:
    """All pairs of `labels` (sorted, distinct), in steps of rows of about `SHARE_PAIRS` pairs each (a series:
    484 labels are 117,000 pairs, a minute under load). O(n^2) similarities."""
    import numpy as np

    n = len(labels)
    values = np.eye(n, dtype=np.float64)
    first = 0
    while first < n:
        last, pairs = first, 0
        while last < n and pairs < SHARE_PAIRS:
            pairs += n - last - 1
            last += 1
        with step(f"WordNet similarities of {count(n, 'label', grouped=True)} (once per set of labels, then cached): rows {first + 1:,}-{last:,} of {n:,}",
                  series=f"WordNet similarities of {count(n, 'label', grouped=True)}"):
            for i in range(first, last):
                for j in range(i + 1, n):
                    values[i, j] = values[j, i] = sim(labels[i], labels[j])
        first = last
    return SimilarityMatrix(labels, values, key)


def matrix_is_cached(vocabulary: Iterable[str]) -> bool:
    """Whether the matrix over `vocabulary` is in the disk cache (no WordNet opened, no NLTK import)."""
    labels = tuple(sorted({normalize_label(v) for v in vocabulary} - {""}))
    return matrix_file(matrix_key(labels, shipped_overrides().text)).is_file()


def matrix_file(key: str) -> Path:
    """Where the matrix cached under `key` is kept."""
    return cache_dir() / "similarity" / f"{key}.npz"


def cached_matrix(labels: tuple[str, ...], key: str) -> SimilarityMatrix | None:
    """The matrix over `labels` (sorted, normalized) cached under `key`, or None (no WordNet opened)."""
    import numpy as np

    path = matrix_file(key)
    if path.is_file():
        try:
            with np.load(path, allow_pickle=False) as data:
                if tuple(str(x) for x in data["labels"]) == labels:
                    return SimilarityMatrix(labels, data["values"], key)
        except (OSError, ValueError, KeyError):
            pass  # unreadable cache entry: recompute and replace it
    return None


def similarity_matrix(
    vocabulary: Iterable[str], *, cache: bool = True, sim: LabelSimilarity | None = None, step: Step = silent_step
) -> SimilarityMatrix:
    """The similarity matrix over `vocabulary` (labels normalized), from the disk cache when possible.

    `sim` (default: this module's rule, mode `paper`) may be any similarity with
    `overrides` and `tag` (`modes.make_similarity`); computing runs in `step`s (`compute_matrix`).
    """
    import numpy as np

    labels = tuple(sorted({normalize_label(v) for v in vocabulary} - {""}))
    overrides = sim.overrides if sim is not None else shipped_overrides()
    key = matrix_key(labels, overrides.text, getattr(sim, "tag", ""))
    found = cached_matrix(labels, key) if cache else None
    if found is not None:
        return found
    result = compute_matrix(labels, sim or LabelSimilarity(overrides=overrides), key, step)
    if cache:
        buf = io.BytesIO()
        np.savez(buf, labels=np.array(labels, dtype=str), values=result.values)
        try:
            atomic_write(matrix_file(key), buf.getvalue())
        except OSError:
            pass  # a read-only cache only costs time
    return result
