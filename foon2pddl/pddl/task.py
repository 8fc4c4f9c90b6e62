"""Planning-task intermediate representation: knows PDDL's structure, not its syntax.

Encodings build a `PlanningTask`; `render` turns it into PDDL text through jinja2
templates; planners and the decoder map action names back to functional units
through `Action.unit`. All names here are already sanitized PDDL identifiers
(see `names.py`); the original labels live in `PlanningTask.labels`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

from ..model.foon import ObjectNode
from ..model.pairing import Role
from ..model.physical import Relation


@dataclass(frozen=True, order=True)
class Atom:
    """A predicate applied to object names or `?variables`."""

    predicate: str
    args: tuple[str, ...] = ()


@dataclass(frozen=True)
class Predicate:
    """A predicate declaration: name and parameter types (`object` when untyped)."""

    name: str
    params: tuple[tuple[str, str], ...] = ()  # (?var, type)
    comment: str = ""


@dataclass(frozen=True)
class Conditional:
    """A conditional effect `(when (and when...) (and add... (not delete)...))`, quantified over `var` of `type`
    when `var` is set: `(forall (?v - type) (when ...))`, and over the further (variable, type) pairs `more`
    (`(forall (?v - type ?w - type2) ...)`: what is on what is on a consumed object). Conditions are read in the
    state before the action."""

    when: tuple[Atom, ...]
    add: tuple[Atom, ...] = ()
    delete: tuple[Atom, ...] = ()
    var: str | None = None
    type: str | None = None
    more: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        if (self.var is None) != (self.type is None) or (self.more and self.var is None):
            raise ValueError("a quantified conditional effect needs both a variable and its type")

    @property
    def quantified(self) -> tuple[tuple[str, str], ...]:
        """Every (variable, type) the effect is quantified over, `var` first."""
        return ((self.var, self.type), *self.more) if self.var is not None else ()

    def atoms(self) -> tuple[Atom, ...]:
        return (*self.when, *self.add, *self.delete)


@dataclass(frozen=True)
class Action:
    """A (possibly parameterised) action; `unit` indexes `PlanningTask.units` (None for auxiliary actions)."""

    name: str
    pre: tuple[Atom, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...] = ()
    params: tuple[tuple[str, str], ...] = ()  # (?var, type)
    cost: int | None = None
    unit: int | None = None
    comment: tuple[str, ...] = ()
    #: encodings over physical objects: per object of the unit, its `pairing.Role` and whether a parameter binds it
    roles: tuple[tuple[Role, bool], ...] = ()
    #: conditional effects, each possibly quantified (`Conditional`): an object leaves whatever holds it
    #: without a parameter per possible holder, the contents of a container go with it (`relational`)
    conditional: tuple[Conditional, ...] = ()
    #: an auxiliary goal action (`reach-goal-<i>`): the goal candidate whose atoms are its precondition
    candidate: ObjectNode | None = None


@dataclass(frozen=True)
class Instance:
    """A physical object of a task: PDDL name, FOON label, the node it starts in (None: not yet made), and
    what it starts in or on (`holder`, another instance's name, with its `relation`; None: it stands free
    or the encoding does not model holders), and its scene id."""

    name: str
    label: str
    start: ObjectNode | None = None
    holder: str | None = None
    relation: Relation | None = None
    #: the object's id in a scene kitchen (`model.scene`), which plans' text and JSON show for `name`
    scene_id: str | None = None


@dataclass(frozen=True)
class PlanningTask:
    """A domain and a problem, ready to render."""

    domain: str
    problem: str
    encoding: str
    level: int
    predicates: tuple[Predicate, ...]
    actions: tuple[Action, ...]
    init: tuple[Atom, ...]
    goal: tuple[Atom, ...]
    types: tuple[tuple[str, str], ...] = ()  # (type, parent type)
    objects: tuple[tuple[str, str], ...] = ()  # (name, type) declared in the problem
    constants: tuple[tuple[str, str], ...] = ()  # (name, type) declared in the domain (actions name them)
    units: tuple = ()  # FunctionalUnit per Action.unit index
    labels: dict[str, str] = field(default_factory=dict, compare=False)  # PDDL name -> original label
    comments: tuple[str, ...] = ()  # header lines for both files
    instances: tuple[Instance, ...] = ()  # encodings over physical objects: every object and where it starts
    #: encodings over physical objects: state constant -> the FOON node it stands for (`(is ?x <constant>)`)
    nodes: tuple[tuple[str, ObjectNode], ...] = ()
    #: encodings that model holders: (container label, content label) pairs FOON's own words contradict each
    #: other about in this task (a product placed in a container whose node does not list it): not checked
    gaps: tuple[tuple[str, str], ...] = ()
    metric: bool = False  # minimize total-cost although no action here has a cost (the domain comes from a file)
    #: objects the problem leaves out (`untouched`: no action can touch them), and their initial facts; a plan's
    #: replay still holds them (`initial_facts`, `type_closure`)
    aside: tuple[tuple[str, str], ...] = ()
    aside_init: tuple[Atom, ...] = ()

    @property
    def initial_facts(self) -> tuple[Atom, ...]:
        """The state a plan's replay starts from: `init` and the facts of the objects set aside."""
        return self.init + self.aside_init

    @property
    def uses_costs(self) -> bool:
        return self.metric or any(a.cost is not None for a in self.actions)

    @property
    def uses_types(self) -> bool:
        """Whether any type other than `object` is declared or used."""
        if self.types:
            return True
        typed = [t for _, t in self.objects + self.constants]
        typed += [t for p in self.predicates for _, t in p.params]
        typed += [t for a in self.actions for _, t in (*a.params, *(q for c in a.conditional for q in c.quantified))]
        return any(t != "object" for t in typed)

    @property
    def requirements(self) -> tuple[str, ...]:
        """Exactly the PDDL requirements the task uses."""
        req = [":strips"]
        if self.uses_types:
            req.append(":typing")
        if any(a.conditional for a in self.actions):
            req.append(":conditional-effects")
        if self.uses_costs:
            req.append(":action-costs")
        return tuple(req)

    def action_for(self, name: str) -> Action | None:
        """The action called `name` (case-insensitive, as planners lower-case)."""
        return self._by_name.get(name.lower())

    @cached_property
    def _by_name(self) -> dict[str, Action]:
        return {a.name.lower(): a for a in self.actions}


