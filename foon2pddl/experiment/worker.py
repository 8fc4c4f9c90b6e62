"""The worker side of a run: one task answers a batch of cells; networks and prepared solvers are cached.

A task is a `Batch`: some goals of one trial, on one network, for one solver,
at one point of the sweep. Whatever process runs it (the main one, or a Dask
worker on this or another machine) builds the network views it needs once and
keeps them (`_CACHE`), keyed by the inputs and the parameters a view depends on,
so networks are never shipped with tasks. Nor are trials: a Dask task is a
`BatchRef` (trial index, goal indexes and labels), and the worker draws the
trials itself, once per point (`draw_at`: seeded, the same in every process;
the labels are checked). A trial's kitchen is hundreds of nodes: pickled with
each of hundreds of tasks it cost the scheduler's process (the main one for a
LocalCluster) seconds of CPU per run. The solver prepared for a (trial, network,
solver) (a fixpoint, an FD translation) is kept too (the last few), so the
next batch of the same trial on the same worker reuses it.

A worker reads the input files itself, by path: on another machine they must
be at the same path (a shared filesystem) with the same contents, which it
checks against the run's fingerprint before answering.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from ..errors import FoonError, FoonInputError
from ..io.files import expand_paths
from ..io.inputs import Network, example_path, load_network
from .networks import DEFAULT_NETWORK, NetworkView, build_view
from .outcomes import Outcome
from .params import Point, label, network_hooks, network_key, protocol_at, transform_kitchen, transform_network
from .protocol import Draw, Protocol, Trial, draw
from .records import CellStatus, Record
from .setting import Setting
from .solvers import get_solver

#: Longest reason kept in a record (unreachable goals can list many missing nodes).
REASON_MAX = 300
#: Prepared solvers a worker keeps (an EXP translation is tens of MB).
PREPARED_KEPT = 2


def input_files(paths: Sequence[str]) -> list[Path]:
    """The FOON files a run reads (the embedded example when no path is given)."""
    return expand_paths(paths or [example_path()])


def fingerprint(paths: Sequence[str]) -> str:
    """SHA-256 over the names and contents of the input files: results belong to these exact inputs."""
    h = hashlib.sha256()
    for p in input_files(paths):
        h.update(p.name.encode() + b"\0" + p.read_bytes() + b"\0")
    return h.hexdigest()


@dataclass(frozen=True)
class Job:
    """What every task of a run shares: the inputs (paths and their fingerprint), protocol and time limit;
    `cache`, a directory of Fast Downward translations the run's processes share (local runs only:
    `setting.Setting`)."""

    paths: tuple[str, ...]
    fingerprint: str
    protocol: Protocol
    time_limit: float
    cache: str | None = None


@dataclass(frozen=True)
class Batch:
    """The pending goals (1-based indexes into the trial's goals) of one (point, trial, network, solver)."""

    trial: Trial
    network: str
    solver: str
    goals: tuple[int, ...]
    point: Point = ()

    @property
    def params(self) -> dict:
        return dict(self.point)

    def ref(self) -> BatchRef:
        """The batch as a Dask task ships it."""
        labels = tuple(self.trial.goals[g - 1].describe() for g in self.goals)
        return BatchRef(self.trial.index, self.network, self.solver, self.goals, labels, self.point)

    def records(self, status: CellStatus, reason: str, time_limit: float | None = None) -> list[Record]:
        """One record per goal with the same status and reason (a failed or lost task)."""
        return self.ref().records(status, reason, time_limit)


@dataclass(frozen=True)
class BatchRef:
    """A batch by reference: its trial by index, its goals by index and label (`Batch.ref`, `resolve`)."""

    trial: int
    network: str
    solver: str
    goals: tuple[int, ...]
    labels: tuple[str, ...]  # the goals' labels, as the run's process drew them
    point: Point = ()

    def resolve(self, job: Job) -> Batch:
        """The batch, its trial drawn in this process; FoonError when this process draws other goals."""
        trials = draw_at(job.paths, job.protocol, self.point).trials
        batch = Batch(trials[self.trial - 1], self.network, self.solver, self.goals, self.point) \
            if 1 <= self.trial <= len(trials) else None
        if batch is None or batch.ref() != self:
            raise FoonError(f"this worker draws other goals for trial {self.trial} than the run's process "
                            "(another foon2pddl version?)")
        return batch

    def records(self, status: CellStatus, reason: str, time_limit: float | None = None) -> list[Record]:
        """One record per goal with the same status and reason (a failed or lost task)."""
        params = dict(self.point)
        return [Record(trial=self.trial, goal=g, network=self.network, solver=self.solver, goal_label=label,
                       status=status, reason=_cut(reason), params=params, time_limit=time_limit)
                for g, label in zip(self.goals, self.labels, strict=True)]


_CACHE: dict = {"networks": {}, "views": {}, "draws": {}, "prepared": OrderedDict(), "checked": set()}


def _network(paths: tuple[str, ...], point: Point) -> Network:
    key = (paths, network_hooks(point))
    nets = _CACHE["networks"]
    if key not in nets:
        if paths not in nets:
            nets[paths] = load_network(list(paths))
        base = nets[paths]
        nets[key] = replace(base, foon=transform_network(base.foon, point)) if key[1] else base
    return nets[key]


def view(paths: tuple[str, ...], protocol: Protocol, point: Point, name: str) -> NetworkView:
    """The network view `name` at `point`, built once per process."""
    key = _view_key(paths, protocol, point, name)
    views = _CACHE["views"]
    if key not in views:
        at = protocol_at(protocol, point)
        views[key] = build_view(name, _network(paths, point), at.level, at.threshold, at.similarity)
    return views[key]


def has_view(paths: tuple[str, ...], protocol: Protocol, point: Point, name: str) -> bool:
    """Whether this process has built `view`'s answer already."""
    return _view_key(paths, protocol, point, name) in _CACHE["views"]


def _view_key(paths: tuple[str, ...], protocol: Protocol, point: Point, name: str) -> tuple:
    return paths, network_key(protocol, point), name


def draw_at(paths: tuple[str, ...], protocol: Protocol, point: Point) -> Draw:
    """The trials at one point of the sweep, drawn once per process on REG at the point's level, before the
    point's network hooks (a hook such as `banned-motions` changes what can be made, not what is asked)."""
    at = protocol_at(protocol, point)
    key = (paths, at)
    draws = _CACHE["draws"]
    if key not in draws:
        unhooked = tuple((n, v) for n, v in point if (n, v) not in network_hooks(point))
        draws[key] = draw(view(paths, protocol, unhooked, DEFAULT_NETWORK).foon, at)
    return draws[key]


def _check_inputs(job: Job) -> None:
    """Refuse to answer from input files that differ from the run's (another machine, no shared filesystem)."""
    if job.fingerprint in _CACHE["checked"]:
        return
    try:
        mine = fingerprint(job.paths)
    except (OSError, FoonInputError) as exc:
        raise FoonError(f"this worker cannot read the input files ({exc}); they must be at the same path on every "
                        "machine", path=",".join(job.paths) or None) from None
    if mine != job.fingerprint:
        raise FoonInputError(",".join(job.paths), 0, "the input files differ on this worker "
                             "(same paths, other contents): use a shared filesystem or identical copies")
    _CACHE["checked"].add(job.fingerprint)


def _prepared(batch: Batch, job: Job):
    key = (job.paths, job.protocol, batch.point, batch.trial.index, batch.network, batch.solver, job.time_limit)
    cache: OrderedDict = _CACHE["prepared"]
    if key in cache:
        cache.move_to_end(key)
        return cache[key]
    v = view(job.paths, job.protocol, batch.point, batch.network)
    kitchen = transform_kitchen(batch.trial.kitchen, batch.point)
    shared = Path(job.cache) if job.cache is not None else None
    per_item = protocol_at(job.protocol, batch.point).objects_per_item
    prepared = get_solver(batch.solver).prepare(Setting(v, kitchen, job.time_limit, shared, per_item))
    cache[key] = prepared
    while len(cache) > PREPARED_KEPT:
        cache.popitem(last=False)
    return prepared


def _cut(reason: str) -> str:
    return reason if len(reason) <= REASON_MAX else reason[:REASON_MAX - 3] + "..."


def run_batch(batch: Batch, job: Job, emit: Callable[[Record], None] | None = None,
              worker: str | None = None) -> list[Record]:
    """Answer every goal of `batch`, passing each record to `emit` as it finishes; return them all.

    Never raises for a solver's failure: a failed preparation or goal becomes an `error` record,
    so every goal of the batch gets exactly one record.
    """
    out: list[Record] = []
    try:
        _check_inputs(job)
        prepared = _prepared(batch, job)
    except Exception as exc:  # noqa: BLE001 - recorded, the run goes on
        status, reason = CellStatus.ERROR, f"preparation failed: {type(exc).__name__}: {exc}"
        if network_hooks(batch.point) and not view(job.paths, job.protocol, batch.point, batch.network).foon.units:
            status, reason = CellStatus.UNSOLVABLE, f"no unit is left at {label(batch.point)}"
        out = batch.records(status, reason, job.time_limit)
        for r in out:
            (emit or _ignore)(r)
        return out
    for g in batch.goals:
        node = batch.trial.goals[g - 1]
        try:
            outcome = _banned(prepared, node, batch.point) or prepared.solve(node)
        except Exception as exc:  # noqa: BLE001 - recorded, the run goes on
            outcome = Outcome(CellStatus.ERROR, f"{type(exc).__name__}: {exc}")
        record = Record(trial=batch.trial.index, goal=g, network=batch.network, solver=batch.solver,
                        goal_label=node.describe(), status=outcome.status, reason=_cut(outcome.reason),
                        times=outcome.times, setup=prepared.setup, units=outcome.units,
                        plan_length=outcome.plan_length, validated=outcome.validated,
                        proven_optimal=outcome.proven_optimal, foon_valid=outcome.foon_valid,
                        bound=outcome.bound, gap=outcome.gap, params=batch.params, worker=worker,
                        time_limit=job.time_limit, executable=outcome.executable,
                        executable_reason=outcome.executable_reason, extra_objects=outcome.extra_objects,
                        repeated=outcome.repeated)
        out.append(record)
        (emit or _ignore)(record)
    return out


def _banned(prepared, node, point: Point) -> Outcome | None:
    """UNSOLVABLE when the point's network hooks (bans, `bans.py`) left no unit making the goal: the
    trial was drawn before the hooks, so a goal may no longer resolve; None otherwise (solve it)."""
    if not network_hooks(point):
        return None
    try:
        prepared.view.goal_of(node)
    except FoonError as exc:  # the goal no longer resolves (UsageError)
        return Outcome(CellStatus.UNSOLVABLE, f"no unit left at {label(point)} makes it: {exc.message}")
    return None


def _ignore(record: Record) -> None:
    pass


def dask_task(ref: BatchRef, job: Job) -> list[Record]:
    """`run_batch` as a Dask task: the records, each naming the worker that computed it."""
    from distributed import get_worker

    try:
        _check_inputs(job)
        batch = ref.resolve(job)
    except Exception as exc:  # noqa: BLE001 - recorded, the run goes on
        return ref.records(CellStatus.ERROR, f"preparation failed: {type(exc).__name__}: {exc}")
    return run_batch(batch, job, worker=get_worker().address)
