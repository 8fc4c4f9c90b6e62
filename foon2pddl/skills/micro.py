"""One micro problem per macro step: the step's objects, where they are, and what FOON says the step does.

Rule (docs/skills.md): the objects are the ones the step binds or changes, plus
their holders before and after the step (transitively: a bowl in the fridge brings
the fridge); everything stands where the trace says, and free-standing objects
stand on the `workspace`. An object in or on a holder the step's unit does not name (a scene's fridge or
counter) stands free for that step as well (`stands_free`): it is taken from there, not poured out of it. Init = those objects' facts before the step, the robot's
hands empty, and the step's outcome as facts tagged with the skill its motion maps
to: `changes` (a physical phase changes), `moves-in`/`moves-on` (moved by a
non-transport skill: poured, scooped, spread), `makes-in`/`makes-on` (a product
appears), `uses-up` (an ingredient is consumed), and the `target`s, the sites the
skill may work on: the changed objects, where moved objects go, where products
appear, where consumed objects were (the workspace only when nothing else is a
site). A tool or hand skill (one that works on one object: `?h ?o`, `?h ?t ?o`)
brings the whole outcome in one application at any target, and its targets are
only the changed objects other than tools when there are any (squeeze the lime,
not the juicer its juice appears in), else the free-standing objects it handles: those it
uses up and, for a bare-hand skill (`?h ?o`, which holds no tool), the step's objects
taken for tools (crack the egg, not the cup its yolk appears in; the relational trace
keeps the egg, unchanged); else the sites above (mix in the bowl whose ingredients become
one mixture); a transfer works at the target its moved objects go to. Goal = the
objects' facts after the step and every hand empty. Objects moved by a transport
skill (pick-and-place) stay `graspable`, and their phase changes are tagged with the
skill that sets them down (`put-in` into a container, `place` onto a surface); objects poured or scooped out of a holder
are not (a robot pours water, it does not grasp it); one that stands free (salt FOON
puts in no container) is, and is moved by holding it (its container, unnamed). A `tool` is
a step object that stands free, holds nothing, stays where it is, and keeps its phase or becomes `dirty`
(knife, spoon, whisk). What a transport step that moves something leaves in place starts in the phase FOON
restates it in (`_restated`: no transport skill changes an object it does not set down). A tool or hand skill
carries nothing that stands free: such an object that the step moves (the skillet a `heat` puts on the stove, the
block of cheese grated into a bowl) gets no `moves-*` fact and is picked and set down by transport skills; a tool
skill still moves what lies in or on a holder (the sauce a brush coats the rib with). A portion (`portions`) stands
where its source is before every step but a tool or hand skill's: picked up there, or poured from its holder.

Names: trace ids become PDDL names through one `NameTable` per trace (valid ids
stay as they are), with the domain's constants, the workspace and the hands
reserved; a phase (an object's non-relational states, `chopped`) gets one name
for the whole trace, so the replay compares facts across steps.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from functools import cached_property

from ..model.foon import ObjectNode
from ..model.physical import ObjectState, PhysicalTrace, Relation
from ..model.places import places
from ..pddl.names import NameTable
from ..pddl.render import render_problem
from ..pddl.task import Atom, PlanningTask
from .domain import TRANSPORT, SkillDomain

__all__ = ["MicroProblem", "Naming", "dynamic_facts", "micro_problem", "phase_of", "portions", "step_objects"]

WORKSPACE = "workspace"
#: The phase FOON gives a utensil after use: a tool may end in it (a spoon gets dirty), not in any other.
USED = "dirty"
_RELATIONAL = {"contains", "empty"}


def phase_of(node: ObjectNode) -> tuple[str, ...]:
    """An object's physical phase: its states other than where it is or what it holds (`chopped`, `on`)."""
    return tuple(s.describe() for s in node.states
                 if not (s.related and s.label in ("in", "on")) and s.label not in _RELATIONAL
                 and not (s.label in ("in", "on") and s.ingredients)) or ("plain",)


