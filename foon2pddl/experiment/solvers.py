"""The solvers an experiment compares, by name, each prepared once per (trial, network).

A solver is prepared for one network view and one trial kitchen (`prepare`),
which does the work shared by the goals of the batch (its time is the batch's
`setup`), then answers goals one by one (`solve`). Native solvers share the
reachability fixpoint (complete, optimal) or the network index (greedy);
`fd-tree` and `fd-tree-opt` translate the unpruned `tree` encoding once per run
from the default kitchen, start each trial from its kitchen and swap goals in
the translated task (`planners.goal_replanner.GoalReplanner`); `fd-state`, `fd-instances`
and `fd-relational` compile and plan each goal afresh with their `encoding`, pruned
per goal (the physical ones may need a wash or a second bowl where FOON's semantics
does not, and solve fewer goals than `native-complete`); `fd-lifted-gen` plans over
the concrete network with category types, on GEN only, translated once per trial
too. Every tree a solver returns is validated by simulation from the kitchen the
solver was given; a tree that fails is an `error`.
"""

from __future__ import annotations

import time
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path

from ..errors import UsageError
from ..model.foon import ObjectNode
from ..model.kitchen import Kitchen
from ..model.tasktree import validate
from ..model.words import first_of
from ..status import cell_status
from .networks import NETWORKS, NetworkView, lifted_networks
from .records import CellStatus

#: Default time limit (seconds) of one planner run.
DEFAULT_TIME_LIMIT = 60.0
#: Optimal search of `fd-tree-opt`: seq-opt-lmcut's A* with LM-cut plus atom-centric stubborn sets, a
#: partial-order reduction that keeps optimality. FOON's delete-free tasks are full of independent units
#: that plain A* orders every possible way: on the shared subgraphs (GEN, 20 goals) the mean search time
#: per goal drops from 472 ms to 82 ms (max 4.2 s to 0.2 s), with the same optimal tree sizes.
OPTIMAL_SEARCH = ("--search", "astar(lmcut(),pruning=atom_centric_stubborn_sets())")

class Role(StrEnum):
    """What the report uses a solver for."""

    REFERENCE = "reference"  # counts the successes (exactly the goals some task tree reaches)
    AGREEMENT = "agreement"  # a planner that must solve exactly the reference's goals (cell by cell)
    OPTIMUM = "optimum"  # an optimal solver: tree sizes are compared with its
    PAPER = "paper"  # the seed paper's method: the time beside the paper's
    CONCRETE = "concrete"  # returns concrete (REG) trees whatever network it runs on
    OTHER = "other"


@dataclass(frozen=True)
class Outcome:
    """What a solver says about one goal (a record without its key)."""

    status: CellStatus
    reason: str = ""
    times: dict[str, float] = field(default_factory=dict)
    units: int | None = None
    plan_length: int | None = None
    validated: bool | None = None
    proven_optimal: bool | None = None
    foon_valid: bool | None = None
    bound: float | None = None  # anytime optimal search: proven lower bound on the tree's units
    gap: float | None = None  # (units - bound) / units
    executable: str | None = None  # the tree scheduled over the kitchen's objects (`physical`)
    executable_reason: str | None = None
    extra_objects: int | None = None
    repeated: int | None = None  # a physical plan: unit steps firing a unit it fired before


@dataclass(frozen=True)
class Setting:
    """What a solver is prepared for: a network view, the trial's concrete kitchen, a planner time limit;
    `cache`, a directory where Fast Downward translations are shared between the run's processes
    (`fd-tree` and `fd-tree-opt` translate the same task; None: each translates its own); `per_item`,
    the physical objects per kitchen item with which returned trees are scheduled (`physical`)."""

    view: NetworkView
    kitchen: Kitchen
    time_limit: float = DEFAULT_TIME_LIMIT
    cache: Path | None = None
    per_item: int = 1  # physical objects per kitchen item when a returned tree is scheduled


