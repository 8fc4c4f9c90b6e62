"""The `ocp` encoding: the public foon_to_pddl converter's object-centred (OCP) format, with a goal.

The converter's default mode writes object-centred predicates after Agostini et
al. (2021): `(R a b)` reads "R a is b", so `(in cup water)` is water in the cup,
`(under water cup)` the cup under the water, `(on table cup)` the cup on the
table, `(in cup air)` an empty cup. Every object label is a domain constant, with
`air` and `table`; a unit is a parameterless action named after its motion and
focal object (`pour_water_1`). A node's facts, about its object `o`:

* `in [h]` / `on [h]` -> `(in h o)` / `(on h o)` and `(under o h)`; `under [h]` -> `(under h o)`;
* `contains {a, b}` -> `(in o a)`, `(in o b)`; `empty` -> `(in o air)` (`on` for the surfaces
  `plate`, `pizza pan`, `cutting board`);
* the physical states `whole diced chopped sliced mixed ground juiced spread` -> `(is-<s> o)`
  (`mixed` is said of the object's holder, where the stirring happens: `(is-mixed bowl)`);
* a node with no `in`/`on`/`under` state is on the table: `(under o table)`, `(on table o)`
  (except what a `scoop` outputs: it is in the spoon).

An action's precondition is its inputs' facts. Its effect, as the converter
writes it: the outputs' facts that are new; the preconditions it keeps (those
no output fact speaks of with the same predicate and first object, and those
the outputs repeat), re-added; and deletes:

* **contents**: an output container node that says what it holds (`contains`,
  `empty`) replaces what the preconditions had in or on it (`(in cup water)`
  is deleted when the cup comes out `empty`, `(in bowl air)` when it comes out
  holding water);
* **table**: an output object placed in, on or under something leaves the table;
* **states**: a new `(is-<s> o)` deletes `o`'s other `is-` facts.

`under` facts between objects are never deleted, as in the converter's
reference output: after its pour_water example, `(under water cup)` and
`(under water bowl)` both hold. The kitchen's facts (of objects the network
mentions) are the initial state; the goal is the facts of the goal node
(several candidates: auxiliary actions to `(goal-reached)`).

Unlike the converter: names are sanitized and unique (the converter writes `_`
for `-`), untyped (it declares `(:types object - object)`, which parsers
reject), `:requirements` lists what is used (`:strips`, not `:adl`), and the
problem's goal is the goal asked for (the converter's is every goal-marked
node of the file). Not FOON's semantics: facts of different nodes combine and
deletes make order matter, as in `state`; pruning is on the STRIPS task.
"""

from __future__ import annotations

from dataclasses import replace

from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from .costs import unit_cost
from .encoding import DEFAULT_OPTIONS, GOAL_REACHED, EncodeOptions, at_level, goal_actions, header, unit_comment
from .names import NameTable
from .prune import prune_task
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["AIR", "TABLE", "encode_ocp", "node_facts", "unit_effects"]

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


def _holder(node: ObjectNode) -> str | None:
    """What the node's object is in or on (its first such state), None when it says nothing."""
    return next((s.related for s in node.states if s.label in ("in", "on") and s.related), None)


def node_facts(node: ObjectNode, on_table: bool = True) -> tuple[Fact, ...]:
    """The facts of `node` in the converter's reading (see the module doc), without repeats.

    `on_table=False`: a node with no place is not put on the table (what `scoop` outputs).
    """
    o = node.label
    inside = "on" if o in SURFACES else "in"
    out: list[Fact] = []
    placed = False
    for s in node.states:
        if s.label in RELATIONS and s.related:
            placed = True
            out.append((s.label, s.related, o))
            if s.label != "under":
                out.append(("under", o, s.related))
        elif s.label == "empty":
            out.append((inside, o, AIR))
        elif s.label in PHYSICAL_STATES:
            out.append((f"is-{s.label}", (_holder(node) or o) if s.label == "mixed" else o))
        out.extend((inside, o, i) for i in s.ingredients)
    if not placed and on_table:
        out.extend((("under", o, TABLE), ("on", TABLE, o)))
    return tuple(dict.fromkeys(out))


def _describes_contents(node: ObjectNode) -> bool:
    """Whether the node says everything its object holds (`empty`, or a state listing ingredients)."""
    return any(s.label == "empty" or s.ingredients for s in node.states)


def unit_effects(unit: FunctionalUnit) -> tuple[tuple[Fact, ...], tuple[Fact, ...], tuple[Fact, ...]]:
    """(precondition, add, delete) facts of `unit` (see the module doc), each in first-seen order.

    O(facts^2) per unit; units have a handful of nodes.
    """
    pre = tuple(dict.fromkeys(f for n in unit.inputs for f in node_facts(n)))
    scoop = unit.motion.label == "scoop"
    out = tuple(dict.fromkeys(f for n in unit.outputs for f in node_facts(n, on_table=not scoop)))
    outs = set(out)
    new = [f for f in out if f not in pre]
    holders = {n.label for n in unit.outputs if _describes_contents(n)}
    moved = {n.label for n in unit.outputs if any(s.label in RELATIONS and s.related for s in n.states)}
    states = {f[1]: f for f in new if f[0].startswith("is-")}

    def deleted(f: Fact) -> bool:
        if f in outs:
            return False
        if f[0] in ("in", "on") and f[1] in holders:  # contents replaced
            return True
        if (f[0] == "on" and f[1] == TABLE and f[2] in moved) or (f[0] == "under" and f[2] == TABLE and f[1] in moved):
            return True
        return f[0].startswith("is-") and f[1] in states  # another physical state

    delete = tuple(f for f in pre if deleted(f))
    kept = [f for f in pre if f not in delete and (f in outs or not any(g[:2] == f[:2] for g in out))]
    return pre, tuple(dict.fromkeys((*new, *kept))), delete


def action_name(unit: FunctionalUnit) -> str:
    """The converter's operator name before its index: the motion, then its focal object if any.

    The focal object is the first input with no ingredients that the motion moves (`pick-and-place`,
    `pour`, `sprinkle`, `insert`: motion descriptor 1) or acts on (`slice`, `dice`, `chop`, `cut`,
    `scoop`, `scoop and pour`: descriptor 0); `mix` and `stir` of a node with ingredients: `ingredients`.
    """
    motion = unit.motion.label
    for n in unit.inputs:
        has_ingredients = any(s.ingredients for s in n.states)
        if not has_ingredients:
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
    init_facts = tuple(dict.fromkeys(x for n in sorted(inp.kitchen) if n.label in mentioned for x in node_facts(n)))
    goal_facts = [(c, node_facts(c)) for c in inp.candidates]

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
    if several:
        goal_atom = Atom(GOAL_REACHED)
        predicates.append(Predicate(GOAL_REACHED, comment="a goal candidate was made"))
        actions.extend(goal_actions(table, [(c, atoms(fs)) for c, fs in goal_facts], goal_atom, options))
        goal_atoms: tuple[Atom, ...] = (goal_atom,)
    else:
        goal_atoms = atoms(goal_facts[0][1])

    task = PlanningTask(
        domain="foon-ocp",
        problem=table.name(f"make {goal.describe()}", key=("problem",)),
        encoding="ocp",
        level=inp.level,
        predicates=tuple(predicates),
        actions=tuple(actions),
        init=atoms(init_facts),
        goal=goal_atoms,
        constants=tuple((obj[label], "object") for label in labels),
        units=f.units,
        labels=table.labels,
    )
    if options.prune:
        task = prune_task(task)
    kept = sum(a.unit is not None for a in task.actions)
    return replace(task, comments=header("ocp", inp, options, kept))
