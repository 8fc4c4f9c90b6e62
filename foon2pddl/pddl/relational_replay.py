"""Plans of the `relational` encoding as physical traces, with real holders: its replay and view hooks.

`relational_trace` applies each plan step to the task's facts (ground
preconditions are not checked here: `planners.decode.simulate_plan` does that)
and reads the trace off the facts alone: an object's node is the FOON node of its
`(is ?x ?s)` fact (`task.nodes`; `not-yet-made`: not made, `consumed`: consumed),
its holder the object of its `(in ?h ?x)` or `(on ?h ?x)` fact. Nothing the
encoding decides is redone here, so the trace is exactly what the PDDL says, and
the independent replay (`planners.physical_replay`) judges the encoding itself.
Per unit step, each role is bound to the parameter the action gives it, or (a
role checked by `(occupied s)`) to the object in the role's node that holds, or
is held by, a bound object where the unit says so, else one holding a bound object the unit takes out of a holder
of that label it does not name (the two bowls of salt and pepper a level-2 sprinkle reads, the salt in one of
them), else the first such object by name; the binding says what the unit requires of it (`Action.roles`: its node
before, and the node it must end in). Every other object the step changes or
names (a portion poured off, a holder the unit does not name, contents that
followed their container) is bound with its node before and after the step. An
object with two holders is a PlanDecodeError (the encoding promises at most one). A scene's
objects are named by their scene ids (`Instance.scene_id`), not their PDDL names.
O(steps x (facts + objects)).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from ..io.recipe_words import soiled
from ..model.aliases import unit_aliases
from ..model.foon import ObjectNode
from ..model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, Relation, TraceStep, renamed
from ..model.places import places
from .encode_instances import NOT_MADE
from .holder_words import task_aliases
from .holders import relational_roles
from .instance_replay import source_of
from .registry import PlanDecodeError
from .relational_sweep import CONSUMED
from .tallies import COUNT_TYPE
from .task import Atom, PlanningTask, apply_action, type_closure
from .trace_view import TraceView, changed, show_node

__all__ = ["RELATIONAL_VIEW", "relational_json", "relational_text", "relational_trace", "step_words"]

_RELATIONS = {r.value for r in Relation}


def _holders(facts: set[Atom]) -> dict[str, tuple[str, Relation]]:
    out: dict[str, tuple[str, Relation]] = {}
    for a in sorted(facts):
        if a.predicate in _RELATIONS and len(a.args) == 2:
            h, x = a.args
            if x in out:
                raise PlanDecodeError(f"{x} is {out[x][1]} {out[x][0]} and {a.predicate} {h} at once")
            out[x] = (h, Relation(a.predicate))
    return out


def _states(task: PlanningTask, facts: set[Atom], last: dict[str, ObjectNode | None]) -> dict[str, ObjectState]:
    """Every object's state in `facts`; a consumed object keeps the node it had (`last`)."""
    nodes = dict(task.nodes)
    holder = _holders(facts)
    node: dict[str, ObjectNode | None] = {x.name: None for x in task.instances}
    consumed: set[str] = set()
    for a in sorted(facts):
        if a.predicate == "is" and len(a.args) == 2 and a.args[0] in node:
            if a.args[1] == CONSUMED:
                consumed.add(a.args[0])
            elif a.args[1] != NOT_MADE:
                if node[a.args[0]] is not None:  # an encoding whose effects set two states: say so, never pick one
                    raise PlanDecodeError(f"{a.args[0]} is {node[a.args[0]].describe()!r} and "
                                          f"{nodes[a.args[1]].describe()!r} at once")
                node[a.args[0]] = nodes[a.args[1]]
    return {x: ObjectState(x, last.get(x) if x in consumed else node[x], *holder.get(x, (None, None)),
                           x in consumed) for x in node}


