"""JSON export and import of a FOON (schema: docs/json-schema.md, docs/foon.schema.json).

The export is deterministic (units in network order, fields in a fixed order,
attributes at their default left out) with one unit per line. The import
checks every item and reports the first problem as a `FoonSyntaxError` naming
the file, the line of the offending JSON item and its place
(`units[3].inputs[0].states[1].label`).
"""

from __future__ import annotations

import difflib
import json
from pathlib import Path
from typing import Any

from ..errors import FoonSyntaxError
from ..model.foon import Foon, FunctionalUnit, Motion, ObjectNode, Source, State, make_node, make_state, normalize_label
from ..model.levels import LEVELS
from .constraints_file import is_constraints
from .json_text import decode_tracked, line_of, load_json, text_problem, unknown_key
from .parser import read_text

FORMAT = "foon2pddl.foon"
VERSION = 1

# ---------------------------------------------------------------- export


def state_to_dict(state: State) -> dict[str, Any]:
    """`{"label", "related"?, "ingredients"?}`."""
    out: dict[str, Any] = {"label": state.label}
    if state.related:
        out["related"] = state.related
    if state.ingredients:
        out["ingredients"] = list(state.ingredients)
    return out


def node_to_dict(node: ObjectNode) -> dict[str, Any]:
    """`{"label", "states", "motion_flag"?, "goal"?, "dish"?}` (defaults 0, false, null left out)."""
    out: dict[str, Any] = {"label": node.label, "states": [state_to_dict(s) for s in node.states]}
    if node.motion_flag:
        out["motion_flag"] = node.motion_flag
    if node.goal:
        out["goal"] = True
    if node.dish is not None:
        out["dish"] = node.dish
    return out


def unit_to_dict(unit: FunctionalUnit) -> dict[str, Any]:
    """`{"inputs", "motion", "outputs", "sources"}`."""
    m = unit.motion
    motion: dict[str, Any] = {"label": m.label}
    if m.start is not None:
        motion["start"] = m.start
    if m.end is not None:
        motion["end"] = m.end
    if m.composite:
        motion["composite"] = True
    sources = []
    for s in unit.sources:
        src: dict[str, Any] = {"path": s.path, "line": s.line}
        if s.url is not None:
            src["url"] = s.url
        if s.expanded_from is not None:
            src["expanded_from"] = s.expanded_from
        sources.append(src)
    return {
        "inputs": [node_to_dict(n) for n in unit.inputs],
        "motion": motion,
        "outputs": [node_to_dict(n) for n in unit.outputs],
        "sources": sources,
    }


def foon_to_dict(foon: Foon) -> dict[str, Any]:
    """The whole network as plain JSON data."""
    return {"format": FORMAT, "version": VERSION, "level": foon.level,
            "units": [unit_to_dict(u) for u in foon.units]}


def write_json(foon: Foon) -> str:
    """Deterministic JSON text of a network: header fields, then one unit per line."""
    lines = [json.dumps(unit_to_dict(u), ensure_ascii=False) for u in foon.units]
    head = f'{{"format": {json.dumps(FORMAT)}, "version": {VERSION}, "level": {foon.level}, "units": ['
    body = "\n" + ",\n".join(lines) + "\n" if lines else ""
    return head + body + "]}\n"


# ---------------------------------------------------------------- import


class _Invalid(Exception):
    """A problem at a place in the JSON tree (a path of keys and indexes)."""

    def __init__(self, where: tuple[str | int, ...], message: str, belongs: tuple[str, ...] = ()) -> None:
        super().__init__(message)
        self.where = where
        self.message = message
        self.belongs = belongs  # a file of another kind: the inputs that take it (`errors.INPUTS`)


def _pointer(where: tuple[str | int, ...]) -> str:
    text = ""
    for step in where:
        text += f"[{step}]" if isinstance(step, int) else (f".{step}" if text else step)
    return text or "top level"


def _fields(data: Any, where: tuple, what: str, required: tuple[str, ...], optional: tuple[str, ...]) -> dict:
    if not isinstance(data, dict):
        raise _Invalid(where, f"expected {what} (a JSON object), found {_kind(data)}")
    allowed = required + optional
    for key in required:
        if key not in data:
            # `stats` for `states`: name what the file has
            typo = difflib.get_close_matches(key, [k for k in data if k not in allowed], n=1)
            if typo:
                _, words = unknown_key(typo, allowed, what, meant=key)
                raise _Invalid(where + (typo[0],), words)
            raise _Invalid(where, f"{what} lacks the required field {key!r}")
    if (bad := unknown_key(data, allowed, what)) is not None:
        raise _Invalid(where + (bad[0],), bad[1])
    return data


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string",
            list: "a list", dict: "an object"}.get(type(value), type(value).__name__)


