"""FOON-EXP: copies of functional units with an object replaced by a similar one.

For each unit and each object label among its nodes, every other label of the
vocabulary at least `threshold` similar (Wu-Palmer, `similarity.py`) gives one
copy of the unit with that object substituted everywhere in the unit (node
label, related objects, ingredient lists; `substitute.py`). A label the unit
already mentions is not substituted in (two objects would become one). Copies
mark their sources `expanded_from=<original label>` and `expanded_to=<its replacement>`
(so a tree can say which label replaced which); duplicates (also of
original units) are removed with `dedupe.dedupe_units`, originals first, so an
original unit keeps its unmarked provenance. One substitution per copy, as in
the seed paper, with what the unit makes from the object renamed along
(`substitute.product_renames`): squeezing a lime makes `lime juice`, not the
recipe's `lemon juice`. Each such derived pair (`lemon juice` -> `lime juice`) is
then substituted like a similar pair into every unit that mentions the product
(anywhere: node, related object, ingredient), so the renamed product flows down
the recipe (`pour lime juice`, `pitcher (contains {lime juice})`, ...), and
its own products are renamed in turn, until no new pair appears. Conversely a
product is not substituted away from its source (`squeeze lime -> lime juice`
gets no `lemon juice` copy: `substitute.renames_product_away`).

The copying runs in shares of `SHARE` units, each in the caller's `Step` (a series), then the
derived pairs and the duplicate removal in one step each, so that a command says how far it is.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from ..errors import UsageError
from ..io.steps import Step, silent_step
from ..model.bulk import bulk
from ..model.dedupe import dedupe_units
from ..model.foon import Foon, FunctionalUnit
from ..model.kitchen import Kitchen
from ..model.words import count
from .modes import DEFAULT_MODE, mode_matrix
from .similarity import SimilarityMatrix
from .substitute import product_renames, renames_product_away, substitute_unit, unit_labels

#: The seed paper's similarity threshold for FOON-EXP.
DEFAULT_THRESHOLD = 0.89
#: Units copied in one step (about 0.5 CPU s on the shared subgraphs).
SHARE = 128


@dataclass(frozen=True)
class Expansion:
    """The expanded network and how it was made."""

    foon: Foon
    threshold: float
    original_units: int
    copies: int  # substituted copies generated, before removing duplicates
    substitutions: tuple[tuple[str, str], ...]  # (label, similar label) pairs used, sorted
    derived: tuple[tuple[str, str], ...] = ()  # (product, renamed product) pairs propagated, sorted
    similarity: str = DEFAULT_MODE  # the similarity mode (`modes.py`)
    matrix: SimilarityMatrix | None = field(default=None, compare=False, repr=False)  # the one it substituted by

    def title(self) -> str:
        """`FOON-EXP (threshold T)`, naming the similarity unless it is the paper's (whose outputs stay as they were)."""
        mode = "" if self.similarity == "paper" else f"{self.similarity} similarity, "
        return f"FOON-EXP ({mode}threshold {self.threshold})"

    @property
    def added_units(self) -> int:
        return len(self.foon.units) - self.original_units


def vocabulary(foon: Foon, kitchen: Kitchen | None = None, extra: Iterable[str] = ()) -> tuple[str, ...]:
    """Object labels of the network's nodes, plus the kitchen's and `extra` ones, sorted."""
    labels = {n.label for n in foon.nodes}
    if kitchen is not None:
        labels.update(n.label for n in kitchen.nodes)
    labels.update(extra)
    return tuple(sorted(labels))


def is_expanded(unit: FunctionalUnit) -> bool:
    """Whether a unit exists only as an EXP copy (its first source is marked)."""
    return bool(unit.sources) and unit.sources[0].expanded_from is not None


@bulk  # millions of new long-lived objects: full collections rescanning them held the GIL 1.1 s (steps late)
def expand(
    foon: Foon,
    matrix: SimilarityMatrix | None = None,
    *,
    threshold: float = DEFAULT_THRESHOLD,
    max_units: int | None = None,
    kitchen: Kitchen | None = None,
    similarity: str = DEFAULT_MODE,
    step: Step = silent_step,
) -> Expansion:
    """FOON-EXP of `foon` (at its level) over the vocabulary of `matrix` (default: the `similarity` mode's
    matrix over the network's and kitchen's labels), its slow parts in `step` (module doc).

    Raises UsageError when the result would hold more than `max_units` units.
    """
    if not 0 < threshold <= 1:
        raise UsageError(f"similarity threshold must be in (0, 1], not {threshold}")
    if matrix is None:
        matrix = mode_matrix(vocabulary(foon, kitchen), similarity)
    known = set(matrix.labels)
    similar_cache: dict[str, tuple[tuple[str, float], ...]] = {}
    keys = {u.key for u in foon.units}
    copies: list[FunctionalUnit] = []
    used: set[tuple[str, str]] = set()
    derived: dict[tuple[str, str], None] = {}

    def add(unit: FunctionalUnit, old: str, new: str) -> None:
        extra = product_renames(unit, {old: new})
        copy = substitute_unit(unit, {old: new, **extra}, note=old, to=new)
        copies.append(copy)
        keys.add(copy.key)
        for pair in extra.items():
            derived.setdefault(pair, None)
        if max_units is not None and len(keys) > max_units:
            raise UsageError(f"FOON-EXP would exceed {count(max_units, 'unit')} (threshold {threshold}); "
                             "raise the threshold or the unit limit")

    mentions: dict[str, list[FunctionalUnit]] = {}
    total = len(foon.units)
    for first in range(0, total, SHARE):
        with step(f"expanding {count(total, 'unit', grouped=True)} onto similar objects: units {first + 1:,}-{min(first + SHARE, total):,}",
                  series=f"expanding {count(total, 'unit', grouped=True)}"):
            for unit in foon.units[first:first + SHARE]:
                mentioned = unit_labels(unit)
                for label in mentioned:
                    mentions.setdefault(label, []).append(unit)
                for old in sorted({n.label for n in (*unit.inputs, *unit.outputs)}):
                    if old not in known:
                        continue
                    if old not in similar_cache:
                        similar_cache[old] = matrix.similar(old, threshold)
                    for new, _ in similar_cache[old]:
                        if new in mentioned or renames_product_away(unit, old, new):
                            continue
                        add(unit, old, new)
                        used.add((old, new))
    done: set[tuple[str, str]] = set()
    with step("substituting the products renamed along into the units that use them"):
        while len(done) < len(derived):  # derived products flow down the recipes that use them
            old, new = pair = next(p for p in derived if p not in done)
            done.add(pair)
            for unit in mentions.get(old, ()):
                if new not in unit_labels(unit) and not renames_product_away(unit, old, new):
                    add(unit, old, new)
    with step(f"removing duplicates among {count(total + len(copies), 'unit', grouped=True)}"):
        units = dedupe_units((*foon.units, *copies))
    return Expansion(Foon(units, foon.level), threshold, len(foon.units), len(copies), tuple(sorted(used)),
                     tuple(sorted(derived)), similarity, matrix)