class Naming:
    """PDDL names for one trace: objects, phases, hands and the workspace (see the module doc)."""

    def __init__(self, trace: PhysicalTrace, domain: SkillDomain, hands: int) -> None:
        self.table = NameTable()
        for c in domain.skills:
            self.table.reserve(c)
        self.workspace = self.table.name(WORKSPACE, key=("workspace",))
        self.hands = tuple(self.table.name(f"hand_{k}", key=("hand", k)) for k in range(1, hands + 1))
        self.ids = {o.id: self.table.name(o.id, key=("object", o.id)) for o in trace.objects}
        self.back = {name: oid for oid, name in self.ids.items()}
        self.back[self.workspace] = WORKSPACE

    def phase(self, node: ObjectNode) -> str:
        key = phase_of(node)
        return self.table.name("phase " + ", ".join(key), key=("phase", key))

    def holder(self, state: ObjectState) -> Atom:
        """`(in bowl_1 onion_1)`, `(on board_1 onion_1)`, or `(on workspace onion_1)` when it stands free."""
        if state.holder is None:
            return Atom("on", (self.workspace, self.ids[state.id]))
        return Atom(str(state.relation), (self.ids[state.holder], self.ids[state.id]))


def dynamic_facts(naming: Naming, states: Mapping[str, ObjectState], ids: Iterable[str]) -> set[Atom]:
    """The changing facts of `ids` in `states`: holder, placed and phase when it exists, else consumed/unmade."""
    out: set[Atom] = set()
    for oid in ids:
        s, name = states[oid], naming.ids[oid]
        if s.exists:
            out |= {naming.holder(s), Atom("placed", (name,)), Atom("state", (name, naming.phase(s.node)))}
        elif s.consumed:
            out.add(Atom("consumed", (name,)))
        else:
            out.add(Atom("unmade", (name,)))
    return out


def step_objects(trace: PhysicalTrace, index: int) -> tuple[str, ...]:
    """The ids of step `index`'s objects and of their holders before and after it (transitively), sorted."""
    step = trace.steps[index]
    before, after = trace.after(index - 1), trace.after(index)
    found = set(step.objects) | {c.id for c in step.changes}
    todo = list(found)
    while todo:
        oid = todo.pop()
        for states in (before, after):
            h = states[oid].holder
            if h is not None and h not in found:
                found.add(h)
                todo.append(h)
    return tuple(sorted(found))


@dataclass(frozen=True)
class MicroProblem:
    """A step's micro problem: its skill, objects (trace ids), per-step facts, init, goal and PDDL problem."""

    index: int
    skill: str
    objects: tuple[str, ...]
    statics: frozenset[Atom]
    init: tuple[Atom, ...]
    goal: tuple[Atom, ...]
    task: PlanningTask
    #: Facts of the portions a transport or transfer step moves, where they stand before it (`portions`): the replay
    #: adds them before the step's skills, as the portion is separated from what it was part of.
    split: frozenset[Atom] = frozenset()
    #: (phase fact before, after) of the objects a transport step restates without moving them (`_restated`):
    #: the step starts with them in their new phase, in its init and in the replay.
    restated: tuple[tuple[Atom, Atom], ...] = ()

    @cached_property
    def text(self) -> str:
        return render_problem(self.task)

    @property
    def actions(self) -> frozenset[str]:
        """The skills the micro task may use: the transport skills and the step's own."""
        return frozenset((*TRANSPORT, self.skill))


def _roles(trace: PhysicalTrace) -> tuple[set[str], set[str]]:
    """(containers, surfaces): every object something is ever in, or on, or whose node says it holds things."""
    containers, surfaces = set(), set()
    for states in trace.states():
        for s in states.values():
            if s.holder is not None:
                (containers if s.relation is Relation.IN else surfaces).add(s.holder)
            if s.node is not None and any(x.label in _RELATIONAL for x in s.node.states):
                containers.add(s.id)
    return containers, surfaces


def works_on(domain: SkillDomain, skill: str) -> bool:
    """Whether `skill` works on one placed object (`?h ?o`, or `?h ?t ?o` with a tool), not a transfer."""
    return _operands(domain, skill) in (("?o",), ("?t", "?o"))


def _bare_hand(domain: SkillDomain, skill: str) -> bool:
    """Whether `skill` works on one object with the bare hand (`?h ?o`: crack, squeeze), holding no tool."""
    return _operands(domain, skill) == ("?o",)


def _operands(domain: SkillDomain, skill: str) -> tuple[str, ...] | None:
    schema = domain.by_name.get(skill)
    return None if schema is None else tuple(v for v, _ in schema.params[1:])


def _is_tool(oid: str, b: ObjectState, a: ObjectState, touched: set[str], rigid: set[str], holders: set,
             free) -> bool:
    """A step object that stands free (on the workspace: the pepper in a bowl, the pan on the stove are no tools),
    holds nothing, stays where it is, and keeps its phase or becomes `dirty`."""
    return (oid in touched and oid not in rigid and oid not in holders and b.exists and a.exists
            and free(b) and free(a)
            and (phase_of(b.node) == phase_of(a.node) or USED in phase_of(a.node)))


