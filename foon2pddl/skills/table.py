"""The motion-to-skill table: which robot skill carries out a FOON step's outcome.

A JSON file `{"motions": {"pour": "pour", "pick-and-place": "place", ...}}`
(shipped: `foon2pddl/data/skills/motions.json`; `--skill-table FILE` replaces it).
Motion labels are compared normalized (lower case, spaces collapsed) with a
composite `*` suffix dropped. An optional `"by_hand": {motion: skill}` names the skill
that carries out a motion when its step lists no tool (FOON's `peel` of an avocado
without a knife: `peel-by-hand`; `fold` of a tortilla without a spoon: `shape`).
A motion the table does not list has no skill: its
steps stay abstract (reported by name, never dropped). `coverage` counts, per
motion, the units (of a network) or firings (of plans) whose motion maps.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from ..errors import FoonSyntaxError
from ..io.foon_lines import CONTROL_CHARS
from ..io.json_text import load_json, unknown_key
from ..io.parser import read_text
from ..model.foon import normalize_label
from ..model.where import shown_path
from .domain import SkillDomain

__all__ = ["Coverage", "MotionTable", "coverage", "parse_table", "read_table", "shipped_table"]

KEYS = ("motions", "by_hand", "description", "$schema")


def motion_key(label: str) -> str:
    return normalize_label(label).removesuffix("*").strip()


@dataclass(frozen=True)
class MotionTable:
    """Motion label -> skill name (sorted pairs), motion -> the skill of a step without a tool (sorted
    pairs, a motion of `pairs` each), and where the table was read from."""

    pairs: tuple[tuple[str, str], ...]
    source: str = ""
    hand_pairs: tuple[tuple[str, str], ...] = ()

    @property
    def table(self) -> dict[str, str]:
        return dict(self.pairs)

    def skill_of(self, motion: str) -> str | None:
        """The skill of a motion label, or None when the table does not list it."""
        return self.table.get(motion_key(motion))

    def hand_skill_of(self, motion: str) -> str | None:
        """The skill of a motion's steps that list no tool, or None (then the motion's own skill)."""
        return dict(self.hand_pairs).get(motion_key(motion))

    def check(self, domain: SkillDomain) -> None:
        """FoonSyntaxError when the table names a skill the domain does not define."""
        names = set(domain.by_name)
        for motion, skill in (*self.pairs, *self.hand_pairs):
            if skill not in names:
                raise FoonSyntaxError(self.source or "<motions>", 0,
                                      f"motion {motion!r} maps to skill {skill!r}, which {domain.path} does not define")


def parse_table(text: str, path: str = "<motions>") -> MotionTable:
    """Read a motion table; FoonSyntaxError (path, line) for anything but label -> skill strings."""
    data = load_json(text, path)
    if not isinstance(data, dict) or not isinstance(data.get("motions"), dict):
        raise FoonSyntaxError(path, 1, 'a motion table is a JSON object with "motions": {motion: skill}')
    if (bad := unknown_key(data, KEYS)) is not None:
        raise FoonSyntaxError(path, _line(text, bad[0]), bad[1])
    pairs = _pairs(data["motions"], text, path)
    hand = data.get("by_hand", {})
    if not isinstance(hand, dict):
        raise FoonSyntaxError(path, _line(text, "by_hand"), '"by_hand" is a JSON object {motion: skill}')
    hand_pairs = _pairs(hand, text, path)
    for motion in hand_pairs:
        if motion not in pairs:
            raise FoonSyntaxError(path, _line(text, motion), f"by_hand motion {motion!r} is not in \"motions\"")
    return MotionTable(tuple(sorted(pairs.items())), path, tuple(sorted(hand_pairs.items())))


def _pairs(entries: dict, text: str, path: str) -> dict[str, str]:
    pairs: dict[str, str] = {}
    for motion, skill in entries.items():
        line = _line(text, motion)
        if not isinstance(skill, str) or not skill.strip() or CONTROL_CHARS.search(motion + skill):
            raise FoonSyntaxError(path, line, f"motion {motion!r}: the skill must be a non-empty name")
        key = motion_key(motion)
        if key in pairs and pairs[key] != skill.strip().lower():
            raise FoonSyntaxError(path, line, f"motion {key!r} is mapped twice")
        pairs[key] = skill.strip().lower()
    return pairs


def _line(text: str, key: str) -> int:
    import json

    at = text.find(json.dumps(key))
    return text.count("\n", 0, at) + 1 if at >= 0 else 1


def read_table(path: str | Path) -> MotionTable:
    return parse_table(read_text(Path(path)), str(path))


def shipped_table() -> MotionTable:
    """The motion table shipped with foon2pddl, named by its path in the package (`shipped_domain`'s way)."""
    ref = resources.files("foon2pddl") / "data" / "skills" / "motions.json"
    return parse_table(ref.read_text(), shown_path(str(ref)))


@dataclass(frozen=True)
class Coverage:
    """Per motion label (normalized): how often it occurs and whether it maps; the mapped share."""

    counts: tuple[tuple[str, int], ...]
    mapped: frozenset[str]

    @property
    def total(self) -> int:
        return sum(n for _, n in self.counts)

    @property
    def covered(self) -> int:
        return sum(n for m, n in self.counts if m in self.mapped)

    @property
    def share(self) -> float:
        return self.covered / self.total if self.total else 1.0

    @property
    def unmapped(self) -> tuple[tuple[str, int], ...]:
        return tuple((m, n) for m, n in self.counts if m not in self.mapped)


def coverage(motions: Iterable[str], table: MotionTable) -> Coverage:
    """Coverage of motion labels (one per unit, or per firing in plans), most frequent first, ties by label."""
    counts: Mapping[str, int] = Counter(motion_key(m) for m in motions)
    ordered = tuple(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))
    return Coverage(ordered, frozenset(m for m in counts if table.skill_of(m) is not None))