class Prepared:
    """A solver ready for the goals of one batch; `setup` is the preparation time in seconds."""

    setup: float = 0.0

    def solve(self, node: ObjectNode) -> Outcome:  # pragma: no cover - interface
        raise NotImplementedError


@dataclass(frozen=True)
class Solver:
    """A registered solver: name, what it is, its preparation, the networks it applies to (None: all),
    its role in the report and its cost rank (batches of costlier solvers start first: better load balance)."""

    name: str
    description: str
    prepare: Callable[[Setting], Prepared]
    networks: tuple[str, ...] | None = None
    planner: bool = False
    role: Role = Role.OTHER
    cost: int = 0
    whole_batches: bool = False  # one task per (trial, network): its preparation is too costly to repeat
    encoding: str | None = None  # the encoding it compiles each goal with (`pddl.compile.ENCODINGS`), if one

    def applies_to(self, network: str) -> bool:
        return self.networks is None or network in self.networks


def _native_outcome(result, kitchen_nodes, seconds: float, per_item: int = 1) -> Outcome:
    """Outcome of a `Retrieval`, its tree validated from `kitchen_nodes` and scheduled over their objects."""
    times = {"retrieve": seconds}
    if result.tree is None:
        return Outcome(cell_status(result.status), result.detail or result.reason, times)
    t0 = time.perf_counter()
    check = validate(result.tree, kitchen_nodes)
    times["validate"] = time.perf_counter() - t0
    if not check.ok:
        return Outcome(CellStatus.ERROR, "tree does not validate: " + first_of(check.problems, 3), times,
                       len(result.tree), None, False, result.proven_optimal, False, *_bound(result))
    return Outcome(CellStatus.SOLVED, result.detail, times, len(result.tree), None, True, result.proven_optimal,
                   True, *_bound(result), **physical(result.tree, kitchen_nodes, per_item, times))


def physical(tree, kitchen_nodes, per_item: int, times: dict[str, float]) -> dict:
    """The Outcome fields of `tree` scheduled over `per_item` objects per kitchen node
    (`planners.executable.schedule`, its time in `times["schedule"]`): the verdict, why not, and for a
    tree the kitchen runs short for, the objects it needs beyond the kitchen's (None when more objects
    would not do: a unit must fire again)."""
    from ..planners.executable import Verdict, needed, schedule

    t0 = time.perf_counter()
    verdict = schedule(tree, kitchen_nodes, per_item=per_item)
    extra = None
    if verdict.verdict is Verdict.SHORT:
        unlimited = needed(tree, kitchen_nodes)
        if unlimited.ok:
            extra = sum(max(0, n - per_item) for _, n in unlimited.drawn)
    times["schedule"] = time.perf_counter() - t0
    return {"executable": str(verdict.verdict), "executable_reason": verdict.message or None, "extra_objects": extra}


def physical_plan(trace, kitchen_nodes, per_item: int, times: dict[str, float]) -> dict:
    """The Outcome fields of a physical plan (its `trace`, replayed when decoded) against `per_item` objects
    per kitchen node (`planners.executable.drawn_by_plan`, its time in `times["schedule"]`): `short` when
    the planner, given as many objects as the goal may need, used more than the kitchen has (how many more),
    and how many of its unit steps fire a unit the plan fired before."""
    from ..planners.executable import Verdict, drawn_by_plan

    t0 = time.perf_counter()
    verdict = drawn_by_plan(trace, kitchen_nodes, per_item)
    extra = sum(max(0, n - per_item) for _, n in verdict.drawn) if verdict.verdict is Verdict.SHORT else None
    fired: set = set()
    repeated = 0
    for step in trace.steps:
        repeated += step.unit in fired
        fired.add(step.unit)
    times["schedule"] = time.perf_counter() - t0
    return {"executable": str(verdict.verdict), "executable_reason": verdict.message or None, "extra_objects": extra,
            "repeated": repeated}


