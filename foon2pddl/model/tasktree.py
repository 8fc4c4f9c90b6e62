"""Task trees: the units that, run in order from a kitchen, make a goal.

A TaskTree is what every solver returns (native retrieval and mapped-back
planner plans alike) and is checked the same way, by simulation.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from .containment import Containment, is_auxiliary, is_inference, rule_holds
from .foon import FunctionalUnit, ObjectNode
from .words import count


@dataclass(frozen=True)
class TaskTree:
    """Units in executable order and the goal node the last of them makes available."""

    units: tuple[FunctionalUnit, ...]
    goal: ObjectNode
    level: int = 3

    def __len__(self) -> int:
        return len(self.units)

    def __repr__(self) -> str:
        """Goal and unit count only (the dataclass repr lists every node of every unit)."""
        return f"<TaskTree for {self.goal.describe()!r}: {count(len(self.units), 'unit')}, level {self.level}>"

    def _repr_html_(self) -> str:
        """Jupyter: the goal and the numbered units (`motion: inputs -> outputs`), labels escaped."""
        from html import escape

        steps = "".join(f"<li>{escape(u.describe())}</li>" for u in self.units)
        return (f"<div><b>task tree for {escape(self.goal.describe())}</b>: {count(len(self.units), 'unit')}, "
                f"level {self.level}<ol>{steps}</ol></div>")


@dataclass(frozen=True)
class Validation:
    """Result of simulating a tree from a kitchen: ok, or the first problems found."""

    ok: bool
    problems: tuple[str, ...] = ()
    inferred: tuple[ObjectNode, ...] = ()  # containers made available by the containment rule, in order

    def __bool__(self) -> bool:
        return self.ok


def validate(tree: TaskTree, kitchen_nodes: frozenset[ObjectNode] | set[ObjectNode],
             containment: Containment | str = Containment.STRICT,
             beside: Sequence[Iterable[ObjectNode]] = ()) -> Validation:
    """Run the units in order: every input must be available when its unit runs, and the goal at the end.

    `beside`: per unit, nodes available after it beside its outputs (a holder a relational plan's step emptied
    that FOON's unit does not list: `planners.trace_check.emptied`).

    Under `Containment.INFER` the containment rule (`containment.rule_holds`) applies: an
    inference step must hold by the rule, and a missing container input is inferred when
    the rule holds for it; `Validation.inferred` lists the containers inferred. Under strict,
    an inference step is a problem.
    """
    infer = Containment(containment) is Containment.INFER
    available = set(kitchen_nodes)
    problems: list[str] = []
    inferred: list[ObjectNode] = []

    def note(nodes) -> None:
        inferred.extend(n for n in nodes if not is_auxiliary(n) and n not in inferred)

    for step, unit in enumerate(tree.units, start=1):
        if is_inference(unit):
            bad = [n for n in unit.outputs if not (infer and rule_holds(n, available, tree.level))]
            if bad:
                why = "the containment rule does not hold" if infer else "containment inference needs infer"
                problems.append(f"step {step} ({unit.motion.label}): {why} for: "
                                + "; ".join(n.describe() for n in bad))
            else:
                note(n for n in unit.outputs if n not in available)
            available.update(unit.outputs)
            continue
        missing = [n for n in unit.inputs if n not in available]
        if infer and missing:
            made = [n for n in missing if rule_holds(n, available, tree.level)]
            note(made)
            available.update(made)
            missing = [n for n in missing if n not in available]
        if missing:
            problems.append(
                f"step {step} ({unit.motion.label}): input not available: "
                + "; ".join(n.describe() for n in missing)
            )
        available.update(unit.outputs)
        available.update(beside[step - 1] if step <= len(beside) else ())
    if infer and tree.goal not in available and rule_holds(tree.goal, available, tree.level):
        note([tree.goal])
        available.add(tree.goal)
    if tree.goal not in available:
        problems.append(f"goal not produced: {tree.goal.describe()}")
    return Validation(not problems, tuple(problems), tuple(inferred))


def justify(units: tuple[FunctionalUnit, ...] | list[FunctionalUnit],
            kitchen_nodes: frozenset[ObjectNode] | set[ObjectNode], goal: ObjectNode,
            keep: frozenset[int] = frozenset()) -> tuple[FunctionalUnit, ...]:
    """The units of a delete-free run that the goal needs, in their original order.

    A planner's plan may contain steps that make nothing the goal depends on;
    a task tree should not. Backward from the goal, each needed node is credited
    to the latest earlier unit that makes it (so units already kept are reused),
    and that unit's inputs become needed; nodes the kitchen holds need nothing.
    The result still runs from the kitchen whenever the whole plan did. The units at the
    positions in `keep` are kept too, with what they need (a must-use object's unit).
    """
    needed = {goal} - set(kitchen_nodes)
    kept: list[int] = []
    for i in range(len(units) - 1, -1, -1):
        made = needed.intersection(units[i].outputs)
        if made or i in keep:
            kept.append(i)
            needed -= made
            needed.update(n for n in units[i].inputs if n not in kitchen_nodes)
    return tuple(units[i] for i in reversed(kept))