def _named(unit) -> frozenset[str]:
    """The labels a unit names: its objects, the places its states name, their ingredients."""
    nodes = (*unit.inputs, *unit.outputs)
    return frozenset({n.label for n in nodes} | {s.related for n in nodes for s in n.states if s.related}
                     | {i for n in nodes for i in n.ingredients})


def stands_free(trace: PhysicalTrace, index: int):
    """Whether an object stands free for step `index`: on the workspace, or in or on a holder the step's unit does
    not name (a scene's counter or fridge: the whisk on the counter is a tool, the sugar in the fridge is taken out
    and poured by holding it, not by tipping the fridge). A unit with no nodes (a hand-built trace's) names no
    holder and tells nothing: there only the workspace is free. O(1) per call after O(unit) set-up."""
    named = _named(trace.steps[index].unit)
    if not named:
        return lambda s: s.holder is None
    labels = {o.id: o.label for o in trace.objects}
    return lambda s: s.holder is None or labels.get(s.holder) not in named


def set_aside(trace: PhysicalTrace, index: int) -> tuple[tuple[str, Relation | None, str], ...]:
    """The step's objects that would pass for tools but for where they lie: unchanged, staying in or on a holder
    the step's unit names (so `stands_free` says no), though their own node names no place (a scene's knife on a
    counter labelled `surface`, where the recipe's board stands `on [surface]`): (id, relation, holder) each, for
    a step that finds no tool to say why. O(objects of the step)."""
    before, after = trace.after(index - 1), trace.after(index)
    free = stands_free(trace, index)
    return tuple((oid, b.relation, b.holder) for oid in step_objects(trace, index)
                 if (b := before[oid]).holder is not None and not free(b) and b.node is not None
                 and not places(b.node) and (a := after[oid]).holder == b.holder and a.node == b.node)


def _restated(before: Mapping[str, ObjectState], after: Mapping[str, ObjectState],
              ids: Iterable[str]) -> dict[str, ObjectState]:
    """The objects of a transport step whose phase FOON restates though they stay where they are, in their state
    after it (`skillet (heated, on [stove])` -> `skillet (contains {butter}, on [stove])`): transport skills change
    only what they set down, so setting such an object down again would be a pick and a place that do nothing.
    Only when the step moves some other object (else setting the changed object down is the step); {} otherwise."""
    ids = tuple(ids)

    def stays(oid: str) -> bool:
        b, a = before[oid], after[oid]
        return b.exists and a.exists and (b.holder, b.relation) == (a.holder, a.relation)

    if all(stays(oid) or not before[oid].exists or not after[oid].exists for oid in ids):
        return {}
    return {oid: after[oid] for oid in ids if stays(oid) and phase_of(before[oid].node) != phase_of(after[oid].node)}


def portions(trace: PhysicalTrace, index: int, ids: Iterable[str]) -> dict[str, ObjectState]:
    """The portions step `index` makes (the relational encoding's `SPLITS`: some of the diced avocado on the
    board, ground beef out of its packet), as they stand before the step: where the object they are taken
    from is, in its state. A portion is an object of `ids` the step makes of a label that an object of
    `ids` already has, in a holder, and keeps after the step (first by id). O(|ids|^2)."""
    before, after = trace.after(index - 1), trace.after(index)
    ids = sorted(ids)
    sources = [x for x in ids if before[x].exists and after[x].exists and before[x].holder is not None]
    out = {}
    for oid in ids:
        if before[oid].exists or not after[oid].exists:
            continue
        src = next((x for x in sources if before[x].node.label == after[oid].node.label), None)
        if src is not None:
            out[oid] = replace(before[src], id=oid)
    return out


