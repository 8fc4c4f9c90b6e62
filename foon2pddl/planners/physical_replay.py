"""An independent physical replay of a plan: does every object sit where FOON says, after every step?

`replay(trace)` walks a `model.physical.PhysicalTrace` from its initial state,
recomputing each snapshot from the step's changes, and compares it with FOON's
own words, never with an encoding's facts (it is the oracle that checks them).

**States** (the initial state, step -1, and the state after every step):

* a holder exists: every existing object in or on something is held by an object that
  is made and not consumed (`HOLDER_GONE`). An object made earlier whose node became
  None (FOON gives it no state any more: a carton FOON leaves out of a pour's outputs,
  a bowl a unit fills without listing it) is *undescribed*: still there, it can hold
  things and stands for its label in a container, but nothing is checked of its own
  state or contents;
* placement: an object whose node says `in [C]` / `on [C]` is directly in / on an
  object labelled C (`MISPLACED`); when its node names several places (`in [bowl]`,
  `in [microwave]`), the direct holder matches one and the others are further up the
  holder chain (or the holder's label and the object's are a pair `PhysicalTrace.gaps` reports: the
  pour's `bowl (contains {garlic butter})` beside `garlic butter (in [food processor bowl])`). An
  object whose node names no place may have a holder only when it
  has had it since the initial state and its initial node named no place either (a
  scene's placement FOON is silent about: the bowl on `counter_1`); any other holder
  is `UNEXPECTED_HOLDER` (a board that is cut on, then carried, still holding the onion);
* contents, for holders of a *container label* (a label some node of the trace gives a `contains`, `empty` or
  `with` state and some node names as a place; a stove or a table, whose nodes never describe what is on them, may
  hold anything, and a `contains` list on a mixture nothing is put in names its ingredients), when its node
  describes its contents (a `contains`, `empty` or `with` state: `cutting board (dirty)` with the bread still on it
  says nothing about what is on the board, so nothing is checked): the labels a container's node lists (`contains
  {a, b}`, `contains [a]`) are exactly covered by the existing objects in or on it, directly or through others (the
  dressing on the carrot in the bowl). An ingredient list names what went into a mixture, so an object *stands for*
  its label plus every object it absorbed: a consumed object is absorbed by the objects its step changed that end
  up in the holder it was in (or under the mixture it was on, consumed too; or, when it stood free or none end up
  there, by the objects the step made: the rice wrapped into the onigiri), transitively. A listed label nothing in the container stands for (nor the
  container itself, when it is a mixture that absorbed it) is `MISSING_CONTENT` (unless the trace's builder
  reported that FOON's own nodes contradict each other about that container label and content label,
  `PhysicalTrace.gaps`: then the pair is not checked), or `STALE_SOURCE` when an object of that label left the
  container in a step that gave the container no new node (FOON leaves a pour's source out of the unit's outputs,
  so its list goes stale), or `CLAIMED_TWICE` when the only objects of that label are in other containers that list
  it too (two bowls claim one salmon). An object that stands for nothing the list names is `UNLISTED_CONTENT`, or
  `HELD_BY_EMPTY` when the node lists nothing (emptied, or a board that "becomes dirty" with the onion still on
  it). Only objects whose node names a place count as contents: FOON lists what it places, and a placeless object
  with a holder is judged by the placement rule above.

**Steps**, for step k:

* only bound objects change (`UNBOUND_CHANGE`);
* a bound object exists before the step (`NOT_AVAILABLE`: not made yet, or consumed),
  unless the step makes it, and then it did not exist (`REMADE`); its node before the
  step is the binding's `before`, and after it the binding's `after` (or `before` when
  the unit leaves it unchanged), unless the step consumes it (`STATE_MISMATCH`);
* an object that leaves a holder was in a holder its input node names, read as this step or the one that set
  the node reads it (or of a pair `trace.gaps` reports), and that holder is bound in the step (`WRONG_SOURCE`; exempt: leaving the undescribed initial holder, the fridge a
  scene put the onion in); the holder it arrives in is bound (`UNBOUND_TARGET`);
* a bound object whose node (before or after) names `in [C]` while the step binds objects labelled C as
  roles or chosen holders (not a board an effect emptied, nor one it makes, for a node from before it) is in one
  of those (`HOLDER_NOT_BOUND`: a plan defrosts bowl_7 in the microwave while the salmon sits in bowl_2), unless
  `trace.gaps` reports C's or the holder's pair (the unit's only bowl lists its contents without the onion);
* where the step does its work (`replay_where`), read off holders and bindings alone (no FOON list), so it
  holds for `trace.gaps`' pairs too, where the encoding binds the holder late. An object the step consumes is in the holder of an object
  the step makes (or on a mixture it consumes there; `CONSUMED_ELSEWHERE`: 0050's mix at level 2 made the egg
  mixture in bowl_1 of the milk in bowl_2), unless it stood free, the step makes nothing held, or the step brings
  it there: it rests on its holder (the slice lifted onto the sandwich), or the unit names a holder of its
  holder's label besides where it makes its products (the measuring cup of a pour and stir, or a second bowl).
  Any other object the step changes, in a holder of label C, while the step changes objects labelled C that it
  binds as roles or chosen holders (the bowl a pour empties), is in a C it binds so too (`HOLDER_NOT_BOUND`
  for work in place or used up, `WRONG_SOURCE` for a move: the unit empties bowl_1 while the milk leaves bowl_2);
  where anything arrives, and what holds that, is no such C, and a bowl the step binds and leaves as it is says
  nothing of where the work is (`ACT-0003-blueberry_muffin.txt:220` names a bowl of batter and pours the
  blueberry from its own). Exempt, as for a source: the undescribed initial holder. Reported once per step, kind
  and object.

FOON's names are read through the trace's aliases (`salad` for `carrot salad`), and a node a step sets also
through that step's own (`TraceStep.aliases`: the club sandwich's `toothpick (in [sandwich])`).

A state disagreement is reported at the state where it arises and not again while it
persists (`ReplayReport.affected_steps` still counts every step after which one holds).
Order: by step, then checks in the order above, objects by id. Time: O(steps x objects).
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.foon import ObjectNode
from ..model.physical import ObjectState, PhysicalTrace, Relation, TraceStep
from ..model.places import describes_contents, listed, places
from .foon_places import container_labels, step_source
from .replay_findings import Disagreement, DisagreementKind, ReplayReport
from .replay_where import where_done

__all__ = ["replay"]


class _Replay:
    """The walk's working state: labels, initial placements, absorbed labels, findings."""

    def __init__(self, trace: PhysicalTrace, aliases: Mapping[str, str]) -> None:
        self.trace = trace
        self.aliases = aliases
        self.label = {o.id: o.label for o in trace.objects}
        self.initial = {s.id: s for s in trace.initial}
        self.containers = container_labels(trace, aliases)
        self.gaps: dict[str, frozenset[str]] = {}  # container label -> content labels not checked in it
        for c, x in ((aliases.get(c, c), aliases.get(x, x)) for c, x in trace.gaps):
            self.gaps[c] = self.gaps.get(c, frozenset()) | {x}
        self.absorbed: dict[str, frozenset[str]] = {}
        self.stale: dict[tuple[str, str], tuple[ObjectNode, int]] = {}  # (holder, label) -> (its node, step)
        self.found: list[Disagreement] = []
        self.active: set[tuple] = set()
        self.seen: set[str] = set()  # objects that have existed: with no node later, they are undescribed
        self.read: dict[str | None, Mapping[str, str]] = {}  # object -> its aliases and the setting step's

    def present(self, state: ObjectState) -> bool:
        """Physically there: existing, or made earlier and not consumed, with no FOON node any more."""
        return not state.consumed and (state.node is not None or state.id in self.seen)

    def status(self, state: ObjectState) -> str:
        return ("consumed" if state.consumed else "described by no FOON node" if self.present(state)
                else "not made yet")

    def reading(self, oid: str | None) -> Mapping[str, str]:
        """The names `oid`'s node is read through: the task's aliases, and those of the step that set it."""
        return self.read.get(oid, self.aliases)

    def places(self, node: ObjectNode | None, oid: str | None = None) -> tuple[tuple[Relation, str], ...]:
        return tuple((r, self.reading(oid).get(c, c)) for r, c in places(node))

    def listed(self, node: ObjectNode | None, oid: str | None = None) -> frozenset[str]:
        return frozenset(self.reading(oid).get(x, x) for x in listed(node))

    def kept(self, oid: str, state: ObjectState) -> bool:
        """Still in the holder a start state put it in while its node named no place (the scene's fridge)."""
        first = self.initial[oid]
        return state.holder == first.holder and not self.places(first.node, oid)

    def stands_for(self, oid: str) -> frozenset[str]:
        return self.absorbed.get(oid, frozenset()) | {self.label[oid]}

    # ---- states

    def check_state(self, states: Mapping[str, ObjectState], step: int, source: str) -> bool:
        """Report the state disagreements that are new since the previous state; whether any holds."""
        now: list[Disagreement] = []

        def add(kind: DisagreementKind, objects: tuple[str, ...], message: str) -> None:
            now.append(Disagreement(kind, step, objects, source, message))

        existing = sorted(i for i, s in states.items() if s.exists)
        self.seen.update(existing)
        for oid in existing:
            self._placement(states, oid, add)
        self._contents(states, existing, add)
        keys = {(d.kind, d.objects, d.message) for d in now}
        self.found += [d for d in now if (d.kind, d.objects, d.message) not in self.active]
        self.active = keys
        return bool(now)

    def _placement(self, states: Mapping[str, ObjectState], oid: str, add) -> None:
        s = states[oid]
        named = self.places(s.node, oid)
        if s.holder is not None and not self.present(states[s.holder]):
            add(DisagreementKind.HOLDER_GONE, (oid, s.holder), f"{oid} is {s.relation} {s.holder}, which "
                f"is {self.status(states[s.holder])}")
        if not named:
            first = self.initial[oid]
            if s.holder is not None and not (s.holder == first.holder and not self.places(first.node, oid)):
                add(DisagreementKind.UNEXPECTED_HOLDER, (oid, s.holder),
                    f"{oid} is {s.relation} {s.holder}, but its node {s.node.describe()!r} names no place")
            return
        if s.holder is None:
            add(DisagreementKind.MISPLACED, (oid,), f"{oid} is {_say(named)} by its node, but is in or on nothing")
            return
        here = (s.relation, self.label[s.holder])
        if here not in named:
            if not self.stands_for(oid) & self.gaps.get(here[1], frozenset()):
                add(DisagreementKind.MISPLACED, (oid, s.holder),
                    f"{oid} is {_say(named)} by its node, but is {s.relation} {s.holder} (a {here[1]})")
            return
        chain, at = set(), states[s.holder].holder
        while at is not None:
            chain.add(self.label[at])
            at = states[at].holder
        far = [(r, c) for r, c in named if (r, c) != here and c not in chain]
        if far:
            add(DisagreementKind.MISPLACED, (oid, s.holder),
                f"{oid} is {_say(tuple(far))} by its node, but {s.holder} is in or on no {far[0][1]}")

    def _contents(self, states: Mapping[str, ObjectState], existing: list[str], add) -> None:
        inside: dict[str, list[str]] = {}
        cover: dict[str, list[str]] = {}  # also undescribed objects: they still stand for what they are
        for oid, st in states.items():
            if st.holder is not None and self.present(st) and (st.node is None or self.places(st.node, oid)):
                cover.setdefault(st.holder, []).append(oid)
                if st.node is not None:
                    inside.setdefault(st.holder, []).append(oid)
        holders = [h for h in existing if self.label[h] in self.containers]
        claims: dict[str, list[str]] = {}
        for h in holders:
            for x in self.listed(states[h].node, h):
                claims.setdefault(x, []).append(h)
        for h in holders:
            node, items = states[h].node, self.listed(states[h].node, h)
            if not describes_contents(node):  # `cutting board (dirty)`: silent about what is on it
                continue
            covered = frozenset().union(self.absorbed.get(h, frozenset()),
                                        *map(self.stands_for, _below(h, cover)))
            gap = self.gaps.get(self.label[h], frozenset())
            for x in sorted(items - covered - gap):
                others = [o for o in existing if self.label[o] == x and states[o].holder in claims.get(x, ())]
                left = self.stale.get((h, x))
                if left is not None and left[0] == node:
                    add(DisagreementKind.STALE_SOURCE, (h,), f"{h} still lists {x}, which left it at step "
                        f"{left[1] + 1}: that unit's outputs give {h} no state without it")
                elif others:
                    add(DisagreementKind.CLAIMED_TWICE, (h, *sorted(others)),
                        f"{h} lists {x}, but the only {x} ({', '.join(sorted(others))}) is in "
                        f"{', '.join(sorted({states[o].holder for o in others}))}, which lists it too")
                else:
                    add(DisagreementKind.MISSING_CONTENT, (h,), f"{h} lists {x}, but nothing in it is {x} "
                        "or was made from it")
            for o in inside.get(h, ()):
                if self.stands_for(o) & (items | gap):
                    continue
                if items:
                    add(DisagreementKind.UNLISTED_CONTENT, (h, o),
                        f"{o} is {states[o].relation} {h}, whose node lists only {', '.join(sorted(items))}")
                else:
                    add(DisagreementKind.HELD_BY_EMPTY, (h, o),
                        f"{o} is {states[o].relation} {h}, whose node {node.describe()!r} lists nothing")

    # ---- steps

    def check_step(self, step: TraceStep, before: Mapping[str, ObjectState], after: Mapping[str, ObjectState]) -> None:
        k, source, motion = step.index, step_source(step), step.unit.motion.label
        bound = set(step.objects)

        def add(kind: DisagreementKind, objects: tuple[str, ...], message: str) -> None:
            self.found.append(Disagreement(kind, k, objects, source, f"{motion}: {message}"))

        words, prior = {**self.aliases, **dict(step.aliases)}, {b.object: self.reading(b.object) for b in step.bindings}
        for b in step.bindings:  # a node the step sets is the unit's words: read through its own aliases
            if after[b.object].node not in (None, before[b.object].node):
                self.read[b.object] = words
        for c in sorted(step.changes, key=lambda c: c.id):
            if c.id not in bound and c != before[c.id]:
                add(DisagreementKind.UNBOUND_CHANGE, (c.id,), f"{c.id} changes, but the step does not use it")
        for b in step.bindings:
            was, now = before[b.object], after[b.object]
            if b.before is None:
                if self.present(was):
                    add(DisagreementKind.REMADE, (b.object,), f"the step makes {b.object}, which already exists")
            elif not was.exists:
                add(DisagreementKind.NOT_AVAILABLE, (b.object,),
                    f"{b.object} is {self.status(was)}, the step needs {b.before.describe()!r}")
            elif was.node != b.before:
                add(DisagreementKind.STATE_MISMATCH, (b.object,),
                    f"{b.object} is {was.node.describe()!r}, the step needs {b.before.describe()!r}")
            want = b.after if b.after is not None else b.before
            undescribed = b.after is None and now.node is None and was.exists  # the unit gives it no output
            if want is not None and not now.consumed and now.node != want and not undescribed:
                have = now.node.describe() if now.node is not None else "not made"
                add(DisagreementKind.STATE_MISMATCH, (b.object,),
                    f"{b.object} ends {have!r}, the step makes it {want.describe()!r}")
        for b in step.bindings:
            self._moves(b.object, b.before, before, after, bound, add, prior[b.object])
            h = before[b.object].holder
            if h is not None and after[b.object].holder != h and self.label[b.object] in self.listed(after[h].node, h):
                self.stale[(h, self.label[b.object])] = (after[h].node, k)
        self._holders_bound(step, before, after, add)
        said = {(d.kind, d.objects[0]) for d in self.found if d.step == k}
        where_done(step, before, after, self.label, self.kept, lambda n, o: {c for _, c in self.places(n, o)}, said, add)
        self._absorb(step, before, after)

    def _moves(self, oid, node_before, before, after, bound, add, prior) -> None:
        was, now = before[oid], after[oid]
        if was.holder == now.holder:
            return
        if was.holder is not None and not self.kept(oid, was):
            h, n = self.label[was.holder], node_before or was.node  # in the words of the step that set it, or this one's
            named = {c for _, c in self.places(n, oid)} | {prior.get(c, c) for _, c in places(n)}
            if h not in named and not self.stands_for(oid) & self.gaps.get(h, frozenset()):  # as for placement
                add(DisagreementKind.WRONG_SOURCE, (oid, was.holder), f"{oid} leaves {was.holder}, a {h} its input node does not name")
            elif was.holder not in bound:
                add(DisagreementKind.WRONG_SOURCE, (oid, was.holder),
                    f"{oid} leaves {was.holder}, which the step does not use")
        if now.holder is not None and now.holder not in bound:
            add(DisagreementKind.UNBOUND_TARGET, (oid, now.holder),
                f"{oid} goes {now.relation} {now.holder}, which the step does not use")

    def _holders_bound(self, step: TraceStep, before, after, add) -> None:
        by_label: dict[str, set[str]] = {}  # the unit's objects and the holders it chose, not what an effect
        made = {b.object for b in step.bindings if b.before is None}  # emptied; none it makes holds before
        for b in step.bindings:
            if b.role:
                by_label.setdefault(self.label[b.object], set()).add(b.object)
        seen = set()
        for b in step.bindings:
            for node, state, new in ((b.before, before[b.object], made), (b.after or b.before, after[b.object], made if b.after is None else set())):
                if not state.exists or state.holder is None:
                    continue
                gap = self.gaps.get(self.label[state.holder], frozenset())
                for rel, c in self.places(node):
                    if self.stands_for(b.object) & (self.gaps.get(c, frozenset()) | gap):
                        continue  # FOON's words contradict each other here: reported, and bound late
                    ours = by_label.get(c, set()) - {b.object} - new
                    if ours and rel == state.relation and state.holder not in ours and (b.object, c) not in seen:
                        seen.add((b.object, c))
                        add(DisagreementKind.HOLDER_NOT_BOUND, (b.object, state.holder, *sorted(ours)),
                            f"the step uses {', '.join(sorted(ours))}, but {b.object} is {rel} {state.holder}")

    def _absorb(self, step: TraceStep, before, after) -> None:
        changed = [c.id for c in step.changes if after[c.id].exists]
        made = [i for i in changed if not before[i].exists]
        for c in step.changes:
            if not c.consumed or before[c.id].consumed:
                continue
            h = before[c.id].holder
            while h is not None and after[h].consumed:  # on a mixture consumed too: the holder under it
                h = before[h].holder
            takers = [i for i in changed if i != c.id and after[i].holder is not None
                      and after[i].holder in (h, c.holder)] if h is not None else []
            for t in takers or made:
                self.absorbed[t] = self.absorbed.get(t, frozenset()) | self.stands_for(c.id)


