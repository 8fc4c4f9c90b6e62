"""Constraints files (JSON, see docs/constraints.md and docs/constraints.schema.json).

```json
{"name": "one-armed robot", "without_motions": ["pour"], "without": ["peanut"],
 "must_use": ["lettuce"], "rates": {"slice": 0.9}, "costs": {"stir": 0.1},
 "without_skills": ["sprinkle"], "skill_costs": {"pick": 2}}
```

`without_skills` and `skill_costs` are a robot's skills (docs/skills.md): skills it
lacks, and what each skill costs in a skill plan (non-negative integers).

Every key is optional; unknown keys are errors (a typo must not silently allow a
motion). `costs` are -ln(success rate), so a cost c is the rate exp(-c): a cost of 0
means the motion always succeeds. A cost over `MAX_COST` (about 744.4, where exp(-c)
underflows to 0) is read as `MAX_COST`: the smallest positive rate, a motion used
only when nothing else makes the goal. Errors name the file and the line of the key.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path

from ..errors import FoonSyntaxError, UsageError
from ..model.constraints import Constraint, Constraints, Kind, combine, make_constraints
from .foon_lines import CONTROL_CHARS
from .json_text import key_line, load_json, unknown_key
from .parser import read_text
from .rates import Rates, refuse_rates

#: File key -> constraint kind of its list of labels.
LIST_KEYS = {"without_motions": Kind.WITHOUT_MOTION, "without": Kind.WITHOUT, "must_use": Kind.MUST_USE}
KEYS = (*LIST_KEYS, "name", "rates", "costs", "without_skills", "skill_costs", "$schema", "description")
#: The smallest positive float and the cost it stands for (-ln of it): larger costs are read as this.
MIN_RATE = math.ulp(0.0)
MAX_COST = -math.log(MIN_RATE)


def is_constraints(data: object) -> bool:
    """Whether decoded JSON reads as a constraints document: an object with keys, each a constraints key."""
    return isinstance(data, dict) and bool(data) and all(key in KEYS for key in data)


def _labels(value, path: str, line: int, key: str) -> list[str]:
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise FoonSyntaxError(path, line, f"{key!r} must be a list of labels (strings)")
    for v in value:
        if CONTROL_CHARS.search(v) or not v.strip():
            raise FoonSyntaxError(path, line, f"{key!r}: label {v!r} is empty or has control characters")
    return value


def _table(value, path: str, line: int, key: str) -> dict[str, float]:
    if not isinstance(value, dict) or not all(isinstance(v, int | float) and not isinstance(v, bool)
                                              for v in value.values()):
        raise FoonSyntaxError(path, line, f"{key!r} must map motion labels to numbers")
    return value


def _other_kind(data: object) -> tuple[str, tuple[str, ...]] | None:
    """What a JSON document given as constraints is instead (a kitchen, a scene, a network) and the inputs
    that take it; None when it may be constraints."""
    if isinstance(data, list) and data and all(isinstance(item, dict) for item in data):
        return "a JSON list of objects is a kitchen or a goal list (docs/format.md), not a constraints file", \
            ("kitchen", "goals")
    if isinstance(data, dict) and "objects" in data and not is_constraints(data):
        return "a JSON document with \"objects\" is a scene kitchen (docs/scene.md), not a constraints file", \
            ("kitchen",)
    if isinstance(data, dict) and "format" in data and "units" in data:  # a network's JSON export (jsonio)
        return "this is a FOON network (JSON, docs/json-schema.md), not a constraints file", ("paths",)
    return None


def parse_constraints(text: str, path: str = "<constraints>") -> Constraints:
    """Parse a constraints document; FoonSyntaxError naming path and line on any problem."""
    refuse_rates(text, path, "a constraints file")
    data = load_json(text, path)  # located errors for bad JSON, deep nesting, huge integers
    other = _other_kind(data)
    if other:
        raise FoonSyntaxError(path, 1, other[0], belongs=other[1])
    if not isinstance(data, dict):
        raise FoonSyntaxError(path, 1, "a constraints file is a JSON object")
    if (bad := unknown_key(data, KEYS)) is not None:
        raise FoonSyntaxError(path, key_line(text, bad[0]), bad[1])
    items = [Constraint(kind, v, path) for key, kind in LIST_KEYS.items()
             for v in _labels(data.get(key, []), path, key_line(text, key), key)]
    rates: list[tuple[str, float]] = []
    for key in ("rates", "costs"):
        line = key_line(text, key)
        for motion, number in _table(data.get(key, {}), path, line, key).items():
            if key == "costs":
                if not 0.0 <= number < math.inf:
                    raise FoonSyntaxError(path, line, f"cost of {motion!r} must be >= 0, not {number!r}")
                number = max(math.exp(-number), MIN_RATE)
            rates.append((motion, float(number)))
    lacks = _labels(data.get("without_skills", []), path, key_line(text, "without_skills"), "without_skills")
    line = key_line(text, "skill_costs")
    skill_costs = data.get("skill_costs", {})
    if not isinstance(skill_costs, dict) or not all(isinstance(v, int) and not isinstance(v, bool) and v >= 0
                                                    for v in skill_costs.values()):
        raise FoonSyntaxError(path, line, "'skill_costs' must map skill names to non-negative integers")
    try:
        return make_constraints(items, rates, (path,), lacks, skill_costs.items())
    except ValueError as exc:
        raise FoonSyntaxError(path, key_line(text, "rates"), str(exc)) from None


def read_constraints(path: str | Path) -> Constraints:
    """Read one constraints file."""
    p = Path(path)
    return parse_constraints(read_text(p), str(p))


def load_constraints(files: Iterable[str | Path] = (), without_motions: Iterable[str] = (),
                     without: Iterable[str] = (), must_use: Iterable[str] = (),
                     without_skills: Iterable[str] = ()) -> Constraints:
    """Constraints files combined with one-off labels (the CLI's `--constraints` and flags)."""
    flags = [Constraint(Kind.WITHOUT_MOTION, m, "<options>") for m in without_motions]
    flags += [Constraint(Kind.WITHOUT, x, "<options>") for x in without]
    flags += [Constraint(Kind.MUST_USE, x, "<options>") for x in must_use]
    without_skills = tuple(without_skills)
    for kind, value in [(c.kind.value, c.value) for c in flags] + [("without-skill", s) for s in without_skills]:
        if CONTROL_CHARS.search(value) or not value.strip():
            raise UsageError(f"{kind} {value!r}: the label is empty or has control characters")
    parts = [read_constraints(f) for f in files]
    try:
        return combine(*parts, make_constraints(flags, sources=("<options>",) if flags or without_skills else (),
                                                without_skills=without_skills))
    except ValueError as exc:  # two files give one motion different rates
        raise FoonSyntaxError(", ".join(str(f) for f in files), 0, str(exc)) from None


def with_rates(rates: Rates | None, constraints: Constraints) -> Rates | None:
    """A rates file's table with the constraints' rates added (None when neither gives any).

    A motion both give is an error (FoonSyntaxError naming both sources) unless the rates agree.
    """
    if not constraints.rates:
        return rates
    base = rates or Rates()
    table = dict(base.table)
    for motion, rate in constraints.rates:
        if table.get(motion, rate) != rate:
            raise FoonSyntaxError(", ".join(constraints.sources), 0,
                                  f"motion {motion!r} has rate {rate:g} here and {table[motion]:g} in "
                                  f"{base.source or 'the rates file'}")
        table[motion] = rate
    return Rates(table, base.default, " + ".join(s for s in (base.source, *constraints.sources) if s))