def relational_trace(task: PlanningTask, steps: Sequence[str]) -> PhysicalTrace:
    """The plan as a trace with holders (see the module doc)."""
    facts = set(task.initial_facts)
    types = type_closure(task)
    label = {x.name: x.label for x in task.instances}
    counts = {name for name, t in task.constants if t == COUNT_TYPE}  # a tally's (`pddl.tallies`): no object
    now = _states(task, facts, {})
    units = [task.units[a.unit] for a in task.actions if a.unit is not None]
    out = []
    for n, step in enumerate(steps, start=1):
        name, *args = step.split()
        action = task.action_for(name)
        if action is None:
            raise PlanDecodeError(f"plan step {n} ({step}) names no action of the task")
        if len(args) != len(action.params):
            raise PlanDecodeError(f"plan step {n} ({step}): {len(action.params)} arguments expected, got {len(args)}")
        unknown = [a for a in args if a not in label and a not in counts]
        if unknown:
            raise PlanDecodeError(f"plan step {n} ({step}): {unknown[0]} is not an object of the task")
        bind = {v: a for (v, _), a in zip(action.params, args, strict=True)}
        facts = apply_action(facts, action, bind, types)
        was, now = now, _states(task, facts, {x: s.node for x, s in now.items()})
        if action.unit is None:
            continue
        unit = task.units[action.unit]
        names = _role_objects(unit, action, args, was, now, label, step, n)
        bindings = [Binding(x, role.before, role.after) for (role, _), x in zip(action.roles, names, strict=True)]
        named = set(names)
        moved = sorted(x for x in now if now[x] != was[x])
        ends = [h for x in moved for h in (was[x].holder, now[x].holder) if h is not None and was[x].holder != now[x].holder]
        for x in (*(a for a in args if a in label), *moved, *sorted(set(ends))):
            if x not in named:
                named.add(x)
                after = now[x].node if now[x].node != was[x].node and not now[x].consumed else None
                bindings.append(Binding(x, was[x].node if was[x].exists else None, after, role=x in args))
        changes = tuple(now[x] for x in sorted(now) if now[x] != was[x])
        out.append(TraceStep(len(out), unit, tuple(bindings), changes, source_of(unit), unit_aliases(unit)))
    start = _states(task, set(task.initial_facts), {})
    aliases = task_aliases(units, label.values(), [x.start for x in task.instances])
    trace = PhysicalTrace(tuple(PhysicalObject(x.name, x.label) for x in task.instances),
                          tuple(start[x.name] for x in task.instances), tuple(out), aliases, task.gaps)
    shown = {x.name: x.scene_id for x in task.instances if x.scene_id not in (None, x.name)}
    return renamed(trace, shown) if shown else trace  # a scene's objects by their ids


def _role_objects(unit, action, args, was, now, label, step, n) -> list[str]:
    """The object bound to each role: its parameter, or for a role checked by `(occupied s)` an object in its
    node, chosen so that holders agree with the unit: the holder of a named object the unit places in that role,
    or an object held by a named role the unit places it in, else one holding a named object the unit takes out of
    a holder of that label it does not name (else the first such by name). Roles linked to a
    named one are chosen first, then the rest in role order. O(roles^2 x objects)."""
    given = iter(args)
    names: list[str | None] = [next(given) if bound else None for _, bound in action.roles]
    rels = relational_roles(unit)
    roles = [role for role, _ in action.roles]

    def fits(k: int) -> list[str]:
        return [x for x in sorted(was) if label[x] == roles[k].label and was[x].node == roles[k].before
                and was[x].exists and x not in names]

    def linked(k: int, pool: list[str]) -> list[str]:
        out = []
        for j, r in enumerate(rels):
            if names[j] is None or j == k:
                continue
            for place, states in ((r.source, was), (r.target, now)):
                if place is not None and place.role == k and states[names[j]].holder in pool:
                    out.append(states[names[j]].holder)
            place = rels[k].source
            if place is not None and place.role == j:
                out += [x for x in pool if was[x].holder == names[j]]
        return out

    while None in names:
        todo = [k for k, x in enumerate(names) if x is None]
        picked = False
        for k in todo:
            found = linked(k, fits(k))
            if found:
                names[k], picked = found[0], True
        if picked:
            continue
        k = todo[0]
        pool = fits(k)
        # an unnamed holder and what it holds: a pair that agrees, if the state has one
        inner = [j for j in todo if j != k and rels[j].source is not None and rels[j].source.role == k]
        pairs = [h for h in pool if any(was[x].holder == h for j in inner for x in fits(j))]
        # else one holding a named object the unit takes from a holder of that label it does not name
        held = [h for h in pool if any(names[j] is not None and was[names[j]].holder == h for j, r in enumerate(rels)
                                       if r.source is not None and r.source.role is None and r.source.holder == roles[k].label)]
        pick = (pairs or held or pool or [None])[0]
        if pick is None:
            raise PlanDecodeError(f"plan step {n} ({step}): no {roles[k].label} is {show_node(roles[k].before)}")
        names[k] = pick
    return names


