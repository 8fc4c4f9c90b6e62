"""The ground units a lifted FOON-GEN network can fire from a kitchen: delete-relaxed reachability of its bindings.

A lifted unit binds each parameter (an input label of category C) to any object whose
category is C or refines it (its PDDL type is a subtype of C). `ground` runs the fixpoint
of those bindings over concrete nodes: from the kitchen's nodes, a binding fires when every
input node of the unit, with the binding substituted, is reached, and its output nodes are
then reached too. This is the lifted task's delete relaxation read at the level of nodes
(an atom determines its node, `lifted_atoms.node_of`), so every action a plan can apply is
one of the returned instances: an over-approximation, hence sound for pruning, and exact
up to the orderings of same-category objects the atoms fix.

Semi-naive evaluation: a unit is joined in full once its parameter-free inputs are all
reached, then again only for each newly reached node that fits one of its parameterized
inputs, with that input fixed to the node. A node fits an input when they agree on the
label (unless it is a parameter) and on the set of state labels (a substitution keeps
both); the binding is then found by trying the node's labels for the input's unbound
parameters, which is complete since each parameter is mentioned in the input node.
Cost: O(instances x inputs x candidates per input), about a second on the universal FOON
of the 100 shared subgraphs (1,845 units, 3,000 reached nodes).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass

from ..model.constraints import node_labels
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from .categories import CategoryIndex
from .substitute import substitute_node

__all__ = ["Grounded", "ground", "input_labels", "unit_params"]

Key = tuple[str | None, frozenset[str]]

#: Steps `ground` may take: the `absent` policy takes ~62,000 on the universal FOON; `blocked` and `all`
#: bind nearly every object and grow past any budget (FD's translator times out on them too).
WORK_LIMIT = 500_000


class _TooMany(Exception):
    """The grounding went past its step limit."""


@dataclass(frozen=True)
class Grounded:
    """The reachable ground instances of a lifted network: `units[i]` is the unit index of instance i,
    `inputs[i]` its input nodes (ids into `nodes`); `makers[n]` the instances that make node n (have it among
    their outputs and not among their inputs); `kitchen` marks the kitchen's node ids."""

    nodes: tuple[ObjectNode, ...]
    node_id: Mapping[ObjectNode, int]
    units: tuple[int, ...]
    inputs: tuple[tuple[int, ...], ...]
    makers: tuple[tuple[int, ...], ...]
    kitchen: bytes


def input_labels(unit: FunctionalUnit) -> frozenset[str]:
    """Labels mentioned by the unit's input nodes (labels, related objects, ingredients)."""
    return frozenset().union(*map(node_labels, unit.inputs))


def unit_params(unit: FunctionalUnit, generalize: Callable[[str], bool], index: CategoryIndex) -> dict[str, str]:
    """The unit's parameters: input label -> its category (categorized labels `generalize` accepts)."""
    return {x: cat for x in sorted(input_labels(unit)) if (cat := index.choose(x)) is not None and generalize(x)}


def _key(node: ObjectNode, params: Mapping[str, str]) -> Key:
    return (None if node.label in params else node.label, frozenset(s.label for s in node.states))


class _Fits:
    """Whether an object may fill a parameter of a category (its own category is it or refines it), memoized."""

    def __init__(self, index: CategoryIndex) -> None:
        self.index = index
        self.memo: dict[tuple[str, str], bool] = {}

    def __call__(self, cat: str, label: str) -> bool:
        hit = self.memo.get((cat, label))
        if hit is None:
            own = self.index.choose(label)
            hit = own is not None and (own == cat or cat in self.index.ancestors(own))
            self.memo[(cat, label)] = hit
        return hit


def _matches(node: ObjectNode, params: Mapping[str, str], binding: dict[str, str], target: ObjectNode,
             fits: _Fits) -> Iterator[dict[str, str]]:
    """Every extension of `binding` under which `node` becomes `target`."""
    free = [x for x in sorted(node_labels(node)) if x in params and x not in binding]
    options = [[y for y in sorted(node_labels(target)) if fits(params[x], y)] for x in free]
    for values in itertools.product(*options):
        b = {**binding, **dict(zip(free, values, strict=True))}
        if substitute_node(node, {k: v for k, v in b.items() if k != v}) == target:
            yield b