def _bound(result) -> tuple[float | None, float | None]:
    """(bound, gap) of an anytime retrieval that reports a lower bound (None, None otherwise)."""
    bound = getattr(result, "bound", None)
    if bound is None or result.tree is None or not len(result.tree):
        return None, None
    return float(bound), max(0.0, (len(result.tree) - bound) / len(result.tree))


class _Native(Prepared):
    """Native retrieval by `method` on the view's network, kitchen mapped through the view."""

    def __init__(self, setting: Setting, method: str) -> None:
        from ..analysis.index import index_of
        from ..analysis.reachability import reachable

        view = setting.view
        t0 = time.perf_counter()
        self.view = view
        self.method = method
        self.per_item = setting.per_item
        self.kitchen_nodes = view.map_kitchen(setting.kitchen).project(view.foon.level).nodes
        index_of(view.foon)
        self.reach = reachable(view.foon, self.kitchen_nodes)
        self.setup = time.perf_counter() - t0

    def solve(self, node: ObjectNode) -> Outcome:
        from ..retrieval.api import retrieve

        nodes = self.kitchen_nodes
        t0 = time.perf_counter()
        result = retrieve(self.view.foon, nodes, self.view.goal_of(node), self.method, reach=self.reach)
        return _native_outcome(result, nodes, time.perf_counter() - t0, self.per_item)


def _plan_outcome(outcome, steps: tuple[str, ...], kitchen_nodes=None, per_item: int = 1) -> Outcome:
    """Outcome of a planner run mapped back to a tree (`PlanOutcome`). A plan over physical objects (its
    `trace`) is executable when it decodes (decoding replays it: `planners.decode.check_trace`, with
    holders the relational replay); another valid tree is scheduled over the objects of `kitchen_nodes`
    when given (`physical`)."""
    times = dict(outcome.timings)
    tree = outcome.tree
    units = len(tree) if tree is not None else None
    status = cell_status(outcome.status)  # `error` when a plan was found that does not decode or validate
    foon_valid = outcome.validation.ok if outcome.validation is not None else None
    validated = None if tree is None else status == CellStatus.SOLVED
    if status == CellStatus.SOLVED:
        reason = "" if foon_valid is not False else "tree fails FOON simulation: " + first_of(
            outcome.validation.problems, 2)
        if outcome.trace is not None:  # a plan over physical objects: decoding replayed it object by object
            scheduled: dict = physical_plan(outcome.trace, kitchen_nodes or frozenset(), per_item, times)
        elif kitchen_nodes is not None and foon_valid:
            scheduled = physical(tree, kitchen_nodes, per_item, times)
        else:
            scheduled = {}
        return Outcome(status, reason, times, units, len(steps), validated, None, foon_valid, **scheduled)
    return Outcome(status, outcome.message, times, units, len(steps) if steps else None, validated, None,
                   foon_valid)


#: Replanners from a view's default kitchen a process keeps, by view (`_FdReuse`): (view, replanner).
_FROM_DEFAULT: OrderedDict[tuple, tuple[NetworkView, object]] = OrderedDict()
#: Views whose replanner `_FROM_DEFAULT` keeps (an EXP one holds a compiled task and its translation).
DEFAULT_KEPT = 3


class _FdReuse(Prepared):
    """Fast Downward on the unpruned `tree` encoding, translated once, goals swapped in.

    One compilation and translation from the view's default kitchen serves every trial (a trial's kitchen
    is drawn from it): the trial's kitchen only cuts down the initial state (`GoalReplanner.for_kitchen`),
    so a run translates each network once per process instead of once per trial. A kitchen not within
    the default one (a sweep's kitchen hook) gets its own translation. `setup` includes the default
    kitchen's compilation and translation in the batch that made them.
    """

    def __init__(self, setting: Setting, optimal: bool) -> None:
        from ..planners.goal_replanner import GoalReplanner

        view = setting.view
        self.view = view
        self.time_limit = setting.time_limit
        self.per_item = setting.per_item
        t0 = time.perf_counter()
        kitchen = view.map_kitchen(setting.kitchen)
        default = _from_default(setting)
        try:
            replanner = default.for_kitchen(kitchen)
        except ValueError:  # a kitchen not within the default one: its own translation
            replanner = GoalReplanner(view.foon, kitchen, "tree", view.foon.level, time_limit=setting.time_limit,
                                      cache=setting.cache)
        self.replanner = replanner.with_search(optimal=True, search=OPTIMAL_SEARCH) if optimal else replanner
        self.setup = time.perf_counter() - t0

    def solve(self, node: ObjectNode) -> Outcome:
        outcome = self.replanner.plan(self.view.goal_of(node), time_limit=self.time_limit)
        return _plan_outcome(outcome, outcome.result.plan, self.replanner.kitchen_nodes, self.per_item)


