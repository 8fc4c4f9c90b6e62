"""Action schemas split where their parameters multiply: a chain of small actions under a lock, joined back.

A relational unit that mixes five ingredients in a bowl binds the bowl and one object of each ingredient: a
planner grounds every combination its relaxed reachability allows, the product of the objects per parameter
(blueberry muffin of the odd-index universal FOON, `ACT-0003-blueberry_muffin.txt:159`: 26 bowls x 6 salt x 6
baking soda x 6 baking powder x 11 flour x 3 flour mixtures; 18,954 ground operators, a minute of translation).
Most of those parameters are only checked: the ingredient must be in the bowl in its node, and what happens to
it is what a quantified effect of the action does to every object of its label there (`relational_sweep`), so
the parameter's own effects say nothing the quantified one does not. Such a parameter is *checked*; the others
(those an effect names) are *kept*. The checked parameters fall into groups linked by the preconditions that
name two of them (a bowl of salt and the salt in it); each group's preconditions name besides only kept ones.

An action whose parameters' objects multiply past `SPLIT_ABOVE`, or whose *weight* (bindings x (1 + the objects
its quantified effects range over)) passes `SWEEPS_PER_BINDING` times that, is split (action schema splitting, as
planners' compilations for large schemas do) into a chain, when every part weighs less than the whole. Bindings
are counted as a planner grounds them: parameters a static precondition links (no action changes it: a tally's
low and high counts, `next-count`) multiply as the facts it matches, not as their objects, and every part checks
the static preconditions over the parameters it binds (a chain is not free: while it is under way only its parts
apply, and each is a step to the heuristic). Parts that *bind*:

* `<action>-begin` takes the lock (`(chain idle)`, which every other action and the goal need, becomes the chain's
  first stage) and, like each `<action>-check-i` after it, binds some parameters where the preconditions over
  them and those bound before hold: each kept parameter in turn (recorded, `(<action>-arg-k x)`, for the parts
  after), then each group of checked ones; neighbours are one part while their parameters multiply to at most
  `SPLIT_ABOVE` (a pour binds its two bowls, then the flour with the bowl it is in).

Parts that *do* (`<action>-do-i`, the last `<action>-end`, which gives `(chain idle)` back): the action's effects
(less the checked parameters' own, which the quantified effects do), grouped by the parameters they name, each
group bound from the records alone: a sweep that empties whichever holder the egg was in grounds once per egg,
not once per egg, bowl, whisk and batter (the cranberry-walnut pancake of the odd-index universal FOON, its mix at
`0004-pancake_batter.txt:58`: 1,620 ground `end` parts with 14 sweeps over every object; 26 s of translation
CPU in all). Groups
are ordered so that they do what the action does in one step, where conditions read the state before it and an
add wins over a delete: no group changes an atom a later group's conditions may read, none adds an atom a later
group may delete (two atoms may be one when their predicates match and each pair of arguments may be one
object, by type); groups that must each come first are one part. A group joins its neighbour when that binds
no more combinations than the larger of the two.

The chain's stages make the parts fire in that order. Nothing but the chain's parts applies while the lock is taken,
the binding parts change nothing but the lock, stages and records, and they check every precondition before any
part does an effect, so a chain fires exactly when the action applies in the state where it began, with the same
effects: a split task has a plan exactly when the task has, and `Split.join` turns each chain of a plan back into
the one action with every binding (what replay and the task tree read: one unit firing). Tasks whose actions all
stay whole are returned unchanged (no lock). Applied by `planners.solve.plan` to the task it gives the planner
(not with `optimal`: the parts would count as steps); `compile` writes the task whole.
O(actions x (parameters x preconditions + effect groups^3 + (effect atoms)^2)).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import prod

from .effect_order import EffectPart, effect_parts, variables
from .prune import static_facts
from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["CHAIN", "IDLE", "SPLIT_ABOVE", "SWEEPS_PER_BINDING", "Split", "split"]

#: `(chain s)`: where the chains are, one fact at any time: `(chain idle)` (no chain under way: every action but
#: a chain's later parts needs it, and so does the goal) or the stage a chain is at. One predicate over constants
#: of its own type, so Fast Downward's invariant synthesis finds it at once: with a 0-ary fact per stage and the
#: records apart it tried ~94,000 candidate invariants combining them (the odd-universal croquette: translation
#: past the 60 s limit).
CHAIN, CHAIN_TYPE, IDLE = "chain", "chain-stage", "idle"
#: An action whose parameters' objects multiply past this is split where it can be.
SPLIT_ABOVE = 4096
#: ... and so is one whose bindings times the objects its quantified effects range over (plus one) pass this many
#: times `SPLIT_ABOVE`: a planner looks at each sweep's objects once per binding (the odd-index universal shrimp mango
#: salad's mix: 3,600 bindings, 14 sweeps, 251,200 ground effects). 8 since 64 left whole the odd-index universal chocolate
#: cake's blend (`ACT-0068-apple_cake.txt:199`, 14 times the bound: a quarter of its small task's ground effects).
SWEEPS_PER_BINDING = 8


@dataclass(frozen=True)
class Split:
    """A task with some actions split into chains, and how a plan's chains join back into those actions."""

    task: PlanningTask
    #: part name -> (the action's name, the action's parameter index each argument of the part binds, last part)
    parts: dict[str, tuple[str, tuple[int, ...], bool]] = field(default_factory=dict)

    def join(self, steps: tuple[str, ...]) -> tuple[str, ...]:
        """`steps` (plan steps of `task`) with each chain of parts as the one action it splits, fully bound."""
        out: list[str] = []
        values: dict[int, str] = {}
        for step in steps:
            name, *args = step.split()
            if name not in self.parts:
                out.append(step)
                continue
            action, slots, last = self.parts[name]
            values.update(zip(slots, args, strict=True))
            if last:
                out.append(" ".join((action, *(values[i] for i in range(len(values))))))
                values = {}
        return tuple(out)


