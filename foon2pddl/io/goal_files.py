"""Goal text and goal files: `onion: chopped, in [bowl]` and FOON O/S lines -> GoalSpec."""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import FoonSyntaxError
from ..model.foon import make_state, normalize_label
from ..model.goal import GoalSpec, spec_of_node
from .parser import parse_objects, read_text

_STATE = re.compile(r"^(?P<label>[^\[\]{}]*?)\s*(?:\[(?P<rel>[^\[\]]*)\])?\s*(?:\{(?P<ing>[^{}]*)\})?$")


def _split_states(text: str) -> list[str]:
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
            if depth < 0:
                raise ValueError(f"unbalanced bracket in goal states {text!r}")
        if ch == "," and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    if depth:
        raise ValueError(f"unbalanced bracket in goal states {text!r}")
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def parse_goal_spec(text: str) -> GoalSpec:
    """Parse the goal syntax; raises ValueError with what was expected."""
    label, sep, rest = text.partition(":")
    label = normalize_label(label)
    if not label:
        raise ValueError("goal has no object label (expected 'label' or 'label: state, ...')")
    if not sep:
        return GoalSpec(label)
    states = []
    for part in _split_states(rest):
        m = _STATE.match(part)
        if not m or not m.group("label").strip():
            raise ValueError(f"cannot read state {part!r} (expected 'state', 'state [object]' or 'state {{a, b}}')")
        ing = [i for i in (m.group("ing") or "").split(",") if i.strip()]
        states.append(make_state(m.group("label"), m.group("rel") or "", ing))
    return GoalSpec(label, tuple(sorted(set(states))))


def read_goal_file(path: str | Path) -> GoalSpec:
    """A goal file: exactly one object node written as FOON O/S lines."""
    p = Path(path)
    nodes = parse_objects(read_text(p), str(p))
    if len(nodes) != 1:
        raise FoonSyntaxError(str(p), nodes[1][1] if len(nodes) > 1 else 0,
                              f"goal file must hold exactly one object node, found {len(nodes)}")
    return spec_of_node(nodes[0][0])
