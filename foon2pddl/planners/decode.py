"""Plan -> task tree: map plan steps back to functional units and check the result.

Each step names an action and its arguments; the compiled task maps them back to
a functional unit (`registry.Compiled.unit_of`: `Action.unit`, grounded with the
arguments for lifted encodings; auxiliary actions such as an encoding's goal
actions are skipped). The tree's goal is the first goal candidate (at the task's
level) the units make.

Two checks always run: the plan against the task's own STRIPS semantics
(`simulate_plan`: preconditions hold, deletes then adds, goal at the end) and
the tree by FOON simulation from the kitchen, exactly like a native retrieval
(`tasktree.validate`). Encodings with FOON's semantics (`tree`, `foon-compat`,
`gen-lifted`, `instances`) must pass both; the `state` encoding combines facts of different
nodes, so its plans need only pass the first, and the FOON check is reported
as information. An encoding over physical objects (`instances`) keeps every step (a unit may fire
more than once, on other objects) and registers a replay hook (`registry.Encoding.replay`) giving the
plan as a `model.physical.PhysicalTrace`: a third check replays it on FOON's nodes
(`trace_check.check_states`). On request, and when the task is small, the plan
is also checked by unified-planning's sequential plan validator, independent
of our code (it imports UP, ~1.5 s, hence opt-in).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace

from ..model.containment import containment_of
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.goal import Goal
from ..model.levels import project_node
from ..model.physical import PhysicalTrace
from ..model.tasktree import TaskTree, Validation, justify, validate
from ..model.where import short_path, unit_where
from ..model.words import count, first_of
from ..pddl.compile import as_compiled
from ..pddl.registry import Compiled, PlanDecodeError
from ..pddl.task import Atom, PlanningTask, apply_action, type_closure
from .result import step_action
from .trace_check import check_states, emptied, emptied_notes

__all__ = ["Decoded", "PlanDecodeError", "check", "decode", "finished", "goal_node", "plan_tree", "plan_units",
           "run_plan", "simulate_plan", "to_tree", "up_validation", "used_steps"]

#: Largest task (actions) checked with UP's validator: its cost grows fast with size.
UP_VALIDATE_MAX_ACTIONS = 300


@dataclass(frozen=True)
class Decoded:
    """The task tree a plan stands for, with its checks.

    `validation`: FOON simulation of the tree; `plan_check`: the plan under the
    task's STRIPS semantics; `up_validation`: UP's verdict (None when not run);
    `foon_semantics`: whether the encoding promises FOON's semantics (then
    `validation` must pass too); `trace`: the plan object by object (None for
    encodings with no physical objects) and `trace_check` its replay; `steps`: the plan as reported,
    the planner's steps the tree does not use left out (`used_steps`, named in `notes`).
    """

    tree: TaskTree
    validation: Validation
    plan_check: Validation = Validation(True)
    up_validation: Validation | None = None
    foon_semantics: bool = True
    notes: tuple[str, ...] = ()
    trace: PhysicalTrace | None = None
    trace_check: Validation | None = None
    steps: tuple[str, ...] = ()  # the plan's steps the tree uses (`used_steps`), a valid plan of the task

    @property
    def ok(self) -> bool:
        return (self.plan_check.ok and (self.up_validation is None or self.up_validation.ok)
                and (self.trace_check is None or self.trace_check.ok)
                and (self.validation.ok or not self.foon_semantics))

    @property
    def problems(self) -> tuple[str, ...]:
        """What failed, the checks that decide `ok` first."""
        out = self.plan_check.problems + (self.up_validation.problems if self.up_validation is not None else ())
        out += self.trace_check.problems if self.trace_check is not None else ()
        return out + (self.validation.problems if self.foon_semantics else ())


def plan_units(task: PlanningTask | Compiled, steps: Sequence[str]) -> tuple[FunctionalUnit, ...]:
    """The functional units of a plan's steps, in order; PlanDecodeError for a step that maps to none."""
    compiled = as_compiled(task)
    units = []
    for n, step in enumerate(steps, start=1):
        name, *args = step.split()
        action = compiled.task.action_for(name)
        if action is None:
            raise PlanDecodeError(f"plan step {n} ({step}) names no action of the task")
        try:
            unit = compiled.unit_of(action, tuple(args))
        except PlanDecodeError as exc:
            raise PlanDecodeError(f"plan step {n} ({step}): {exc}") from None
        if unit is not None:
            units.append(unit)
    return tuple(units)


def delete_free(task: PlanningTask) -> bool:
    """No action deletes anything: applying a unit's action again changes nothing."""
    return not any(a.delete or a.conditional for a in task.actions)


