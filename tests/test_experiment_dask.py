"""The experiment on Dask distributed: a LocalCluster gives the same records as one process; a cluster
reached by `--scheduler` (started here on 127.0.0.1) loses a killed worker's cells and a rerun redoes them."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from collections import Counter
from dataclasses import replace
from pathlib import Path

import pytest

from foon2pddl.experiment import grid, runner
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.records import CellStatus, Record
from foon2pddl.experiment.solvers import SOLVERS

pytest.importorskip("distributed")

ROOT = Path(__file__).resolve().parents[1]
SOLVED = ("native-greedy", "native-complete", "native-optimal", "fd-tree")


def _comparable(records) -> dict:
    """Records without what legitimately differs between runs: times, shared setup time, worker."""
    return {r.key: replace(r, times={}, setup=0.0, worker=None) for r in records}


def test_local_cluster_of_two_workers_equals_one_process(tmp_path):
    config = Config((), Protocol(trials=2, goals=5), ("reg", "gen"), SOLVED, tmp_path / "one")
    one = runner.run(config, progress=False)
    two = runner.run(replace(config, out_dir=tmp_path / "two", jobs=2), progress=False)
    assert one.ran == two.ran == 2 * 5 * 2 * len(SOLVED)
    assert {r.worker for r in one.records} == {None}
    assert all(r.worker and r.worker.startswith("tcp://") for r in two.records)
    assert _comparable(two.records) == _comparable(one.records)
    assert any(r.solved for r in one.records) and any(not r.solved for r in one.records)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_for(port: int, seconds: float = 60.0) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=1):
                return
        except OSError:
            time.sleep(0.2)
    raise RuntimeError(f"nothing listens on 127.0.0.1:{port}")


@pytest.fixture
def cluster(tmp_path):
    """A Dask scheduler and two single-threaded workers (no nanny: a dead worker stays dead), all stopped after."""
    port = _free_port()
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), str(ROOT / "tests"), os.environ.get("PYTHONPATH", "")]),
           "DASK_DISTRIBUTED__SCHEDULER__ALLOWED_FAILURES": "0",
           "FOON2PDDL_CRASH_MARKER": str(tmp_path / "crashed")}
    procs = []

    def start(*args):
        procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_" + args[0], *args[1:]], env=env,
                                      stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True))

    address = f"tcp://127.0.0.1:{port}"
    try:
        start("scheduler", "--host", "127.0.0.1", "--port", str(port), "--dashboard-address", ":0")
        _wait_for(port)
        yield address, env, start
    finally:
        for p in procs:
            try:
                os.killpg(p.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        for p in procs:
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()


def _start_workers(address, env, start, count=2) -> None:
    from distributed import Client

    for _ in range(count):
        start("worker", address, "--nthreads", "1", "--no-nanny", "--preload", "dask_crash_preload")
    with Client(address, timeout="30s") as client:
        client.wait_for_workers(count, timeout=60)


def test_scheduler_path_with_a_killed_worker_resumes_every_cell_exactly_once(tmp_path, cluster, monkeypatch):
    address, env, start = cluster
    sys.path.insert(0, str(ROOT / "tests"))
    try:
        import dask_crash_preload
    finally:
        sys.path.remove(str(ROOT / "tests"))
    monkeypatch.setitem(SOLVERS, "crash-once", dask_crash_preload.CRASH_ONCE)
    protocol = Protocol(trials=2, goals=6)
    reference = runner.run(Config((), protocol, ("reg", "gen"), ("native-complete",), tmp_path / "ref"),
                           progress=False)
    crash_goal = next(r.goal_label for r in reference.records if r.trial == 1 and r.goal == 3 and r.network == "reg")
    monkeypatch.setenv("FOON2PDDL_CRASH_MARKER", env["FOON2PDDL_CRASH_MARKER"])
    env["FOON2PDDL_CRASH_GOAL"] = crash_goal
    _start_workers(address, env, start)

    config = Config((), protocol, ("reg", "gen"), ("crash-once", "native-complete"), tmp_path / "run",
                    scheduler=address)
    first = runner.run(config, progress=False)
    assert Path(env["FOON2PDDL_CRASH_MARKER"]).exists()  # a worker really died mid-run
    lost = [r for r in first.records if r.status == CellStatus.LOST]
    assert first.lost == len(lost) > 0
    assert {(r.solver, r.trial) for r in lost} >= {("crash-once", 1)}
    assert all("rerun" in r.reason for r in lost)

    again = runner.run(config, progress=False)
    assert again.ran == len(lost) and again.lost == 0
    lines = [Record.from_json(x) for x in config.results_path.read_text().splitlines()]
    answered = Counter(r.key for r in lines if r.status != CellStatus.LOST)
    assert set(answered) == grid.cell_keys(config) and set(answered.values()) == {1}
    mine = {k[:3] + ("native-complete",) + k[4:]: r for k, r in _comparable(again.records).items()
            if k[3] == "crash-once"}
    ref = _comparable(reference.records)
    assert {k: replace(r, solver="native-complete") for k, r in mine.items()} == ref
