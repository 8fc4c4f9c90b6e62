"""Where the cells run: in this process, or on Dask distributed.

- `run_here`: one batch after the other in the calling process (`--jobs 1`).
- `run_dask`: every batch is a Dask task (`worker.dask_task`, shipping the
  batch by reference: `worker.BatchRef`), submitted
  costliest first (Dask priorities); `jobs` > 1 starts a `LocalCluster` of
  `jobs` single-threaded worker processes on this machine, `scheduler` sends the
  tasks to an existing cluster (`dask scheduler` + `dask worker` elsewhere).
  Each task's records come back as it finishes and are passed to `sink` in
  the calling process (which appends them to the results file at once), so
  results stream in whatever runs them. A task whose worker died (Dask retries
  it on another worker first, up to its `allowed-failures`) or that was killed
  or cancelled gives `lost` records for its cells: the run goes on, and a rerun
  redoes them. Interrupting the run (Ctrl-C, SIGTERM) cancels the pending
  tasks and closes a LocalCluster with its workers; records already written
  stay. A cluster without a live worker (none connected, or each dying before it
  has been up for a poll: `Liveness`) for `no_worker_limit` seconds while no task
  finishes gives `lost` records for every pending cell: such a run ends, it never hangs.

`require_dask` and `check_scheduler` run before any work (`runner.run`): a missing
Dask, a malformed address, a port that is not a Dask scheduler (silent, or
answering like HTTP) are errors in seconds, before any output is written.
"""

from __future__ import annotations

import importlib.util
import logging
import re
import socket
import threading
import time
import uuid
from collections.abc import Callable, Sequence
from contextlib import nullcontext

from ..errors import FoonError, MissingDependencyError, UsageError
from ..io.steps import Step, silent_step
from ..model.words import count
from .progress import Progress
from .records import CellStatus, Record
from .worker import Batch, Job, dask_task, run_batch

Sink = Callable[[Record], None]

#: Seconds without a live worker (and without a finished task) after which pending cells are lost.
NO_WORKER_LIMIT = 60.0
#: Seconds between checks of the cluster's workers while no task finishes.
POLL = 1.0
#: Seconds a scheduler has to accept a connection and send its handshake (`check_scheduler`).
CONNECT_TIMEOUT = 10.0
#: Largest handshake accepted from a scheduler (a Dask handshake is a few hundred bytes).
HANDSHAKE_MAX = 1 << 20
_INSTALL = "pip install 'foon2pddl[experiment]' (or 'dask[distributed]')"
#: Dask's address schemes other than TCP: passed to Dask unprobed.
_OTHER_SCHEMES = ("tls", "ws", "wss", "inproc", "ucx")
_TCP = re.compile(r"(?:tcp://)?(?:\[(?P<v6>[0-9A-Fa-f:.%]+)\]|(?P<host>[^\s:/\[\]]+)):(?P<port>\d{1,5})")


def require_dask() -> None:
    """MissingDependencyError with the install command unless Dask distributed is installed (not imported)."""
    try:
        found = importlib.util.find_spec("distributed") is not None
    except (ImportError, ValueError):
        found = False
    if not found:
        raise MissingDependencyError("parallel and distributed runs need Dask", _INSTALL)


def parse_scheduler(address: str) -> tuple[str, int] | None:
    """(host, port) of a TCP scheduler address (`tcp://HOST:PORT`, `HOST:PORT`, `[IPv6]:PORT`); None for
    another scheme Dask knows (tls://, ws://, ...). UsageError for anything else."""
    scheme = address.partition("://")[0] if "://" in address else "tcp"
    if scheme in _OTHER_SCHEMES:
        return None
    m = _TCP.fullmatch(address.strip())
    if m is None or not 0 < int(m["port"]) < 65536:
        raise UsageError(f"scheduler address {address!r} is not tcp://HOST:PORT (PORT 1-65535)")
    return m["v6"] or m["host"], int(m["port"])


def _recv(sock: socket.socket, n: int, deadline: float) -> bytes:
    data = b""
    while len(data) < n:
        sock.settimeout(max(0.001, deadline - time.monotonic()))
        chunk = sock.recv(min(n - len(data), 65536))
        if not chunk:
            raise ConnectionResetError(104, "connection closed")
        data += chunk
    return data


