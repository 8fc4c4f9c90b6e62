"""The registry of network kinds (REG, EXP, GEN) and their views: which network is searched, kitchen and goal to match.

- `reg`: the network as read;
- `exp`: FOON-EXP over the network's and the kitchen's object labels (`expand.py`);
  kitchen and goal as given;
- `gen`: FOON-GEN (`compress.py`); kitchen and goal abstracted through the category
  index, so native retrieval finds a category-level tree. Planning uses the lifted
  encoding instead (`pddl.encode_lifted`, `NetworkKind.encoding`), whose plans
  name concrete kitchen objects.

Each kind is a `NetworkKind` entry of `NETWORKS` with its `build` callable, its label
and what the CLI's hints, constraints and the experiment need to know of it; the CLI's
`--network` choices, the experiment's networks and the retrieve, compile and plan
commands all read `NETWORKS`, and no other module names a kind. Adding a kind is one
`register(NetworkKind(...))` (docs/extending.md).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path

from ..errors import UsageError
from ..io.inputs import Network, load_goal_spec
from ..model.constraints import node_labels
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from ..model.kitchen import Kitchen
from ..model.levels import check_level, project
from ..model.words import count
from .categories import CategoryIndex, load_index
from .compress import abstract_goal, abstract_kitchen, abstract_node, category_map, compress
from .expand import DEFAULT_THRESHOLD, expand
from .modes import DEFAULT_MODE
from .similarity import SimilarityMatrix
from .substitute import substitute_node

__all__ = ["DEFAULT_NETWORK", "NETWORKS", "NetworkKind", "NetworkView", "PaperFigures", "Substitutes", "ViewOptions",
           "get_network", "lifted_networks", "network_view", "register"]


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
    names: Mapping[ObjectNode, Mapping[str, str]] = field(default_factory=dict)  # GEN: `Compression.names`
    matrix: SimilarityMatrix | None = None  # EXP: the similarities its substitutes were chosen by

    def kitchen_strays(self, nodes: Iterable[ObjectNode], reg: Foon) -> list[ObjectNode]:
        """The kitchen `nodes` (at this view's level) that are neither a node of `reg` nor, mapped, of this view."""
        own = set(self.foon.nodes)
        known = set(reg.nodes)
        return [n for n in nodes if n not in known and self.map_node(n) not in own]

    def goal(self, goal: str | None, goal_file: str | Path | None, listing: str = "foon2pddl goals") -> Goal:
        """The user's goal (its text, or a goal file) mapped and resolved against this network."""
        return self.resolve(load_goal_spec(goal, goal_file), listing)

    def resolve(self, spec: GoalSpec, listing: str = "foon2pddl goals") -> Goal:
        """A goal as the user wrote it, mapped and resolved against this network (`listing`: the command listing
        its goals, which an error names).

        When nothing matches and the goal names labels the category index files nowhere (GEN keeps them as
        written, so `in [pan]` cannot match GEN's `in [pans]`), the error says which.
        """
        try:
            return resolve_goal(self.map_goal(spec), self.foon, listing=listing)
        except UsageError as exc:
            index = self.index
            words = [spec.label, *(w for s in spec.states or () for w in (s.related, *s.ingredients) if w)]
            kept = sorted({w for w in words if index and not index.choose(w) and not index.is_category(w)})
            if not kept:
                raise
            raise UsageError(f"{exc}; the category index files {', '.join(map(repr, kept))} in no category, so "
                             f"{self.name.upper()} keeps {'it' if len(kept) == 1 else 'them'} as written, and no "
                             f"{self.name.upper()} node names {'it' if len(kept) == 1 else 'them'}") from None

    def map_kitchen(self, kitchen: Kitchen) -> Kitchen:
        """Another (concrete) kitchen as this network sees it."""
        return kitchen if self.index is None else abstract_kitchen(kitchen, self.index, self.names)

    def goal_of(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node`, as this network sees it (UsageError if it has no match)."""
        read = self.names.get(node)  # GEN: the names its units read as their object's category
        return resolve_goal(self.map_goal(spec_of_node(substitute_node(node, read) if read else node)), self.foon)

    def concrete_goal(self, node: ObjectNode) -> Goal:
        """The goal asking for the concrete `node` on the concrete network."""
        return Goal(spec_of_node(node), (node,), self.concrete.level)


class Substitutes(StrEnum):
    """What stands in for an object constraints ban: nothing (the network as read), the most similar
    allowed object (EXP), an allowed member of its category (GEN)."""

    NONE = "none"
    SIMILAR = "similar"
    CATEGORY = "category"


@dataclass(frozen=True)
class ViewOptions:
    """How a kind builds its network: EXP's similarity `threshold`, `max_units` and `similarity` mode,
    GEN's category `index` (None: the shipped one)."""

    threshold: float = DEFAULT_THRESHOLD
    max_units: int | None = None
    index: CategoryIndex | None = None
    similarity: str = DEFAULT_MODE


@dataclass(frozen=True)
class PaperFigures:
    """The seed paper's figures for a network: success range (percent of goals) and greedy ms per trial."""

    successes: tuple[int, int]
    time_ms: float


@dataclass(frozen=True)
class NetworkKind:
    """A registered network kind.

    `build(net, level, kitchen, options)` gives its `NetworkView`; `label` is its name in
    reports (REG); `description` the `--network` help, `summary` the experiment report's
    (`{similarity}`: the run's similarity mode).
    `encoding`: compile and plan use this encoding over the concrete (REG) network instead
    of compiling the view (None: the user's choice over the view). `as_read`: the network
    as read (the default; other kinds are hinted when it cannot make a goal). `hint`: what
    a hint says the kind offers ("" never hinted), built for a hint only on networks of at
    most `hint_max_units` units; `slow_step(net, kitchen)`: a message to show before a
    build that will take seconds (None: it will not). `substitutes`: what stands in for
    banned objects. `schedule`: experiment batches on kinds with a lower value start first.
    `building`: what the CLI says while a slow build runs (`{units}`: the network's units).
    `requires()`: raises `MissingDependencyError` (with the install command) when what
    building the kind needs is missing; called before long work (the experiment checks
    every network of a run before its first cell).
    """

    name: str
    label: str
    description: str
    build: Callable[[Network, int, Kitchen, ViewOptions], NetworkView]
    summary: str = ""
    encoding: str | None = None
    as_read: bool = False
    hint: str = ""
    hint_max_units: int = 0
    slow_step: Callable[[Network, Kitchen], str | None] | None = None
    substitutes: Substitutes = Substitutes.NONE
    paper: PaperFigures | None = None
    schedule: int = 0
    building: str = ""
    requires: Callable[[], None] = lambda: None


def _reg(net: Network, level: int, kitchen: Kitchen, options: ViewOptions) -> NetworkView:
    reg = net.at(level)
    return NetworkView(DEFAULT_NETWORK, reg, kitchen, _same, reg)


def _exp(net: Network, level: int, kitchen: Kitchen, options: ViewOptions) -> NetworkView:
    e = expand(net.foon, threshold=options.threshold, max_units=options.max_units, kitchen=kitchen,
               similarity=options.similarity)
    note = f"{e.title()}: {e.original_units} -> {count(len(e.foon.units), 'unit')}"
    return NetworkView(_EXP, project(e.foon, level), kitchen, _same, net.at(level), note=note, matrix=e.matrix)


def _exp_slow_step(net: Network, kitchen: Kitchen) -> str | None:
    from .expand import vocabulary
    from .modes import mode_matrix_is_cached

    if mode_matrix_is_cached(vocabulary(net.foon, kitchen)):
        return None
    return "checking whether FOON-EXP can make it: computing its WordNet similarity matrix (once per set of labels, then cached)"


def _wordnet() -> None:
    from .wordnet import check_available

    check_available()


def _gen(net: Network, level: int, kitchen: Kitchen, options: ViewOptions) -> NetworkView:
    ix = options.index or load_index()
    c = compress(net.foon, ix)
    note = f"FOON-GEN ({count(len(ix), 'category')}): {c.original_units} -> {count(len(c.foon.units), 'unit')}" + (
        f"; {count(len(c.readings), 'name')} read as their unit's object (`generalize` lists them)" if c.readings else "")
    labels = set().union(*(node_labels(n) for n in kitchen.nodes))
    mapping = category_map(sorted(labels - {""}), ix)
    return NetworkView(_GEN, project(c.foon, level), abstract_kitchen(kitchen, ix, c.names),
                       lambda spec: abstract_goal(spec, ix), net.at(level), ix, note,
                       lambda node: abstract_node(node, mapping, c.names), c.names)


DEFAULT_NETWORK, _EXP, _GEN = "reg", "exp", "gen"

#: Network name -> kind, the default first.
NETWORKS: dict[str, NetworkKind] = {k.name: k for k in (
    NetworkKind(DEFAULT_NETWORK, "REG", "the network as read", _reg, "the network as read", as_read=True,
                paper=PaperFigures((15, 53), 2120.0), schedule=2),
    NetworkKind(_EXP, "EXP", f"FOON-EXP (similar objects, threshold {DEFAULT_THRESHOLD})", _exp,
                "FOON-EXP, WordNet similarity (mode `{similarity}`) >= 0.89", hint="FOON-EXP (similar objects stand in)",
                hint_max_units=600, slow_step=_exp_slow_step, substitutes=Substitutes.SIMILAR,
                paper=PaperFigures((14, 62), 15217.0), schedule=0, requires=_wordnet,
                building="building FOON-EXP of {units} (WordNet similarities: once per set of labels, then cached)"),
    NetworkKind(_GEN, "GEN", "FOON-GEN (categories; compile/plan use the lifted encoding whose plans name kitchen "
                "objects)", _gen, "FOON-GEN, objects replaced by their categories", encoding="gen-lifted",
                hint="FOON-GEN (object categories)", hint_max_units=2500, substitutes=Substitutes.CATEGORY,
                paper=PaperFigures((66, 87), 1167.5), schedule=1, building="building FOON-GEN of {units}"),
)}


def register(kind: NetworkKind) -> NetworkKind:
    """Add (or replace) a network kind; returns it."""
    NETWORKS[kind.name] = kind
    return kind


def get_network(name: str) -> NetworkKind:
    """The kind called `name` (UsageError listing the known ones)."""
    try:
        return NETWORKS[name]
    except KeyError:
        raise UsageError(f"network must be one of {', '.join(NETWORKS)}, not {name!r}") from None


def lifted_networks() -> tuple[str, ...]:
    """The kinds whose planning uses their own (lifted) encoding over the concrete network."""
    return tuple(k.name for k in NETWORKS.values() if k.encoding is not None)


def network_view(net: Network, kind: str, level: int, kitchen: Kitchen, *, threshold: float = DEFAULT_THRESHOLD,
                 max_units: int | None = None, index: CategoryIndex | None = None,
                 similarity: str = DEFAULT_MODE) -> NetworkView:
    """The view of kind `kind` (REG, EXP, GEN, ...) of `net` at `level`, with `kitchen` (at `level`) and the goal
    mapped to match; EXP with the `similarity` mode (`modes.py`)."""
    check_level(level)
    return get_network(kind).build(net, level, kitchen, ViewOptions(threshold, max_units, index, similarity))