def ground(foon: Foon, kitchen: frozenset[ObjectNode], generalize: Callable[[str], bool],
           index: CategoryIndex, limit: int = WORK_LIMIT) -> Grounded | None:
    """The reachable ground instances of `foon`'s units lifted under `generalize` (see the module doc), or None
    when finding them takes more than `limit` steps (candidate nodes tried and bindings found)."""
    units = foon.units
    params = [unit_params(u, generalize, index) for u in units]
    fits = _Fits(index)
    fixed_watch: dict[ObjectNode, list[int]] = {}
    watch: dict[Key, list[tuple[int, int]]] = {}
    missing = []
    lifted: list[tuple[int, ...]] = []  # unit -> positions of its inputs that mention a parameter
    # (unit, position) -> the labels a fitting node must have, the category its label must fit, and how many
    # labels it may have at most (a substitution may merge labels, never add one)
    sieve: dict[tuple[int, int], tuple[frozenset[str], str | None, int]] = {}
    for ui, u in enumerate(units):
        ps = params[ui]
        fixed = {n for n in u.inputs if not (node_labels(n) & ps.keys())} - kitchen
        missing.append(len(fixed))
        for n in fixed:
            fixed_watch.setdefault(n, []).append(ui)
        lifted.append(tuple(pos for pos, n in enumerate(u.inputs) if node_labels(n) & ps.keys()))
        for pos in lifted[-1]:
            n = u.inputs[pos]
            watch.setdefault(_key(n, ps), []).append((ui, pos))
            sieve[(ui, pos)] = (frozenset(node_labels(n) - ps.keys()), ps.get(n.label), len(node_labels(n)))
    node_id: dict[ObjectNode, int] = {}
    buckets: dict[Key, list[ObjectNode]] = {}
    queue: list[ObjectNode] = []

    def may_fit(ui: int, pos: int, m: ObjectNode) -> bool:
        labels, cat, most = sieve[(ui, pos)]
        have = node_labels(m)
        return len(have) <= most and labels <= have and (cat is None or fits(cat, m.label))

    def reach(m: ObjectNode) -> None:
        if m not in node_id:
            node_id[m] = len(node_id)
            states = frozenset(s.label for s in m.states)
            buckets.setdefault((m.label, states), []).append(m)
            buckets.setdefault((None, states), []).append(m)
            queue.append(m)

    seen: set[tuple[int, tuple[tuple[str, str], ...]]] = set()
    out_units: list[int] = []
    out_inputs: list[tuple[int, ...]] = []
    out_made: list[tuple[int, ...]] = []

    def join(ui: int, pos: int | None, m: ObjectNode | None) -> None:
        u, ps = units[ui], params[ui]
        todo = [k for k in lifted[ui] if k != pos]

        def rec(i: int, b: dict[str, str]) -> Iterator[dict[str, str]]:
            if i == len(todo):
                yield b
                return
            n = u.inputs[todo[i]]
            if all(x in b for x in node_labels(n) if x in ps):
                if substitute_node(n, {k: v for k, v in b.items() if k != v}) in node_id:
                    yield from rec(i + 1, b)
                return
            for cand in buckets.get(_key(n, ps), ()):
                work[0] += 1
                if work[0] > limit:
                    raise _TooMany
                if not may_fit(ui, todo[i], cand):
                    continue
                for bb in _matches(n, ps, b, cand, fits):
                    yield from rec(i + 1, bb)

        starts = [{}] if pos is None else list(_matches(u.inputs[pos], ps, {}, m, fits))
        for start in starts:
            for b in rec(0, start):
                work[0] += 1
                key = (ui, tuple(sorted(b.items())))
                if key in seen:
                    continue
                seen.add(key)
                mapping = {k: v for k, v in b.items() if k != v}
                ins = tuple(dict.fromkeys(substitute_node(n, mapping) for n in u.inputs))
                outs = [substitute_node(n, mapping) for n in u.outputs]
                for o in outs:
                    reach(o)
                out_units.append(ui)
                out_inputs.append(tuple(node_id[n] for n in ins))
                out_made.append(tuple(dict.fromkeys(node_id[o] for o in outs if o not in ins)))

    for n in sorted(kitchen, key=lambda n: (n.label, n.states)):
        reach(n)
    work = [0]  # candidate nodes tried and bindings found: past `limit`, give up
    try:
        for ui in range(len(units)):
            if not missing[ui]:
                join(ui, None, None)
        done = 0
        while done < len(queue):
            m = queue[done]
            done += 1
            for ui in fixed_watch.get(m, ()):
                missing[ui] -= 1
                if not missing[ui]:
                    join(ui, None, None)
            states = frozenset(s.label for s in m.states)
            for key in ((m.label, states), (None, states)):
                for ui, pos in watch.get(key, ()):
                    if not missing[ui] and may_fit(ui, pos, m):
                        join(ui, pos, m)
    except _TooMany:
        return None
    nodes = tuple(node_id)
    marks = bytearray(len(nodes))
    for n in kitchen:
        marks[node_id[n]] = 1
    makers: list[list[int]] = [[] for _ in nodes]
    for i, made in enumerate(out_made):
        for n in made:
            makers[n].append(i)
    return Grounded(nodes, node_id, tuple(out_units), tuple(out_inputs), tuple(map(tuple, makers)), bytes(marks))