def _label(data: dict, key: str, where: tuple, what: str) -> str:
    value = data[key]
    if not isinstance(value, str):
        raise _Invalid(where + (key,), f"{what} must be a non-empty string, found {_kind(value)}")
    if not value.strip():
        raise _Invalid(where + (key,), f"{what} must be a non-empty string, found a blank one")
    problem = text_problem(value, what)
    if problem:
        raise _Invalid(where + (key,), problem)
    return value


def _opt(data: dict, key: str, types: tuple[type, ...], default: Any, where: tuple, what: str) -> Any:
    value = data.get(key, default)
    if value is default:
        return value
    if not isinstance(value, types) or (bool not in types and isinstance(value, bool)):
        raise _Invalid(where + (key,), f"{what} must be {' or '.join(_kind(t()) for t in types)}, "
                                       f"found {_kind(value)}")
    return value


def _strings(data: dict, key: str, where: tuple, what: str) -> list[str]:
    items = _opt(data, key, (list,), [], where, what)
    for i, item in enumerate(items):
        if not isinstance(item, str) or not item.strip():
            raise _Invalid(where + (key, i), f"{what} must hold non-empty strings, found {_kind(item)}")
        problem = text_problem(item, what)
        if problem:
            raise _Invalid(where + (key, i), problem)
    return items


def _state(data: Any, where: tuple, level: int) -> State:
    d = _fields(data, where, "state", ("label",), ("related", "ingredients"))
    label = _label(d, "label", where, "state label")
    related = _opt(d, "related", (str,), "", where, "related object")
    problem = text_problem(related, "related object")
    if problem:
        raise _Invalid(where + ("related",), problem)
    ingredients = _strings(d, "ingredients", where, "ingredients")
    if ingredients and level < 3:
        raise _Invalid(where + ("ingredients",), f"ingredient list in a level-{level} network (level 3 only)")
    return make_state(label, related, ingredients)


def _node(data: Any, where: tuple, level: int) -> ObjectNode:
    d = _fields(data, where, "object node", ("label", "states"), ("motion_flag", "goal", "dish"))
    label = _label(d, "label", where, "object label")
    states_raw = d["states"]
    if not isinstance(states_raw, list):
        raise _Invalid(where + ("states",), f"states must be a list, found {_kind(states_raw)}")
    if states_raw and level == 1:
        raise _Invalid(where + ("states",), "states in a level-1 network (object labels only)")
    states = [_state(s, where + ("states", i), level) for i, s in enumerate(states_raw)]
    flag = _opt(d, "motion_flag", (int,), 0, where, "motion_flag")
    goal = _opt(d, "goal", (bool,), False, where, "goal")
    dish = _opt(d, "dish", (int,), None, where, "dish")
    return make_node(label, states, motion_flag=flag, goal=goal, dish=dish)


def _nodes(d: dict, key: str, where: tuple, level: int) -> tuple[ObjectNode, ...]:
    items = d[key]
    if not isinstance(items, list):
        raise _Invalid(where + (key,), f"{key} must be a list of object nodes, found {_kind(items)}")
    if not items:
        raise _Invalid(where + (key,), f"{key} is empty (a unit needs at least one)")
    nodes = tuple(_node(n, where + (key, i), level) for i, n in enumerate(items))
    # at level 3 a node written twice is one object; below it, one node per object (`levels.project_unit`)
    return tuple(dict.fromkeys(nodes)) if level == 3 else nodes


def _motion(data: Any, where: tuple) -> Motion:
    d = _fields(data, where, "motion", ("label",), ("start", "end", "composite"))
    label = _label(d, "label", where, "motion label")
    if label.rstrip().endswith("*"):
        raise _Invalid(where + ("label",), "motion label ends with '*' (write \"composite\": true instead)")
    start = _opt(d, "start", (str,), None, where, "start time")
    end = _opt(d, "end", (str,), None, where, "end time")
    for key, value in (("start", start), ("end", end)):
        problem = value and text_problem(value, f"{key} time")
        if problem:
            raise _Invalid(where + (key,), problem)
    composite = _opt(d, "composite", (bool,), False, where, "composite")
    return Motion(normalize_label(label), start, end, composite)