def _from_default(setting: Setting):
    """The `tree` replanner from the view's default kitchen serving kitchens within it, built once per process."""
    from ..planners.goal_replanner import GoalReplanner

    view = setting.view
    key = (id(view), setting.time_limit, setting.cache)  # the translation's own time limit and cache too
    if key in _FROM_DEFAULT and _FROM_DEFAULT[key][0] is view:
        _FROM_DEFAULT.move_to_end(key)
        return _FROM_DEFAULT[key][1]
    replanner = GoalReplanner(view.foon, view.kitchen, "tree", view.foon.level, time_limit=setting.time_limit,
                              cache=setting.cache, kitchens=True)
    _FROM_DEFAULT[key] = (view, replanner)
    while len(_FROM_DEFAULT) > DEFAULT_KEPT:
        _FROM_DEFAULT.popitem(last=False)
    return replanner


class _FdFresh(Prepared):
    """Fast Downward on one encoding, compiled (pruned) and translated for each goal.

    For an encoding whose valid plans are FOON task trees (`instances`), a goal that no
    task tree reaches from the kitchen has no plan either: the trial's reachability
    fixpoint (built once, the `setup`) answers it `unsolvable` without compiling or
    translating, as `fd-tree`'s shared translation answers it without searching.
    """

    def __init__(self, setting: Setting, encoding: str) -> None:
        from ..analysis.reachability import reachable
        from ..pddl.compile import ENCODINGS

        t0 = time.perf_counter()
        self.view = setting.view
        self.kitchen = setting.view.map_kitchen(setting.kitchen)
        self.encoding = encoding
        self.time_limit = setting.time_limit
        self.per_item = setting.per_item
        self.reach = None
        if ENCODINGS[encoding].foon_semantics:
            foon = self.view.foon
            self.reach = reachable(foon, self.kitchen.project(foon.level).nodes)
        self.setup = time.perf_counter() - t0

    def solve(self, node: ObjectNode) -> Outcome:
        from ..planners.solve import plan

        foon = self.view.foon
        goal = self.view.goal_of(node)
        if self.reach is not None:
            t0 = time.perf_counter()
            if not any(self.reach.can_make(c) for c in goal.candidates):
                return Outcome(CellStatus.UNSOLVABLE, "no task tree reaches the goal from the kitchen, so no plan "
                               f"of the {self.encoding} encoding does", {"reachability": time.perf_counter() - t0})
        outcome = plan(foon, self.kitchen, goal, self.encoding, foon.level, time_limit=self.time_limit)
        return _plan_outcome(outcome, outcome.result.plan, self.kitchen.project(foon.level).nodes, self.per_item)


