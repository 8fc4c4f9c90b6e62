"""Many goals on one network and kitchen, translated once (`GoalReplanner`): it compiles the network without
goal-directed pruning and with every node as a goal candidate, which gives each node's goal atoms (the
preconditions of the encoding's per-candidate goal actions) under names that no longer depend on the goal, and
searches that one translation per goal (`planners.fd_reuse`).
"""

from __future__ import annotations

import copy
import time
from dataclasses import replace
from pathlib import Path

from ..generalize.categories import CategoryIndex
from ..io.rates import Rates
from ..model.foon import Foon
from ..model.goal import Goal, GoalSpec
from ..model.kitchen import Kitchen
from ..model.levels import project, project_node
from ..pddl.compile import DEFAULT_ENCODING, compile_goal
from ..pddl.task import PlanningTask, candidate_alternatives
from . import DEFAULT_PLANNER
from .decode import run_plan
from .solve import PlanOutcome, outcome_of

__all__ = ["GoalReplanner"]


class GoalReplanner:
    """Many goals on one network and kitchen: a planner that can reuse a translation (`Planner.translate_once`;
    Fast Downward's) translates once, then searches per goal.

    Any registered encoding whose goal is one goal action per candidate works, the lifted
    `gen-lifted` one included (give its `category_index`; a candidate may have several goal
    actions there, one per way its atom can be written). `with_search` gives a replanner on
    the same translation with other search options (an optimal search beside a satisficing one).
    `cache`: a directory of translations shared by processes (`fd_reuse.TranslatedTask.build`).
    `kitchens`: also serve kitchens within `kitchen` (`for_kitchen`) on an encoding whose kitchen sets only
    the initial state (`Encoding.kitchen_init`; ignored on others): one compilation and translation then
    serve every trial of an experiment, each drawn from one default kitchen.
    """

    def __init__(self, foon: Foon, kitchen: Kitchen, encoding: str = DEFAULT_ENCODING, level: int = 3, *,
                 optimal: bool = False, costs: str | None = None, rates: Rates | None = None,
                 time_limit: float | None = None, search: tuple[str, ...] | None = None,
                 planner: str = DEFAULT_PLANNER, category_index: CategoryIndex | None = None,
                 cache: Path | None = None, kitchens: bool = False) -> None:
        from ..errors import UsageError
        from ..pddl.compile import encoding_named
        from .registry import lookup

        translate_once = lookup(planner).translate_once
        if translate_once is None:
            raise UsageError(f"planner {planner!r} cannot reuse one translation for many goals")
        t0 = time.perf_counter()
        at_level = project(foon, level)
        nodes = tuple(sorted(at_level.nodes))
        every = Goal(GoalSpec("any node"), nodes, level)
        compiled = compile_goal(at_level, kitchen, every, encoding, level, prune=False, costs=costs, rates=rates,
                                category_index=category_index)
        task = compiled.task
        self.node_atoms = candidate_alternatives(task, nodes)
        goal_atoms = set(task.goal)
        base = replace(task, actions=tuple(a for a in task.actions
                                           if not (a.unit is None and goal_atoms & set(a.add))))
        self.compiled = replace(compiled, task=base)
        self.encode_seconds = time.perf_counter() - t0
        self.level = level
        self.kitchen_nodes = kitchen.project(level).nodes
        self.kitchens = kitchens and encoding_named(encoding).kitchen_init
        kw = {"cache": cache} if cache is not None else {}
        if self.kitchens:
            kw["forgettable"] = True
        self.translated = translate_once(base, optimal=optimal, time_limit=time_limit, search=search, **kw)

    @property
    def task(self) -> PlanningTask:
        return self.translated.task

    def with_search(self, *, optimal: bool = False, search: tuple[str, ...] | None = None) -> GoalReplanner:
        """This replanner searching with other options, on the same translation (nothing is translated again)."""
        other = copy.copy(self)
        other.translated = replace(self.translated, optimal=optimal, search=search)
        return other

    def for_kitchen(self, kitchen: Kitchen) -> GoalReplanner:
        """This replanner from `kitchen`, whose nodes are among the kitchen it was built from, with nothing
        compiled or translated again: the initial state loses the goal atoms of the nodes `kitchen` lacks
        (`Encoding.kitchen_init`) and the translation starts from it (`TranslatedTask.at_init`). ValueError
        unless built with `kitchens` on such an encoding and `kitchen` is within it. O(task)."""
        nodes = kitchen.project(self.level).nodes
        if not self.kitchens or not nodes <= self.kitchen_nodes:
            raise ValueError("this replanner serves only kitchens within the one it was built from, on an "
                             "encoding whose kitchen sets only the initial state")
        atoms = self.node_atoms
        kept = {a for n in nodes for alt in atoms.get(n, ()) for a in alt}
        gone = {a for n in self.kitchen_nodes - nodes for alt in atoms.get(n, ()) for a in alt} - kept
        task = replace(self.task, init=tuple(a for a in self.task.init if a not in gone))
        other = copy.copy(self)
        other.compiled = replace(self.compiled, task=task)
        other.kitchen_nodes = nodes
        other.translated = self.translated.at_init(task)
        return other

    def plan(self, goal: Goal, time_limit: float | None = None, up_validate: bool = False) -> PlanOutcome:
        """Plan for one goal on the shared translation."""
        t0 = time.perf_counter()
        candidates = sorted({project_node(c, self.level) for c in goal.candidates})
        alternatives = [alt for c in candidates for alt in self.node_atoms.get(c, ())]
        timings = {"encode": time.perf_counter() - t0}
        result = self.translated.solve(alternatives, time_limit)
        # Check the plan against the alternative it reaches, as the goal of the task.
        state, _ = run_plan(self.task, result.plan)
        reached = next((a for a in alternatives if set(a) <= state), alternatives[0] if alternatives else ())
        compiled = replace(self.compiled, task=replace(self.task, goal=tuple(reached)))
        return outcome_of(result, compiled, goal, self.kitchen_nodes, timings, up_validate)
