"""A tiny physical world for tests: objects with explicit holders, steps built from what changes.

`World` keeps every object's `ObjectState`; `step(motion, changes, uses)` turns the
new states of the changed objects (plus the ids of objects used unchanged) into a
`TraceStep` whose bindings are read off the world before and after, and whose unit
lists the before nodes as inputs and the after nodes as outputs. `random_world`
draws consistent cooking traces (pours between bowls, in-place cuts, mixes that
consume a bowl's contents into a new mixture) for property tests: every node it
writes says exactly where the object is and what each bowl holds.
"""

from __future__ import annotations

from dataclasses import replace

from foon2pddl.model.foon import FunctionalUnit, Motion, ObjectNode, Source, make_node, make_state
from foon2pddl.model.physical import Binding, ObjectState, PhysicalObject, PhysicalTrace, TraceStep


def node(label: str, *states) -> ObjectNode:
    """`node("onion", "chopped", ("in", "bowl"), ("contains", ["a", "b"]))`."""
    made = []
    for s in states:
        if isinstance(s, str):
            made.append(make_state(s))
        elif isinstance(s[1], str):
            made.append(make_state(s[0], s[1]))
        else:
            made.append(make_state(s[0], "", s[1]))
    return make_node(label, made)


def contents(label: str, items, *extra) -> ObjectNode:
    """A container node: `contains {items}` (or `empty` when there are none)."""
    return node(label, ("contains", sorted(items)), *extra) if items else node(label, "empty", *extra)


class World:
    """Mutable test helper (see the module doc)."""

    def __init__(self, objects: dict[str, str], initial: dict[str, ObjectState]) -> None:
        self.objects = tuple(PhysicalObject(i, lab) for i, lab in sorted(objects.items()))
        self.initial = tuple(initial.get(i, ObjectState(i)) for i, _ in sorted(objects.items()))
        self.now = {s.id: s for s in self.initial}
        self.steps: list[TraceStep] = []

    def label(self, oid: str) -> str:
        return next(o.label for o in self.objects if o.id == oid)

    def step(self, motion: str, changes: list[ObjectState], uses: tuple[str, ...] = (), line: int = 0) -> None:
        bindings, inputs, outputs = [], [], []
        for c in changes:
            was = self.now[c.id]
            before = was.node if was.exists else None
            after = None if c.consumed else c.node
            bindings.append(Binding(c.id, before, after))
            inputs += [before] if before is not None else []
            outputs += [after] if after is not None else []
        for u in uses:
            bindings.append(Binding(u, self.now[u].node, None))
            inputs.append(self.now[u].node)
            outputs.append(self.now[u].node)
        unit = FunctionalUnit(tuple(inputs), Motion(motion), tuple(outputs), (Source("recipe.txt", line),))
        self.steps.append(TraceStep(len(self.steps), unit, tuple(bindings), tuple(changes)))
        self.now.update((c.id, c) for c in changes)

    def trace(self) -> PhysicalTrace:
        return PhysicalTrace(self.objects, self.initial, tuple(self.steps))


def salsa_world() -> World:
    """Onion slid from a board into bowl_1, salt poured in from a shaker, both mixed into salsa (3 steps)."""
    w = World({"board_1": "cutting board", "bowl_1": "bowl", "bowl_2": "bowl", "onion_1": "onion",
               "salt_1": "salt", "shaker_1": "shaker", "salsa_1": "salsa", "spoon_1": "spoon",
               "knife_1": "knife"},
              {"board_1": ObjectState("board_1", contents("cutting board", ["onion"])),
               "bowl_1": ObjectState("bowl_1", contents("bowl", [])),
               "bowl_2": ObjectState("bowl_2", contents("bowl", [])),
               "onion_1": ObjectState("onion_1", node("onion", "chopped", ("on", "cutting board")), "board_1", "on"),
               "salt_1": ObjectState("salt_1", node("salt", ("in", "shaker")), "shaker_1", "in"),
               "shaker_1": ObjectState("shaker_1", contents("shaker", ["salt"])),
               "spoon_1": ObjectState("spoon_1", node("spoon")),
               "knife_1": ObjectState("knife_1", node("knife"), "board_1", "on")})
    w.step("slide", [ObjectState("onion_1", node("onion", "chopped", ("in", "bowl")), "bowl_1", "in"),
                     ObjectState("board_1", contents("cutting board", [])),
                     ObjectState("bowl_1", contents("bowl", ["onion"]))], line=10)
    w.step("pour", [ObjectState("salt_1", node("salt", ("in", "bowl")), "bowl_1", "in"),
                    ObjectState("shaker_1", contents("shaker", [])),
                    ObjectState("bowl_1", contents("bowl", ["onion", "salt"]))], line=20)
    w.step("mix", [ObjectState("onion_1", node("onion", "chopped", ("in", "bowl")), "bowl_1", "in", consumed=True),
                   ObjectState("salt_1", node("salt", ("in", "bowl")), "bowl_1", "in", consumed=True),
                   ObjectState("salsa_1", node("salsa", ("in", "bowl")), "bowl_1", "in"),
                   ObjectState("bowl_1", contents("bowl", ["salsa"]))], uses=("spoon_1",), line=30)
    return w


