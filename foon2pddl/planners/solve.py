"""Planning end to end: compile, render, plan, decode, validate, with the time of each phase.

`plan` handles one goal in any registered encoding (`pddl.compile.ENCODINGS`,
the lifted FOON-GEN one included) with any planner; `outcome_of` decodes and validates a planner's result (also
`goal_replanner.GoalReplanner`'s, many goals on one translation).
"""

from __future__ import annotations

import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field, replace

from ..generalize.categories import CategoryIndex
from ..io.rates import Rates
from ..model.constraints import Constraints
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.levels import project_node
from ..model.physical import PhysicalTrace
from ..model.tasktree import TaskTree, Validation
from ..model.words import count, first_of
from ..pddl.compile import DEFAULT_ENCODING, compile_goal
from ..pddl.constraints import GoalExcluded
from ..pddl.holder_reach import drop_unreachable
from ..pddl.interchangeable import in_order
from ..pddl.prune import counted_only, drop_unbindable
from ..pddl.registry import Compiled
from ..pddl.render import render
from ..pddl.restore import fewer, returns, with_restore
from ..pddl.split_actions import Split, split
from ..pddl.task import PlanningTask
from ..pddl.transfer import transfer_network
from ..status import PlanStatus
from . import DEFAULT_PLANNER, PlanResult, run_planner
from .copies import busy
from .decode import Decoded, PlanDecodeError, check, finished, plan_tree
from .physical_replay import replay
from .replay_findings import DisagreementKind

__all__ = ["PHASES", "PlanOutcome", "outcome_of", "plan", "plan_counted", "plan_restoring"]

#: The planner named by the outcome of a goal that constraints exclude (nothing was planned).
EXCLUDED = "constraints"

#: The planner named by the outcome of a goal no reachable state of the objects applies (`pddl.holder_reach`).
UNREACHED = "holder reachability"
#: The note of a task counted wide with makers by holder reach, planned when every other was out of holder reach.
OUT_OF_REACH = "the task counted from first makers is out of holder reach: counted wide with makers chosen by holder reach"
#: `plan`'s note when the wide task, counted with a needed node made by another of its makers, gave no valid plan
OWN_PLAN = "the wide count with another maker of a node gave no valid plan"

#: The time limit (s) of a plan with fewer objects than a plan to fall back on: `plan_restoring`'s second plan, and
#: `plan`'s task counted small (or the caller's, when shorter), there in CPU seconds of the planner's processes (a
#: loaded machine stretches their wall time: at load 4-5 the odd-index universal FOON's chocolate cake took 18 s of
#: wall time to translate its small task, 7 s of CPU, and was planned wide, 40 s).
RETRY_SECONDS = 10.0
#: The least time a later plan gets when those before it used up the limit: a call may end a few times this late (the
#: wide task, FOON's own plan unfolded and the holder-reach task each get it, and each whole task after its counted units).
MIN_REST = 1.0
#: The clock the time left is measured on (a module name, so a test can set it).
_now = time.monotonic

#: Phases in the order they run (the CLI adds `load` first).
PHASES = ("load", "encode", "write", "translate", "search", "decode", "validate")


@dataclass(frozen=True)
class PlanOutcome:
    """A planner's result, the task tree its plan stands for and that tree's validation."""

    result: PlanResult
    compiled: Compiled
    decoded: Decoded | None = None
    decode_error: str | None = None
    timings: dict[str, float] = field(default_factory=dict, compare=False, hash=False)

    @property
    def task(self) -> PlanningTask:
        return self.compiled.task

    @property
    def status(self) -> PlanStatus:
        """The planner's status, or `error` when a plan was found but does not decode or validate."""
        if self.result.solved and (self.decoded is None or not self.decoded.ok):
            return PlanStatus.ERROR
        return self.result.status

    @property
    def tree(self) -> TaskTree | None:
        return self.decoded.tree if self.decoded is not None else None

    @property
    def steps(self) -> tuple[str, ...]:
        """The plan as reported: the planner's steps the tree uses (`decode.used_steps`), or all of them."""
        return self.decoded.steps if self.decoded is not None and self.decoded.steps else tuple(self.result.plan)

    @property
    def trace(self) -> PhysicalTrace | None:
        """The plan object by object (encodings over physical objects; None otherwise or without a plan)."""
        return self.decoded.trace if self.decoded is not None else None

    @property
    def validation(self) -> Validation | None:
        return self.decoded.validation if self.decoded is not None else None

    @property
    def rejected(self) -> tuple[str, ...]:
        """The physical replay's words on a plan the planner found and the replay rejects, first problem first
        (empty otherwise): a plan that is physically wrong (`physical_replay`), not a planner that failed."""
        d = self.decoded if self.result.solved else None
        found = d.trace_check if d is not None and d.plan_check.ok else None
        return () if found is None or found.ok else found.problems

    @property
    def message(self) -> str:
        """Why there is no valid tree (empty when there is one)."""
        if self.decode_error:
            return self.decode_error
        if self.result.solved and self.decoded is not None and not self.decoded.ok:
            return "plan does not validate: " + first_of(self.decoded.problems, 3)
        return "" if self.result.solved else self.result.message


