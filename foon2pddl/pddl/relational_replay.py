"""Plans of the `relational` encoding as physical traces, with real holders: its replay and view hooks.

`relational_trace` applies each plan step to the task's facts (ground
preconditions are not checked here: `planners.decode.simulate_plan` does that)
and records, per unit step, the object bound to each role (parameters first;
read-only objects checked by `(occupied s)` take the first object, by name, in
the role's node), the late-bound holders (the remaining parameters, and the
holders objects were released from by a quantified delete), and the
new node, holder and consumed flag of every object the step changes.
Consumption is read from FOON's lists: after the step, an object in a container
whose new node describes its contents (`contains`, `empty`) but no longer lists
the object's label, that the step did not change, and that the container listed
before or the step reads, became part of the mixture (it is bound to the step
and marked consumed), and so did everything in or on a consumed object. An object with two
holders is a PlanDecodeError (the encoding promises at most one). Two more
FOON completions happen here, where the plan says which objects: a late-bound
source holder no longer lists what left it (its PDDL state is unchanged, so a
later step that needs its old node shows as a state mismatch), and an object
the unit gives no output node, that names a place (or was moved there by an
implied move) and sits in the holder where the step makes a new object, became
part of it (`garlic (in [bowl])` and `ground beef (in [bowl])` where the mix
makes `meat mix (in [bowl])`; `rib` picked onto the tray where `barbecued ribs`
appear).
O(steps x (facts + objects)).
"""

from __future__ import annotations

from collections.abc import Sequence

from ..model.foon import ObjectNode
from ..model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, Relation, TraceStep
from ..model.places import describes_contents, listed, place_of
from .holders import list_gaps, relational_roles, task_aliases, without
from .instance_replay import source_of
from .registry import PlanDecodeError
from .task import Atom, PlanningTask, released
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


