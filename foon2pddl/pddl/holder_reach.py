"""Actions no reachable state applies: states and (holder state, content state) pairs, over-approximated.

A relational task (`encode_relational`) can be unsolvable in a way relaxed reachability does not see: the
apple turnover's pour takes `cooking pan (contains {butter})` with `butter (in [pan], melted)` in that very pan,
and the only unit that melts butter in a pan leaves the pan `greased {butter}`; each node alone is reachable,
the two together in one pan are not. Fast Downward then searches every arrangement of the task's bowls and
butters until its time limit (experiment REG trial 1 goal 12). `drop_unreachable` computes, by a fixpoint
over the actions, every state an object may reach (`(is ?x s)`), every pair of states a holder and what it
holds may have together (`(in ?h ?x)`, `(on ?h ?x)`) and every other fluent atom, and drops the actions
whose preconditions need a state or a pair outside them, and the conditional effects whose conditions do.

Over-approximation (never drops an action some plan applies): an action counts as applicable when each
precondition alone is in the sets; an object whose state the action does not say may be in any state
(`ANY`); a pair whose holder or content changes state may end with either of them changed or not, except
that an object the action takes out of a named holder (`(in ?h ?x)` in its precondition) is in no other
holder (each object is in or on at most one), so only that pair carries its new state; conditional effects
count as firing. Atoms of other predicates whose arguments are not all named count as reachable.
"""

from __future__ import annotations

from dataclasses import replace

from ..model.where import unit_where
from ..model.words import first_of
from .task import Action, Atom, PlanningTask

#: A state nothing says: the object may be in any state.
ANY = "*"
#: Predicates that place one object in or on another.
HOLDS = ("in", "on")
#: Units named when the goal is out of reach.
SHOWN = 3
#: Why the goal is out of reach when no holder pair keeps it there (`drop_unreachable`'s `any_cause`).
NO_STATE = "no reachable state makes what the goal needs"


def _fits(have: str, need: str) -> bool:
    return have == need or have == ANY or need == ANY