def _sizes(task: PlanningTask) -> dict[str, int]:
    """Objects (and constants) per type, subtypes' counted in their ancestors'."""
    parent = dict(task.types)
    sizes: dict[str, int] = {}
    for _, t in (*task.objects, *task.constants):
        seen = set()
        while t is not None and t not in seen:
            seen.add(t)
            sizes[t] = sizes.get(t, 0) + 1
            t = parent.get(t)
    return sizes


def _renamed(atom: Atom, var: str, to: str) -> Atom:
    return Atom(atom.predicate, tuple(to if x == var else x for x in atom.args))


def _subsumed(effect: Atom, adds: bool, action: Action, below: dict[str, set[str]]) -> bool:
    """Whether a quantified conditional effect of `action` does `effect` whatever its parameter: for some
    parameter p of `effect`, a conditional over one variable of p's type or an ancestor's, whose condition with
    p for the variable is among the preconditions, adds (deletes) `effect` with p for the variable."""
    pre = set(action.pre)
    types = dict(action.params)
    for p in {x for x in effect.args if x in types}:
        for c in action.conditional:
            if c.var is None or c.more or types[p] not in below.get(c.type, ()):
                continue
            if all(_renamed(w, c.var, p) in pre for w in c.when) \
                    and effect in {_renamed(x, c.var, p) for x in (c.add if adds else c.delete)}:
                return True
    return False


def _groups(checked: list[str], pre: tuple[Atom, ...]) -> list[list[str]]:
    """The checked parameters linked by preconditions naming two of them, in parameter order."""
    group = {v: i for i, v in enumerate(checked)}
    for a in pre:
        linked = sorted({group[x] for x in a.args if x in group})
        for g in linked[1:]:
            for v, h in group.items():
                if h == g:
                    group[v] = linked[0]
    return [[v for v in checked if group[v] == g] for g in sorted(set(group.values()))]