def _portions(step: TraceStep, before: dict[str, ObjectState], after: dict[str, ObjectState],
              made: list[str]) -> list[tuple[str, str]]:
    """(portion, source) for each object a step makes of a label that a bound, surviving object already has:
    a part poured or scooped out of what stays behind (a carton keeps its cream)."""
    def label(s: ObjectState) -> str | None:
        return s.node.label if s.node is not None else None

    sources = [b.object for b in step.bindings if b.before is not None and not after[b.object].consumed]
    out = []
    for m in made:
        src = next((x for x in sources if label(before[x]) == label(after[m]) and before[x].holder), None)
        if src is not None:
            out.append((m, src))
    return out


def _into(at: ObjectState) -> str:
    """` into H` (in) or ` onto H` (on) for the holder `at` puts an object in; empty for none."""
    return f" {'into' if at.relation is Relation.IN else 'onto'} {at.holder}" if at.holder else ""


def _at(relation: Relation | None, holder: str) -> str:
    """` on H` (on) or ` in H` (any other relation): where an object stays, said as a place."""
    return f" {'on' if relation is Relation.ON else 'in'} {holder}"


def _outward(x: str, fixed: set[str], before: dict[str, ObjectState],
             after: dict[str, ObjectState]) -> tuple[tuple[Relation | None, str], ...]:
    """(relation, holder) from `x`'s holder outward, while the holder is in `fixed` and each link stays put:
    `in bowl_1`, then `in microwave_1` when the step names the microwave. O(depth); a cycle stops it."""
    out: list[tuple[Relation | None, str]] = []
    seen = {x}
    while (was := before.get(x)) is not None and was.holder in fixed and was.holder not in seen \
            and after[x].holder == was.holder:
        out.append((was.relation, was.holder))
        seen.add(x := was.holder)
    return tuple(out)


@dataclass(frozen=True)
class _Moves:
    """Where a step moves things (`_moved`): each move said (`x from h into g`), where each goes, the holders the
    moves name, the objects first taken out of a holder the unit does not list, the holders lifted off their place
    (something leaves them by the step), and what the step makes that is no portion."""

    said: tuple[str, ...]
    dests: tuple[str | None, ...]
    holders: frozenset[str]
    taken: tuple[tuple[str, str], ...]
    lifted: tuple[tuple[str, str], ...]
    made: tuple[str, ...]


def _moved(step: TraceStep, before: dict[str, ObjectState], after: dict[str, ObjectState]) -> _Moves:
    """The first rule of where a thing is said: what changes holder, from where, into what. A portion made of a
    surviving object (`m (a portion of s) from h into g`), each bound object whose holder changes, a holder the
    unit does not list left first (`take x out of fridge_1`), and a holder something leaves (poured out, or used
    up in it) that itself leaves its place for none, lifted (`take squeezer_1 off surface_1`). O(bindings)."""
    made = [b.object for b in step.bindings if b.before is None]
    moves, dests, holders, taken = [], [], set(), []
    listed = {b.object for b in step.bindings if b.role}  # the objects the unit names
    for m, src in _portions(step, before, after, made):
        moves.append(f"{m} (a portion of {src})" + (f" from {before[src].holder}" if before[src].holder else "")
                     + _into(after[m]))
        dests.append(after[m].holder)
        holders.update({src, m} | {h for h in (before[src].holder, after[m].holder) if h})
        made.remove(m)
    poured_from = {before[b.object].holder for b in step.bindings  # what something leaves by this step
                   if b.before is not None and before[b.object].holder != after[b.object].holder}
    lifted = []
    for b in step.bindings:
        x, was, now = b.object, before[b.object], after[b.object]
        if b.before is not None and was.holder != now.holder and not now.consumed:
            if was.holder and now.holder is None and x in poured_from:  # lifted to work from, not itself poured
                lifted.append((x, f"take {x} {'out of' if was.relation is Relation.IN else 'off'} {was.holder}"))
                holders.add(was.holder)
                continue
            into = _into(now)
            if was.holder and was.holder not in listed and not places(b.before):
                taken.append((x, f"take {x} {'out of' if was.relation is Relation.IN else 'off'} {was.holder}"))
                moves.append(x + into)
            else:
                moves.append(f"{x}" + (f" from {was.holder}" if was.holder else "") + into)
            dests.append(now.holder)
            holders.update(h for h in (was.holder, now.holder) if h)
    return _Moves(tuple(moves), tuple(dests), frozenset(holders), tuple(taken), tuple(lifted), tuple(made))


