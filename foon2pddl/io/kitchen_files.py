"""Kitchen files: JSON (search-project convention), FOON-style O/S lines, one node per line."""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import FoonSyntaxError
from ..model.foon import ObjectNode, State, make_node, make_state
from ..model.kitchen import Kitchen
from .foon_lines import LINE_ID, NETWORK_NOT_OBJECTS, parse_objects
from .json_text import item_lines, line_of, load_json, text_problem, unknown_key
from .parser import read_text
from .rates import refuse_rates

#: The keys of a kitchen or goal item in the JSON convention; any other is an error.
ITEM_KEYS = ("label", "states", "ingredients", "container")


def json_node(item: object, path: str, index: int) -> ObjectNode:
    """One `{"label", "states", "ingredients", "container"}` item of the JSON convention.

    `states` are state labels; `container` becomes the state `in [container]`;
    `ingredients` become the state `contains {...}`. `index` counts from 0; errors name the item counted from 1
    (`item 1` is the first, as a user counts) and line 0 (`read_json_nodes` locates them).
    """
    if not isinstance(item, dict) or not isinstance(item.get("label"), str) or not item["label"].strip():
        raise FoonSyntaxError(path, 0, f"item {index + 1}: expected an object with a non-empty string 'label'")
    states_raw = item.get("states") or []
    ingredients = item.get("ingredients") or []
    container = item.get("container")
    label = item["label"]
    problem = text_problem(label, "label")
    if problem:
        raise FoonSyntaxError(path, 0, f"item {index + 1}: {problem}")
    if (bad := unknown_key(item, ITEM_KEYS)) is not None:
        raise FoonSyntaxError(path, 0, f"item {index + 1} ({label}): {bad[1]}")
    if not isinstance(states_raw, list) or not all(isinstance(s, str) for s in states_raw):
        raise FoonSyntaxError(path, 0, f"item {index + 1} ({label}): 'states' must be a list of strings")
    if not isinstance(ingredients, list) or not all(isinstance(s, str) for s in ingredients):
        raise FoonSyntaxError(path, 0, f"item {index + 1} ({label}): 'ingredients' must be a list of strings")
    if container is not None and not isinstance(container, str):
        raise FoonSyntaxError(path, 0, f"item {index + 1} ({label}): 'container' must be a string or null")
    for what, text in [("state", s) for s in states_raw] + [("ingredient", s) for s in ingredients] + \
            [("container", container or "")]:
        problem = text_problem(text, what)
        if problem:
            raise FoonSyntaxError(path, 0, f"item {index + 1} ({label}): {problem}")
    states: list[State] = [make_state(s) for s in states_raw if s.strip()]
    if container and container.strip():
        states.append(make_state("in", container))
    if ingredients:
        states.append(make_state("contains", "", ingredients))
    return make_node(item["label"], states)


def read_json_nodes(path: Path) -> list[ObjectNode]:
    """Nodes of a JSON list in the public search projects' convention."""
    text = read_text(path)
    return json_nodes(load_json(text, str(path)), text, path)


def json_nodes(data: object, text: str, path: Path) -> list[ObjectNode]:
    """Nodes of decoded JSON in the public search projects' convention (`text` locates problems)."""
    if not isinstance(data, list):
        what, belongs = _not_a_kitchen(data)
        raise FoonSyntaxError(str(path), 1, what, belongs=belongs)
    nodes = []
    for i, item in enumerate(data):
        try:
            nodes.append(json_node(item, str(path), i))
        except FoonSyntaxError as exc:  # locate the item (a re-parse, only on error)
            raise FoonSyntaxError(exc.path, line_of(text, (i,)), exc.what, belongs=exc.belongs) from None
    return nodes


def _not_a_kitchen(data: object) -> tuple[str, tuple[str, ...]]:
    """What a JSON document that is no list of objects (and no scene) is, and the inputs that take it."""
    from .constraints_file import is_constraints
    from .jsonio import FORMAT

    if isinstance(data, dict) and data.get("format") == FORMAT:
        return "this is a FOON network (JSON, docs/json-schema.md), not a kitchen", ("paths",)
    if is_constraints(data):
        return "this is a constraints file (docs/constraints.md), not a kitchen", ("constraints",)
    return 'expected a JSON list of objects, or a scene: {"objects": [...]} (docs/scene.md)', ()