def candidate_atoms(task: PlanningTask, nodes: tuple[ObjectNode, ...]) -> dict[ObjectNode, tuple[Atom, ...]]:
    """Goal candidate -> its goal atoms, for a task compiled with `nodes` as the candidates.

    Encodings add one auxiliary goal action per candidate (`Action.candidate` names it; its
    precondition is the candidate's atoms); with a single candidate the task's goal is its
    atoms. Raises ValueError when the goal actions are not exactly one per candidate.
    O(actions).
    """
    aux = [a for a in task.actions if a.candidate is not None]
    if len(nodes) == 1 and not aux:
        return {nodes[0]: task.goal}
    found = {a.candidate: a.pre for a in aux}
    if len(found) != len(aux) or set(found) != set(nodes):
        raise ValueError(f"{task.encoding} encoding: expected one goal action per candidate ({len(nodes)}), "
                         f"found {len(aux)} for {len(set(found) & set(nodes))} of them")
    return {node: found[node] for node in nodes}


def candidate_alternatives(task: PlanningTask, nodes: tuple[ObjectNode, ...]
                           ) -> dict[ObjectNode, tuple[tuple[Atom, ...], ...]]:
    """Goal candidate -> every way of having it: the preconditions of its goal actions, in task order.

    As `candidate_atoms`, for encodings that may give a candidate several goal actions (the lifted
    one: one per way its atom can be written, `pddl.lifted_atoms.representations`). Raises ValueError
    unless every candidate, and nothing else, has one or more. O(actions).
    """
    aux = [a for a in task.actions if a.candidate is not None]
    if len(nodes) == 1 and not aux:
        return {nodes[0]: (task.goal,)}
    found: dict[ObjectNode, list[tuple[Atom, ...]]] = {}
    for a in aux:
        found.setdefault(a.candidate, []).append(a.pre)
    if set(found) != set(nodes):
        raise ValueError(f"{task.encoding} encoding: expected goal actions for each of {len(nodes)} candidates, "
                         f"found them for {len(set(found) & set(nodes))} (and {len(set(found) - set(nodes))} others)")
    return {node: tuple(found[node]) for node in nodes}