def micro_problem(trace: PhysicalTrace, index: int, skill: str, naming: Naming, domain: SkillDomain,
                  roles: tuple[set[str], set[str]] | None = None) -> MicroProblem:
    """The micro problem of step `index` carried out by `skill` (see the module doc). O(objects of the step)."""
    before, after = trace.after(index - 1), trace.after(index)
    ids = step_objects(trace, index)
    carries = works_on(domain, skill)  # a tool or hand skill: what stands free and moves, the robot carries
    split = {} if carries else portions(trace, index, ids)  # picked up, or poured, from where their source is
    before = {**before, **split}
    restated = _restated(before, after, ids) if skill in TRANSPORT else {}
    found_before, before = before, {**before, **restated}  # no transport skill changes what it does not set down
    containers, surfaces = roles if roles is not None else _roles(trace)
    n = naming.ids
    ws = naming.workspace
    tag = domain.constant(skill)
    statics: set[Atom] = {Atom("surface", (ws,))}
    rigid: set[str] = set()

    free = stands_free(trace, index)

    def where(s: ObjectState) -> str:
        return ws if s.holder is None else n[s.holder]

    def rel(s: ObjectState) -> str:
        return "on" if s.relation in (None, Relation.ON) else "in"

    touched = set(trace.steps[index].objects) | {c.id for c in trace.steps[index].changes}
    sites: dict[int, list[str]] = {0: [], 1: [], 2: [], 3: []}  # changed, moved-to, made-in, used-up-in
    handled: list[str] = []  # used-up objects that stood free: the robot's hand reaches them (the egg it cracks)
    for oid in ids:
        b, a = before[oid], after[oid]
        if not b.exists and a.exists:
            statics.add(Atom(f"makes-{rel(a)}", (tag, n[oid], where(a), naming.phase(a.node))))
            sites[2].append(where(a))
        elif b.exists and not a.exists:
            statics.add(Atom("uses-up", (tag, n[oid])))
            sites[3].append(where(b))
            if free(b):
                handled.append(n[oid])
        elif b.exists:
            if (b.holder, b.relation) != (a.holder, a.relation) and skill not in TRANSPORT and not (
                    carries and free(b)):
                statics.add(Atom(f"moves-{rel(a)}", (tag, n[oid], where(a))))
                sites[1].append(where(a))
                if not free(b):
                    rigid.add(oid)
            if phase_of(b.node) != phase_of(a.node):
                how = tag
                if skill in TRANSPORT and "put-in" in domain.by_name and "place" in domain.by_name:
                    how = domain.constant("put-in" if a.relation is Relation.IN else "place")  # what sets it down
                statics.add(Atom("changes", (how, n[oid], naming.phase(b.node), naming.phase(a.node))))
                sites[0].append(n[oid])
    holders = {s.holder for states in (before, after) for s in (states[i] for i in ids) if s.holder is not None}
    tools = {oid for oid in ids if _is_tool(oid, found_before[oid], after[oid], touched, rigid, holders, free)}
    worked = [x for x in sites[0] if naming.back.get(x) not in tools]
    if carries and not worked:  # nothing changes phase: the object the hand handles, not where products appear
        worked = handled + ([n[t] for t in sorted(tools)] if _bare_hand(domain, skill) else [])
    if worked and carries:
        targets = list(dict.fromkeys(worked))  # squeeze the lime, not the juicer its juice appears in
    else:
        targets = list(dict.fromkeys(x for _, found in sorted(sites.items()) for x in found))
    if len(targets) > 1 and ws in targets:
        targets.remove(ws)
    statics |= {Atom("target", (tag, x)) for x in targets}
    for oid in ids:
        if oid not in rigid:
            statics.add(Atom("graspable", (n[oid],)))
        if oid in containers:
            statics.add(Atom("container", (n[oid],)))
        if oid in surfaces:
            statics.add(Atom("surface", (n[oid],)))
        if oid in tools:
            statics.add(Atom("tool", (n[oid],)))
    hands = {Atom("hand-empty", (h,)) for h in naming.hands}
    init = tuple(sorted(dynamic_facts(naming, before, ids) | hands | statics | {Atom("placed", (ws,))}))
    goal = tuple(sorted(dynamic_facts(naming, after, ids) | hands | {Atom("placed", (ws,))}))
    phases = sorted({a.args[-1] for a in (*init, *goal) if a.predicate == "state"}
                    | {a.args[-1] for a in statics if a.predicate.startswith("makes-")}
                    | {x for a in statics if a.predicate == "changes" for x in a.args[2:]})
    objects = ((*((h, "hand") for h in naming.hands), (ws, "thing"), *((n[i], "thing") for i in ids),
                *((p, "phase") for p in phases)))
    task = PlanningTask(domain.name, f"step-{index + 1}", "skills", 3, (), (), init, goal, objects=objects,
                        metric=True, comments=(f"step {index + 1}: {trace.steps[index].unit.describe()}",
                                                   f"skill {skill}"))
    return MicroProblem(index, skill, ids, frozenset(statics), init, goal, task,
                        frozenset(dynamic_facts(naming, split, split)),
                        tuple((Atom("state", (n[oid], naming.phase(found_before[oid].node))),
                               Atom("state", (n[oid], naming.phase(s.node)))) for oid, s in sorted(restated.items())))
