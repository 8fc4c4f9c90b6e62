"""The registry of networks (REG, EXP, GEN) and their views: which network is searched, kitchen and goal to match.

- `reg`: the network as read;
- `exp`: FOON-EXP over the network's and the kitchen's object labels (`expand.py`);
  kitchen and goal as given;
- `gen`: FOON-GEN (`compress.py`); kitchen and goal abstracted through the category
  index, so native retrieval finds a category-level tree. Planning uses the lifted
  encoding instead (`pddl.encode_lifted`, `NetworkKind.encoding`), whose plans
  name concrete kitchen objects.

The CLI's `--network` choices, the experiment's networks and the retrieve, compile
and plan commands all read `NETWORKS`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import UsageError
from ..io.inputs import Network, goal_spec
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from ..model.kitchen import Kitchen
from ..model.levels import check_level, project
from .categories import CategoryIndex, load_index
from .compress import abstract_goal, abstract_kitchen, category_map, compress
from .expand import DEFAULT_THRESHOLD, expand
from .modes import DEFAULT_MODE
from .substitute import substitute_node

__all__ = ["NETWORKS", "NetworkKind", "NetworkView", "network_view"]


@dataclass(frozen=True)
class NetworkKind:
    """A registered network kind: its name, what it is, and the encoding PDDL commands use for it.

    `encoding`: compile and plan use this encoding over the concrete (REG) network
    instead of compiling the view (None: the user's choice over the view).
    """

    name: str
    description: str
    encoding: str | None = None


#: Network name -> kind, the default first.
NETWORKS: dict[str, NetworkKind] = {k.name: k for k in (
    NetworkKind("reg", "the network as read"),
    NetworkKind("exp", f"FOON-EXP (similar objects, threshold {DEFAULT_THRESHOLD})"),
    NetworkKind("gen", "FOON-GEN (categories; compile/plan use the lifted encoding whose plans name kitchen objects)",
                encoding="gen-lifted"),
)}


def _same(x):
    return x


@dataclass(frozen=True, eq=False)
class NetworkView:
    """A network at one level with the kitchen and goal mappings that go with it.

    `foon` is the network searched; `kitchen` the kitchen given to `network_view`, as
    this network sees it; `concrete` the network as read (REG) at the same level;
    `index` the category index of GEN (None otherwise).
    """

    name: str
    foon: Foon
    kitchen: Kitchen
    map_goal: Callable[[GoalSpec], GoalSpec]
    concrete: Foon
    index: CategoryIndex | None = None
    note: str = ""
    map_node: Callable[[ObjectNode], ObjectNode] = _same  # a kitchen node as this view sees it

    def kitchen_strays(self, nodes: Iterable[ObjectNode], reg: Foon) -> list[ObjectNode]:
        """The kitchen `nodes` (at this view's level) that are neither a node of `reg` nor, mapped, of this view."""
        own = set(self.foon.nodes)
        known = set(reg.nodes)
        return [n for n in nodes if n not in known and self.map_node(n) not in own]

    def goal(self, goal: str | None, goal_file: str | Path | None) -> Goal:
        """The user's goal (its text, or a goal file) mapped and resolved against this network."""
        return self.resolve(goal_spec(goal, goal_file))

    def resolve(self, spec: GoalSpec) -> Goal:
        """A goal as the user wrote it, mapped and resolved against this network."""
        return resolve_goal(self.map_goal(spec), self.foon)

    def map_kitchen(self, kitchen: Kitchen) -> Kitchen:
        """Another (concrete) kitchen as this network sees it."""
        return kitchen if self.index is None else abstract_kitchen(kitchen, self.index)

    def goal_of(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node`, as this network sees it (UsageError if it has no match)."""
        return resolve_goal(self.map_goal(spec_of_node(node)), self.foon)

    def concrete_goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node` on the concrete network."""
        return Goal(spec_of_node(node), (node,), self.concrete.level)


def network_view(net: Network, kind: str, level: int, kitchen: Kitchen, *, threshold: float = DEFAULT_THRESHOLD,
                 max_units: int | None = None, index: CategoryIndex | None = None,
                 similarity: str = DEFAULT_MODE) -> NetworkView:
    """REG, EXP or GEN of `net` at `level`, with `kitchen` (at `level`) and the goal mapped to match;
    EXP with the `similarity` mode (`modes.py`)."""
    check_level(level)
    reg = net.at(level)
    if kind == "reg":
        return NetworkView(kind, reg, kitchen, _same, reg)
    if kind == "exp":
        e = expand(net.foon, threshold=threshold, max_units=max_units, kitchen=kitchen, similarity=similarity)
        note = f"{e.title()}: {e.original_units} -> {len(e.foon.units)} units"
        return NetworkView(kind, project(e.foon, level), kitchen, _same, reg, note=note)
    if kind == "gen":
        ix = index or load_index()
        c = compress(net.foon, ix)
        note = f"FOON-GEN ({len(ix)} categories): {c.original_units} -> {len(c.foon.units)} units"
        labels = {x for n in kitchen.nodes for x in (n.label, *(y for s in n.states for y in (s.related, *s.ingredients)))}
        mapping = category_map(sorted(labels - {""}), ix)
        return NetworkView(kind, project(c.foon, level), abstract_kitchen(kitchen, ix),
                           lambda spec: abstract_goal(spec, ix), reg, ix, note, lambda node: substitute_node(node, mapping))
    raise UsageError(f"network must be one of {', '.join(NETWORKS)}, not {kind!r}")
