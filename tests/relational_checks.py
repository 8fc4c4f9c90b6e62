"""Relational plans in tests: planned, solved, and replay-clean (the disagreements shown when not)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon, FunctionalUnit, ObjectNode
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.model.pairing import Role
from foon2pddl.model.where import beyond_foon
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.relational_plan import count_roles, plan_unit
from foon2pddl.planners import solve
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan


def clean_plan(foon: Foon, kitchen: Kitchen, goal: Goal, **options):
    """The `relational` plan of `goal`, asserted solved and replay-clean."""
    outcome = plan(foon, kitchen, goal, "relational", **options)
    assert outcome.status == "solved", outcome.message
    report = replay(outcome.trace)
    assert report.ok, [d.describe() for d in report.disagreements]
    return outcome


def rejected_plan(foon: Foon, kitchen: Kitchen, goal: Goal, where: str, **options):
    """The `relational` plan of `goal` from `plan`'s counts alone (`solve.plan_counted`), asserted physically wrong:
    the planner found one, no count gave a right one (status `error`), and every step the physical replay rejects is
    FOON's unit `where` (`file:line`, the file's name), as `consumed-elsewhere` (FOON's words there contradict each
    other about a holder, issue 21). `plan` itself then falls back to an assumed transfer: asserted solved,
    replay-clean, each step beyond FOON naming `where`, and the note once."""
    outcome = solve.plan_counted(foon, kitchen, goal, "relational", **options)
    assert outcome.status == "error" and outcome.rejected, outcome.message
    for problem in outcome.rejected:
        assert f"/{where}: step " in problem and problem.endswith("[consumed-elsewhere]"), problem
    fallback = clean_plan(foon, kitchen, goal, **options)
    beyond = [u for u in fallback.tree.units if beyond_foon(u)]
    assert beyond and all(beyond_foon(u).endswith(f"/{where}") for u in beyond)
    assert len([n for n in fallback.decoded.notes if n.startswith("transfer: beyond FOON")]) == 1
    return outcome


def alone_roles(kitchen: frozenset[ObjectNode]) -> Callable[[FunctionalUnit], tuple[Role, ...]]:
    """The relational reading of each unit alone from `kitchen` (`relational_plan.plan_unit`: nothing silent, nothing
    stitched), as the roles `instance_counts.derive_counts` and `count_order` take (`count_roles`)."""
    def roles_of(unit: FunctionalUnit) -> tuple[Role, ...]:
        return count_roles(plan_unit(unit, kitchen, frozenset(), frozenset(), frozenset(), frozenset(), frozenset()))
    return roles_of


def compiled_counts(monkeypatch) -> list[str]:
    """The counts `planners.solve.plan` compiles from now on, in order: `small` or `wide`, and the keyword that counts
    it again (`through`, `placed`, `own`)."""
    seen: list[str] = []
    real = solve.compile_goal

    def recording(*args, **options):
        mode = [k for k in ("through", "placed", "own") if options.get(k)]
        seen.append(" ".join(["small" if options.get("narrow") else "wide", *mode]))
        return real(*args, **options)

    monkeypatch.setattr(solve, "compile_goal", recording)
    return seen


def planned_counts(monkeypatch) -> list[str]:
    """The counts `planners.solve.plan` hands on to be planned from now on (holder reach first, then a planner), in
    order, named as `compiled_counts` names them."""
    names = compiled_counts(monkeypatch)
    made: dict[int, tuple[str, object]] = {}  # id of a compiled task -> its count's name (and the task, kept alive)
    compiling, dropping = solve.compile_goal, solve.drop_unbindable
    seen: list[str] = []

    def compiled(*args, **options):
        out = compiling(*args, **options)
        made[id(out.task)] = (names[-1], out.task)
        return out

    def planned(task):
        seen.append(made[id(task)][0])
        return dropping(task)

    monkeypatch.setattr(solve, "compile_goal", compiled)
    monkeypatch.setattr(solve, "drop_unbindable", planned)
    return seen


def clean_unit_plan(units, kitchen_nodes, goal_node: ObjectNode, **options):
    """`clean_plan` of `goal_node` over a network of `units` from a kitchen of `kitchen_nodes` (`options`: `plan`'s)."""
    return clean_plan(Foon(tuple(units)), Kitchen(frozenset(kitchen_nodes)),
                      Goal(GoalSpec(goal_node.label), (goal_node,)), **options)


def dish_goal(path: Path) -> tuple[Foon, Goal]:
    """A recipe file's network and its (first) dish as the goal."""
    foon, _ = load([path])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    return foon, resolve_goal(spec_of_node(dish), foon)


def clean_dish_plan(path: Path):
    """`clean_plan` of a recipe file's (first) dish from its default kitchen, 60 s."""
    foon, goal = dish_goal(path)
    return clean_plan(foon, default_kitchen(foon), goal, time_limit=60)


def rejected_dish_plan(path: Path, where: str):
    """`rejected_plan` of a recipe file's (first) dish from its default kitchen, 60 s, at its unit `where` (a line)."""
    foon, goal = dish_goal(path)
    return rejected_plan(foon, default_kitchen(foon), goal, f"{path.name}:{where}", time_limit=60)


def instances_objects(path: Path) -> int:
    """How many objects the `instances` problem of a recipe file's (first) dish declares (the floor `relational`
    is held to, dish by dish)."""
    foon, goal = dish_goal(path)
    return len(compile_goal(foon, default_kitchen(foon), goal, "instances").task.objects)


def within_instances(foon: Foon, dish_prefix: str):
    """`clean_plan` of the dish of `foon` whose description starts with `dish_prefix` from its default kitchen (60 s),
    asserted to have no more objects in its problem than `instances`' task counted small (issue 21's floor)."""
    dish = next(x for x in sorted(foon.dishes) if x.describe().startswith(dish_prefix))
    goal = resolve_goal(spec_of_node(dish), foon)
    outcome = clean_plan(foon, default_kitchen(foon), goal, time_limit=60)
    floor = len(compile_goal(foon, default_kitchen(foon), goal, "instances", narrow=True).task.objects)
    assert len(outcome.task.objects) <= floor, (len(outcome.task.objects), floor)
    return outcome