def first_occurrences(units: Sequence[FunctionalUnit]) -> tuple[FunctionalUnit, ...]:
    """The units without repeats of one already applied (first occurrence kept, order kept)."""
    return tuple(dict.fromkeys(units))


def goal_node(goal: Goal, level: int, kitchen_nodes: Iterable[ObjectNode],
              units: Sequence[FunctionalUnit]) -> ObjectNode:
    """The first goal candidate (at `level`) that the kitchen plus the units' outputs hold, else the first candidate."""
    candidates = sorted({project_node(c, level) for c in goal.candidates})
    available = set(kitchen_nodes)
    for u in units:
        available.update(u.outputs)
    return next((c for c in candidates if c in available), candidates[0])


def goal_adders(task: PlanningTask, steps: Sequence[str]) -> frozenset[int]:
    """Positions (among the plan's unit steps) of the first unit step adding each goal atom that no
    auxiliary action adds (such as a must-use `(used-X)`): the tree keeps them."""
    aux = {a for x in task.actions if x.unit is None for a in x.add}
    wanted = set(task.goal) - aux
    found: set[int] = set()
    position = 0
    for step in steps:
        action = task.action_for(step_action(step))
        if action is None or action.unit is None:
            continue
        hit = wanted.intersection(action.add)
        if hit:
            found.add(position)
            wanted -= hit
        position += 1
    return frozenset(found)


def plan_tree(task: PlanningTask | Compiled, steps: Sequence[str], goal: Goal,
              kitchen_nodes: Iterable[ObjectNode]) -> TaskTree:
    """The task tree of the plan's own units (before `Compiled.finish`); PlanDecodeError for a step that maps
    to no unit.

    For encodings with FOON's semantics, steps the goal does not need are dropped
    (`tasktree.justify`); in delete-free tasks so are repeats of a unit already applied
    (`check` notes them); the raw plan is still checked step by step in `check`.
    """
    compiled = as_compiled(task)
    kitchen_nodes = frozenset(kitchen_nodes)
    units = plan_units(compiled, steps)
    if delete_free(compiled.task):
        units = first_occurrences(units)
    target = goal_node(goal, compiled.task.level, kitchen_nodes, units)
    if compiled.foon_semantics and not compiled.every_step:
        units = justify(units, kitchen_nodes, target, goal_adders(compiled.task, steps))
    return TaskTree(units, target, compiled.task.level)


def finished(compiled: Compiled, plain: TaskTree, steps: Sequence[str], kitchen_nodes: Iterable[ObjectNode]) -> TaskTree:
    """The tree to report for the plan tree `plain`: the encoding's `Compiled.finish` of it (the lifted encoding
    renames what a substituted object made), else `plain`."""
    return plain if compiled.finish is None else compiled.finish(plain, steps, frozenset(kitchen_nodes))


def to_tree(task: PlanningTask | Compiled, steps: Sequence[str], goal: Goal,
            kitchen_nodes: Iterable[ObjectNode]) -> TaskTree:
    """The task tree of a plan, as reported (`plan_tree`, then `finished`)."""
    compiled = as_compiled(task)
    return finished(compiled, plan_tree(compiled, steps, goal, kitchen_nodes), steps, kitchen_nodes)


def _step_units(compiled: Compiled, steps: Sequence[str]) -> list[FunctionalUnit | None]:
    """The unit of each plan step (None for auxiliary actions such as goal actions, and unknown actions)."""
    out = []
    for step in steps:
        name, *args = step.split()
        action = compiled.task.action_for(name)
        out.append(None if action is None else compiled.unit_of(action, tuple(args)))
    return out


def used_steps(compiled: Compiled, steps: Sequence[str], plain: TaskTree) -> tuple[str, ...]:
    """The plan's steps the tree `plain` (`plan_tree`) uses, in order: the first step of each of its units,
    and the auxiliary steps (goal actions) that still apply without the others.

    A satisficing planner may fire steps no goal needs (lama-first on a lifted FOON-GEN task fires a second
    juice chain); the plan reported, counted and written is the one the tree stands for. Checked by
    simulation (O(steps x effects)): when the kept steps are not a valid plan of the task (an encoding with
    deletes), or every step is a real firing (`every_step`), or the encoding lacks FOON's semantics, the
    plan as found.
    """
    if compiled.every_step or not compiled.foon_semantics:
        return tuple(steps)
    task, kept, seen = compiled.task, set(plain.units), set()
    state, types, out = set(task.initial_facts), type_closure(task), []
    for n, (step, unit) in enumerate(zip(steps, _step_units(compiled, steps), strict=True), start=1):
        if unit is not None and (unit not in kept or unit in seen):
            continue
        after, problem = apply_step(task, state, step, n, types)
        if problem is not None:
            if unit is None:
                continue  # a goal action for a node only left-out steps made
            return tuple(steps)
        seen.add(unit)
        state = after
        out.append(step)
    return tuple(out) if set(task.goal) <= state else tuple(steps)


