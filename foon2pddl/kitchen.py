"""Kitchens: the object nodes available before any unit runs.

Three file formats are read (FOON-style O/S lines, the JSON convention of public
FOON search projects, and one goal-syntax node per line), and a network's
default kitchen is derived by the rule documented in `default_kitchen`.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from .errors import FoonSyntaxError
from .levels import project_node
from .model import Foon, ObjectNode, State, make_node, make_state
from .parser import parse_objects, read_text

#: States an object is in before anyone touches it. An input node whose states
#: are all base states is in the default kitchen even if some unit also produces
#: it (a mixer goes off -> on -> off; without this rule `off` would never be available).
BASE_STATES: frozenset[str] = frozenset(
    {
        "off", "off (ready)", "empty", "clean", "whole", "raw", "uncooked", "uncook",
        "unpeeled", "uncracked", "closed", "sealed", "dry", "frozen", "ready",
        "solid", "liquid", "granulated", "powder", "fresh", "cold", "room temperature",
    }
)


@dataclass(frozen=True)
class Kitchen:
    """A set of available object nodes at one hierarchy level."""

    nodes: frozenset[ObjectNode]
    level: int = 3
    source: str = ""

    def __contains__(self, node: object) -> bool:
        return node in self.nodes

    def __len__(self) -> int:
        return len(self.nodes)

    def project(self, level: int) -> Kitchen:
        """The kitchen as seen at `level`."""
        if level >= self.level:
            return self
        return Kitchen(frozenset(project_node(n, level) for n in self.nodes), level, self.source)

    def sorted_nodes(self) -> list[ObjectNode]:
        """Nodes in a stable order (for writing and display)."""
        return sorted(self.nodes)


def starting_nodes(foon: Foon) -> frozenset[ObjectNode]:
    """Input nodes that no unit creates (a unit that passes a node through unchanged does not create it)."""
    created = {n for u in foon.units for n in u.outputs if n not in u.inputs}
    return frozenset(n for u in foon.units for n in u.inputs if n not in created)


def default_kitchen(foon: Foon, base_states: Iterable[str] = BASE_STATES) -> Kitchen:
    """Starting nodes plus every input node whose states are all base states."""
    base = frozenset(base_states)
    extra = {
        n for u in foon.units for n in u.inputs
        if n.states and all(s.label in base and not s.related and not s.ingredients for s in n.states)
    }
    return Kitchen(starting_nodes(foon) | frozenset(extra), foon.level, "default kitchen")


def json_node(item: object, path: str, index: int) -> ObjectNode:
    """One `{"label", "states", "ingredients", "container"}` item of the JSON convention.

    `states` are state labels; `container` becomes the state `in [container]`;
    `ingredients` become the state `contains {...}`.
    """
    if not isinstance(item, dict) or not isinstance(item.get("label"), str) or not item["label"].strip():
        raise FoonSyntaxError(path, 0, f"item {index}: expected an object with a non-empty string 'label'")
    states_raw = item.get("states") or []
    ingredients = item.get("ingredients") or []
    container = item.get("container")
    if not isinstance(states_raw, list) or not all(isinstance(s, str) for s in states_raw):
        raise FoonSyntaxError(path, 0, f"item {index} ({item['label']}): 'states' must be a list of strings")
    if not isinstance(ingredients, list) or not all(isinstance(s, str) for s in ingredients):
        raise FoonSyntaxError(path, 0, f"item {index} ({item['label']}): 'ingredients' must be a list of strings")
    if container is not None and not isinstance(container, str):
        raise FoonSyntaxError(path, 0, f"item {index} ({item['label']}): 'container' must be a string or null")
    states: list[State] = [make_state(s) for s in states_raw if s.strip()]
    if container and container.strip():
        states.append(make_state("in", container))
    if ingredients:
        states.append(make_state("contains", "", ingredients))
    return make_node(item["label"], states)


def read_json_nodes(path: Path) -> list[ObjectNode]:
    """Nodes of a JSON list in the public search projects' convention."""
    text = read_text(path)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise FoonSyntaxError(str(path), exc.lineno, f"invalid JSON: {exc.msg}") from None
    if not isinstance(data, list):
        raise FoonSyntaxError(str(path), 1, "expected a JSON list of objects")
    return [json_node(item, str(path), i) for i, item in enumerate(data)]


def read_node_lines(text: str, path: str) -> list[ObjectNode]:
    """One node per line in the goal syntax (`onion: whole`); `#` comments allowed."""
    from .goals import parse_goal_spec

    nodes = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        try:
            spec = parse_goal_spec(line)
        except ValueError as exc:
            raise FoonSyntaxError(path, lineno, str(exc), line) from None
        nodes.append(make_node(spec.label, spec.states or ()))
    return nodes


def _looks_like_foon(text: str) -> bool:
    for line in text.splitlines():
        s = line.strip()
        if s and not s.startswith("#"):
            return s.startswith("//") or (s[:1] in "OS" and "\t" in s)
    return False


def read_kitchen(path: str | Path) -> Kitchen:
    """Read a kitchen file: `.json`, FOON-style O/S lines, or one goal-syntax node per line."""
    p = Path(path)
    if p.suffix.lower() == ".json":
        nodes = read_json_nodes(p)
    else:
        text = read_text(p)
        if _looks_like_foon(text):
            nodes = [n for n, _ in parse_objects(text, str(p))]
        else:
            nodes = read_node_lines(text, str(p))
    if not nodes:
        raise FoonSyntaxError(str(p), 0, "kitchen file lists no object nodes")
    return Kitchen(frozenset(nodes), 3, str(p))


def write_kitchen(kitchen: Kitchen) -> str:
    """FOON-style text of a kitchen (readable by `read_kitchen`)."""
    from .writer import write_node

    return "".join(write_node(n) + "//\n" for n in kitchen.sorted_nodes())