def _split_one(action: Action, sizes: dict[str, int], below: dict[str, set[str]], above: int, taken: set[str],
               kind: dict[str, str], static: dict[str, list[tuple[str, ...]]]):
    """The chain of parts of `action` with their join entries, or None when it stays whole."""
    size = {v: sizes.get(t, 0) for v, t in action.params}
    fixed = [a for a in action.pre if a.predicate in static and variables((a,))]

    def fixed_over(names) -> list[Atom]:  # the static preconditions a part binding `names` checks
        return [a for a in fixed if variables((a,)) <= set(names)]

    matches = {a: _facts(a, static) for a in fixed}  # once per action: `bindings` is asked for every merge tried

    def bindings(names) -> int:
        return _bindings(names, size, [(matches[a], variables((a,))) for a in fixed_over(names)])

    def weight(names, conditional) -> int:  # bindings x (1 + objects its sweeps range over)
        return bindings(names) * (1 + sum(prod(sizes.get(t, 0) for _, t in c.quantified) for c in conditional))

    whole = weight(size, action.conditional)
    if bindings(size) <= above and whole <= above * SWEEPS_PER_BINDING:
        return None
    own = [e for e in action.add if not _subsumed(e, True, action, below)]
    own_del = [e for e in action.delete if not _subsumed(e, False, action, below)]
    named = variables((*own, *own_del, *(x for c in action.conditional for x in c.atoms())))
    order = [v for v, _ in action.params]
    kept = [v for v in order if v in named]
    checked = [v for v in order if v not in named]
    # binding parts: each kept parameter with the preconditions over it and those bound before it, then each group
    # of checked ones with the preconditions naming it; neighbours merged while they multiply to at most `above`
    binds: list[tuple[set[str], list[Atom]]] = []
    done: set[str] = set()
    for v in kept:
        done.add(v)
        atoms = [a for a in action.pre if v in variables((a,)) and variables((a,)) <= done]
        binds.append(({v, *variables(atoms)}, atoms))
    ground = [a for a in action.pre if not variables((a,))]  # with the first part
    binds[:1] = [(binds[0][0], ground + binds[0][1])] if binds else [(set(), ground)]
    for g in _groups(checked, action.pre):
        atoms = [a for a in action.pre if variables((a,)) & set(g)]
        binds.append(({*g, *variables(atoms)}, atoms))
    binds = _merged(binds, lambda a, b: bindings(a | b) <= above)
    effects = _merged([(p.names, p) for p in effect_parts(action, own, own_del, below, kind)],
                      lambda a, b: bindings(a | b) <= max(bindings(x) for x in (a, b)))
    names_of = [x for x, _ in binds] + [x for x, _ in effects]
    if not effects or len(names_of) < 2 or max(*(weight(x, ()) for x, _ in binds),
                                               *(weight(x, e.conditional) for x, e in effects)) >= whole:
        return None
    types = dict(action.params)
    index = {v: i for i, v in enumerate(order)}
    n = len(names_of)
    stage = [f"{action.name}-stage-{i}" for i in range(n - 1)]
    record = {v: f"{action.name}-arg-{v[1:]}" for v in kept}
    checks, does = len(binds) - 1, len(effects) - 1
    names = [f"{action.name}-begin", *(f"{action.name}-check-{i}" for i in range(1, checks + 1)),
             *(f"{action.name}-do-{i}" for i in range(1, does + 1)), f"{action.name}-end"]
    if taken & {*stage, *record.values(), *names}:
        raise ValueError(f"splitting {action.name}: a part's name is taken")
    last_use = {v: max(i for i, x in enumerate(names_of) if v in x) for v in kept}
    zero = 0 if action.cost is not None else None
    parts, bound = [], set()
    for i, vs in enumerate(names_of):
        new = [v for v in order if v in vs and v not in bound and v in record]
        old = [v for v in order if v in vs and v in bound]
        bound |= vs
        body = binds[i][1] if i < len(binds) else []
        body = [*body, *(a for a in fixed_over(vs) if a not in body)]  # static: true whenever it held, so each part checks
        eff = effects[i - len(binds)][1] if i >= len(binds) else EffectPart(set())
        parts.append(Action(
            names[i], params=tuple((v, types[v]) for v in order if v in vs), unit=action.unit, roles=action.roles,
            pre=(_at(IDLE if i == 0 else stage[i - 1]), *(Atom(record[v], (v,)) for v in old), *body),
            add=(_at(IDLE if i == n - 1 else stage[i]), *(Atom(record[v], (v,)) for v in new), *eff.add),
            delete=(_at(IDLE if i == 0 else stage[i - 1]),
                    *(Atom(record[v], (v,)) for v in old if last_use[v] == i), *eff.delete),
            conditional=tuple(eff.conditional), cost=action.cost if i == n - 1 else zero,
            comment=action.comment if i == 0 else ()))
    join = {p.name: (action.name, tuple(index[v] for v, _ in p.params), p is parts[-1]) for p in parts}
    predicates = [Predicate(record[v], (("?x", types[v]),), f"{action.name} binds {v} to ?x") for v in kept]
    return parts, join, predicates, stage


