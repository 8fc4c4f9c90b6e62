"""The task's physical objects, named: the counted ones numbered per label (`vinegar_2`, `counted_name`), those
added after them, and a scene's by their ids. One way to name an object the counts give, for both encodings over
physical objects (`encode_instances`, and the relational one's `relational_init` and `relational_objects`).
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model.foon import ObjectNode
from ..model.scene import SceneObject
from .names import NameTable
from .task import Instance

__all__ = ["counted_name", "counted_objects", "named_objects", "scene_instances"]


def counted_name(table: NameTable, label: str, k: int) -> str:
    """The PDDL name of the `k`-th object of `label` (`vinegar_2`), through the task's name `table`."""
    return table.name(f"{label} {k}", key=("instance", label, k))


def named_objects(table: NameTable, instances: list[Instance], nodes: Iterable[ObjectNode]) -> list[Instance]:
    """`instances` plus one object per node of `nodes`, numbered after its label's last one."""
    out = list(instances)
    for node in nodes:
        k = 1 + sum(x.label == node.label for x in out)
        out.append(Instance(counted_name(table, node.label, k), node.label, node))
    return out


def counted_objects(table: NameTable, counts) -> list[Instance]:
    """The counted objects, numbered per label: kitchen ones in their nodes, then the not yet made."""
    starts: dict[str, list[ObjectNode | None]] = {}
    for node, k in counts.at_node:
        starts.setdefault(node.label, []).extend([node] * k)
    for label, k in counts.unmade:
        starts.setdefault(label, []).extend([None] * k)
    return [Instance(counted_name(table, label, k), label, node)
            for label in sorted(starts) for k, node in enumerate(starts[label], start=1)]


def scene_instances(table: NameTable, scene: Iterable[SceneObject], unmade: Iterable[tuple[str, int]]) -> list[Instance]:
    """A scene's objects as the task's objects (`model.scene`): named by their ids (through `table`, so no id
    can break or inject into PDDL), in their nodes, in or on their holders; then the `unmade` objects (label,
    count) the units make, numbered per label after the scene's objects of that label (`vinegar_2`)."""
    objs = sorted(scene)
    name = {o.id: table.name(o.id, key=("scene", o.id)) for o in objs}
    out = [Instance(name[o.id], o.label, o.node, name[o.holder] if o.holder is not None else None, o.relation,
                    o.id) for o in objs]
    for label, k in unmade:
        first = 1 + sum(o.label == label for o in objs)
        out += [Instance(counted_name(table, label, i), label) for i in range(first, first + k)]
    return out