def unneeded_steps_note(compiled: Compiled, steps: Sequence[str], tree: TaskTree, shown: int = 8) -> tuple[str, ...]:
    """A note naming the plan steps whose unit the task tree (`plan_tree`) left out because the goal does not
    need them (`tasktree.justify`; a satisficing plan may hold detours), numbered as in the plan; () when none."""
    kept = set(tree.units)
    seen: set = set()
    out = []
    for n, unit in enumerate(_step_units(compiled, steps), start=1):
        if unit is None or unit in seen:
            continue  # bookkeeping actions (goal reached) and repeats are not units of the plan's own
        seen.add(unit)
        if unit not in kept:  # where it was read: a left-out unit may look like a kept one renamed (gen-lifted)
            src = f" at {unit_where(unit, short_path)}" if unit.source else ""
            out.append(f"{n} ({unit.motion.label}{src}: {', '.join(o.describe() for o in unit.outputs[:2])})")
    if not out:
        return ()
    return (f"the planner's plan has {count(len(steps), 'step')}; {len(out)} the goal does not need {'is' if len(out) == 1 else 'are'} left out: "
            + first_of(out, shown),)


def renamed_note(plain: TaskTree, tree: TaskTree) -> tuple[str, ...]:
    """A note naming the objects `Compiled.finish` renamed between the plan's tree `plain` and the tree reported
    (the plan's steps keep the task's names: a lifted plan's `lemon_juice` squeezed from a lime is the tree's
    `lime juice`); () when none. Node by node: a renamed object is made by a unit, so some node has its label."""
    pairs = {(a.label, b.label) for u, v in zip(plain.units, tree.units, strict=True)
             for a, b in zip((*u.inputs, *u.outputs), (*v.inputs, *v.outputs), strict=True) if a.label != b.label}
    if not pairs:
        return ()
    return ("the plan's steps keep the recipe's name for what a kitchen object standing in made; the task tree "
            "renames it: " + ", ".join(f"{a} -> {b}" for a, b in sorted(pairs)),)


def check(tree: TaskTree, kitchen_nodes: frozenset[ObjectNode], task: PlanningTask | Compiled,
          steps: Sequence[str], *, up_validate: bool = False,
          candidates: Iterable[ObjectNode] | None = None, plain: TaskTree | None = None) -> Decoded:
    """Validate a decoded tree by simulation, and the plan with UP when asked and the task is small.

    `candidates`: the goal's nodes at the task's level (default: the tree's goal), for the instance check.
    `plain`: the plan's own tree before `Compiled.finish` (`plan_tree`; default: `tree`), which says the
    steps the tree uses.
    """
    compiled = as_compiled(task)
    plain = tree if plain is None else plain
    up = None
    if up_validate and len(compiled.task.actions) <= UP_VALIDATE_MAX_ACTIONS:
        up = up_validation(compiled.task, steps)
    notes: tuple[str, ...] = ()
    if delete_free(compiled.task):
        units = plan_units(compiled, steps)
        repeats = len(units) - len(first_occurrences(units))
        if repeats:
            notes = (f"dropped {count(repeats, 'plan step')} repeating a unit already applied "
                     "(no effect in this delete-free encoding)",)
    if compiled.foon_semantics and not compiled.every_step:
        notes += unneeded_steps_note(compiled, steps, plain) + renamed_note(plain, tree)
    # a task compiled under --containment infer holds inference units: validate under the same rule. The tree is
    # checked from the kitchen as given, not as an encoding completes it: an object the completion starts in a
    # state some unit makes (`macaroni (cooked, in [pot])`) must not let a plan skip the cooking; only what the
    # kitchen's own nodes say is where they say (`Compiled.placed`) is added; with holders, each step's emptied
    # holders too (`trace_check.emptied`: the stove a pan is taken off, which FOON's unit does not list)
    trace, broken = None, None
    if compiled.replay is not None:
        try:
            trace = compiled.replay(compiled.task, steps)
        except PlanDecodeError as exc:
            broken = Validation(False, (str(exc),))
    beside = emptied(trace) if trace is not None and compiled.holders else ()
    beside = beside if len(beside) == len(tree.units) else ()
    notes += emptied_notes(trace, kitchen_nodes | compiled.placed, beside) if beside else ()
    decoded = Decoded(tree, validate(tree, kitchen_nodes | compiled.placed, containment_of(compiled.task.units),
                                     beside), simulate_plan(compiled.task, steps), up, compiled.foon_semantics,
                      compiled.notes + notes, steps=used_steps(compiled, steps, plain))
    if compiled.replay is None:  # an encoding with no physical objects
        return decoded
    if trace is None:
        return replace(decoded, trace_check=broken)
    wanted = tuple(candidates) if candidates is not None else (tree.goal,)
    if not compiled.holders:  # no holders modelled: say what the physical replay finds with inferred ones
        from .instance_physical import replay_note

        decoded = replace(decoded, notes=decoded.notes + replay_note(compiled.task, trace))
    return replace(decoded, trace=trace, trace_check=check_trace(trace, wanted, compiled.holders))