def with_change(trace: PhysicalTrace, step: int, change: ObjectState) -> PhysicalTrace:
    """`trace` with `change` replacing (or added to) the changes of `step`, bindings untouched."""
    s = trace.steps[step]
    changes = tuple(c for c in s.changes if c.id != change.id) + (change,)
    steps = list(trace.steps)
    steps[step] = replace(s, changes=changes)
    return replace(trace, steps=tuple(steps))


def with_initial(trace: PhysicalTrace, state: ObjectState) -> PhysicalTrace:
    return replace(trace, initial=tuple(state if s.id == state.id else s for s in trace.initial))


# ---- random consistent worlds


def random_world(draw, st) -> World:
    """A consistent trace drawn with hypothesis (`draw`, `st` = hypothesis.strategies)."""
    foods = draw(st.lists(st.sampled_from(["salt", "onion", "sugar", "milk", "lime", "egg"]),
                          min_size=1, max_size=4, unique=True))
    bowls = [f"bowl_{i}" for i in range(1, draw(st.integers(2, 4)) + 1)]
    objects = {b: "bowl" for b in bowls} | {f"{f}_1": f for f in foods} | {"knife_1": "knife"}
    # each mixture has its own label, as FOON's do (salsa, dough): with every label one object, each change
    # changes what some node says, so a trace without it is inconsistent (two objects of one label in one
    # bowl can restate a list, which no replay could tell from a consistent trace)
    objects |= {f"mixture_{i}": label for i, label in enumerate(["batter", "dough", "paste"], 1)}
    held: dict[str, list[str]] = {b: [] for b in bowls}
    initial = {"knife_1": ObjectState("knife_1", node("knife"))}
    for f in foods:
        b = draw(st.sampled_from(bowls))
        held[b].append(f"{f}_1")
        initial[f"{f}_1"] = ObjectState(f"{f}_1", node(f, "whole", ("in", "bowl")), b, "in")
    for b in bowls:
        initial[b] = ObjectState(b, contents("bowl", [objects[x] for x in held[b]]))
    w = World(objects, initial)
    shape = {f"{f}_1": "whole" for f in foods}
    mixtures = iter(sorted(o for o in objects if o.startswith("mixture")))
    for _ in range(draw(st.integers(1, 6))):
        full = [b for b in bowls if held[b]]
        kind = draw(st.sampled_from(["pour", "cut", "mix"]))
        src = draw(st.sampled_from(full))
        if kind == "pour":
            x = draw(st.sampled_from(held[src]))
            dst = draw(st.sampled_from([b for b in bowls if b != src]))
            held[src].remove(x)
            held[dst].append(x)
            w.step("pour", [ObjectState(x, node(objects[x], shape[x], ("in", "bowl")), dst, "in"),
                            ObjectState(src, contents("bowl", [objects[o] for o in held[src]])),
                            ObjectState(dst, contents("bowl", [objects[o] for o in held[dst]]))])
        elif kind == "cut" and any(shape[x] == "whole" for x in held[src]):
            x = next(x for x in held[src] if shape[x] == "whole")
            shape[x] = "chopped"
            w.step("cut", [ObjectState(x, node(objects[x], "chopped", ("in", "bowl")), src, "in")], uses=("knife_1",))
        elif kind == "mix" and len(held[src]) >= 2:
            m = next(mixtures, None)
            if m is None:
                continue
            gone = [ObjectState(x, w.now[x].node, src, "in", consumed=True) for x in held[src]]
            held[src] = [m]
            shape[m] = "mixed"
            w.step("mix", [*gone, ObjectState(m, node(objects[m], "mixed", ("in", "bowl")), src, "in"),
                           ObjectState(src, contents("bowl", [objects[m]]))])
    return w