def _below(h: str, cover: Mapping[str, list[str]]) -> list[str]:
    """Everything in or on `h`, directly or through other objects (the dressing on the carrot in the bowl)."""
    out, todo = [], list(cover.get(h, ()))
    while todo:
        o = todo.pop()
        out.append(o)
        todo += cover.get(o, ())
    return out


def _say(named: tuple[tuple[Relation, str], ...]) -> str:
    return " and ".join(f"{r} a {c}" for r, c in named)


def replay(trace: PhysicalTrace, aliases: Mapping[str, str] | None = None) -> ReplayReport:
    """Replay `trace` and report every disagreement with FOON (see the module doc).

    `aliases` maps a name FOON writes in an ingredient list or a place to the object label it means
    (`olive oil` -> `green olive oil`, `muff` -> `muffin pan`): label mismatches the caller has reported,
    so they are not reported again as missing or misplaced contents. The trace's own `aliases` (those its
    builder reported) are read too; `aliases` wins where both name one word.
    """
    run = _Replay(trace, {**dict(trace.aliases), **(aliases or {})})
    snapshots = iter(trace.states())
    before = next(snapshots)
    run.check_state(before, -1, "")
    affected = []
    for step, after in zip(trace.steps, snapshots, strict=True):
        n = len(run.found)
        run.check_step(step, before, after)
        if run.check_state(after, step.index, step_source(step)) or len(run.found) > n:
            affected.append(step.index)
        before = after
    return ReplayReport(tuple(run.found), tuple(affected))
