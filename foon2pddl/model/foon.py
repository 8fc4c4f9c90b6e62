"""Immutable FOON model: states, object nodes, motions, functional units and networks.

Labels are stored normalized (lower-cased, whitespace collapsed) so that node
equality *is* node identity at level 3; `levels.project` derives levels 1 and 2.
Attributes that are not identity (motion flag, goal and dish marks, times,
provenance) are excluded from equality and hashing.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from itertools import chain, compress, repeat
from operator import attrgetter, is_not

from .bulk import bulk
from .node_table import NodeTable, first_objects, node_table, unit_index
from .words import count

_WS = re.compile(r"\s+")


@lru_cache(maxsize=1 << 16)
def normalize_label(text: str) -> str:
    """Canonical form of a label: lower-cased, whitespace collapsed, stripped.

    Cached: the same few hundred labels recur tens of thousands of times in a network.
    """
    return _WS.sub(" ", text).strip().lower()


class _HashOnce:
    """Base of the frozen dataclasses hashed constantly (states, nodes, units: sets, dict keys): the hash of
    `_identity()` (the generated dataclass hash's value) is computed once and kept as an attribute (`make_state`
    and `make_node` fill `__dict__` directly: a dict per object, ~64 bytes, for half the build time; 1M units:
    2.76 against 2.55 GB peak, 43 against 48-52 s CPU); a pickle drops it (string hashes differ per process).
    A dataclass replaces an inherited `__hash__`, so each class names this one in its body."""

    def _identity(self) -> tuple:
        raise NotImplementedError

    def __hash__(self) -> int:
        try:
            return self._hash
        except AttributeError:
            value = hash(self._identity())
            object.__setattr__(self, "_hash", value)
            return value

    def __getstate__(self) -> dict:
        state = self.__dict__.copy()
        state.pop("_hash", None)
        return state


@dataclass(frozen=True, order=True)
class State(_HashOnce):
    """A state of an object: `chopped`, `in [bowl]`, `contains {salt, water}`."""

    label: str
    related: str = ""
    ingredients: tuple[str, ...] = ()

    __hash__ = _HashOnce.__hash__

    def __eq__(self, other: object) -> bool:
        """The generated equality (label, related, ingredients), answered at once for the same object."""
        if other.__class__ is not self.__class__:
            return NotImplemented
        return self is other or (self.label == other.label and self.related == other.related
                                 and self.ingredients == other.ingredients)

    def _identity(self) -> tuple:
        return (self.label, self.related, self.ingredients)

    def describe(self) -> str:
        """Human-readable form, also the goal syntax for one state."""
        text = self.label
        if self.related:
            text += f" [{self.related}]"
        if self.ingredients:
            text += " {" + ", ".join(self.ingredients) + "}"
        return text


@dataclass(frozen=True, order=True)
class ObjectNode(_HashOnce):
    """An object in a set of states. Equality is level-3 identity.

    `states` is kept sorted and duplicate-free by the constructors in this
    module (`make_node`), so two nodes with the same states compare equal
    whatever order the source listed them in.
    """

    label: str
    states: tuple[State, ...] = ()
    motion_flag: int = field(default=0, compare=False)
    goal: bool = field(default=False, compare=False)
    dish: int | None = field(default=None, compare=False)

    __hash__ = _HashOnce.__hash__

    def __eq__(self, other: object) -> bool:
        """The generated equality (label and states), answered at once for the same object (a network's nodes
        recur: membership tests mostly meet the very object) or for two hashes that differ (a role's node before
        and after the unit), without building tuples."""
        if other.__class__ is not self.__class__:
            return NotImplemented
        if self is other:
            return True
        try:  # the kept hashes read directly: two calls of `__hash__` were a third of the time of this method
            if self._hash != other._hash:
                return False
        except AttributeError:  # a node built without `make_node`, not hashed yet
            if hash(self) != hash(other):
                return False
        return self.label == other.label and self.states == other.states

    def _identity(self) -> tuple:
        return (self.label, self.states)

    @cached_property
    def ingredients(self) -> frozenset[str]:
        """All ingredients listed on any state of this node."""
        return frozenset(i for s in self.states for i in s.ingredients)

    def describe(self) -> str:
        """`onion (chopped, in [bowl])`: the goal syntax without the colon."""
        if not self.states:
            return self.label
        return f"{self.label} ({', '.join(s.describe() for s in self.states)})"


def make_state(label: str, related: str = "", ingredients: Iterable[str] = ()) -> State:
    """Build a normalized state: ingredient list deduplicated and sorted, "" = no related object. Equal states are
    one object (`_STATES`): two nodes of one value in different units then compare their states by identity, in C
    (`ObjectNode.__eq__` met 6.2 million such pairs of states in GEN trial 10 goal 57, a Python call each)."""
    items = set(map(normalize_label, ingredients)) - {""}
    identity = (normalize_label(label), normalize_label(related), tuple(sorted(items)))
    try:
        return _STATES[identity]
    except KeyError:
        pass
    fields = (state := _new(State)).__dict__  # the fields set directly, then the hash (as `make_node` does)
    fields["label"], fields["related"], fields["ingredients"] = identity
    fields["_hash"] = hash(identity)
    return _STATES.setdefault(identity, state)


#: The states `make_state` built, by their fields: a few thousand in the largest network (FOON's state words and
#: contents lists), kept for the life of the process.
_STATES: dict[tuple[str, str, tuple[str, ...]], State] = {}


def make_node(label: str, states: Iterable[State] = (), *, motion_flag: int = 0, goal: bool = False,
              dish: int | None = None) -> ObjectNode:
    """Build a normalized node: label normalized, states sorted and deduplicated. Its hash is computed here
    (every node is hashed: in a network's table, sets, dict keys), which costs less than on first use."""
    states = _sorted_states(tuple(states))
    label = normalize_label(label)
    # the frozen dataclass's fields set directly: its `__init__` calls `object.__setattr__` once per field,
    fields = (node := _new(ObjectNode)).__dict__  # which costs twice as much
    fields["label"], fields["states"], fields["motion_flag"], fields["goal"], fields["dish"] = (
        label, states, motion_flag, goal, dish)
    fields["_hash"] = hash((label, states))
    return node


def make_unit(inputs: tuple[ObjectNode, ...], motion: Motion, outputs: tuple[ObjectNode, ...],
              sources: tuple[Source, ...]) -> FunctionalUnit:
    """`FunctionalUnit(inputs, motion, outputs, sources)` built as `make_node` builds nodes (a reader's units)."""
    fields = (unit := _new(FunctionalUnit)).__dict__
    fields["inputs"], fields["motion"], fields["outputs"], fields["sources"] = inputs, motion, outputs, sources
    return unit


def make_source(path: str, line: int) -> Source:
    """`Source(path, line)` built as `make_node` builds nodes (one per unit read)."""
    fields = (source := _new(Source)).__dict__
    fields["path"], fields["line"], fields["url"], fields["expanded_from"], fields["expanded_to"] = path, line, None, None, None
    return source


_new = object.__new__  # with the fields set in `__dict__`: what `make_node` and its kin build

#: `State`'s dataclass order as a key read in C (the generated `__lt__` builds two tuples per comparison).
_STATE_ORDER = attrgetter("label", "related", "ingredients")


def _sorted_states(states: tuple[State, ...]) -> tuple[State, ...]:
    """`states` in `State` order without repeats (the first of equal states kept), compared by their fields
    (`_STATE_ORDER`, read in C) rather than hashed by `State.__hash__`, a Python call per state."""
    if len(states) < 2:
        return states
    if len(states) == 2:  # the usual case
        one, two = map(_STATE_ORDER, states)
        return states if one < two else states[::-1] if two < one else states[:1]
    by_fields = dict(zip(map(_STATE_ORDER, reversed(states)), reversed(states), strict=True))  # the first last
    return tuple(map(by_fields.__getitem__, sorted(by_fields)))


@dataclass(frozen=True)
class Motion:
    """The manipulation of a unit. `composite` marks a `*`-suffixed label."""

    label: str
    start: str | None = field(default=None, compare=False)
    end: str | None = field(default=None, compare=False)
    composite: bool = field(default=False, compare=False)


@dataclass(frozen=True)
class Source:
    """Where a unit was read: file path (or recipe name) and 1-based line."""

    path: str
    line: int = 0
    url: str | None = None
    expanded_from: str | None = None
    expanded_to: str | None = None  # the label that replaced `expanded_from` (set by FOON-EXP; not serialized)


@dataclass(frozen=True)
class FunctionalUnit(_HashOnce):
    """Inputs -> motion -> outputs, with the places it was read from; hashed once (`_HashOnce`), as nodes are."""
    inputs: tuple[ObjectNode, ...]
    motion: Motion
    outputs: tuple[ObjectNode, ...]
    sources: tuple[Source, ...] = field(default=(), compare=False)
    __hash__ = _HashOnce.__hash__

    def _identity(self) -> tuple:
        return (self.inputs, self.motion, self.outputs)

    @property
    def key(self) -> tuple[str, frozenset[ObjectNode], frozenset[ObjectNode]]:
        """Duplicate-detection key: motion label with the sets of input and output nodes."""
        try:  # cached as an attribute (as `_HashOnce` keeps a hash)
            return self._key
        except AttributeError:
            value = (self.motion.label, frozenset(self.inputs), frozenset(self.outputs))
            object.__setattr__(self, "_key", value)
            return value

    @property
    def source(self) -> Source | None:
        """The first place this unit was read from."""
        return self.sources[0] if self.sources else None

    def describe(self) -> str:
        """One-line summary: `chop: onion (whole), knife -> onion (chopped)`."""
        ins = ", ".join(n.describe() for n in self.inputs)
        outs = ", ".join(n.describe() for n in self.outputs)
        return f"{self.motion.label}: {ins} -> {outs}"


@dataclass(frozen=True)
class Foon:
    """A functional object-oriented network: units in a stable order, plus indexes.

    `level` records which hierarchy level the nodes are expressed at (3 = as read).
    """

    units: tuple[FunctionalUnit, ...]
    level: int = 3

    def __repr__(self) -> str:
        """Counts only: the full dataclass repr of a network runs to hundreds of kilobytes."""
        return (f"<Foon level {self.level}: {count(len(self.units), 'unit')}, {count(len(self.nodes), 'object node')}, "
                f"{count(len(self.motions), 'motion')}>")

    def _repr_html_(self) -> str:
        """Jupyter: a summary table (level, units, object nodes, labels, motions, recipes' dishes)."""
        from html import escape

        dishes = sorted({n.label for u in self.units for n in u.outputs if n.dish is not None})
        rows = [("level", str(self.level)), ("units", str(len(self.units))),
                ("object nodes", str(len(self.nodes))), ("object labels", str(len({n.label for n in self.nodes}))),
                ("motions", str(len(self.motions))),
                ("dishes", ", ".join(dishes[:12]) + (f", ... ({len(dishes)})" if len(dishes) > 12 else ""))]
        body = "".join(f"<tr><th>{k}</th><td>{escape(v)}</td></tr>" for k, v in rows)
        return f"<table><caption>FOON</caption>{body}</table>"

    def __iter__(self) -> Iterator[FunctionalUnit]:
        return iter(self.units)

    def __len__(self) -> int:
        return len(self.units)

    @cached_property
    @bulk
    def table(self) -> NodeTable[ObjectNode]:
        """The network's nodes numbered (`NodeTable`): what network-sized passes work on instead of hashing nodes."""
        return node_table(self.units)

    @property
    def nodes(self) -> tuple[ObjectNode, ...]:
        """Every distinct object node, in order of first appearance."""
        return self.table.nodes

    @cached_property
    @bulk
    def producers(self) -> dict[ObjectNode, tuple[int, ...]]:
        """Node -> indexes of the units that output it."""
        return unit_index(self.table.outputs, first_objects(self.units, self.table.outputs, "outputs"))

    @cached_property
    @bulk
    def produced_by_label(self) -> dict[str, tuple[ObjectNode, ...]]:
        """Object label -> the produced nodes with that label, in `producers` order (goal lookup by label)."""
        acc: dict[str, list[ObjectNode]] = {}
        for n in first_objects(self.units, self.table.outputs, "outputs").values():
            acc.setdefault(n.label, []).append(n)
        return {k: tuple(v) for k, v in acc.items()}

    @cached_property
    @bulk
    def consumers(self) -> dict[ObjectNode, tuple[int, ...]]:
        """Node -> indexes of the units that take it as input."""
        return unit_index(self.table.inputs, first_objects(self.units, self.table.inputs, "inputs"))

    @cached_property
    def dishes(self) -> frozenset[ObjectNode]:
        """The nodes some unit outputs marked as its recipe's dish (the `O` line's 4th field). C-level loops."""
        outputs = list(chain.from_iterable(map(attrgetter("outputs"), self.units)))
        return frozenset(compress(outputs, map(is_not, map(attrgetter("dish"), outputs), repeat(None))))

    @cached_property
    def motions(self) -> tuple[str, ...]:
        """Distinct motion labels, sorted."""
        return tuple(sorted({u.motion.label for u in self.units}))