def _seated(moves: list[str], dests: Sequence[str | None], worked: set[str], before: dict[str, ObjectState],
            after: dict[str, ObjectState]) -> set[str]:
    """The second rule: a changed object (in `worked`) that holds where a move goes is that move's place
    (`onto pancake_1 on plate_1`): said after the last move into each destination (`moves` is extended in
    place), and returned, so that it is not said again as changed. O(moves)."""
    stands = set()
    for d, i in {d: i for i, d in enumerate(dests) if d}.items():  # the last move into each destination
        was_at, now_at = before.get(d), after.get(d)
        if now_at is not None and was_at is not None and now_at.holder in worked and was_at.holder == now_at.holder:
            moves[i] += _at(now_at.relation, now_at.holder)
            stands.add(now_at.holder)
    return stands


def _stays(worked: list[str], fixed: set[str], where: list[str], before: dict[str, ObjectState],
           after: dict[str, ObjectState]) -> tuple[dict[tuple[tuple[Relation | None, str], ...], list[str]],
                                                   dict[str, tuple[tuple[Relation | None, str], ...]], set[str]]:
    """The third rule: where a worked object, and the holder of what the step makes (`where`), stay, outward while
    the step names the holders (`fixed`; `_outward`): the worked objects grouped by that chain (`cut avocado_1 on
    cutting_board_1`), the chain of each holder in `where`, and the holders some chain says (a worked object
    holding another's place is said as that place, not as changed). O(objects x depth)."""
    chains = {x: _outward(x, fixed, before, after) for x in worked}
    rooms = {w: _outward(w, fixed, before, after) for w in where}
    at = {h for chain in (*chains.values(), *rooms.values()) for _, h in chain}
    groups: dict[tuple[tuple[Relation | None, str], ...], list[str]] = {}
    for x in worked:  # a worked object holding another's place is said as that place (the microwave going off)
        if x not in at:
            groups.setdefault(chains[x], []).append(x)
    return groups, rooms, at


