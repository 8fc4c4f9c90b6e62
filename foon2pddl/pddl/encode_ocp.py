"""The `ocp` encoding: the public foon_to_pddl converter's object-centred (OCP) format, with a goal.

The converter's default mode writes object-centred predicates after Agostini et
al. (2021): `(R a b)` reads "R a is b", so `(in cup water)` is water in the cup,
`(under water cup)` the cup under the water, `(on table cup)` the cup on the
table, `(in cup air)` an empty cup. Every object label is a domain constant, with
`air` and `table`; a unit is a parameterless action named after its motion and
focal object (`pour_water_1`). A node's facts, about its object `o`, as the
converter reads it:

* `in [h]` / `on [h]` -> `(in h o)` / `(on h o)` and `(under o h)`; `under [h]` -> `(under h o)`;
* `empty` -> `(in o air)` (`(on o air)` for the surfaces `plate`, `pizza pan`, `cutting board`);
* the physical states `whole diced chopped sliced mixed ground juiced spread` -> `(is-<s> o)`
  (`mixed` is said of the object's holder, where the stirring happens: `(is-mixed bowl)`);
* a node with no `in`/`on`/`under` place is on the table: `(under o table)`, `(on table o)`
  (not among the outputs of a `scoop`: they are in the spoon);
* nothing else: `contains {a, b}` writes no fact (what is in a container is said by the
  contents' own `in [h]`), nor do `liquid`, `clean`, ...

An action's precondition is its inputs' facts, and its effect, as the converter
writes it:

* **new**: the outputs' facts that are not preconditions;
* **kept** (re-added): the preconditions that no output fact speaks of (same
  predicate and first argument; any `is-` fact speaks of every `is-` fact), and
  those the outputs repeat;
* **deleted**: a precondition not kept that a new fact replaces: the same
  predicate and first argument with `air` on either side (`(in cup air)` when
  water comes in, `(in cup water)` when the cup comes out `empty`), or the same
  arguments under another predicate (`(is-whole onion)` when it comes out
  `chopped`).

So nothing leaves the table or its old holder unless air says so: after the
converter's pour_water example, `(under water cup)` and `(under water bowl)`
both hold, and an object put into a bowl is still `(on table o)`, exactly as in
the converter's reference output (`tests/data/foon_to_pddl-examples/`). The
kitchen's facts (of objects the network mentions) are the initial state, a kitchen
container's `contains {...}` written as its contents' nodes would (`(in bowl water)`).

Unlike the converter: the goal is the goal asked for, not every goal-marked node
of the file. Its facts are the node's in the converter's goal reading (`in [h]`
without `(under o h)`), plus `(in o a)` for each `a` of its `contains {...}`
that the kitchen or an action writes: the fact the converter's goal gets from
the contents' own node (for pour_water, `bowl: contains {water}, on [table]`
gives exactly the converter's goal). Several candidates: auxiliary actions to
`(goal-reached)`. Names are sanitized and unique (the
converter writes `_` for ` ` and `-`); untyped (it declares `(:types object -
object)`, which parsers reject); `:requirements` lists what is used; `mixed` is
said of the node's own holder (the converter's placeholder takes the next place
written in the file, whose state order foon2pddl does not keep) or of the object
when it has none (the converter would write the placeholder `LOC`); an empty
surface is `(on o air)` in goals too (the converter writes `on` there for the
cutting board only, so a goal of an empty plate was unreachable). Not FOON's
semantics: facts of different nodes combine and deletes make order matter, as in
`state`; pruning is on the STRIPS task. Not modelled, as in the converter:
consumption, quantities, and object identity beyond the label (one `cup`).
"""

from __future__ import annotations

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.places import place_of
from .costs import unit_cost
from .encode_state import fact_task
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, unit_comment
from .names import NameTable
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["AIR", "TABLE", "action_name", "encode_ocp", "goal_facts_of", "node_facts", "unit_effects"]

#: The converter's relation predicates: `(R a b)` reads "R a is b".
RELATIONS = ("in", "on", "under")

#: FOON states the converter writes as `(is-<state> o)`.
PHYSICAL_STATES = ("whole", "diced", "chopped", "sliced", "mixed", "ground", "juiced", "spread")