def outcome_of(result: PlanResult, compiled: Compiled, goal: Goal, kitchen_nodes: frozenset[ObjectNode],
               timings: dict[str, float], up_validate: bool) -> PlanOutcome:
    """Decode and validate a planner result; fold its timings into `timings`."""
    for phase in ("write", "translate", "search"):
        if phase in result.timings:
            _add(timings, phase, result.timings[phase])
    if not result.solved:
        return PlanOutcome(result, compiled, timings=timings)
    t0 = time.perf_counter()
    try:
        plain = plan_tree(compiled, result.plan, goal, kitchen_nodes)
        tree = finished(compiled, plain, result.plan, kitchen_nodes)
    except PlanDecodeError as exc:
        _add(timings, "decode", time.perf_counter() - t0)
        return PlanOutcome(result, compiled, decode_error=str(exc), timings=timings)
    _add(timings, "decode", time.perf_counter() - t0)
    t0 = time.perf_counter()
    decoded = check(tree, kitchen_nodes, compiled, result.plan, up_validate=up_validate,
                    candidates=sorted({project_node(c, compiled.task.level) for c in goal.candidates}), plain=plain)
    _add(timings, "validate", time.perf_counter() - t0)
    return PlanOutcome(result, compiled, decoded, timings=timings)


def plan(foon: Foon, kitchen: Kitchen, goal: Goal, encoding: str = DEFAULT_ENCODING, level: int = 3,
         **options) -> PlanOutcome:
    """`plan_counted` (its doc: the counts tried, in order); when the plan of every count it tried is one the physical
    replay rejects, and only as `consumed-elsewhere` at units whose words leave an ingredient in another holder than
    the one they make their product in (`pddl.transfer`), the network with an assumed transfer unit per such
    ingredient (`pour`, source `assumed-transfer:K`, beyond FOON) is planned once more, with the same options, and
    kept when it solves, with a note naming the units (issue 21: a physically right plan that says what FOON left out,
    rather than `error`). Any other outcome is `plan_counted`'s, unchanged."""
    outcome = plan_counted(foon, kitchen, goal, encoding, level, **options)
    if encoding != "relational" or outcome.status != PlanStatus.ERROR or not outcome.rejected or outcome.trace is None:
        return outcome
    found = replay(outcome.trace).disagreements
    if not found or any(d.kind is not DisagreementKind.CONSUMED_ELSEWHERE for d in found):
        return outcome
    wheres = sorted({d.source for d in found})
    augmented, added = transfer_network(foon, wheres)
    if not added:
        return outcome
    again = plan_counted(augmented, kitchen, goal, encoding, level, **options)
    if again.status != PlanStatus.SOLVED:
        return outcome
    return _noted(again, f"transfer: beyond FOON, {count(added, 'assumed pour')} of an ingredient into the holder the "
                         f"unit makes its product in, where FOON's words leave it in another: {', '.join(wheres)}")