def check_scheduler(address: str, timeout: float = CONNECT_TIMEOUT, step: Step = silent_step) -> None:
    """Fail fast unless `address` is a Dask scheduler: well formed, accepting connections, and sending a
    Dask handshake (an 8-byte little-endian length, then that many bytes, at most HANDSHAKE_MAX) within
    `timeout` seconds. A Dask scheduler writes its handshake first, so nothing is sent to the port:
    a silent port or an HTTP server (which waits for a request) fails here, not in Dask's client.
    The wait is a `step` (the CLI says it): a host that never answers left 11.4 s without a line (stop 58)."""
    where = parse_scheduler(address)
    if where is None:
        return
    deadline = time.monotonic() + timeout
    try:
        with step(f"checking the Dask scheduler {address} (its handshake, within {timeout:g} s)"), \
                socket.create_connection(where, timeout=timeout) as sock:
            size = int.from_bytes(_recv(sock, 8, deadline), "little")
            if not 0 < size <= HANDSHAKE_MAX:
                raise FoonError(f"{address} is not a Dask scheduler (its first message claims {size} bytes)")
            _recv(sock, size, deadline)
    except TimeoutError:
        raise FoonError(f"{address} is not a Dask scheduler: no handshake within {timeout:g} s") from None
    except OSError as exc:
        raise FoonError(f"cannot reach the Dask scheduler {address}: {exc.strerror or exc}") from None


def counted(progress: Progress, record: Record) -> None:
    """`record` done: counted in its (solver, network) group with its time (`Progress.left`)."""
    progress.update(group=(record.solver, record.network), seconds=record.time)


def run_here(batches: Sequence[Batch], job: Job, sink: Sink, progress: Progress) -> None:
    """Run the batches one by one in this process."""
    def emit(record: Record) -> None:
        sink(record)
        counted(progress, record)

    for batch in batches:
        run_batch(batch, job, emit=emit)


def _dashboard(client) -> str | None:
    """The dashboard link, when the cluster serves one (it needs bokeh)."""
    try:
        import bokeh  # noqa: F401
    except ImportError:
        return None
    try:
        return client.dashboard_link
    except Exception:  # noqa: BLE001 - no dashboard is not an error
        return None


def connect(jobs: int, scheduler: str | None):
    """A Dask client and the LocalCluster it owns (None for an existing scheduler)."""
    try:
        import distributed
    except ImportError:
        raise MissingDependencyError("parallel and distributed runs need Dask", _INSTALL) from None

    # Dask's own log lines (a nanny interrupted while starting, a scratch directory already removed with the
    # command's private TMPDIR) are noise here: lost tasks and unreachable schedulers are reported as such.
    # So is asyncio's "Task exception was never retrieved" for a nanny whose worker a signal ended while it
    # started (the run reports the interrupt itself, exit 130/143).
    logging.getLogger("distributed").setLevel(logging.CRITICAL)
    logging.getLogger("asyncio").setLevel(logging.CRITICAL)
    if scheduler is not None:
        try:
            return distributed.Client(scheduler, timeout="20s"), None
        except (OSError, TimeoutError) as exc:
            raise FoonError(f"cannot reach the Dask scheduler {scheduler}: {exc}") from None
    import multiprocessing

    import dask

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    # Forked workers inherit the network views this process built (`worker.view`): a local run builds
    # each network once, not once per worker. Set for the whole run, not only while the cluster starts:
    # a nanny reads it again whenever it restarts a worker, and a spawned one (the default) neither
    # inherits the views nor the quiet signal handling of forked children (`io.interrupts`), so a
    # SIGTERM while it started printed its traceback.
    dask.config.set({"distributed.worker.multiprocessing-method": method})
    try:
        cluster = distributed.LocalCluster(n_workers=jobs, threads_per_worker=1, processes=True,
                                           dashboard_address=":0", silence_logs=logging.CRITICAL)
        return distributed.Client(cluster), cluster
    except BaseException:  # an interrupt while starting: no cluster may outlive the run
        close_local_clusters()
        raise


def close_local_clusters() -> None:
    """Close, quietly, every local cluster still open (one interrupted while starting has no handle):
    otherwise Dask's exit hook closes it and prints a traceback."""
    from distributed.core import Status
    from distributed.deploy.spec import SpecCluster

    for cluster in list(SpecCluster._instances):
        try:
            if getattr(cluster, "status", Status.closed) != Status.closed:
                cluster.close(timeout=10)
        except BaseException:  # noqa: BLE001 - best effort while stopping
            pass


