"""The substitution pairs a FOON-EXP uses, with the evidence for each: what `expand --pairs` prints.

One row per (label, substitute) pair of `Expansion.substitutions` (kind `similar`:
similarity, common ancestor and the two senses, from the mode's `explain`), then
one per derived pair (kind `derived`: a product renamed along, e.g. lemon juice ->
lime juice, with the similar pair it follows from). Rows are in the expansion's
sorted order, so the output is deterministic.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import asdict, dataclass

from .expand import Expansion
from .modes import make_similarity
from .senses import Overrides

COLUMNS = ("label", "substitute", "similarity", "ancestor", "label_sense", "substitute_sense", "kind")


@dataclass(frozen=True)
class PairRow:
    """One substitution pair of an expansion and why it was made."""

    label: str
    substitute: str
    similarity: float | None
    ancestor: str
    label_sense: str
    substitute_sense: str
    kind: str  # similar | derived


def substitution_pairs(e: Expansion, extra: Overrides | None = None) -> tuple[PairRow, ...]:
    """The rows of `e` (module doc); opens WordNet for the evidence."""
    sim = make_similarity(e.similarity, extra=extra)
    rows = []
    for a, b in e.substitutions:
        ev = sim.explain(a, b)
        sa, sb = (ev.sense_a, ev.sense_b) if a <= b else (ev.sense_b, ev.sense_a)
        rows.append(PairRow(a, b, round(ev.similarity, 6), ev.ancestor, sa, sb, "similar"))
    rows += [PairRow(a, b, None, "", "", "", "derived") for a, b in e.derived]
    return tuple(rows)


def format_pairs(rows: Iterable[PairRow], fmt: str) -> str:
    """TSV with a header line (`fmt` foon), or a JSON list of objects (`fmt` json)."""
    rows = list(rows)
    if fmt == "json":
        return json.dumps([asdict(r) for r in rows], indent=2) + "\n"
    def cell(v) -> str:
        return "" if v is None else f"{v:.4f}" if isinstance(v, float) else str(v)
    return "".join("\t".join(cell(getattr(r, c)) for c in COLUMNS) + "\n" for r in rows).join(
        ["\t".join(COLUMNS) + "\n", ""])