def _source(data: Any, where: tuple) -> Source:
    d = _fields(data, where, "source", ("path",), ("line", "url", "expanded_from"))
    path = d["path"]
    if not isinstance(path, str):
        raise _Invalid(where + ("path",), f"source path must be a string, found {_kind(path)}")
    line = _opt(d, "line", (int,), 0, where, "source line")
    if line < 0:
        raise _Invalid(where + ("line",), "source line must be >= 0")
    url = _opt(d, "url", (str,), None, where, "source url")
    expanded = _opt(d, "expanded_from", (str,), None, where, "expanded_from")
    return Source(path, line, url, expanded)


def _unit(data: Any, where: tuple, level: int) -> FunctionalUnit:
    d = _fields(data, where, "functional unit", ("inputs", "motion", "outputs"), ("sources",))
    inputs = _nodes(d, "inputs", where, level)
    motion = _motion(d["motion"], where + ("motion",))
    outputs = _nodes(d, "outputs", where, level)
    sources_raw = _opt(d, "sources", (list,), [], where, "sources")
    sources = tuple(_source(s, where + ("sources", i)) for i, s in enumerate(sources_raw))
    return FunctionalUnit(inputs, motion, outputs, sources)


def _foon(data: Any) -> Foon:
    if isinstance(data, list):
        raise _Invalid((), "expected a FOON JSON document (a JSON object), found a list: a JSON list of objects "
                           "is a kitchen or a goal list (docs/format.md), not a network", ("kitchen", "goals"))
    if isinstance(data, dict) and "objects" in data and "format" not in data:
        raise _Invalid((), "a JSON document with \"objects\" is a scene kitchen (docs/scene.md), not a network",
                       ("kitchen",))
    if is_constraints(data):
        raise _Invalid((), "this is a constraints file (docs/constraints.md), not a network", ("constraints",))
    d = _fields(data, (), "FOON JSON document", ("format", "version", "units"), ("level",))
    if d["format"] != FORMAT:
        raise _Invalid(("format",), f"not a foon2pddl FOON (expected \"format\": \"{FORMAT}\", found {d['format']!r})")
    version = d["version"]
    if not isinstance(version, int) or isinstance(version, bool) or not 1 <= version <= VERSION:
        raise _Invalid(("version",), f"unsupported version {version!r} (this program reads version {VERSION})")
    level = _opt(d, "level", (int,), 3, (), "level")
    if level not in LEVELS:
        raise _Invalid(("level",), f"level must be 1, 2 or 3, found {level!r}")
    units = d["units"]
    if not isinstance(units, list):
        raise _Invalid(("units",), f"units must be a list, found {_kind(units)}")
    return Foon(tuple(_unit(u, ("units", i), level) for i, u in enumerate(units)), level)


def foon_from_dict(data: Any, path: str = "<json>") -> Foon:
    """Build a network from JSON data; a problem raises FoonSyntaxError naming the item."""
    try:
        return _foon(data)
    except _Invalid as exc:
        raise FoonSyntaxError(path, 0, f"{_pointer(exc.where)}: {exc.message}", belongs=exc.belongs) from None


def parse_json(text: str, path: str = "<json>") -> Foon:
    """Parse JSON text of a network; errors name the line and the item (`units[3].motion.label`)."""
    data = load_json(text, path)
    try:
        return _foon(data)
    except _Invalid as exc:
        line = line_of(text, exc.where)
        raise FoonSyntaxError(path, line, f"{_pointer(exc.where)}: {exc.message}", belongs=exc.belongs) from None


def read_json(path: str | Path) -> Foon:
    """Read a network written by `write_json` (or by hand, following the schema)."""
    p = Path(path)
    return parse_json(read_text(p), str(p))


def node_from_dict(data: Any, path: str = "<json>", line: int = 0) -> ObjectNode:
    """An object node from its `node_to_dict` form (FoonSyntaxError naming `path:line` when malformed)."""
    try:
        return _node(data, (), 3)
    except _Invalid as exc:
        raise FoonSyntaxError(path, line, f"{_pointer(exc.where) or 'node'}: {exc.message}") from None


def item_lines(text: str, key: str | None = None) -> list[int]:
    """Line of each item of the top-level JSON list (or of the list under `key` of the top-level
    object); 1-based, [] when there is no such list."""
    root, starts = decode_tracked(text)
    if key is not None and isinstance(root, dict):
        root = root.get(key)
    if not isinstance(root, list):
        return []
    return [text.count("\n", 0, starts.get(id(item), 0)) + 1 for item in root]
