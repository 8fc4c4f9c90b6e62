"""Scene kitchen files: `{"objects": [{"id", "label", "states", "in" | "on"}]}` (docs/scene.md, JSON Schema
`foon2pddl/data/scene.schema.json`), read with every problem a located `FoonSyntaxError`.

An object's `in`/`on` names another object's id (at most one of the two); ids are unique; a state is one
FOON state in the goal syntax (`chopped`, `greased {butter}`), never a place or a contents list: where an
object is, and so what a holder holds, is said by `in`/`on` alone. The nodes are completed against the
network by `model.scene.place_scene` (`placed_scene`). O(objects); a problem's line is found by a
re-parse, only on error.
"""

from __future__ import annotations

from typing import Any

from ..errors import FoonInputError, FoonSyntaxError
from ..model.foon import Foon, make_node
from ..model.kitchen import Kitchen, scene_kitchen
from ..model.physical import Relation
from ..model.scene import SceneObject, SceneProblem, place_scene
from .json_text import line_of, text_problem, unknown_key

__all__ = ["KEYS", "OBJECT_KEYS", "is_scene", "placed_scene", "scene_of"]

#: Keys of the document and of one object (the JSON Schema declares exactly these).
KEYS = ("objects", "$schema", "description", "name")
OBJECT_KEYS = ("id", "label", "states", "in", "on")
#: States that say where an object is or what it holds: a scene says that with `in`/`on`.
_PLACE_STATES = frozenset({"in", "on", "contains"})


def is_scene(data: Any) -> bool:
    """Whether decoded JSON is a scene (an object with `objects`), not the search projects' list of nodes."""
    return isinstance(data, dict) and "objects" in data


def _string(item: dict, key: str, where: str, *, required: bool = True) -> str | None:
    value = item.get(key)
    if value is None and not required:
        return None
    if not isinstance(value, str) or not value.strip():
        raise ValueError(f"{where}: {key!r} must be a non-empty string")
    problem = text_problem(value, key)
    if problem:
        raise ValueError(f"{where}: {problem}")
    return value


def _object(item: Any, k: int) -> SceneObject:
    """Object `k` of the list, counted from 1 as a user counts (its holder checked later); raises ValueError."""
    from .goal_files import parse_state_text

    if not isinstance(item, dict):
        raise ValueError(f"object {k}: expected a JSON object with 'id' and 'label'")
    if (bad := unknown_key(item, OBJECT_KEYS)) is not None:
        raise ValueError(f"object {k}: {bad[1]}")
    oid = _string(item, "id", f"object {k}")
    where = f"object {oid!r}"
    label = _string(item, "label", where)
    raw = item.get("states", [])
    if not isinstance(raw, list) or not all(isinstance(s, str) for s in raw):
        raise ValueError(f"{where}: 'states' must be a list of strings")
    states = []
    for s in raw:
        problem = text_problem(s, "state") or (None if s.strip() else "empty state")
        if problem:
            raise ValueError(f"{where}: {problem}")
        try:
            state = parse_state_text(s.strip())
        except ValueError as exc:
            raise ValueError(f"{where}: {exc}") from None
        if state.label in _PLACE_STATES and (state.related or state.ingredients):
            raise ValueError(f"{where}: state {s!r}: say where an object is with \"in\"/\"on\" and the holder's id; "
                             "what a holder holds is what the scene puts in it")
        states.append(state)
    both = [r for r in Relation if r.value in item]
    if len(both) > 1:
        raise ValueError(f"{where} is in two holders: give one of \"in\" and \"on\"")
    holder = _string(item, both[0].value, where) if both else None
    node = make_node(label, states)
    return SceneObject(oid, node.label, node, holder, both[0] if both else None)


def scene_of(data: dict, text: str, path: str) -> Kitchen:
    """The scene kitchen of a decoded scene document (`text` locates problems), its nodes not yet completed."""
    if (bad := unknown_key(data, KEYS)) is not None:
        raise FoonSyntaxError(path, line_of(text, ()), bad[1])
    items = data["objects"]
    if not isinstance(items, list) or not items:
        raise FoonSyntaxError(path, line_of(text, ("objects",)), "'objects' must be a non-empty list of objects")
    objects: list[SceneObject] = []
    first: dict[str, int] = {}
    for k, item in enumerate(items):
        try:
            obj = _object(item, k + 1)
        except ValueError as exc:
            raise FoonSyntaxError(path, line_of(text, ("objects", k)), str(exc)) from None
        line = line_of(text, ("objects", k))
        if obj.id in first:
            raise FoonSyntaxError(path, line, f"duplicate id {obj.id!r} (first on line {first[obj.id]})")
        first[obj.id] = line
        objects.append(SceneObject(obj.id, obj.label, obj.node, obj.holder, obj.relation, line))
    by_id = {o.id: o for o in objects}
    for o in objects:
        if o.holder is None:
            continue
        if o.holder not in by_id:
            raise FoonSyntaxError(path, o.line, f"object {o.id!r} is {o.relation} {o.holder!r}, which is no id of "
                                                "the scene")
        seen, h = {o.id}, o.holder
        while h is not None:
            if h in seen:
                raise FoonSyntaxError(path, o.line, f"object {o.id!r}: its holders form a cycle through {h!r}")
            seen.add(h)
            h = by_id[h].holder
    return scene_kitchen(objects, path)


def placed_scene(kitchen: Kitchen, foon: Foon) -> Kitchen:
    """A scene kitchen with its nodes completed against `foon` (`model.scene.place_scene`); a contradiction is a
    FoonInputError on the object's line."""
    try:
        objects = place_scene(kitchen.scene, foon.nodes)
    except SceneProblem as exc:
        raise FoonInputError(kitchen.source, exc.obj.line, str(exc)) from None
    return scene_kitchen(objects, kitchen.source, kitchen.level)
