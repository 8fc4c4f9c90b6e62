"""What a physical replay (`physical_replay.replay`) finds: the kinds of disagreement with FOON's words, one
finding (`Disagreement`), and the verdict over a plan (`ReplayReport`)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

__all__ = ["HOLDER_KINDS", "Disagreement", "DisagreementKind", "ReplayReport"]


class DisagreementKind(StrEnum):
    """What a replay found wrong (`physical_replay`'s module doc gives each rule)."""

    HOLDER_GONE = "holder-gone"
    MISPLACED = "misplaced"
    UNEXPECTED_HOLDER = "unexpected-holder"
    MISSING_CONTENT = "missing-content"
    STALE_SOURCE = "stale-source"
    CLAIMED_TWICE = "claimed-twice"
    UNLISTED_CONTENT = "unlisted-content"
    HELD_BY_EMPTY = "held-by-empty"
    UNBOUND_CHANGE = "unbound-change"
    NOT_AVAILABLE = "not-available"
    REMADE = "remade"
    STATE_MISMATCH = "state-mismatch"
    WRONG_SOURCE = "wrong-source"
    UNBOUND_TARGET = "unbound-target"
    HOLDER_NOT_BOUND = "holder-not-bound"
    CONSUMED_ELSEWHERE = "consumed-elsewhere"


#: Kinds about where objects are (holders, placements, contents, pour sources and targets); the others are
#: about the bindings themselves (an encoding's plan that fires a unit on the wrong objects).
HOLDER_KINDS = frozenset(DisagreementKind) - {DisagreementKind.UNBOUND_CHANGE, DisagreementKind.NOT_AVAILABLE,
                                              DisagreementKind.REMADE, DisagreementKind.STATE_MISMATCH}


@dataclass(frozen=True)
class Disagreement:
    """One finding: its kind, the step (-1: the initial state), the objects, the unit's `file:line`, a message."""

    kind: DisagreementKind
    step: int
    objects: tuple[str, ...]
    source: str
    message: str

    def describe(self) -> str:
        """`file.txt:12: step 3: bowl_2 lists tomato, but nothing in it is a tomato [missing-content]`."""
        where = "initial state" if self.step < 0 else f"step {self.step + 1}"
        return f"{self.source + ': ' if self.source else ''}{where}: {self.message} [{self.kind}]"

    __str__ = describe


@dataclass(frozen=True)
class ReplayReport:
    """The verdict: every disagreement (in order), and the steps after which some state disagreement holds."""

    disagreements: tuple[Disagreement, ...]
    affected_steps: tuple[int, ...] = ()

    @property
    def ok(self) -> bool:
        return not self.disagreements

    def kinds(self) -> frozenset[DisagreementKind]:
        return frozenset(d.kind for d in self.disagreements)