class _Reach:
    """The sets the fixpoint grows: states, (relation, holder state, content state) pairs, other atoms."""

    def __init__(self, task: PlanningTask) -> None:
        self.states: set[str] = set()
        self.pairs: set[tuple[str, str, str]] = set()
        self.atoms: set[Atom] = set()
        self.any_of: set[str] = set()  # predicates added with unnamed arguments: every atom counts as reachable
        self.by_holder: dict[str, set[tuple[str, str, str]]] = {}
        self.by_content: dict[str, set[tuple[str, str, str]]] = {}
        state = {}
        for a in task.initial_facts:
            if a.predicate == "is":
                state[a.args[0]] = a.args[1]
                self.states.add(a.args[1])
        for a in task.initial_facts:
            if a.predicate in HOLDS:
                self.add_pairs(a.predicate, (state.get(a.args[0], ANY),), (state.get(a.args[1], ANY),))
            elif a.predicate != "is":
                self.atoms.add(a)

    def add_pairs(self, rel: str, holders, contents) -> None:
        for h in holders:
            for x in contents:
                pair = (rel, h, x)
                if pair not in self.pairs:
                    self.pairs.add(pair)
                    self.by_holder.setdefault(h, set()).add(pair)
                    self.by_content.setdefault(x, set()).add(pair)

    def has_pair(self, rel: str, holder: str, content: str) -> bool:
        if holder == ANY or content == ANY:
            return any(r == rel and _fits(h, holder) and _fits(c, content) for r, h, c in self.pairs)
        return any((rel, h, c) in self.pairs for h in (holder, ANY) for c in (content, ANY))

    def applicable(self, action: Action) -> bool:
        return not _missing(self, action.pre)

    def fire(self, action: Action) -> bool:
        """Add what `action` may make; whether anything was new (per-conditional from-states)."""
        size = (len(self.states), len(self.pairs), len(self.atoms), len(self.any_of))
        pre = _states_in(action.pre)
        entries = []  # (term, from-state, possible states after)
        unconditional = _states_in(action.add)
        for term, s in unconditional.items():
            entries.append((term, pre.get(term, ANY), {s}))
        fired = [c for c in action.conditional if not _missing(self, (*action.pre, *c.when))]
        for c in fired:
            when = _states_in(c.when)
            for term, s in _states_in(c.add).items():
                if term in unconditional:
                    continue
                was = pre.get(term, when.get(term, ANY))
                entries.append((term, was, {s, was}))
        self.states.update(s for _, _, ss in entries for s in ss if s != ANY)
        after: dict[str, set[str]] = {}
        for term, _, ss in entries:
            after.setdefault(term, set()).update(ss)

        def post(term: str) -> set[str]:
            return after.get(term) or {pre.get(term, ANY)}

        added = [*action.add, *(x for c in fired for x in c.add)]
        for a in added:
            if a.predicate in HOLDS:
                self.add_pairs(a.predicate, post(a.args[0]), post(a.args[1]))
            elif a.predicate != "is":
                if any(x.startswith("?") for x in a.args):
                    self.any_of.add(a.predicate)
                else:
                    self.atoms.add(a)
        pinned = {p.args[1] for p in action.pre if p.predicate in HOLDS}
        for p in action.pre:
            if p.predicate in HOLDS and p.args[1] in after:
                self.add_pairs(p.predicate, post(p.args[0]), post(p.args[1]))
        changed = [(w, ss) for _, w, ss in entries]
        loose = [(w, ss) for t, w, ss in entries if t not in pinned]
        touched = set()
        for w, _ in changed:
            touched.update(self.pairs if w == ANY else (*self.by_holder.get(w, ()), *self.by_holder.get(ANY, ())))
        for w, _ in loose:
            touched.update(self.pairs if w == ANY else (*self.by_content.get(w, ()), *self.by_content.get(ANY, ())))
        for rel, h, x in touched:
            holders = {h}.union(*(ss for w, ss in changed if _fits(w, h)))
            contents = {x}.union(*(ss for w, ss in loose if _fits(w, x)))
            self.add_pairs(rel, holders, contents)
        return size != (len(self.states), len(self.pairs), len(self.atoms), len(self.any_of))


def _missing(reach: _Reach, pre: tuple[Atom, ...]) -> list[Atom]:
    """The preconditions in `pre` that `reach` has not reached (a state, a holder pair, another atom)."""
    before = _states_in(pre)
    out = []
    for p in pre:
        if p.predicate == "is":
            if p.args[1] not in reach.states and not p.args[1].startswith("?"):
                out.append(p)
        elif p.predicate in HOLDS:
            if not reach.has_pair(p.predicate, before.get(p.args[0], ANY), before.get(p.args[1], ANY)):
                out.append(p)
        elif p.predicate not in reach.any_of and not any(x.startswith("?") for x in p.args) and p not in reach.atoms:
            out.append(p)
    return out


def _causes(reach: _Reach, gone: tuple[Action, ...], goal: tuple[Atom, ...]) -> list[tuple[Action, Atom]]:
    """The dropped actions whose holder pair is out of reach, on the way back from the goal (breadth first):
    from an unreached state or atom to the dropped actions that would make it."""
    def key(atom: Atom):
        return ("is", atom.args[1]) if atom.predicate == "is" else (atom.predicate, atom.args)

    makers: dict[tuple, list[Action]] = {}
    for a in gone:
        for x in (*a.add, *(y for c in a.conditional for y in c.add)):
            makers.setdefault(key(x), []).append(a)
    todo, seen, out = list(_missing(reach, goal)), set(), []
    while todo:
        atom = todo.pop(0)
        for a in makers.get(key(atom), ()) if atom.predicate not in HOLDS else ():
            if a.name in seen:
                continue
            seen.add(a.name)
            miss = _missing(reach, a.pre)
            before = _states_in(a.pre)  # a pair whose states are each reached: the cause (else follow the state)
            out.extend((a, m) for m in miss if m.predicate in HOLDS
                       and all(before.get(x, ANY) in reach.states for x in m.args))
            todo.extend(m for m in miss if m.predicate not in HOLDS)
    return out