class _LiftedGen(Prepared):
    """Fast Downward on the lifted FOON-GEN task: categories as types, concrete kitchen and goal.

    The whole concrete network is compiled (unpruned, every node a goal candidate) and translated
    once per trial; each goal is then one search on that translation (`GoalReplanner`), as for
    `fd-tree`. Compiling and translating per goal cost ~0.9 s a goal, ~97 % of its time.
    """

    def __init__(self, setting: Setting) -> None:
        from ..planners.goal_replanner import GoalReplanner

        if setting.view.index is None:
            raise UsageError("fd-lifted-gen needs the GEN network's category index")
        t0 = time.perf_counter()
        self.view = setting.view
        self.time_limit = setting.time_limit
        self.per_item = setting.per_item
        concrete = self.view.concrete
        self.replanner = GoalReplanner(concrete, setting.kitchen, NETWORKS[self.view.name].encoding, concrete.level,
                                       time_limit=setting.time_limit, category_index=self.view.index,
                                       cache=setting.cache)
        self.setup = time.perf_counter() - t0

    def solve(self, node: ObjectNode) -> Outcome:
        outcome = self.replanner.plan(self.view.concrete_goal(node), time_limit=self.time_limit)
        return _plan_outcome(outcome, outcome.result.plan, self.replanner.kitchen_nodes, self.per_item)


def _fresh(name: str, description: str, encoding: str) -> Solver:
    """A solver compiling and translating each goal afresh with `encoding` (`_FdFresh`)."""
    return Solver(name, description, lambda s: _FdFresh(s, encoding), planner=True, cost=6, encoding=encoding)


SOLVERS: dict[str, Solver] = {s.name: s for s in (
    Solver("native-greedy", "the seed paper's greedy task tree retrieval", lambda s: _Native(s, "greedy"),
           role=Role.PAPER, cost=1),
    Solver("native-complete", "reachability fixpoint, a tree whenever one exists", lambda s: _Native(s, "complete"),
           role=Role.REFERENCE, cost=0),
    Solver("native-optimal", "fewest distinct units (branch and bound)", lambda s: _Native(s, "optimal"),
           role=Role.OPTIMUM, cost=2),
    Solver("fd-tree", "Fast Downward lama-first, tree encoding, one translation per run (a trial's kitchen is "
                      "its initial state), each goal's relevant operators only",
           lambda s: _FdReuse(s, False), planner=True, role=Role.AGREEMENT, cost=3, whole_batches=True),
    Solver("fd-tree-opt", "Fast Downward A* with LM-cut and atom-centric stubborn sets (optimal), tree encoding, "
                          "one translation per run (a trial's kitchen is its initial state), each goal's relevant "
                          "operators only",
           lambda s: _FdReuse(s, True), planner=True, role=Role.OPTIMUM, cost=5, whole_batches=True),
    _fresh("fd-state", "Fast Downward lama-first, state encoding, compiled per goal (plans checked under the "
                       "encoding's STRIPS semantics; FOON simulation reported apart)", "state"),
    _fresh("fd-instances", "Fast Downward lama-first, instances encoding (physical objects whose states change, "
                           "counts derived per goal), compiled per goal (plans replayed on the objects and "
                           "validated as FOON trees; goals no task tree reaches are answered from the trial's "
                           "fixpoint)", "instances"),
    _fresh("fd-relational", "Fast Downward lama-first, relational encoding (physical objects and what holds "
                            "what), compiled per goal (plans replayed object by object, holders included; goals "
                            "no task tree reaches are answered from the trial's fixpoint)", "relational"),
    Solver("fd-lifted-gen", "Fast Downward lama-first, lifted GEN (category types, concrete objects), one "
                            "translation per trial",
           _LiftedGen, networks=lifted_networks(), planner=True, role=Role.CONCRETE, cost=4, whole_batches=True),
)}


def with_role(role: Role, solvers: tuple[str, ...] | None = None) -> tuple[str, ...]:
    """Names of the registered solvers with `role` (among `solvers` when given), in registry order."""
    return tuple(n for n, s in SOLVERS.items() if s.role == role and (solvers is None or n in solvers))


#: Solvers run when none are named: everything but the slow per-goal encodings.
DEFAULT_SOLVERS = ("native-greedy", "native-complete", "native-optimal", "fd-tree", "fd-lifted-gen")


def get_solver(name: str) -> Solver:
    """The registered solver `name` (ValueError listing the known ones)."""
    try:
        return SOLVERS[name]
    except KeyError:
        raise UsageError(f"unknown solver {name!r} (expected one of {', '.join(SOLVERS)})") from None