def _facts(atom: Atom, static: dict[str, list[tuple[str, ...]]]) -> int:
    """How many static facts the atom matches (its variables match anything)."""
    return sum(all(x.startswith("?") or x == y for x, y in zip(atom.args, row, strict=True))
               for row in static[atom.predicate] if len(row) == len(atom.args))


def _bindings(names, size: dict[str, int], fixed: list[tuple[int, set[str]]]) -> int:
    """At most how many bindings of the parameters `names` a planner grounds where the static atoms `fixed` (over
    them only; each given as the facts it matches and its variables) hold: the product of their objects, each of
    some static atoms over disjoint parameters (those that rule out most first) counted as the facts it matches
    instead of its parameters' product."""
    rated = sorted(fixed, key=lambda r: r[0] / max(1, prod(size[v] for v in r[1])))
    free, n = set(names), 1
    for count, vs in rated:
        if vs <= free and count < prod(size[v] for v in vs):
            free -= vs
            n *= count
    return n * prod(size[v] for v in free)


def _merged(parts: list, fits) -> list:
    """`parts` ((parameter names, content) pairs, in order) with neighbours joined while `fits(names, names)`;
    contents are lists or `EffectPart`s (`effect_order`)."""
    out = [parts[0]] if parts else []
    for names, content in parts[1:]:
        last_names, last = out[-1]
        if fits(last_names, names):
            if isinstance(last, EffectPart):
                last = EffectPart(last.names | content.names, last.add + content.add, last.delete + content.delete,
                             last.conditional + content.conditional)
            else:
                last = last + content
            out[-1] = (last_names | names, last)
        else:
            out.append((names, content))
    return out


def split(task: PlanningTask, above: int | None = None) -> Split:
    """`task` with each action whose parameters multiply past `above` (default `SPLIT_ABOVE`) split into a chain
    (module doc)."""
    above = SPLIT_ABOVE if above is None else above
    sizes = _sizes(task)
    parent = dict(task.types)
    below: dict[str, set[str]] = {}
    for t in {*sizes, *parent, *(t for a in task.actions for _, t in a.params)}:
        s = t
        while s is not None and t not in below.get(s, ()):
            below.setdefault(s, set()).add(t)
            s = parent.get(s)
    taken = {a.name for a in task.actions} | {p.name for p in task.predicates} \
        | {n for pair in (*task.types, *task.objects, *task.constants) for n in pair}
    kind = dict((*task.objects, *task.constants))
    static = static_facts(task)
    actions: list[Action] = []
    predicates: list[Predicate] = []
    stages: list[str] = [IDLE]
    parts: dict[str, tuple[str, tuple[int, ...], bool]] = {}
    for action in task.actions:
        chain = _split_one(action, sizes, below, above, taken | {CHAIN, CHAIN_TYPE, IDLE}, kind, static)
        if chain is None:
            actions.append(action)
            continue
        actions.extend(chain[0])
        parts.update(chain[1])
        predicates.extend(chain[2])
        stages.extend(chain[3])
    if not parts:
        return Split(task)
    if taken & {CHAIN, CHAIN_TYPE, IDLE}:
        raise ValueError(f"splitting actions: the task already names {sorted(taken & {CHAIN, CHAIN_TYPE, IDLE})}")
    actions = [a if a.name in parts else replace(a, pre=(_at(IDLE), *a.pre)) for a in actions]
    return Split(replace(task, actions=tuple(actions), init=(*task.init, _at(IDLE)), goal=(*task.goal, _at(IDLE)),
                         types=(*task.types, (CHAIN_TYPE, "object")),
                         constants=(*task.constants, *((s, CHAIN_TYPE) for s in stages)),
                         predicates=(*task.predicates, Predicate(CHAIN, (("?s", CHAIN_TYPE),),
                                                                 "the chain of parts under way is at ?s (idle: none)"),
                                     *predicates)), parts)


def _at(stage: str) -> Atom:
    return Atom(CHAIN, (stage,))