#: `2 x bowl: empty`: a node-per-line kitchen entry with an instance count.
_COUNT = re.compile(r"(\d+)\s*[x\u00d7]\s+(\S.*)\Z")
#: what reads as a count but is none: `-1 x bowl`, `1.5 x bowl`, `2 x` with no node after it.
_NOT_A_COUNT = re.compile(r"([-+]?\d*[.,]?\d+)\s*[x\u00d7](?:\s|\Z)")


def read_node_lines(text: str, path: str) -> list[tuple[ObjectNode, int | None]]:
    """One node per line in the goal syntax (`onion: whole`), optionally counted (`2 x bowl: empty`).

    The count is how many physical objects are in that state (the `instances` PDDL
    encoding uses it; FOON's own semantics ignores it); None when not given. `#` comments allowed.
    """
    return [(n, k) for n, k, _ in _node_lines(text, path)]


def _node_lines(text: str, path: str) -> list[tuple[ObjectNode, int | None, int]]:
    """`read_node_lines` with each node's line."""
    from .goal_files import parse_goal_spec

    nodes: list[tuple[ObjectNode, int | None, int]] = []
    first = 0
    for lineno, raw in enumerate(text.split("\n"), start=1):  # `\n` only: U+2028 is not a line break here
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        foon = _foon_line(line)
        if foon:
            message = _mixed(foon, first)
            raise FoonSyntaxError(path, lineno, message, line, ("paths",) if message == NETWORK_NOT_OBJECTS else ())
        first = first or lineno
        counted = _COUNT.match(line)
        count = int(counted.group(1)) if counted else None
        if count == 0:  # "none" to a count, "one" to FOON's semantics: neither reading is safe to pick silently
            raise FoonSyntaxError(path, lineno, "a count of 0 lists no object: remove the line, or count at least 1", line)
        wrong = None if counted else _NOT_A_COUNT.match(line)
        if wrong:  # else read as the label `-1 x bowl`, matching no node: a warning, the line's objects lost
            raise FoonSyntaxError(path, lineno, f"a count of {wrong.group(1)}: a count is a whole number of at least 1, "
                                  "then the node (`2 x bowl: empty`)", line)
        try:
            spec = parse_goal_spec(counted.group(2) if counted else line)
        except ValueError as exc:
            raise FoonSyntaxError(path, lineno, str(exc), line) from None
        nodes.append((make_node(spec.label, spec.states or ()), count, lineno))
    return nodes


#: the head of a FOON line written with spaces for tabs: `O278 mixing bowl 1`, `S41 empty`.
_FOON_HEAD = re.compile(r"[OSM]\d+")


def _foon_line(line: str) -> str:
    """`O`, `S`, `M` or `//` for a line in FOON text form (tabs or spaces), else ''."""
    if line.startswith("//"):
        return "//"
    fields = line.split("\t")
    if len(fields) > 1 and LINE_ID.fullmatch(fields[0].strip()):
        return line[0]
    return line[0] if _FOON_HEAD.fullmatch(line.split()[0]) else ""


def _mixed(kind: str, first: int) -> str:
    """The error for a FOON line in a kitchen of one node per line."""
    if kind == "M" and not first:
        return NETWORK_NOT_OBJECTS
    after = f", but line {first} lists a node in the goal syntax" if first else ""
    return (f"a FOON `{kind}` line{after}: a kitchen file is in one form throughout, FOON-style O/S lines "
            "(its first line that is not a comment starts with `//`, or with `O`/`S` and a tab) or one node per "
            "line (`onion: whole`); docs/format.md")


def looks_like_foon(text: str) -> bool:
    for line in text.split("\n"):
        s = line.strip()
        if s and not s.startswith("#"):
            return s.startswith("//") or (s[:1] in "OS" and "\t" in s)
    return False