def plan_counted(foon: Foon, kitchen: Kitchen, goal: Goal, encoding: str = DEFAULT_ENCODING, level: int = 3, *,
                 planner: str = DEFAULT_PLANNER, planner_cmd: str | None = None, optimal: bool = False,
                 time_limit: float | None = None, prune: bool = True, costs: str | None = None,
                 rates: Rates | None = None, category_index: CategoryIndex | None = None,
                 up_validate: bool = False, constraints: Constraints | None = None, search=None,
                 instances: tuple[tuple[str, int], ...] = (),
                 categories: tuple[tuple[str, tuple[str, ...]], ...] = (), cpu_limit: float | None = None) -> PlanOutcome:
    """Compile `goal` over `foon` from `kitchen`, plan, and map the plan back to a validated task tree.

    `encoding` is any registered encoding; `category_index` is the category index of lifted ones (default: the shipped
    one). `time_limit` bounds the planner run (translation and search) in wall time, `cpu_limit` in the CPU seconds of
    the planner's processes. Raises UsageError for bad options (encoding, cost mode). When `constraints` leave no way to
    make the goal, nothing is compiled and the outcome is `unsolvable` (planner `constraints`, an empty task of the
    encoding); a planner's failure is a status, never an exception. `instances`, `categories`: for the `instances`
    encoding (see `pddl.encoding.EncodeOptions`). The planner gets the task without the actions no binding grounds
    (`pddl.prune.drop_unbindable`: same plans, less for it to parse and ground) and without those no reachable state
    applies (`pddl.holder_reach`: a holder and its content in states no plan has together); when that leaves the goal
    out of reach, no planner runs and the outcome is `unsolvable` (planner `holder reachability`, the message naming the
    units). A `relational` task's interchangeable objects are taken in one order (`pddl.interchangeable`: not every bowl
    of a stack is tried), and an action whose parameters multiply is split into a chain of small parts
    (`pddl.split_actions`, not with `optimal`), joined back in the plan. The outcome keeps the compiled task.
    A `relational` task is counted small first (`pddl.relational_objects`; FOON's plan out of holder reach: through the
    stitches alone, then FOON's plan with makers by holder reach): when that has fewer objects and no valid plan within
    `RETRY_SECONDS` of the planner's CPU time (the `time_limit` when shorter; planners that cannot bound CPU take it as
    wall time, `PlanRequest.wall_limit`) and `time_limit` of wall time, the task counted wide is planned within what is
    left of `time_limit` (at least `MIN_REST`), and a note says so; the timings are then both plans'. Each is planned
    first (not with `optimal`) with only the actions of the units of the plan its objects are counted from
    (`Compiled.counted`, `pddl.prune.counted_only`; when that leaves some out and its goal is in holder reach, for any
    cause), within half its limits (`RETRY_SECONDS` of wall time with none), then whole within what is left (at least
    `MIN_REST`). When the wide task (or the small one, not fewer) has no valid plan and its count took a plan with a
    needed node made by another of its makers (`count_plans._other_makers`; seen by compiling the other task: its
    objects differ), the task of FOON's own plan unfolded (`compile_goal(..., own=True)`) is planned within what is left, kept only when it solves, with a note (the
    experiment's REG trial 6 macaroni in the pot: 9 objects with the linguine's pour of water, no relaxed solution;
    14 for FOON's own plan, solved). When the last task planned is out of holder reach, the task counted wide with makers chosen by holder
    reach (`compile_goal(..., placed=True)`, whatever its count; inside the counting the plan with those makers
    competes with the first makers' one and the fewest-counting is kept, `instance_counts.derive_counts`, so it may
    be the wide task again: tests/test_relational_placed_gate.py) is planned within what is left, and a note says so; its outcome is kept only when it solves (a plan the relational
    replay rejects, or none, leaves the outcome naming the units out of holder reach). The counts share one memo
    (`compile_goal`'s `memo`): the network is read, and each distinct count derived, encoded and planned, once per
    call (a count asked for again is the same object, `relational_objects.task_objects`, encoded once by
    `encode_relational`: the narrow count that is the one through the stitches, FOON's own plan unfolded or makers by
    holder reach counting as the wide count, are that task: `plan` compares tasks by identity, FOON's own plan's by
    its objects).
    """
    if planner == DEFAULT_PLANNER and planner_cmd is None:
        from . import fd

        fd.prestart_translator()  # its start-up overlaps the encoding
    timings: dict[str, float] = {}
    counting: dict = {}  # what the compiles of this goal share (its counts: the wide one is each one's start)

    def compiled(narrow: bool, through: bool = False, placed: bool = False, own: bool = False) -> Compiled:
        t0 = time.perf_counter()
        try:
            return compile_goal(foon, kitchen, goal, encoding, level, prune=prune, costs=costs, rates=rates,
                                category_index=category_index, constraints=constraints, instances=instances,
                                categories=categories, narrow=narrow, through=through, placed=placed,
                                memo=counting, own=own)
        finally:
            _add(timings, "encode", time.perf_counter() - t0)

    def planned(task: Compiled, limit: float | None, cpu: float | None = None) -> PlanOutcome:
        t0 = time.perf_counter()
        smaller = drop_unbindable(task.task)  # what the planner would ground to nothing (the lanes' work)
        smaller, unreached = drop_unreachable(smaller)  # what no reachable state applies (holder and content states)
        if unreached is not None:
            _add(timings, "write", time.perf_counter() - t0)
            return PlanOutcome(PlanResult(PlanStatus.UNSOLVABLE, (), UNREACHED, unreached), task, timings=timings)
        # the counted plan's units alone, less to explore (not `optimal`: its best plan may be longer)
        first = None if optimal else counted_only(smaller, task.counted)
        if first is not None:
            first, missed = drop_unreachable(first, any_cause=True)  # not worth a planner's time to prove
            first = first if missed is None else None
        _add(timings, "write", time.perf_counter() - t0)
        if first is not None:
            started = _now()
            half = limit / 2 if limit is not None else None if cpu is not None else RETRY_SECONDS
            out = searched(task, first, half, None if cpu is None else cpu / 2)
            if out.status == PlanStatus.SOLVED:
                return out
            took = _now() - started
            limit = None if limit is None else max(limit - took, MIN_REST)
            # the CPU it used (its wall time, which bounds it, from a planner that does not say)
            cpu = None if cpu is None else max(cpu - (took if out.result.cpu is None else out.result.cpu), MIN_REST)
        return searched(task, smaller, limit, cpu)

    def searched(task: Compiled, smaller: PlanningTask, limit: float | None, cpu: float | None) -> PlanOutcome:
        t0 = time.perf_counter()
        chains = Split(smaller)
        if smaller.encoding == "relational":
            if not optimal:  # an action whose parameters multiply: a chain of small parts, joined back below
                chains = split(smaller)
            smaller = in_order(chains.task)  # interchangeable objects taken in one order: the same plans, less to search
        domain_text, problem_text = render(smaller)
        _add(timings, "write", time.perf_counter() - t0)
        result = run_planner(smaller, domain_text, problem_text, planner=planner, planner_cmd=planner_cmd,
                             optimal=optimal, time_limit=limit, search=search, cpu_limit=cpu)
        result = replace(result, plan=chains.join(result.plan))
        return outcome_of(result, task, goal, kitchen.project(level).nodes, timings, up_validate)

    try:
        small = compiled(True)
    except GoalExcluded as exc:
        empty = PlanningTask("excluded", "excluded", encoding, level, (), (), (), ())
        return PlanOutcome(PlanResult(PlanStatus.UNSOLVABLE, (), EXCLUDED, str(exc)), Compiled(empty),
                           timings=timings)
    started = _now()

    def rest() -> float | None:  # the caller's limit less what the small plan and the wide encoding took
        return None if time_limit is None else max(time_limit - (_now() - started), MIN_REST)

    def own(task: Compiled, out: PlanOutcome) -> PlanOutcome:  # the wide task, no valid plan: FOON's own plan unfolded
        if out.status == PlanStatus.SOLVED or encoding != "relational" or task.task.instances == (
                other := compiled(False, own=True)).task.instances:
            return out
        last = planned(other, rest(), cpu_limit)
        return _noted(last, f"objects: {OWN_PLAN}, {len(task.task.instances)}: planned with the "
                            f"{len(other.task.instances)} FOON's own plan unfolded counts") \
            if last.status == PlanStatus.SOLVED else out

    def reached(out: PlanOutcome) -> PlanOutcome:  # out of holder reach: counted wide, with makers by holder reach
        other = compiled(False, placed=True) if out.result.planner == UNREACHED else None
        if other is None or other.task is out.task:  # the task just found out of holder reach (its count the same)
            return out
        last = planned(other, rest(), cpu_limit)
        # a last try, kept only when it solves: a plan the replay rejects (an invalid plan is an `error`) or no plan
        # leaves the outcome that names the units out of holder reach
        return _noted(last, f"objects: {OUT_OF_REACH}, {len(other.task.instances)}") \
            if last.status == PlanStatus.SOLVED else out

    if not small.narrowed:
        return reached(own(small, planned(small, time_limit, cpu_limit)))
    short = min(time_limit or RETRY_SECONDS, cpu_limit or RETRY_SECONDS, RETRY_SECONDS)

    def smallest() -> PlanOutcome:  # out of holder reach: the plan through the stitches alone, then makers by reach
        nonlocal small
        out = planned(small, time_limit, short)
        for again in ({"through": True}, {"placed": True}):
            if out.result.planner == UNREACHED and (other := compiled(True, **again)).narrowed \
                    and other.task is not small.task:  # counted small through the stitches already (no own plan)
                small, out = other, planned(other, time_limit, short)
        return out

    def widest() -> PlanOutcome:  # counted wide; FOON's own plan unfolded, then makers by holder reach, when no plan
        wide = compiled(False)
        return reached(own(wide, planned(wide, rest(), cpu_limit)))

    outs = _first_solved(smallest, widest)
    if len(outs) == 1:
        return outs[0]
    return _noted(outs[1], f"objects: the {count(len(small.task.instances), 'object')} counted small gave no valid plan within "
                           f"{short:g} s of CPU ({outs[0].status}): planned with the {len(outs[1].task.instances)} "
                           "FOON's plan unfolded counts")