def _states_in(atoms) -> dict[str, str]:
    """Term -> the state its `(is term s)` atom gives (the last one)."""
    return {a.args[0]: a.args[1] for a in atoms if a.predicate == "is"}


def _fixpoint(task: PlanningTask) -> tuple[_Reach, tuple[Action, ...]]:
    """The sets grown from `task`'s init, and the actions they never apply."""
    reach = _Reach(task)
    live: list[Action] = []
    waiting = list(task.actions)
    grew = True
    while grew:
        grew = False
        still = []
        for a in waiting:
            if reach.applicable(a):
                live.append(a)
                grew = True
            else:
                still.append(a)
        waiting = still
        for a in live:
            grew = reach.fire(a) or grew
    return reach, tuple(waiting)


def _firing(reach: _Reach, action: Action) -> Action:
    """`action` without the conditional effects whose conditions no reachable state meets (never fired in the
    fixpoint, so in no plan): Fast Downward grounds each over every binding its relaxed analysis allows (the odd
    universal half's chocolate cake: a scrape's move of a batter in a state only that move keeps, 780 times)."""
    firing = tuple(c for c in action.conditional if not _missing(reach, (*action.pre, *c.when)))
    return action if len(firing) == len(action.conditional) else replace(action, conditional=firing)


def unreachable(task: PlanningTask) -> tuple[Action, ...]:
    """The actions of `task` that no state reachable from its init applies (module doc); () for a task
    of another encoding (only `relational` keeps one state and one holder per object). O(rounds x actions x
    pairs touched)."""
    if task.encoding != "relational":
        return ()
    return _fixpoint(task)[1]


def drop_unreachable(task: PlanningTask, any_cause: bool = False) -> tuple[PlanningTask, str | None]:
    """`task` without the actions `unreachable` finds and the conditional effects no reachable state fires (the same
    plans; `task` itself when there are none),
    and, when the goal is then out of reach, why: the units whose holder and content no plan has together
    (`MOTION at FILE:LINE needs HOLDER holding CONTENT`, the first `SHOWN`, then how many more: `words.first_of`); None when it may be reached, or
    when no holder pair keeps it out of reach (nothing makes a node: the planner's relaxed analysis says so),
    unless `any_cause` (then `NO_STATE`). A task of another encoding is returned as it is."""
    if task.encoding != "relational":
        return task, None
    reach, gone = _fixpoint(task)
    dropped = {a.name for a in gone}
    actions = tuple(_firing(reach, a) for a in task.actions if a.name not in dropped)
    kept = replace(task, actions=actions) if gone or actions != task.actions else task
    missing = _missing(reach, task.goal)
    causes = _causes(reach, gone, task.goal) if missing else []
    if not causes:  # reached, or out of reach with no holder pair on the way: the planner's own analysis says so
        return kept, NO_STATE if missing and any_cause else None
    nodes = dict(task.nodes)
    said = []
    for a, miss in causes:
        before = _states_in(a.pre)
        if a.unit is not None and all(before.get(x, ANY) in nodes for x in miss.args):
            unit = task.units[a.unit]
            holder, content = (nodes[before[x]].describe() for x in miss.args)
            said.append(f"{unit.motion.label} at {unit_where(unit)} needs {holder} holding {content}"
                        if miss.predicate == "in" else
                        f"{unit.motion.label} at {unit_where(unit)} needs {content} on {holder}")
    shown = first_of(said, SHOWN)
    return kept, "no reachable state applies what the goal needs" + (f": {shown}" if shown else "")