#: Objects that hold things on them rather than in them (`(on plate air)`).
SURFACES = frozenset({"plate", "pizza pan", "cutting board"})

#: The converter's two objects beyond FOON's labels: what an empty container holds, and the work surface.
AIR, TABLE = "air", "table"

# A fact over labels: (predicate, object, ...); predicates are `in`, `on`, `under` and `is-<state>`.
Fact = tuple[str, ...]


def node_facts(node: ObjectNode, on_table: bool = True, goal: bool = False) -> tuple[Fact, ...]:
    """The facts of `node` in the converter's reading (see the module doc), without repeats.

    `on_table=False`: a node with no place is not put on the table (what `scoop` outputs).
    `goal=True`: the converter's goal reading (`in [h]` writes no `under` fact).
    """
    o = node.label
    out: list[Fact] = []
    placed = False
    for s in node.states:
        if s.label in RELATIONS and s.related:
            placed = True
            out.append((s.label, s.related, o))
            if s.label == "on" or (s.label == "in" and not goal):
                out.append(("under", o, s.related))
        elif s.label == "empty":
            out.append(("on" if o in SURFACES else "in", o, AIR))
        elif s.label in PHYSICAL_STATES:
            holder = place_of(node) if s.label == "mixed" else None
            out.append((f"is-{s.label}", holder[1] if holder else o))
    if not placed and on_table:
        out.extend((("under", o, TABLE), ("on", TABLE, o)))
    return tuple(dict.fromkeys(out))


def contents_facts(node: ObjectNode, mentioned: set[str]) -> tuple[Fact, ...]:
    """`(in bowl water)` for each item of the node's `contains {...}` that the network mentions: what a kitchen
    container holds, written as the contents' own nodes would write it (a goal the kitchen holds holds at start)."""
    inside = "on" if node.label in SURFACES else "in"
    return tuple((inside, node.label, i) for s in node.states if s.label == "contains" for i in s.ingredients
                 if i in mentioned)


def goal_facts_of(node: ObjectNode, made: set[Fact]) -> tuple[Fact, ...]:
    """The goal facts of `node`: its facts in the converter's goal reading, and what it contains.

    The converter's goal is every final product of the file, so a bowl of water comes with the water's
    `(in bowl water)`; one goal node gives the same through its `contains {water}`, for each listed
    item whose fact the kitchen or an action writes (`bloody mary (contains {vodka})` is never written:
    the vodka is `in [drinking glass]`). O(states).
    """
    inside = "on" if node.label in SURFACES else "in"
    listed = (f for s in node.states if s.label == "contains" for f in ((inside, node.label, i) for i in s.ingredients))
    return tuple(dict.fromkeys((*node_facts(node, goal=True), *(f for f in listed if f in made))))


def _speaks_of(pre: Fact, post: Fact) -> bool:
    """Whether an output fact says something about a precondition (the converter's test for keeping it):
    both are `is-` facts, or they share predicate and first argument."""
    if pre[0] not in RELATIONS and post[0] not in RELATIONS:
        return True
    return pre[:2] == post[:2]


def _replaces(new: Fact, old: Fact) -> bool:
    """Whether a new fact negates a precondition (the converter's two tests): same predicate and first
    argument with `air` on either side, or the same arguments under another predicate."""
    if new[:2] == old[:2] and new[2:] != old[2:]:
        return AIR in (*new[2:], *old[2:])
    return new[0] != old[0] and new[1:] == old[1:]


def unit_effects(unit: FunctionalUnit) -> tuple[tuple[Fact, ...], tuple[Fact, ...], tuple[Fact, ...]]:
    """(precondition, add, delete) facts of `unit` (see the module doc), each in first-seen order.

    O(facts^2) per unit; units have a handful of nodes. The add and delete lists are disjoint.
    """
    pre = tuple(dict.fromkeys(f for n in unit.inputs for f in node_facts(n)))
    scoop = unit.motion.label == "scoop"
    out = tuple(dict.fromkeys(f for n in unit.outputs for f in node_facts(n, on_table=not scoop)))
    before = set(pre)
    new = tuple(f for f in out if f not in before)
    kept = tuple(dict.fromkeys((*(p for p in pre if not any(_speaks_of(p, q) for q in out)),
                                *(q for q in out if q in before))))
    changed = [p for p in pre if p not in set(kept)]
    delete = tuple(dict.fromkeys(p for f in new for p in changed if _replaces(f, p)))
    return pre, tuple(dict.fromkeys((*new, *kept))), delete


