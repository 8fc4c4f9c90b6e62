"""Goal text and goal files: `onion: chopped, in [bowl]` and FOON O/S lines -> GoalSpec."""

from __future__ import annotations

import json
import re
from pathlib import Path

from ..errors import FoonSyntaxError
from ..model.foon import State, make_state, normalize_label
from ..model.goal import GoalSpec, spec_of_node
from ..model.words import count
from .foon_lines import parse_objects
from .json_text import text_problem
from .parser import read_text

_EXPECTED = "(expected 'state', 'state [object]' or 'state {a, b}')"


_SPECIAL = re.compile(r"[\[\]{},]")


def _split_states(text: str) -> list[str]:
    """Split on commas outside brackets; visits only the bracket and comma characters (linear, and
    fast on long runs of ordinary text)."""
    parts, depth, start = [], 0, 0
    for m in _SPECIAL.finditer(text):
        ch = m.group()
        if ch in "[{":
            depth += 1
        elif ch in "]}":
            depth -= 1
            if depth < 0:
                raise ValueError(f"unbalanced bracket in goal states {text!r}")
        elif depth == 0:
            parts.append(text[start:m.start()])
            start = m.end()
    if depth:
        raise ValueError(f"unbalanced bracket in goal states {text!r}")
    parts.append(text[start:])
    return [p.strip() for p in parts if p.strip()]


def _bracketed(text: str, open_: str, close: str) -> tuple[str, str] | None:
    """`(inside, rest)` when `text` starts with `open_ ... close` with no second `open_` inside, else None."""
    if not text.startswith(open_):
        return None
    end = text.find(close, 1)
    if end < 0 or open_ in text[1:end]:
        return None
    return text[1:end], text[end + 1:].lstrip()


def parse_state_text(part: str) -> State:
    """One state: `label`, `label [related]`, `label {a, b}` or `label [related] {a, b}`.

    A left-to-right scan (linear time; the regular expression it replaces backtracked
    cubically on blanks before a bracket). The label holds no bracket; `[...]` may hold
    braces and `{...}` brackets, as before. Raises ValueError.
    """
    cut = min((i for i in (part.find(c) for c in "[]{}") if i >= 0), default=len(part))
    label, rest = part[:cut], part[cut:]
    related, ingredients = "", ""
    inner = _bracketed(rest, "[", "]")
    if inner is not None:
        related, rest = inner
    inner = _bracketed(rest, "{", "}")
    if inner is not None:
        ingredients, rest = inner
    if rest or not label.strip():
        raise ValueError(f"cannot read state {part!r} {_EXPECTED}")
    return make_state(label, related, [i for i in ingredients.split(",") if i.strip()])


def parse_goal_spec(text: str) -> GoalSpec:
    """Parse the goal syntax, or a node as the tools print it (`onion (chopped, in [bowl])`): one
    grammar for --goal, goal lists and kitchen lines. Raises ValueError with what was expected.

    >>> spec = parse_goal_spec("bowl: contains {lettuce, tomato}, on [table]")
    >>> spec.label, [s.describe() for s in spec.states]
    ('bowl', ['contains {lettuce, tomato}', 'on [table]'])
    >>> parse_goal_spec("bowl (contains {lettuce, tomato}, on [table])") == spec
    True
    >>> parse_goal_spec("onion").states is None
    True
    """
    problem = text_problem(text, "the goal")  # goals are label text: no control character reaches a table
    if problem:
        raise ValueError(problem)
    text = text.strip()
    if ":" not in text.split("(", 1)[0] and text.endswith(")") and " (" in text:
        label, _, states = text.partition(" (")
        text = f"{label}: {states[:-1]}"
    label, sep, rest = text.partition(":")
    label = normalize_label(label)
    if not label:
        raise ValueError("goal has no object label (expected 'label' or 'label: state, ...')")
    if "(" in label or ")" in label:  # a printed node cut short: `guacamole (in [bowl]`, no label of the data
        raise ValueError(f"unbalanced parenthesis in the label {label!r} (a node as the tools print it is "
                         "'label (state, ...)')")
    if not sep:
        return GoalSpec(label)
    states = [parse_state_text(part) for part in _split_states(rest)]
    return GoalSpec(label, tuple(sorted(set(states))))


def read_goal_file(path: str | Path) -> GoalSpec:
    """A goal file: exactly one object node written as FOON O/S lines. A JSON list (the public `goal_nodes.json`,
    or `kitchen.json`: the same form) is refused as what it is, a list for `--kitchen` or `--goals` (stop 56's
    newcomer pass: it said only `expected an 'O' or 'S' line`), and so are goals in the goal syntax, one a line."""
    p = Path(path)
    text = read_text(p)
    try:
        nodes = parse_objects(text, str(p))
    except FoonSyntaxError:
        _refuse_json_list(text, str(p))
        _refuse_goal_lines(text, str(p))
        raise
    if len(nodes) != 1:
        raise FoonSyntaxError(str(p), nodes[1][1] if len(nodes) > 1 else 0,
                              f"goal file must hold exactly one object node, found {len(nodes)}")
    return spec_of_node(nodes[0][0])


def _refuse_goal_lines(text: str, path: str) -> None:
    """Raise a located error naming `--goals` when every line of `text` that is no comment is a goal in the goal
    syntax (`guacamole`, `onion: chopped`: one goal a line, as `--goals` reads them); else return. O(length)."""
    lines = [(i, s) for i, raw in enumerate(text.split("\n"), start=1) if (s := raw.strip()) and not s.startswith("#")]
    if any("\t" in line or re.match(r"(?:[OSM]\s|//)", line) for _, line in lines):  # FOON lines with a mistake:
        return  # the parser's error says what is wrong there
    try:
        for _, line in lines:
            parse_goal_spec(line)
    except ValueError:
        return
    if lines:
        raise FoonSyntaxError(path, lines[0][0], f"{count(len(lines), 'goal')} in the goal syntax, one a line, not the "
                                                 "one goal node in FOON O/S lines a goal file holds",
                                                 belongs=("goals",))


def _refuse_json_list(text: str, path: str) -> None:
    """Raise a located error naming `--kitchen` and `--goals` when `text` is a JSON list (of kitchen or goal nodes:
    one form, as `io.parser` names a list of objects given as PATHS); else return."""
    if not text.lstrip().startswith("["):
        return
    try:
        data = json.loads(text)
    except ValueError:
        return
    if isinstance(data, list):
        raise FoonSyntaxError(path, 1, f"a JSON list of {count(len(data), 'object')}, not the one goal node in FOON "
                                       "O/S lines a goal file holds", belongs=("kitchen", "goals"))
