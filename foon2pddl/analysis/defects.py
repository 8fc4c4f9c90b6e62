"""What the dataset checker reports: defects, their kinds, severities and places (the checks: `check`)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import StrEnum

from ..model.constraints import node_labels
from ..model.foon import FunctionalUnit, Source
from ..model.where import shown_path


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"


class DefectKind(StrEnum):
    """Every defect class the checker knows, in report order."""

    SELF_SUPPORTING = "self-supporting"        # only units that consume a node output it
    NO_ENTRY_CYCLE = "no-entry-cycle"          # nodes made only through each other
    IDENTITY_UNIT = "identity-unit"            # outputs equal inputs
    INGREDIENT_MISMATCH = "ingredient-mismatch"  # `c contains {..}` disagrees with the `x in [c]` nodes
    UNKNOWN_OBJECT = "unknown-object"          # a related object or ingredient that is no object anywhere
    SPELLING_VARIANT = "spelling-variant"      # labels differing only in spelling, spacing or plural
    STATE_ORDER = "state-order"                # one node written with its states in different orders
    DUPLICATE_STATE = "duplicate-state"        # a state written twice on one object


SEVERITY = {
    DefectKind.SELF_SUPPORTING: Severity.ERROR,
    DefectKind.NO_ENTRY_CYCLE: Severity.ERROR,
    DefectKind.IDENTITY_UNIT: Severity.ERROR,
    DefectKind.INGREDIENT_MISMATCH: Severity.WARNING,
    DefectKind.UNKNOWN_OBJECT: Severity.WARNING,
    DefectKind.SPELLING_VARIANT: Severity.WARNING,
    DefectKind.STATE_ORDER: Severity.WARNING,
    DefectKind.DUPLICATE_STATE: Severity.WARNING,
}

#: Places listed per defect (the count of all places is kept).
MAX_PLACES = 8


@dataclass(frozen=True)
class Place:
    path: str
    line: int

    def __str__(self) -> str:
        return f"{shown_path(self.path)}:{self.line}"


@dataclass(frozen=True)
class Defect:
    kind: DefectKind
    message: str
    places: tuple[Place, ...] = ()
    total_places: int = 0
    subjects: tuple[str, ...] = field(default=())  # the nodes or labels concerned (described)

    @property
    def severity(self) -> Severity:
        return SEVERITY[self.kind]

    def as_dict(self) -> dict:
        return {"kind": str(self.kind), "severity": str(self.severity), "message": self.message,
                "places": [str(p) for p in self.places], "total_places": self.total_places,
                "subjects": list(self.subjects)}


def places_of(sources: Iterable[Source]) -> tuple[tuple[Place, ...], int]:
    """Sorted distinct places of `sources`: the first MAX_PLACES and how many there are."""
    found = sorted({Place(s.path, s.line) for s in sources}, key=lambda p: (p.path, p.line))
    return tuple(found[:MAX_PLACES]), len(found)


def unit_places(units: Iterable[FunctionalUnit]) -> tuple[tuple[Place, ...], int]:
    """`places_of` the sources of `units`."""
    return places_of(s for u in units for s in u.sources)


def defect(kind: DefectKind, message: str, sources: Iterable[Source] = (), subjects: Sequence[str] = ()) -> Defect:
    places, total = places_of(sources)
    return Defect(kind, message, places, total, tuple(subjects))


def counts(defects: Iterable[Defect]) -> dict[str, int]:
    """Defects per kind, every known kind listed (0 when none), in report order."""
    c = Counter(d.kind for d in defects)
    return {str(k): c.get(k, 0) for k in DefectKind}


def has_errors(defects: Iterable[Defect]) -> bool:
    return any(d.severity is Severity.ERROR for d in defects)


def mentions(foon) -> dict[str, list[Source]]:
    """Every label the network uses (object labels, related objects, ingredients) -> sources of units using it."""
    found: dict[str, list[Source]] = {}
    for unit in foon.units:
        for node in (*unit.inputs, *unit.outputs):
            for name in node_labels(node):
                found.setdefault(name, []).extend(unit.sources)
    return found
