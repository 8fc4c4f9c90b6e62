"""Motion success rates (weighted FOON): `motion<TAB>rate` files.

One motion per line, its label then its success rate in (0, 1] as the last
field (the public files separate them with a tab; any whitespace is accepted
since labels such as `turn on` contain spaces). Blank lines and `#` comments
are skipped. Labels are normalized like FOON labels and a composite `*` suffix
is dropped, so `pour*` units use the rate of `pour`.

A motion the file does not list gets `DEFAULT_RATE` (0.5: no knowledge either
way, and low enough that an unrated motion is never preferred to a rated one
that usually succeeds); pass `default=` to change it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import FoonSyntaxError, UsageError
from ..model.foon import normalize_label
from .parser import read_text

DEFAULT_RATE = 0.5


@dataclass(frozen=True)
class Rates:
    """Success rate per motion label, with the rate used for unlisted motions."""

    table: dict[str, float] = field(default_factory=dict, hash=False)
    default: float = DEFAULT_RATE
    source: str = ""

    def __post_init__(self) -> None:
        if not 0.0 < self.default <= 1.0:
            raise UsageError(f"default rate must be in (0, 1], not {self.default!r}")

    def rate(self, motion: str) -> float:
        """Success rate of a motion label (the default when unlisted)."""
        return self.table.get(motion, self.default)

    def cost(self, motion: str) -> float:
        """-log(rate): additive cost whose minimum sum is the highest success product."""
        return -math.log(self.rate(motion))


def parse_rates(text: str, path: str = "<rates>", default: float = DEFAULT_RATE) -> Rates:
    """Parse rates text; errors name path and line."""
    table: dict[str, float] = {}
    seen_at: dict[str, int] = {}
    for lineno, raw in enumerate(text.split("\n"), start=1):  # `\n` only, as the FOON reader
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        parts = line.rsplit(None, 1)
        if len(parts) != 2:
            raise FoonSyntaxError(path, lineno, "expected 'motion<TAB>rate'", raw)
        label = normalize_label(parts[0]).removesuffix("*").strip()
        try:
            rate = float(parts[1])
        except ValueError:
            raise FoonSyntaxError(path, lineno, f"rate {parts[1]!r} is not a number", raw) from None
        if not label:
            raise FoonSyntaxError(path, lineno, "motion label is empty", raw)
        if not 0.0 < rate <= 1.0:
            raise FoonSyntaxError(path, lineno, f"rate {rate:g} is not in (0, 1]", raw)
        if label in table and table[label] != rate:
            raise FoonSyntaxError(path, lineno, f"motion {label!r} already has rate {table[label]:g} "
                                                f"(line {seen_at[label]})", raw)
        table[label] = rate
        seen_at.setdefault(label, lineno)
    return Rates(table, default, path)


def read_rates(path: str | Path, default: float = DEFAULT_RATE) -> Rates:
    """Read a rates file (see the module doc)."""
    p = Path(path)
    return parse_rates(read_text(p), str(p), default)


def looks_like_rates(text: str) -> bool:
    """Whether `text` reads as a rates file: every line (blank and `#` lines aside) a label, a tab
    and a number, and there is one. Used to say so when such a file is given as something else."""
    lines = [line.strip() for line in text.split("\n") if line.strip() and not line.strip().startswith("#")]
    if not lines:
        return False
    for line in lines:
        label, tab, number = line.rpartition("\t")
        try:
            float(number)
        except ValueError:
            return False
        if not tab or not label.strip():
            return False
    return True


def refuse_rates(text: str, path: str, what: str) -> None:
    """Refuse a rates file given as `what` (`a kitchen`, `a goal list`, ...): a located error naming the option that
    takes it. Stop 55's pass: as a goal list it was 129 `unmatched` goals (`chop 0.10`), exit 1."""
    if looks_like_rates(text):
        raise FoonSyntaxError(path, 1, f"this is a motion success-rates file (`motion<TAB>rate` lines), not {what}",
                              belongs=("rates",))