def type_closure(task: PlanningTask) -> dict[str, frozenset[str]]:
    """Object or constant name -> every type it has (its declared type and the ancestors of it); objects set
    aside (`PlanningTask.aside`) too."""
    parent = dict(task.types)
    out = {}
    for name, t in (*task.objects, *task.aside, *task.constants):
        chain, at = {"object"}, t
        while at is not None and at not in chain:
            chain.add(at)
            at = parent.get(at)
        out[name] = frozenset(chain)
    return out


def goal_at_start(task: PlanningTask) -> bool:
    """Whether the task's goal holds in its initial state (its plan is empty)."""
    return set(task.goal) <= set(task.init)


def _bindings(pre: tuple[Atom, ...], facts: dict[str, list[Atom]], bind: dict[str, str]):
    """Every binding of the `?variables` of `pre` (extending `bind`) under which each atom is in `facts`."""
    if not pre:
        yield bind
        return
    first, rest = pre[0], pre[1:]
    for fact in facts.get(first.predicate, ()):
        if len(fact.args) != len(first.args):
            continue
        new = dict(bind)
        if all(new.setdefault(a, f) == f if a.startswith("?") else a == f
               for a, f in zip(first.args, fact.args, strict=True)):
            yield from _bindings(rest, facts, new)


def settle_goal(task: PlanningTask) -> PlanningTask:
    """`task` with its goal in its initial state when a goal action already applies there.

    An encoding whose goal is `(goal-reached)` reaches it by a goal action (`Action.candidate`,
    cost 0) from a candidate's atoms; when the kitchen already holds a candidate, that action
    applies in the initial state, so the goal holds there: adding its atoms to `init` changes no
    plan's validity, and planners and readers then see the empty plan every other encoding gives.
    A parameterised goal action needs a binding whose objects have the parameters' types (subtypes
    count). O(goal actions x init) for the one-atom preconditions the encodings write.
    """
    if goal_at_start(task):
        return task
    facts: dict[str, list[Atom]] = {}
    for fact in task.init:
        facts.setdefault(fact.predicate, []).append(fact)
    parent = dict(task.types)
    kind = dict(task.objects + task.constants)

    def fits(obj: str, typ: str) -> bool:
        t, seen = kind.get(obj, "object"), set()
        while t not in seen:
            if t == typ:
                return True
            seen.add(t)
            t = parent.get(t, "object")
        return typ == "object"

    for action in task.actions:
        if action.candidate is None or action.delete or not set(task.goal) <= set(action.add) | set(task.init):
            continue
        for bind in _bindings(action.pre, facts, {}):
            if all(v in bind and fits(bind[v], t) for v, t in action.params):
                held = set(task.init)
                return replace(task, init=(*task.init, *(g for g in task.goal if g not in held)))
    return task


def apply_action(state: set[Atom], action: Action, bind: dict[str, str],
                 types: dict[str, frozenset[str]]) -> set[Atom]:
    """The state after `action` under `bind` (its preconditions are not checked): conditional effects read the
    state before the action, then every delete, then every add (PDDL: an add wins over a delete of one atom).

    `types` (`type_closure`) says which objects a quantified effect ranges over. O(|effects| x |objects|).
    """
    def ground(atoms: tuple[Atom, ...], b: dict[str, str]) -> list[Atom]:
        return [Atom(a.predicate, tuple(b.get(x, x) for x in a.args)) for a in atoms]

    add, delete = ground(action.add, bind), ground(action.delete, bind)
    for c in action.conditional:
        scopes = [bind]
        for v, t in c.quantified:
            scopes = [{**b, v: o} for b in scopes for o, ts in types.items() if t in ts]
        for b in scopes:
            if all(a in state for a in ground(c.when, b)):
                add += ground(c.add, b)
                delete += ground(c.delete, b)
    return (state - set(delete)) | set(add)