def check_trace(trace: PhysicalTrace, candidates: Iterable[ObjectNode], holders: bool) -> Validation:
    """A plan's trace replayed on FOON's nodes; with `holders`, also on its holders (`physical_replay`)."""
    found = check_states(trace, candidates)
    if not holders or not found.ok:
        return found
    from .physical_replay import replay

    report = replay(trace)
    return found if report.ok else Validation(False, tuple(d.describe() for d in report.disagreements))


def decode(task: PlanningTask | Compiled, steps: Sequence[str], goal: Goal, kitchen_nodes: frozenset[ObjectNode], *,
           up_validate: bool = False) -> Decoded:
    """The plan's task tree (kitchen nodes at the task's level) with its checks (see the module doc)."""
    compiled = as_compiled(task)
    plain = plan_tree(compiled, steps, goal, kitchen_nodes)
    return check(finished(compiled, plain, steps, kitchen_nodes), kitchen_nodes, compiled, steps,
                 up_validate=up_validate,
                 candidates=sorted({project_node(c, compiled.task.level) for c in goal.candidates}), plain=plain)


def run_plan(task: PlanningTask, steps: Sequence[str]) -> tuple[set[Atom], str | None]:
    """Apply the plan to the task's initial state: (final state, or the state before the first failing step; problem)."""
    state, types = set(task.initial_facts), type_closure(task)
    for n, step in enumerate(steps, start=1):
        after, problem = apply_step(task, state, step, n, types)
        if problem is not None:
            return state, problem
        state = after
    return state, None


def apply_step(task: PlanningTask, state: set[Atom], step: str, n: int,
               types: dict[str, frozenset[str]]) -> tuple[set[Atom], str | None]:
    """The state after plan step number `n`, or (`state`, why it does not apply)."""
    action = task.action_for(step_action(step))
    if action is None:
        return state, f"plan step {n} ({step}) names no action of the task"
    args = step.split()[1:]
    if len(args) != len(action.params):
        return state, f"plan step {n} ({step}): {len(action.params)} arguments expected"
    bind = {var: arg for (var, _), arg in zip(action.params, args, strict=True)}
    missing = [a for a in (Atom(p.predicate, tuple(bind.get(x, x) for x in p.args)) for p in action.pre)
               if a not in state]
    if missing:
        return state, f"plan step {n} ({step}): precondition false: " + first_of(missing, 3, _show, sep=", ")
    return apply_action(state, action, bind, types), None


def simulate_plan(task: PlanningTask, steps: Sequence[str]) -> Validation:
    """The plan under the task's STRIPS semantics: preconditions hold, deletes then adds, the goal at the end."""
    state, problem = run_plan(task, steps)
    if problem is not None:
        return Validation(False, (problem,))
    unmet = [a for a in task.goal if a not in state]
    if unmet:
        return Validation(False, ("goal false after the plan: " + _show(unmet[0]),))
    return Validation(True)


def _show(atom: Atom) -> str:
    return f"({' '.join((atom.predicate, *atom.args))})"


def up_validation(task: PlanningTask, steps: Sequence[str]) -> Validation:
    """The plan checked by UP's SequentialPlanValidator on the task as a UP problem (`up_problem.build_up`)."""
    from unified_planning.plans import ActionInstance, SequentialPlan
    from unified_planning.shortcuts import PlanValidator

    from ..pddl.up_problem import build_up

    up = build_up(task)
    actions = {name.lower(): a for name, a in up.actions.items()}
    objects = {name.lower(): o for name, o in up.objects.items()}
    try:
        plan = SequentialPlan([
            ActionInstance(actions[step_action(s)], [objects[a] for a in s.split()[1:]]) for s in steps
        ])
    except KeyError as exc:
        return Validation(False, (f"UP validator: unknown name {exc.args[0]!r} in plan",))
    with PlanValidator(name="sequential_plan_validator") as validator:
        res = validator.validate(up.problem, plan)
    if res.status.name == "VALID":
        return Validation(True)
    detail = res.reason.name.lower().replace("_", " ") if res.reason is not None else res.status.name.lower()
    if res.inapplicable_action is not None:
        detail += f": {res.inapplicable_action}"
    return Validation(False, (f"UP validator: {detail}",))