def step_words(step: TraceStep, before: dict[str, ObjectState], after: dict[str, ObjectState]) -> str:
    """A step in recipe words with the objects named, O(bindings x depth), depth how many holders `_outward` says outward.

    `pour sugar_1 from bag_1 into pitcher_1`; `mix in bowl_2: lettuce_1, tomato_1 -> salad_1 with spoon_1`:
    the motion, each object that changes holder (from, into), each other object whose state changes (after a
    move: `into bowl_4, changing greek_salad_1`; one that holds where a move goes is that place: `onto pancake_1 on
    plate_1`) and where it stays, outward while the step names the holders (`cut avocado_1 on cutting_board_1`;
    `heat butter_2 in bowl_1 in microwave_1`: a changed object holding another's place is said as that place), then
    what the step consumes and makes (in the holder of what it makes and where that stays: `bake in baking_tray_1 in
    oven_1: ...`; used up with nothing made: `, using up
    butter_1`), then the objects it only uses (not where a changed object stays, nor what already sits in a
    holder something moves into: the dressing the lettuce is poured onto is no tool). A step that only makes
    something (at level 1 no state changes) names its objects, then what it makes, as the recipe's words do:
    `squeeze lime_1, juicer_1, making lime_juice_1`, not lime juice squeezed with a lime.
    An object whose node names no place (`sugar (granulated)`: FOON's unit names no source) moved out of a
    holder the unit does not list (a scene's fridge or shelf: where it is kept, not what the unit pours from)
    is taken out first: `take sugar_1 out of fridge_1, pour it into pitcher_1`. A holder the unit lists, or any
    holder of an object whose node names a place (`sandwich (in [pan])` lifted from a skillet), stays the motion's
    `from`. A holder something leaves (poured out of it, used up in it) that itself leaves its place for none (FOON's
    output `squeezer (dirty)` no longer `on [surface]`) is lifted, not poured: `take squeezer_1 off surface_1, pour
    orange_juice_1 from squeezer_1 into drinking_glass_1`; `take pot_1 off stove_2, drain pot_1, using up water_1`.
    """
    moved = _moved(step, before, after)
    made, moves, taken, lifted = list(moved.made), list(moved.said), moved.taken, moved.lifted
    used = [b.object for b in step.bindings if after[b.object].consumed and not before[b.object].consumed]
    where = sorted({after[m].holder for m in made if after[m].holder})
    holders = moved.holders | set(where)
    rest = [b for b in step.bindings if b.object not in made and b.object not in used and b.object not in holders
            and before[b.object].holder == after[b.object].holder]
    work = [b for b in rest if changed(b)]  # a tool the step only soils is used, not worked (`io.recipe_words`)
    worked = [b for b in work if b.before is None or not soiled(b.before, b.after)]
    if not (worked or moves or made or used):
        worked = work
    stands = _seated(moves, moved.dests, {b.object for b in worked}, before, after)
    worked = [b for b in worked if b.object not in stands]
    into = {after[b.object].holder for b in step.bindings if b.before is not None and b.object not in made
            and before[b.object].holder != after[b.object].holder}
    others = [b.object for b in rest if b not in worked and not (  # not the contents of where something goes
        before[b.object].holder in into and any(s.label in _RELATIONS and s.related for s in b.before.states))]
    # where a worked object stays is a place, not a tool, and so is where that place stays when the step names it:
    # `cut avocado_1 on cutting_board_1 with knife_1`, `heat butter_2 in bowl_1 in microwave_1`
    groups, rooms, at = _stays([b.object for b in worked], set(others) | {b.object for b in worked}, where,
                               before, after)
    said = ", ".join(moves)
    if groups:  # after a move, what else it changes: `into bowl_4, changing greek_salad_1`
        names = ", ".join(", ".join(xs) + "".join(_at(rel, h) for rel, h in chain) for chain, xs in groups.items())
        said = f"{said}, changing {names}" if said else names
    others = [x for x in others if x not in at and x not in stands]
    if made and not (said or used or where):  # only made (level 1: no state changes): as the recipe's words
        return f"{step.unit.motion.label} {', '.join(others)}{', ' if others else ''}making {', '.join(made)}"
    parts = [step.unit.motion.label, said]
    if made:
        rooms_said = ", ".join(w + "".join(_at(rel, h) for rel, h in rooms[w]) for w in where)
        parts.append((f"in {rooms_said}: " if where else "") + ", ".join(used) + (" -> " if used else "")
                     + ", ".join(made))
    elif used:  # used up, nothing made: `pour onion_1 from board_1 into pan_1, using up butter_1`
        said = said or ", ".join(x for x, _ in lifted)  # `take pot_1 off stove_2, drain pot_1, using up water_1`
        parts[1] = said + (", " if said else "") + "using up " + ", ".join(used)
    if others:
        parts.append("with " + ", ".join(others))
    if not (taken or lifted):
        return " ".join(p for p in parts if p)
    if len(taken) == len(moves) == 1:  # the one object taken out is the one the motion moves
        parts[1] = "it" + parts[1][len(taken[0][0]):]
    return ", ".join(t for _, t in (*taken, *lifted)) + ", " + " ".join(p for p in parts if p)


def relational_text(task: PlanningTask, trace: PhysicalTrace) -> str:
    """A cook's account after the task tree: each step in recipe words with the objects named."""
    snaps = list(trace.states())
    lines = ["objects, step by step (relational encoding):"]
    for k, step in enumerate(trace.steps):
        lines.append(f"{k + 1}. {step_words(step, snaps[k], snaps[k + 1])}")
    return "\n".join(lines) + "\n"


def _state_json(s: ObjectState, labels: dict[str, str]) -> dict:
    return {"id": s.id, "label": labels[s.id], "state": s.node.describe() if s.node is not None else None,
            "holder": s.holder, "relation": str(s.relation) if s.relation is not None else None,
            "consumed": s.consumed}


def relational_json(task: PlanningTask, trace: PhysicalTrace) -> dict:
    """The trace as JSON: objects before the plan, then per step the unit, its bindings, every object after it."""
    labels = {o.id: o.label for o in trace.objects}
    snaps = list(trace.states())
    index: dict[int, int] = {}
    for i, u in enumerate(task.units):
        index.setdefault(id(u), i)
    return {
        "initial": [_state_json(s, labels) for _, s in sorted(snaps[0].items())],
        "steps": [{"step": k + 1, "unit": index.get(id(s.unit)), "source": s.source, "motion": s.unit.motion.label,
                   "text": step_words(s, snaps[k], snaps[k + 1]),
                   "bindings": [{"object": b.object, "before": b.before.describe() if b.before else None,
                                 "after": b.after.describe() if b.after else None} for b in s.bindings],
                   "objects": [_state_json(x, labels) for _, x in sorted(snaps[k + 1].items())]}
                  for k, s in enumerate(trace.steps)],
    }


RELATIONAL_VIEW = TraceView("relational", relational_text, relational_json)
