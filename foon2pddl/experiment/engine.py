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
  stay.
"""

from __future__ import annotations

import logging
import uuid
from collections.abc import Callable, Sequence

from .progress import Progress
from .records import CellStatus, Record
from .worker import Batch, Job, dask_task, run_batch

Sink = Callable[[Record], None]


def run_here(batches: Sequence[Batch], job: Job, sink: Sink, progress: Progress) -> None:
    """Run the batches one by one in this process."""
    def emit(record: Record) -> None:
        sink(record)
        progress.update()

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
        from ..errors import MissingDependencyError

        raise MissingDependencyError("parallel and distributed runs need Dask",
                                     "pip install 'foon2pddl[experiment]' (or 'dask[distributed]')") from None

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
            from ..errors import FoonError

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


def run_dask(batches: Sequence[Batch], job: Job, sink: Sink, progress: Progress, *, jobs: int = 2,
             scheduler: str | None = None) -> None:
    """Run the batches as Dask tasks; `sink` gets every record in this process as its task finishes."""
    from distributed import as_completed

    client, cluster = connect(jobs, scheduler)
    futures: dict = {}
    try:
        link = _dashboard(client)
        if link:
            progress.note(f"Dask dashboard: {link}")
        run = uuid.uuid4().hex[:8]
        for i, batch in enumerate(batches):
            future = client.submit(dask_task, batch.ref(), job, key=f"foon2pddl-{run}-{i}", priority=-i, pure=False,
                                   retries=0)
            futures[future] = batch
        for future in as_completed(list(futures)):
            batch = futures.pop(future)
            try:
                records = future.result()
            except Exception as exc:  # noqa: BLE001 - KilledWorker, CancelledError, a worker's crash
                records = batch.records(CellStatus.LOST, f"task lost, a rerun redoes it ({type(exc).__name__}: {exc})")
                progress.note(f"experiment: {len(records)} cells lost ({type(exc).__name__}); a rerun redoes them")
            for record in records:
                sink(record)
                progress.update()
            future.release()
    finally:
        if futures:
            try:
                client.cancel(list(futures), force=True)
            except Exception:  # noqa: BLE001 - closing anyway
                pass
        try:
            client.close()
            if cluster is not None:
                cluster.close()
        finally:
            if cluster is not None:
                close_local_clusters()