def relational_trace(task: PlanningTask, steps: Sequence[str]) -> PhysicalTrace:
    """The plan as a trace with holders (see the module doc)."""
    facts = set(task.init)
    label = {x.name: x.label for x in task.instances}
    node: dict[str, ObjectNode | None] = {x.name: x.start for x in task.instances}
    consumed: set[str] = set()
    holder = _holders(facts)
    units = [task.units[a.unit] for a in task.actions if a.unit is not None]
    aliases = task_aliases(units, label.values(), [x.start for x in task.instances])
    alias = dict(aliases)

    def lists(node: ObjectNode | None) -> frozenset[str]:  # a list read through the task's aliases
        return frozenset(alias.get(x, x) for x in listed(node))
    out = []
    for n, step in enumerate(steps, start=1):
        name, *args = step.split()
        action = task.action_for(name)
        if action is None:
            raise PlanDecodeError(f"plan step {n} ({step}) names no action of the task")
        if len(args) != len(action.params):
            raise PlanDecodeError(f"plan step {n} ({step}): {len(action.params)} arguments expected, got {len(args)}")
        unknown = [a for a in args if a not in node]
        if unknown:
            raise PlanDecodeError(f"plan step {n} ({step}): {unknown[0]} is not an object of the task")
        bind = {v: a for (v, _), a in zip(action.params, args, strict=True)}
        facts -= {Atom(a.predicate, tuple(bind.get(x, x) for x in a.args)) for a in action.delete}
        facts -= released(facts, action.release, bind)
        facts |= {Atom(a.predicate, tuple(bind.get(x, x) for x in a.args)) for a in action.add}
        if action.unit is None:
            holder = _holders(facts)
            continue
        unit = task.units[action.unit]
        rels = relational_roles(unit)
        given = iter(args)
        names: list[str | None] = [next(given) if bound else None for _, bound in action.roles]
        for j, r in enumerate(rels):  # a read-only source holder is the one the moving object is in
            src = r.source.role if r.source is not None and r.moves else None
            if src is not None and names[src] is None and names[j] in holder:
                names[src] = holder[names[j]][0]
        for k, (role, _) in enumerate(action.roles):
            if names[k] is None:
                names[k] = next((x for x in sorted(node) if label[x] == role.label and node[x] == role.before
                                 and x not in consumed and x not in names), None)
                if names[k] is None:
                    raise PlanDecodeError(f"plan step {n} ({step}): no {role.label} is {show_node(role.before)}")
        params = [h for h in given if h not in names]
        was = {x: (node[x], holder.get(x), x in consumed) for x in node}
        bindings = [Binding(x, r.role.before, r.after) for r, x in zip(rels, names, strict=True)]
        for r, x in zip(rels, names, strict=True):
            if r.changes:
                node[x] = r.after
        old_holder, holder = holder, _holders(facts)
        gone: dict[str, set[str]] = {}
        for x in names:
            if x in old_holder and holder.get(x) != old_holder[x]:
                gone.setdefault(old_holder[x][0], set()).add(label[x])
        for h in params:
            gone.setdefault(h, set())
        for h, labels in sorted(gone.items()):  # a read-only or late-bound source no longer holds what left it
            empty = without(node[h], labels, alias) if node[h] is not None and lists(node[h]) & labels else None
            if h in names:
                k = names.index(h)
                if empty is not None and bindings[k].after is None:
                    bindings[k] = Binding(h, bindings[k].before, empty)
                    node[h] = empty
                continue
            bindings.append(Binding(h, node[h], empty))
            node[h] = empty or node[h]
        bound = {b.object for b in bindings}
        changed_now = {x for r, x in zip(rels, names, strict=True) if r.changes}
        read = {x for r, x in zip(rels, names, strict=True) if r.after is None}
        made_in = {holder[x][0] for r, x in zip(rels, names, strict=True) if r.role.before is None and x in holder}
        for r, x in zip(rels, names, strict=True):  # in where a product is made, with no output node: absorbed
            if (r.role.after is None and (r.changes or place_of(r.role.before) is not None)
                    and holder.get(x, ("",))[0] in made_in):
                consumed.add(x)
        for c in sorted(bound):
            if c in consumed or not describes_contents(node[c]):
                continue
            keep, had = lists(node[c]), lists(was[c][0])
            for y in sorted(y for y, (h, _) in holder.items() if h == c):
                if (y not in consumed and y not in changed_now and node[y] is not None and label[y] not in keep
                        and (label[y] in had or y in read)):
                    consumed.add(y)
                    if y not in bound:
                        bindings.append(Binding(y, node[y], None))
        inner = True
        while inner:  # what is in a consumed object went with it
            inner = [y for y, (h, _) in sorted(holder.items()) if h in consumed and y not in consumed
                     and node[y] is not None]
            consumed.update(inner)
            bindings += [Binding(y, node[y], None) for y in inner if y not in {b.object for b in bindings}]
        changes = []
        for x in sorted(node):
            now = (node[x], holder.get(x), x in consumed)
            if now != was[x]:
                h, rel = holder.get(x, (None, None))
                changes.append(ObjectState(x, node[x], h, rel, x in consumed))
        out.append(TraceStep(len(out), unit, tuple(bindings), tuple(changes), source_of(unit)))
    start = _holders(set(task.init))
    initial = tuple(ObjectState(x.name, x.start, *start.get(x.name, (None, None))) for x in task.instances)
    gaps = tuple(sorted({(c, x) for u in units for c, x, _ in list_gaps(u)}))
    return PhysicalTrace(tuple(PhysicalObject(x.name, x.label) for x in task.instances), initial, tuple(out),
                         aliases, gaps)


def step_words(step: TraceStep, before: dict[str, ObjectState], after: dict[str, ObjectState]) -> str:
    """A step in recipe words with the objects named, O(bindings).

    `pour sugar_1 from bag_1 into pitcher_1`; `mix in bowl_2: lettuce_1, tomato_1 -> salad_1 with spoon_1`:
    the motion, each object that changes holder (from, into), each other object whose state changes, then
    what the step consumes and makes (in the holder of what it makes), then the objects it only uses.
    """
    made = [b.object for b in step.bindings if b.before is None]
    used = [b.object for b in step.bindings if after[b.object].consumed and not before[b.object].consumed]
    moves, holders = [], set()
    for b in step.bindings:
        x, was, now = b.object, before[b.object], after[b.object]
        if b.before is not None and was.holder != now.holder and not now.consumed:
            into = f" {'into' if now.relation is Relation.IN else 'onto'} {now.holder}" if now.holder else ""
            moves.append(f"{x}" + (f" from {was.holder}" if was.holder else "") + into)
            holders.update(h for h in (was.holder, now.holder) if h)
    where = sorted({after[m].holder for m in made if after[m].holder})
    holders.update(where)
    rest = [b for b in step.bindings if b.object not in made and b.object not in used and b.object not in holders
            and before[b.object].holder == after[b.object].holder]
    parts = [step.unit.motion.label, ", ".join(moves), ", ".join(b.object for b in rest if changed(b))]
    if used or made:
        parts.append((f"in {', '.join(where)}: " if where else "") + ", ".join(used) + (" -> " if used else "")
                     + ", ".join(made))
    others = [b.object for b in rest if not changed(b)]
    if others:
        parts.append("with " + ", ".join(others))
    return " ".join(p for p in parts if p)


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
