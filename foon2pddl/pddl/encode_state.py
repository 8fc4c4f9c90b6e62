"""The `state` encoding: object-centred, with real state change.

Every object label (and every related object and ingredient) is a domain
constant. A node becomes a set of facts about its object `o`:

* `(available o)`: the object is in the kitchen or was made;
* a plain state `s` -> `(is-s o)` (`chopped` -> `(is-chopped onion)`, `on` -> `(is-on mixer)`);
* a state with a related object `s [r]` -> `(s o r)` (`in [bowl]` -> `(in onion bowl)`);
* a state with ingredients `s {a, b}` (level 3 only) -> `(s o a)`, `(s o b)`
  (`contains {salt}` -> `(contains bowl salt)`), the same binary predicate as `s [x]`.

A unit becomes a parameterless action: preconditions are the facts of its
inputs; for each object among its outputs, the facts its output nodes have and
its input nodes lack are added, and, if the object is also an input, the facts
its input nodes have and its output nodes lack are deleted. Inputs that do not
reappear among the outputs are left as they are (FOON often omits utensils
from the outputs, so disappearance does not mean consumption). The kitchen's
facts (for objects the network mentions) are the initial state; the goal is the
facts of the goal node (several candidates: auxiliary actions to `(goal-reached)`).

Not modelled: consumption of inputs, quantities, object identity beyond the
label (two onions are one object `onion`), and exclusivity other than what a
unit deletes (chopping deletes `is-whole` only because the output lacks it).
Because facts of different nodes combine, this is not FOON's semantics: it can
solve goals native retrieval cannot, and fail on ones it solves. Pruning is
therefore done on the STRIPS task (`prune.prune_task`), not on the FOON.
"""

from __future__ import annotations

from dataclasses import replace

from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .costs import unit_cost
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, goal_actions, header, unit_comment
from .names import NameTable
from .prune import prune_task
from .task import Action, Atom, PlanningTask, Predicate

AVAILABLE = "available"

# A fact before naming: (predicate key, argument labels); the key is ("available",),
# ("is", state label) or ("rel", state label).
Fact = tuple[tuple[str, ...], tuple[str, ...]]


def node_facts(node: ObjectNode) -> frozenset[Fact]:
    """The facts that describe `node` (see the module doc)."""
    o = node.label
    facts: set[Fact] = {((AVAILABLE,), (o,))}
    for s in node.states:
        if s.related:
            facts.add((("rel", s.label), (o, s.related)))
        for ing in s.ingredients:
            facts.add((("rel", s.label), (o, ing)))
        if not s.related and not s.ingredients:
            facts.add((("is", s.label), (o,)))
    return frozenset(facts)


def _by_object(nodes, facts_of) -> dict[str, set[Fact]]:
    out: dict[str, set[Fact]] = {}
    for n in nodes:
        out.setdefault(n.label, set()).update(facts_of(n))
    return out


class _FactsOf:
    """`node_facts`, computed once per node; `cache` holds every node asked for."""

    def __init__(self) -> None:
        self.cache: dict[ObjectNode, frozenset[Fact]] = {}

    def __call__(self, n: ObjectNode) -> frozenset[Fact]:
        got = self.cache.get(n)
        if got is None:
            got = self.cache[n] = node_facts(n)
        return got


def _changes(units, facts_of: _FactsOf) -> list[tuple[set[Fact], set[Fact], set[Fact]]]:
    """Per unit: (pre, add, delete) fact sets; an object's facts change only where it is input and output."""
    changes = []
    for u in units:
        ins = _by_object(u.inputs, facts_of)
        outs = _by_object(u.outputs, facts_of)
        pre = set().union(*ins.values())
        add: set[Fact] = set()
        delete: set[Fact] = set()
        for obj, out_facts in outs.items():
            in_facts = ins.get(obj, set())
            add |= out_facts - in_facts
            if obj in ins:
                delete |= in_facts - out_facts
        changes.append((pre, add, delete))
    return changes


