"""The `--network reg|exp|gen` view: which network a command searches, with the kitchen and goal to match.

- `reg`: the network as read;
- `exp`: FOON-EXP over the network's and the kitchen's object labels (`expand.py`);
  kitchen and goal as given;
- `gen`: FOON-GEN (`compress.py`); kitchen and goal abstracted through the category
  index, so native retrieval finds a category-level tree. The PDDL commands
  (`compile`, `plan`) use the lifted encoding instead (`lifted.py`), whose plans
  name concrete kitchen objects.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import UsageError
from ..io.inputs import Network, goal_spec
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec, resolve_goal
from ..model.kitchen import Kitchen
from ..model.levels import check_level, project
from .categories import CategoryIndex, load_index
from .compress import abstract_goal, abstract_kitchen, category_map, compress
from .expand import DEFAULT_THRESHOLD, expand
from .substitute import substitute_node

NETWORKS = ("reg", "exp", "gen")


@dataclass(frozen=True)
class NetworkView:
    """A network at one level with the kitchen and goal mapping that go with it."""

    kind: str
    foon: Foon
    kitchen: Kitchen
    map_goal: Callable[[GoalSpec], GoalSpec]
    note: str = ""
    map_node: Callable[[ObjectNode], ObjectNode] = lambda node: node  # a kitchen node as this view sees it

    def kitchen_strays(self, nodes: Iterable[ObjectNode], reg: Foon) -> list[ObjectNode]:
        """The kitchen `nodes` (at this view's level) that are neither a node of `reg` nor, mapped, of this view."""
        own = set(self.foon.nodes)
        known = set(reg.nodes)
        return [n for n in nodes if n not in known and self.map_node(n) not in own]

    def goal(self, goal: str | None, goal_file: str | Path | None) -> Goal:
        """The user's goal (`--goal` text or `--goal-file`) mapped and resolved against this network."""
        return self.resolve(goal_spec(goal, goal_file))

    def resolve(self, spec: GoalSpec) -> Goal:
        """A goal as the user wrote it, mapped and resolved against this network."""
        return resolve_goal(self.map_goal(spec), self.foon)


def network_view(net: Network, kind: str, level: int, kitchen: Kitchen, *, threshold: float = DEFAULT_THRESHOLD,
                 max_units: int | None = None, index: CategoryIndex | None = None) -> NetworkView:
    """REG, EXP or GEN of `net` at `level`, with `kitchen` (at `level`) and the goal mapped to match."""
    check_level(level)
    if kind == "reg":
        return NetworkView(kind, net.at(level), kitchen, lambda spec: spec)
    if kind == "exp":
        e = expand(net.foon, threshold=threshold, max_units=max_units, kitchen=kitchen)
        note = f"FOON-EXP (threshold {threshold}): {e.original_units} -> {len(e.foon.units)} units"
        return NetworkView(kind, project(e.foon, level), kitchen, lambda spec: spec, note)
    if kind == "gen":
        ix = index or load_index()
        c = compress(net.foon, ix)
        note = f"FOON-GEN ({len(ix)} categories): {c.original_units} -> {len(c.foon.units)} units"
        labels = {x for n in kitchen.nodes for x in (n.label, *(y for s in n.states for y in (s.related, *s.ingredients)))}
        mapping = category_map(sorted(labels - {""}), ix)
        return NetworkView(kind, project(c.foon, level), abstract_kitchen(kitchen, ix),
                           lambda spec: abstract_goal(spec, ix), note, lambda node: substitute_node(node, mapping))
    raise UsageError(f"network must be one of {', '.join(NETWORKS)}, not {kind!r}")
