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

An action whose parameters' objects multiply past `SPLIT_ABOVE` is split (action schema splitting, as planners'
compilations for large schemas do) into a chain, when every part is smaller than the whole:

* `<action>-begin` binds the kept parameters where the preconditions over them alone hold, takes the lock
  (`(chain idle)`, which every other action and the goal need, becomes the chain's first stage) and records
  each binding, `(<action>-arg-k x)`;
* one `<action>-check-i` per group binds the group where its preconditions hold, over the recorded values of the
  kept parameters they name;
* `<action>-end` does the action's effects (less the checked parameters' own, which the quantified effects do)
  on the recorded values, frees the records and gives the lock back (`(chain idle)`).

The chain's stages make the parts fire in that order. Nothing but the chain's parts applies while the lock is taken and
the parts before the last change nothing but the lock, stages and records, so a chain fires exactly when the
action applies in the state where it began, with the same effects: a split task has a plan exactly when the task
has, and `Split.join` turns each chain of a plan back into the one action with every binding (what replay and
the task tree read: one unit firing). Tasks whose actions all stay whole are returned unchanged (no lock).
Applied by `planners.solve.plan` to the task it gives the planner (not with `optimal`: the parts would count as
steps); `compile` writes the task whole. O(actions x parameters x preconditions).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import prod

from .task import Action, Atom, PlanningTask, Predicate

__all__ = ["CHAIN", "IDLE", "SPLIT_ABOVE", "Split", "split"]

#: `(chain s)`: where the chains are, one fact at any time: `(chain idle)` (no chain under way: every action but
#: a chain's later parts needs it, and so does the goal) or the stage a chain is at. One predicate over constants
#: of its own type, so Fast Downward's invariant synthesis finds it at once: with a 0-ary fact per stage and the
#: records apart it tried ~94,000 candidate invariants combining them (the odd-universal croquette: translation
#: past the 60 s limit).
CHAIN, CHAIN_TYPE, IDLE = "chain", "chain-stage", "idle"
#: An action whose parameters' objects multiply past this is split where it can be.
SPLIT_ABOVE = 4096


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


def _vars(atoms) -> set[str]:
    return {x for a in atoms for x in a.args if x.startswith("?")}


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


def _split_one(action: Action, sizes: dict[str, int], below: dict[str, set[str]], above: int, taken: set[str]):
    """The chain of parts of `action` with their join entries, or None when it stays whole."""
    size = {v: sizes.get(t, 0) for v, t in action.params}
    whole = prod(size.values())
    if whole <= above:
        return None
    own = [e for e in action.add if not _subsumed(e, True, action, below)]
    own_del = [e for e in action.delete if not _subsumed(e, False, action, below)]
    named = _vars((*own, *own_del, *(x for c in action.conditional for x in c.atoms())))
    kept = [v for v, _ in action.params if v in named]
    checked = [v for v, _ in action.params if v not in named]
    groups = _groups(checked, action.pre)
    checks = [[a for a in action.pre if _vars((a,)) & set(g)] for g in groups]
    over = [[v for v in kept if v in _vars(atoms)] for atoms in checks]
    if not groups or max(prod(size[v] for v in (*k, *g)) for k, g in zip(over, groups, strict=True)) >= whole \
            or prod(size[v] for v in kept) >= whole:
        return None
    types = dict(action.params)
    index = {v: i for i, (v, _) in enumerate(action.params)}
    stage = [f"{action.name}-stage-{i}" for i in range(len(groups) + 1)]
    record = {v: f"{action.name}-arg-{v[1:]}" for v in kept}
    names = [f"{action.name}-begin", *(f"{action.name}-check-{i}" for i in range(1, len(groups) + 1)),
             f"{action.name}-end"]
    if taken & {*stage, *record.values(), *names}:
        raise ValueError(f"splitting {action.name}: a part's name is taken")
    base = [a for a in action.pre if not _vars((a,)) & set(checked)]
    recorded = tuple(Atom(record[v], (v,)) for v in kept)
    zero = 0 if action.cost is not None else None
    begin = replace(action, name=names[0], params=tuple((v, types[v]) for v in kept),
                    pre=(_at(IDLE), *base), add=(_at(stage[0]), *recorded), delete=(_at(IDLE),),
                    conditional=(), cost=zero)
    parts = [begin]
    for i, (g, atoms, k) in enumerate(zip(groups, checks, over, strict=True)):
        parts.append(replace(action, name=names[i + 1], params=tuple((v, types[v]) for v in (*k, *g)),
                             pre=(_at(stage[i]), *(Atom(record[v], (v,)) for v in k), *atoms),
                             add=(_at(stage[i + 1]),), delete=(_at(stage[i]),), conditional=(), cost=zero,
                             comment=()))
    parts.append(replace(action, name=names[-1], params=begin.params, pre=(_at(stage[-1]), *recorded, *base),
                         add=(_at(IDLE), *own), delete=(_at(stage[-1]), *recorded, *own_del), comment=()))
    join = {p.name: (action.name, tuple(index[v] for v, _ in p.params), p is parts[-1]) for p in parts}
    predicates = [Predicate(record[v], (("?x", types[v]),), f"{action.name} binds {v} to ?x") for v in kept]
    return parts, join, predicates, stage


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
    actions: list[Action] = []
    predicates: list[Predicate] = []
    stages: list[str] = [IDLE]
    parts: dict[str, tuple[str, tuple[int, ...], bool]] = {}
    for action in task.actions:
        chain = _split_one(action, sizes, below, above, taken | {CHAIN, CHAIN_TYPE, IDLE})
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
