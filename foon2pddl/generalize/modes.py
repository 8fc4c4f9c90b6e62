"""The registry of similarity modes: which label similarity substitutions use.

- `cook` (the default): `cook.CookSimilarity`, food senses for ingredients, artifact
  senses for tools, the deepest common ancestor, broad ancestors rejected;
- `paper`: `similarity.LabelSimilarity`, the seed paper's Wu-Palmer over every kitchen
  sense (NLTK's definition), kept for reproduction: its outputs do not change.

FOON-EXP (`--network exp`, `expand`), `--without X` substitution, the hints and the
`similarity` command all read `SIMILARITY_MODES`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from ..errors import UsageError
from ..io.steps import Step, silent_step
from ..model.foon import normalize_label
from ..model.words import count
from .senses import Overrides, shipped_overrides
from .similarity import LabelSimilarity, SimilarityMatrix, cached_matrix, matrix_file, matrix_key, similarity_matrix

__all__ = ["DEFAULT_MODE", "SIMILARITY_MODES", "SimilarityMode", "make_similarity", "mode_matrix",
           "mode_matrix_is_cached"]


@dataclass(frozen=True)
class SimilarityMode:
    """A registered similarity: its name, what it is, and its shipped overrides."""

    name: str
    description: str
    overrides: Callable[[], Overrides]


def _cook_overrides() -> Overrides:
    from .cook import cook_overrides

    return cook_overrides()


#: Mode name -> mode, the default first.
SIMILARITY_MODES: dict[str, SimilarityMode] = {m.name: m for m in (
    SimilarityMode("cook", "role senses, deepest common ancestor, broad ancestors rejected", _cook_overrides),
    SimilarityMode("paper", "the seed paper's Wu-Palmer over all kitchen senses (NLTK)", shipped_overrides),
)}
DEFAULT_MODE = next(iter(SIMILARITY_MODES))


def check_mode(mode: str) -> str:
    if mode not in SIMILARITY_MODES:
        raise UsageError(f"similarity must be one of {', '.join(SIMILARITY_MODES)}, not {mode!r}")
    return mode


def make_similarity(mode: str = DEFAULT_MODE, *, reader=None, extra: Overrides | None = None):
    """The label similarity of `mode`; `extra` extends the overrides."""
    overrides = SIMILARITY_MODES[check_mode(mode)].overrides()
    if extra is not None:
        overrides = overrides.extended(extra)
    if mode == "paper":
        return LabelSimilarity(reader, overrides)
    from .cook import CookSimilarity

    return CookSimilarity(reader, overrides)


def _labels(vocabulary: Iterable[str]) -> tuple[str, ...]:
    return tuple(sorted({normalize_label(v) for v in vocabulary} - {""}))


def _key(labels: tuple[str, ...], mode: str, extra: Overrides | None) -> str:
    overrides = SIMILARITY_MODES[check_mode(mode)].overrides()
    if extra is not None:
        overrides = overrides.extended(extra)
    if mode == "paper":
        return matrix_key(labels, overrides.text)
    from .cook import DEFAULT_BREADTH, cache_tag

    return matrix_key(labels, overrides.text, cache_tag(DEFAULT_BREADTH, overrides))


def mode_matrix(vocabulary: Iterable[str], mode: str = DEFAULT_MODE, *, cache: bool = True,
                extra: Overrides | None = None, step: Step = silent_step) -> SimilarityMatrix:
    """The similarity matrix of `mode` over `vocabulary` (disk-cached; a hit opens no WordNet); a miss
    opens WordNet and computes the pairs in `step`s (`similarity.compute_matrix`). A hit is read in a
    `step` too: numpy's import and the file took 0.43 s of CPU on the subgraphs, seconds under load
    (stop 55's pass: `expand --similarity paper` went 5.6 s without a line at load 30)."""
    labels = _labels(vocabulary)
    key = _key(labels, mode, extra)
    if cache and matrix_file(key).is_file():
        with step(f"reading the WordNet similarities of {count(len(labels), 'label', grouped=True)} from the cache"):
            found = cached_matrix(labels, key)
        if found is not None:
            return found
    with step(f"opening WordNet for the similarities of {count(len(labels), 'label', grouped=True)} (once per set of labels, then cached)"):
        sim = make_similarity(mode, extra=extra)
    return similarity_matrix(labels, cache=cache, sim=sim, step=step)


def mode_matrix_is_cached(vocabulary: Iterable[str], mode: str = DEFAULT_MODE, extra: Overrides | None = None) -> bool:
    """Whether `mode`'s matrix over `vocabulary` is in the disk cache (no WordNet opened, no NLTK import)."""
    labels = _labels(vocabulary)
    return matrix_file(_key(labels, mode, extra)).is_file()
