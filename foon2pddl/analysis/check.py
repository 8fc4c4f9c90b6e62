"""Dataset checker: defects a researcher must fix or know about before using a FOON.

Each defect has a kind (`DefectKind`), a severity (errors make a network give
wrong answers or none: self-supporting producers, cycles with no entry, units
that change nothing; warnings mark inconsistencies that silently split or lose
nodes), a message and the places (file:line of the units or objects) involved.
The checks live in `check_units` (network structure, one pass each) and
`check_labels` (labels and the written form of nodes); `check` runs them all in
a fixed order, so the report is deterministic.
"""

from __future__ import annotations

from . import check_labels, check_units
from .defects import (
    MAX_PLACES,
    SEVERITY,
    Defect,
    DefectKind,
    Place,
    Severity,
    counts,
    defect,
    has_errors,
    mentions,
    places_of,
    unit_places,
)

__all__ = ["MAX_PLACES", "SEVERITY", "Defect", "DefectKind", "Place", "Severity", "check", "counts", "defect",
           "has_errors", "mentions", "places_of", "unit_places"]


def check(foon, raw_objects=(), lemma=None) -> list[Defect]:
    """Every check, in `DefectKind` order: network structure, then labels and written form."""
    found = [*check_units.self_supporting(foon), *check_units.no_entry_cycles(foon),
             *check_units.identity_units(foon), *check_units.ingredient_mismatches(foon),
             *check_units.unknown_objects(foon),
             *check_labels.spelling_variants(mentions(foon), lemma), *check_labels.written_form(raw_objects)]
    order = list(DefectKind)
    return sorted(found, key=lambda d: order.index(d.kind))