def _add(timings: dict[str, float], phase: str, seconds: float) -> None:
    """`seconds` added to `phase` of `timings` (a plan made twice reports both)."""
    timings[phase] = timings.get(phase, 0.0) + seconds


def _first_solved(*attempts: Callable[[], PlanOutcome]) -> tuple[PlanOutcome, ...]:
    """The outcomes of `attempts`, run in order until one is solved (a valid plan): the last one is, or none is."""
    outs: list[PlanOutcome] = []
    for attempt in attempts:
        outs.append(attempt())
        if outs[-1].status == PlanStatus.SOLVED:
            break
    return tuple(outs)


def plan_restoring(foon: Foon, kitchen: Kitchen, goal: Goal, encoding: str = DEFAULT_ENCODING, level: int = 3,
                   **options) -> PlanOutcome:
    """`plan` with restoring units (`pddl.restore`): the network with its restoring units, at the counts they
    allow. When that gives no valid plan (the encoding needs two at once where the unfolded plan reuses one),
    it plans as `plan` does, without them (with its own time limit). A plan that had fewer of the objects in the
    states the restoring units make busy at once than it was given (`planners.copies.busy`: it used them one after
    another) is made again, with the restoring units and only those (`pddl.restore.fewer`), within `RETRY_SECONDS`
    of the planner's CPU (and the caller's wall limit: a loaded machine gives the same plan); it is kept when valid,
    else the first plan is. A note gives the counts and which plan was kept."""
    augmented, counted = with_restore(foon, kitchen, goal, level)
    lowered = ", ".join(f"{k} x {n.describe()}" for n, k in counted.counts if (n, k) not in kitchen.counts)
    outs = _first_solved(lambda: plan(augmented, counted, goal, encoding, level, **options),
                         lambda: plan(foon, kitchen, goal, encoding, level, **options))
    outcome = outs[0]
    note = "restore: restoring units added (an assumption beyond FOON); " + (
        f"objects in the states they restore: {lowered}" if lowered else "no count lowered")
    if outs[-1].status != PlanStatus.SOLVED:
        return _noted(outcome, note)
    if len(outs) > 1:
        outcome, counted, note = outs[1], kitchen, note + f" gave no valid plan ({outcome.status}): planned without them"
    if outcome.trace is None:
        return _noted(outcome, note)
    back = returns(augmented)
    low = fewer(counted, kitchen, back, Counter(o.node for o in outcome.trace.initial),
                busy(outcome.trace, lambda node, start: back.get(node) == start))
    if low is not None:  # the plan used them one after another: plan again with no more than it had busy at once
        cpu = min(options.get("cpu_limit") or RETRY_SECONDS, RETRY_SECONDS)
        tighter = plan(augmented, low, goal, encoding, level, **{**options, "cpu_limit": cpu})
        said = ", ".join(f"{k} x {n.describe()}" for n, k in low.counts if (n, k) not in counted.counts)
        if tighter.status == PlanStatus.SOLVED:
            outcome, note = tighter, note + f"; planned again with them and the most the plan had in use at once: {said}"
        else:
            note += f"; planned again with them and the most the plan had in use at once, {said}: {tighter.status}, kept"
    return _noted(outcome, note)


def _noted(outcome: PlanOutcome, note: str) -> PlanOutcome:
    """`outcome` with `note` after its decoded plan's notes (as it is when nothing was decoded)."""
    if outcome.decoded is None:
        return outcome
    return replace(outcome, decoded=replace(outcome.decoded, notes=(*outcome.decoded.notes, note)))