def _predicates(table: NameTable, facts: set[Fact]) -> tuple[dict[tuple[str, ...], str], list[Predicate]]:
    """Predicate names (fact key -> name) and declarations of `facts`, `available` first, in key order."""
    pred_name: dict[tuple[str, ...], str] = {(AVAILABLE,): AVAILABLE}
    predicates = [Predicate(AVAILABLE, (("?o", "object"),), "the object is in the kitchen or was made")]
    for key in sorted({k for k, _ in facts} - {(AVAILABLE,)}):
        kind, label = key
        if kind == "is":
            name = table.name(f"is-{label}", key=("pred", key))
            predicates.append(Predicate(name, (("?o", "object"),), f"?o is {label}"))
        else:
            name = table.name(label, key=("pred", key))
            predicates.append(Predicate(name, (("?o", "object"), ("?r", "object")), f"?o {label} [?r] or {{?r}}"))
        pred_name[key] = name
    return pred_name, predicates


def encode_state(
    foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3, options: EncodeOptions = DEFAULT_OPTIONS
) -> PlanningTask:
    """The object-centred task of `foon` (see the module doc)."""
    inp = at_level(foon, kitchen, goal, level)
    f = inp.foon
    facts_of = _FactsOf()
    changes = _changes(f.units, facts_of)
    mentioned = {a for fs in facts_of.cache.values() for _, args in fs for a in args}
    init_facts = set().union(*(facts_of(n) for n in inp.kitchen if n.label in mentioned))
    goal_facts = [(c, facts_of(c)) for c in inp.candidates]

    every = set(init_facts).union(*(fs for _, fs in goal_facts), *(x for ch in changes for x in ch))
    table = NameTable()
    table.reserve(AVAILABLE, "available")
    several = len(inp.candidates) > 1
    if several:
        table.reserve(GOAL_REACHED, "goal reached")
    pred_name, predicates = _predicates(table, every)
    labels = sorted({a for _, args in every for a in args})
    obj = {label: table.name(label, key=("object", label)) for label in labels}

    def atoms(facts) -> tuple[Atom, ...]:
        return tuple(sorted(Atom(pred_name[k], tuple(obj[a] for a in args)) for k, args in facts))

    actions = [Action(table.name(f"{u.motion.label} u{i}", key=("unit", i)),
                      pre=atoms(pre), add=atoms(add), delete=atoms(delete),
                      cost=unit_cost(u, options.costs, options.rates), unit=i, comment=unit_comment(u, i))
               for i, (u, (pre, add, delete)) in enumerate(zip(f.units, changes, strict=True))]
    return fact_task("state", inp, goal, table, options, predicates, actions, [(c, atoms(fs)) for c, fs in goal_facts],
                     atoms(init_facts), tuple((obj[label], "object") for label in labels), goal_predicate_at=1)


def fact_task(encoding: str, inp, goal: Goal, table: NameTable, options: EncodeOptions,
              predicates: list[Predicate], actions: list[Action], goal_atoms: list[tuple[ObjectNode, tuple[Atom, ...]]],
              init: tuple[Atom, ...], constants: tuple[tuple[str, str], ...], goal_predicate_at: int) -> PlanningTask:
    """The task of a one-object-per-label fact encoding (`state`, `ocp`) from its unit actions: the goal is the
    one candidate's atoms, or `(goal-reached)` reached by a goal action per candidate (its predicate inserted at
    `goal_predicate_at`); relevance-pruned when the options ask; the header counts the unit actions kept."""
    actions = list(actions)
    if len(goal_atoms) > 1:
        reached = Atom(GOAL_REACHED)
        predicates = [*predicates[:goal_predicate_at], Predicate(GOAL_REACHED, comment="a goal candidate was made"),
                      *predicates[goal_predicate_at:]]
        actions.extend(goal_actions(table, goal_atoms, reached, options))
        goal_atom: tuple[Atom, ...] = (reached,)
    else:
        goal_atom = goal_atoms[0][1]
    task = PlanningTask(
        domain=f"foon-{encoding}",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding=encoding,
        level=inp.level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=init,
        goal=goal_atom,
        constants=constants,
        units=inp.foon.units,
        labels=table.labels,
    )
    if options.prune:
        task = prune_task(task)
    kept = sum(a.unit is not None for a in task.actions)
    return replace(task, comments=header(encoding, inp, options, kept))