class Liveness:
    """Whether a cluster still has a worker: `check` asks the scheduler for its workers; a worker counts
    as live once it has been seen at two checks (it stayed up over a poll), so workers that die while
    starting do not keep a run waiting. `dead`: none live and no task finished for `limit` seconds."""

    def __init__(self, client, limit: float) -> None:
        self.client = client
        self.limit = limit
        self.since: dict[str, float] = {}  # worker address -> when first seen
        self.last = time.monotonic()  # last sign of life: a live worker or a finished task

    def finished(self) -> None:
        self.last = time.monotonic()

    def dead(self) -> bool:
        now = time.monotonic()
        try:
            workers = set(self.client.nthreads())
        except Exception:  # noqa: BLE001 - a scheduler that does not answer has no live worker either
            workers = set()
        self.since = {w: self.since.get(w, now) for w in workers}
        if any(now - t >= POLL / 2 for t in self.since.values()):
            self.last = now
        return now - self.last > self.limit


def run_dask(batches: Sequence[Batch], job: Job, sink: Sink, progress: Progress, *, jobs: int = 2,
             scheduler: str | None = None, no_worker_limit: float = NO_WORKER_LIMIT, step: Step = silent_step) -> None:
    """Run the batches as Dask tasks; `sink` gets every record in this process as its task finishes.
    Cells still pending when the cluster has had no live worker for `no_worker_limit` s are `lost`.
    `step` wraps stopping a local cluster's workers (seconds under load: the command says so)."""
    from distributed import as_completed

    client, cluster = connect(jobs, scheduler)
    futures: dict = {}
    stopped = threading.Event()  # the run is over: the watcher stops
    try:
        link = _dashboard(client)
        if link:
            progress.note(f"Dask dashboard: {link}")
        run = uuid.uuid4().hex[:8]
        for i, batch in enumerate(batches):
            future = client.submit(dask_task, batch.ref(), job, key=f"foon2pddl-{run}-{i}", priority=-i, pure=False,
                                   retries=0)
            futures[future] = batch
        alive = Liveness(client, no_worker_limit)
        expired = threading.Event()  # set by the watcher when the cluster had no live worker too long
        watcher = threading.Thread(target=_watch, args=(alive, expired, stopped, futures, client), daemon=True,
                                   name="foon2pddl-liveness")
        watcher.start()
        reason = f"task lost: no live Dask worker for {no_worker_limit:g} s; a rerun redoes it"
        for future in as_completed(list(futures)):
            batch = futures.pop(future)
            if expired.is_set() and future.cancelled():
                for record in batch.records(CellStatus.LOST, reason):
                    sink(record)
                    counted(progress, record)
                continue
            _deliver(batch, future, sink, progress)
            alive.finished()
        if expired.is_set():
            progress.note(f"experiment: no live Dask worker for {no_worker_limit:g} s; the cells still pending "
                          "were lost, a rerun redoes them")
    finally:
        stopped.set()
        if futures:
            try:
                client.cancel(list(futures), force=True)
            except Exception:  # noqa: BLE001 - closing anyway
                pass
        progress.close()  # the bar's line ends before the step's line (a terminal's bar is redrawn in place)
        try:
            with step(f"stopping the {jobs} Dask workers") if cluster is not None else nullcontext():
                client.close()
                if cluster is not None:
                    cluster.close()
        finally:
            if cluster is not None:
                close_local_clusters()


def _watch(alive: Liveness, expired: threading.Event, stopped: threading.Event, futures: dict, client) -> None:
    """In a daemon thread, every POLL s until `stopped`: when `alive` says the cluster is dead, set `expired`
    and cancel the pending futures (`futures`, the main thread's dict of them; the main thread, waiting in
    `as_completed`, then records them lost). The main thread's own waiting is left as it was, so interrupts
    reach it as before; no future is referenced here longer than the main thread keeps it."""
    while not stopped.wait(POLL):
        if alive.dead():
            expired.set()
            for _ in range(100):  # the main thread may pop a finished future meanwhile: take the snapshot again
                try:
                    pending = list(futures)
                    break
                except RuntimeError:
                    continue
            else:
                return
            try:
                client.cancel(pending, force=True)
            except Exception:  # noqa: BLE001 - the run is ending anyway
                pass
            return


def _deliver(batch: Batch, future, sink: Sink, progress: Progress) -> None:
    """Pass a finished task's records to `sink` (`lost` ones when the task failed or was cancelled)."""
    try:
        records = future.result()
    except Exception as exc:  # noqa: BLE001 - KilledWorker, CancelledError, a worker's crash
        records = batch.records(CellStatus.LOST, f"task lost, a rerun redoes it ({type(exc).__name__}: {exc})")
        progress.note(f"experiment: {count(len(records), 'cell')} lost ({type(exc).__name__}); a rerun redoes them")
    for record in records:
        sink(record)
        counted(progress, record)
    future.release()