#: An object's label as a list of objects writes it: up to 5 words of letters, digits, `'` and `-` (no sentence).
_LABEL = re.compile(r"[^\W\d_][\w'-]*(?: [\w'-]+){0,4}")


def refuse_object_lines(text: str, path: str) -> None:
    """Refuse a list of objects, one a line, given as a network (stop 55's pass: `stats utensils.txt` said only
    `expected an 'O', 'S' or 'M' line`): a located error naming the options that take it. Bare labels (`knife`)
    may be a utensils list, a kitchen or a goal list; objects with states (`onion: whole`, `2 x bowl`) a kitchen
    or a goal list. Text that is no such list (a FOON line, a line whose label is no label but a sentence, a line
    no goal parses) is left to the parser's error."""
    lines = [raw.strip() for raw in text.split("\n") if raw.strip() and not raw.strip().startswith("#")]
    heads = [(_COUNT.match(line).group(2) if _COUNT.match(line) else line).split(":", 1)[0].strip() for line in lines]
    if not lines or not all(_LABEL.fullmatch(h) for h in heads) or any(line.endswith(".") for line in lines):
        return
    try:
        listed = _node_lines(text, path)
    except FoonSyntaxError:
        return
    bare = all(k is None and not n.states for n, k, _ in listed)
    raise FoonSyntaxError(path, 1, "it reads as a list of objects, one a line (no `O`, `S`, `M` or `//` line), not "
                          "a network", belongs=("utensils", "kitchen", "goals") if bare else ("kitchen", "goals"))


def read_kitchen(path: str | Path) -> Kitchen:
    """Read a kitchen file: `.json` (a scene, `io.scene_file`, or the search projects' list of nodes),
    FOON-style O/S lines, or one goal-syntax node per line."""
    p = Path(path)
    counts: dict[ObjectNode, int] = {}
    if p.suffix.lower() == ".json":
        from .scene_file import is_scene, scene_of

        text = read_text(p)
        data = load_json(text, str(p))
        if is_scene(data):
            return scene_of(data, text, str(p))
        nodes = json_nodes(data, text, p)
        listed = list(zip(nodes, item_lines(text), strict=True))
    else:
        text = read_text(p)
        refuse_rates(text, str(p), "a kitchen")
        if looks_like_foon(text):
            listed = parse_objects(text, str(p))
        else:
            counted = _node_lines(text, str(p))
            listed = [(n, line) for n, _, line in counted]
            for n, k, _ in counted:
                if k is not None:
                    counts[n] = counts.get(n, 0) + k
        nodes = [n for n, _ in listed]
    if not nodes:
        raise FoonSyntaxError(str(p), 0, "kitchen file lists no object nodes")
    lines: dict[ObjectNode, int] = {}
    for n, line in listed:
        lines.setdefault(n, line)
    return Kitchen(frozenset(nodes), 3, str(p), tuple(sorted(counts.items())), lines=tuple(sorted(lines.items())))


def write_kitchen(kitchen: Kitchen) -> str:
    """FOON-style text of a kitchen (readable by `read_kitchen`)."""
    from .writer import write_node

    return "".join(write_node(n) + "//\n" for n in kitchen.sorted_nodes())


def parse_utensils(text: str, path: str = "<utensils>") -> frozenset[str]:
    """Utensil labels, one a line (`utensils.txt`); blank lines and `#` comments skipped, labels normalized."""
    from ..model.foon import normalize_label
    from .foon_lines import CONTROL_CHARS

    refuse_rates(text, path, "a utensils list")
    labels = set()
    for lineno, raw in enumerate(text.split("\n"), start=1):  # `\n` only, as every reader
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if CONTROL_CHARS.search(line) or "\t" in line:
            raise FoonSyntaxError(path, lineno, "expected one object label a line", raw)
        labels.add(normalize_label(line))
    return frozenset(labels)


def read_utensils(path: str | Path) -> frozenset[str]:
    """`parse_utensils` of a file."""
    p = Path(path)
    return parse_utensils(read_text(p), str(p))
