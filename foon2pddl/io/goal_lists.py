"""Many goals in one file: `--goals FILE` (or `-` for standard input).

Formats, recognized by content:
- JSON list in the search projects' convention (`goal_nodes.json`): items
  `{"label", "states", "ingredients", "container"}` (as kitchen JSON items);
- JSON written by `goals --json` (an object with a `goals` list of rows holding `node`);
- FOON text: several object nodes as O/S lines (separated by new `O` lines or `//`);
- plain text, one goal a line: the goal syntax (`onion: chopped`), a node as the
  tools print it (`onion (chopped, in [bowl])`), or a row of the `goals` table
  (`yes   3  * onion (chopped)`), so `goals --reachable | ... --goals -` works.
Every goal keeps the file and line it came from for error messages and reports.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

from ..errors import FoonSyntaxError
from ..model.foon import make_node
from ..model.goal import GoalSpec, spec_of_node
from .foon_lines import parse_objects
from .goal_files import parse_goal_spec
from .json_text import load_json
from .jsonio import item_lines, node_from_dict
from .kitchen_files import json_node, looks_like_foon
from .parser import read_text
from .rates import refuse_rates

#: A row of the `goals` text table: made (5 columns), round (5), 2 spaces, dish mark (5), node.
_TABLE_ROW = re.compile(r"^(?:yes  |no   )[ \d]{5}  [* ] {4}(?P<node>\S.*)$")
#: The summary and header lines of the `goals` table.
_TABLE_OTHER = re.compile(r"^(?:reachable: \d+ of \d+ (?:goal candidates|dishes) |made\s+round\s+dish\s+goal$)")


@dataclass(frozen=True)
class GoalEntry:
    """One goal of a batch and where it was given (`<goal>` and 0 for a command-line `--goal`)."""

    spec: GoalSpec
    path: str = "<goal>"
    line: int = 0


def parse_described(text: str) -> GoalSpec:
    """A node as `describe()` prints it (`onion (chopped, in [bowl])`) or the goal syntax; ValueError if neither."""
    return parse_goal_spec(text)


def parse_goal_lines(text: str, path: str) -> list[GoalEntry]:
    """Plain text: one goal a line (module doc); `#` comments and blank lines skipped."""
    out = []
    for lineno, raw in enumerate(text.split("\n"), start=1):
        line = raw.strip()
        if not line or line.startswith("#") or _TABLE_OTHER.match(line):
            continue
        m = _TABLE_ROW.match(raw.rstrip())
        try:
            spec = parse_described(m.group("node") if m else line)
        except ValueError as exc:
            raise FoonSyntaxError(path, lineno, str(exc), line) from None
        out.append(GoalEntry(spec, path, lineno))
    return out


def parse_goal_json(text: str, path: str) -> list[GoalEntry]:
    """A goal_nodes.json list, or the `goals --json` document."""
    data = load_json(text, path)  # located errors for bad JSON, deep nesting, huge integers
    if isinstance(data, dict) and isinstance(data.get("goals"), list):
        rows = data["goals"]
        lines = item_lines(text, "goals")
        out = []
        for i, row in enumerate(rows):
            if not isinstance(row, dict) or "node" not in row:
                raise FoonSyntaxError(path, 0, f"goals[{i}]: expected a row with a 'node' object")
            node = node_from_dict(row["node"], path, lines[i] if i < len(lines) else 0)
            out.append(GoalEntry(spec_of_node(node), path, lines[i] if i < len(lines) else 0))
        return out
    if not isinstance(data, list):
        raise FoonSyntaxError(path, 1, "expected a JSON list of goal objects ({label, states, ingredients, "
                                       "container}) or the goals JSON document (the goals command's JSON output)")
    lines = item_lines(text)
    out = []
    for i, item in enumerate(data):
        line = lines[i] if i < len(lines) else 0
        try:
            node = json_node(item, path, i)
        except FoonSyntaxError as exc:
            raise FoonSyntaxError(path, line, exc.message) from None
        out.append(GoalEntry(spec_of_node(node), path, line))
    return out


def parse_goal_list(text: str, path: str) -> list[GoalEntry]:
    """Goals of a goal-list text in any of the formats of the module doc."""
    refuse_rates(text, path, "a goal list")
    head = text.lstrip()[:1]
    if head in "[{" and head:
        entries = parse_goal_json(text, path)
    elif looks_like_foon(text):
        entries = [GoalEntry(spec_of_node(make_node(n.label, n.states)), path, line)
                   for n, line in parse_objects(text, path)]
    else:
        entries = parse_goal_lines(text, path)
    if not entries:
        raise FoonSyntaxError(path, 0, "goal list holds no goals")
    return entries


def read_goal_list(path: str | Path) -> list[GoalEntry]:
    """`parse_goal_list` of a file, or of standard input for `-`."""
    if str(path) == "-":
        return parse_goal_list(sys.stdin.read(), "<stdin>")
    p = Path(path)
    return parse_goal_list(read_text(p), str(p))