def action_name(unit: FunctionalUnit) -> str:
    """The converter's operator name before its index: the motion, then its focal object if any.

    The focal object is the first input with no ingredients that the motion moves (`pick-and-place`,
    `pour`, `sprinkle`, `insert`: motion descriptor 1) or acts on (`slice`, `dice`, `chop`, `cut`,
    `scoop`, `scoop and pour`: descriptor 0); `mix` and `stir` of a node with ingredients: `ingredients`.
    """
    motion = unit.motion.label
    for n in unit.inputs:
        if not n.ingredients:
            if (motion in ("pick-and-place", "pour", "sprinkle", "insert") and n.motion_flag == 1) or (
                    motion in ("slice", "dice", "chop", "cut", "scoop", "scoop and pour") and n.motion_flag == 0):
                return f"{motion} {n.label}"
        elif motion in ("mix", "stir"):
            return f"{motion} ingredients"
    return motion


def encode_ocp(
    foon: Foon, kitchen: Kitchen, goal: Goal, level: int = 3, options: EncodeOptions = DEFAULT_OPTIONS
) -> PlanningTask:
    """The converter's object-centred task of `foon` (see the module doc)."""
    inp = at_level(foon, kitchen, goal, level)
    f = inp.foon
    effects = [unit_effects(u) for u in f.units]
    mentioned = {x for fs in effects for part in fs for fact in part for x in fact[1:]}
    init_facts = tuple(dict.fromkeys(x for n in sorted(inp.kitchen) if n.label in mentioned
                                     for x in (*node_facts(n), *contents_facts(n, mentioned))))
    made = {*init_facts, *(x for _, add, _ in effects for x in add)}
    goal_facts = [(c, goal_facts_of(c, made)) for c in inp.candidates]

    table = NameTable()
    for name in RELATIONS:
        table.reserve(name, name)
    several = len(inp.candidates) > 1
    if several:
        table.reserve(GOAL_REACHED, "goal reached")
    every = [*init_facts, *(x for _, fs in goal_facts for x in fs), *(x for fs in effects for part in fs for x in part)]
    states = sorted({x[0] for x in every if x[0].startswith("is-")})
    pred = {**{r: r for r in RELATIONS}, **{s: table.name(s, key=("pred", s)) for s in states}}
    labels = sorted({x for fact in every for x in fact[1:]} | {AIR, TABLE})
    obj = {label: table.name(label, key=("object", label)) for label in labels}

    def atoms(facts) -> tuple[Atom, ...]:
        return tuple(Atom(pred[p], tuple(obj[x] for x in args)) for p, *args in facts)

    actions = [Action(table.name(f"{action_name(u)} {i}", key=("unit", i)),
                      pre=atoms(pre), add=atoms(add), delete=atoms(delete),
                      cost=unit_cost(u, options.costs, options.rates), unit=i, comment=unit_comment(u, i))
               for i, (u, (pre, add, delete)) in enumerate(zip(f.units, effects, strict=True))]
    predicates = [Predicate("in", (("?h", "object"), ("?x", "object")), "in ?h is ?x (?x is in ?h; air: ?h is empty)"),
                  Predicate("on", (("?h", "object"), ("?x", "object")), "on ?h is ?x (?x is on ?h)"),
                  Predicate("under", (("?x", "object"), ("?h", "object")), "under ?x is ?h (?x is on or in ?h)"),
                  *(Predicate(pred[s], (("?o", "object"),), f"?o is {s[3:]}") for s in states)]
    return fact_task("ocp", inp, goal, table, options, predicates, actions, [(c, atoms(fs)) for c, fs in goal_facts],
                     atoms(init_facts), tuple((obj[label], "object") for label in labels),
                     goal_predicate_at=len(predicates))
