"""Reliability of the experiment: resume never reuses a cell computed under other settings, damaged
state files are reported not raised, missing extras are refused before any work, a full disk loses
nothing, bad scheduler addresses fail fast and a cluster without workers cannot hang the run."""

from __future__ import annotations

import json
import os
import resource
import socket
import subprocess
import sys
import threading
import time
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import ROOT

from foon2pddl.cli import main
from foon2pddl.experiment import runner
from foon2pddl.experiment.config import Config
from foon2pddl.experiment.protocol import Protocol
from foon2pddl.experiment.records import CellStatus, Record, read_records

HOOKS = ROOT / "tests" / "hooks"
SMALL = ("--trials", "1", "--goals", "3", "--solvers", "native-greedy", "--no-progress")


def config(out: Path, **kw) -> Config:
    return Config((), Protocol(trials=1, goals=3), ("reg", "gen"), ("native-greedy",), out, **kw)


def comparable(records) -> dict:
    return {r.key: replace(r, times={}, setup=0.0, worker=None) for r in records}


def cli(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    return result


def foon2pddl(*args, env: dict | None = None, timeout: float = 300, **kw) -> subprocess.CompletedProcess:
    full = dict(os.environ, PYTHONPATH=os.pathsep.join((str(ROOT), str(HOOKS))), **(env or {}))
    return subprocess.run([sys.executable, "-m", "foon2pddl", *map(str, args)], capture_output=True, text=True,
                          env=full, timeout=timeout, **kw)


# ---------------------------------------------------------------- 1. cells belong to their time limit


def test_resume_under_another_time_limit_recomputes_every_cell(tmp_path):
    short = runner.run(config(tmp_path, time_limit=0.05), progress=False)
    assert short.ran == 6 and all(r.time_limit == 0.05 for r in short.records)
    longer = runner.run(config(tmp_path, time_limit=60), progress=False)
    assert longer.ran == 6 and longer.skipped == 0
    assert all(r.time_limit == 60 for r in longer.records)
    again = runner.run(config(tmp_path, time_limit=60), progress=False)
    assert again.ran == 0 and again.skipped == 6


def test_old_records_without_a_time_limit_take_the_protocol_files(tmp_path):
    first = runner.run(config(tmp_path, time_limit=5), progress=False)
    lines = [json.loads(x) for x in (tmp_path / "results.jsonl").read_text().splitlines()]
    for d in lines:
        del d["time_limit"]  # as written before cells recorded their limit
    (tmp_path / "results.jsonl").write_text("".join(json.dumps(d) + "\n" for d in lines))
    assert runner.run(config(tmp_path, time_limit=5), progress=False).ran == 0
    assert runner.run(config(tmp_path, time_limit=7), progress=False).ran == first.ran


# ---------------------------------------------------------------- 19. a record of another goal is recomputed


def test_record_whose_goal_label_differs_is_recomputed(tmp_path):
    first = runner.run(config(tmp_path), progress=False)
    path = tmp_path / "results.jsonl"
    lines = path.read_text().splitlines()
    data = json.loads(lines[0])
    data["goal_label"] = "something else"
    lines[0] = json.dumps(data)
    path.write_text("\n".join(lines) + "\n")
    again = runner.run(config(tmp_path), progress=False)
    assert again.ran == 1
    assert comparable(again.records) == comparable(first.records)


# ---------------------------------------------------------------- 9. deep nesting in the state files


def test_deeply_nested_result_line_is_reported_and_recomputed(tmp_path):
    first = runner.run(config(tmp_path), progress=False)
    path = tmp_path / "results.jsonl"
    lines = path.read_text().splitlines()
    lines[1] = "[" * 200_000 + "]" * 200_000
    path.write_text("\n".join(lines) + "\n")
    warnings: list[str] = []
    assert len(read_records(path, warnings)) == 5 and f"{path}:2: warning: " in warnings[0]
    again = runner.run(config(tmp_path), progress=False)
    assert again.ran == 1 and comparable(again.records) == comparable(first.records)
    (tmp_path / "runs.jsonl").write_text("[" * 200_000 + "\n")
    assert runner.read_runs(tmp_path / "runs.jsonl") == ()


def test_deeply_nested_protocol_file_is_an_error_not_a_traceback(tmp_path):
    assert cli("experiment", *SMALL, "-o", tmp_path).exit_code == 0
    (tmp_path / "protocol.json").write_text("[" * 200_000)
    r = cli("experiment", *SMALL, "-o", tmp_path)
    assert r.exit_code == 2 and f"{tmp_path / 'protocol.json'}: error: " in r.stderr, r.output


# ---------------------------------------------------------------- 11, 15. missing extras: refused before any work


@pytest.mark.parametrize("env, args, hint", [
    ({"FOON2PDDL_TEST_BLOCK": "distributed"}, ("--jobs", "2"), "pip install 'foon2pddl[experiment]'"),
    ({"FOON2PDDL_TEST_BLOCK": "distributed"}, ("--scheduler", "tcp://127.0.0.1:1"),
     "pip install 'foon2pddl[experiment]'"),
    ({"FOON2PDDL_TEST_NO_WORDNET": "1"}, (), "nltk.downloader wordnet"),
    ({"FOON2PDDL_TEST_BLOCK": "nltk"}, (), "pip install 'foon2pddl[gen]'"),
])
def test_experiment_without_an_extra_exits_2_before_any_cell(tmp_path, env, args, hint):
    out = tmp_path / "run"
    r = foon2pddl("experiment", *SMALL, *args, "-o", out, env={**env, "FOON2PDDL_CACHE": str(tmp_path / "c")})
    assert r.returncode == 2 and hint in r.stderr and "Traceback" not in r.stderr, r.stderr
    assert not out.exists()  # nothing written, nothing computed


def test_experiment_without_wordnet_runs_the_networks_that_do_not_need_it(tmp_path):
    r = foon2pddl("experiment", *SMALL, "--networks", "reg,gen", "-o", tmp_path / "run",
                  env={"FOON2PDDL_TEST_NO_WORDNET": "1", "FOON2PDDL_CACHE": str(tmp_path / "c")})
    assert r.returncode == 0, r.stderr


def test_expand_without_nltk_says_how_to_install_it(tmp_path):
    r = foon2pddl("expand", "-o", tmp_path / "x.txt", env={"FOON2PDDL_TEST_BLOCK": "nltk",
                                                           "FOON2PDDL_CACHE": str(tmp_path / "c")})
    assert r.returncode == 2 and "pip install 'foon2pddl[gen]'" in r.stderr and "Traceback" not in r.stderr
    assert not (tmp_path / "x.txt").exists()


# ---------------------------------------------------------------- 10. a full disk loses nothing


def _file_size_limit(limit: int):
    def apply() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))  # writes past it fail (EFBIG)
    return apply


def test_full_disk_is_an_error_and_a_resume_completes_the_run(tmp_path):
    out = tmp_path / "run"
    args = ("experiment", "--trials", "2", "--goals", "5", "--solvers", "native-greedy", "--networks", "reg,gen",
            "--no-progress", "-o", out)
    r = foon2pddl(*args, preexec_fn=_file_size_limit(3000))
    assert r.returncode == 2 and "Traceback" not in r.stderr and "cannot write" in r.stderr, r.stderr
    kept = read_records(out / "results.jsonl")
    assert 0 < len(kept) < 20
    r = foon2pddl(*args)
    assert r.returncode == 0, r.stderr
    assert f"{20 - len(kept)} cells run, {len(kept)} reused" in r.stdout
    whole = runner.run(Config((), Protocol(trials=2, goals=5), ("reg", "gen"), ("native-greedy",),
                              tmp_path / "ref"), progress=False)
    assert comparable(read_records(out / "results.jsonl").values()) == comparable(whole.records)


def test_output_directory_under_a_file_is_a_located_error(tmp_path):
    (tmp_path / "f").write_text("x\n")
    r = cli("experiment", *SMALL, "-o", tmp_path / "f" / "run")
    assert r.exit_code == 2 and "error: " in r.stderr, r.output


# ---------------------------------------------------------------- 8. scheduler addresses that are not Dask


def _server(behaviour: str):
    """A TCP server on 127.0.0.1 that answers like HTTP or stays silent; (address, stop)."""
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    sock.listen()
    sock.settimeout(0.2)
    stop = threading.Event()
    held = []

    def serve() -> None:
        while not stop.is_set():
            try:
                conn, _ = sock.accept()
            except OSError:
                continue
            held.append(conn)
            if behaviour == "http":
                try:
                    conn.recv(65536)
                    conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")
                except OSError:
                    pass

    threading.Thread(target=serve, daemon=True).start()

    def close() -> None:
        stop.set()
        for c in held:
            c.close()
        sock.close()

    return f"tcp://127.0.0.1:{sock.getsockname()[1]}", close


@pytest.mark.parametrize("address", ["nothing", "tcp://127.0.0.1", "tcp://[::1", "tcp://127.0.0.1:99999",
                                     "tcp://:8786"])
def test_malformed_scheduler_address_is_a_usage_error_before_any_output(tmp_path, address):
    pytest.importorskip("distributed")
    r = cli("experiment", *SMALL, "--scheduler", address, "-o", tmp_path / "run")
    assert r.exit_code == 2 and "scheduler" in r.stderr, r.output
    assert not (tmp_path / "run").exists()


@pytest.mark.parametrize("behaviour", ["http", "silent"])
def test_a_port_that_is_not_dask_fails_fast_before_any_output(tmp_path, behaviour):
    pytest.importorskip("distributed")
    address, close = _server(behaviour)
    try:
        t0 = time.monotonic()
        r = foon2pddl("experiment", *SMALL, "--scheduler", address, "-o", tmp_path / "run", timeout=120)
        assert time.monotonic() - t0 < 60
    finally:
        close()
    assert r.returncode == 2 and "Dask scheduler" in r.stderr and "Traceback" not in r.stderr, r.stderr
    assert not (tmp_path / "run").exists()


# ---------------------------------------------------------------- 3. a cluster with no live worker cannot hang the run


def test_a_cluster_without_workers_loses_its_cells_in_bounded_time(tmp_path):
    distributed = pytest.importorskip("distributed")
    import dask

    with dask.config.set({"distributed.scheduler.idle-timeout": None}), \
            distributed.LocalCluster(n_workers=0, processes=False, dashboard_address=":0") as cluster:
        t0 = time.monotonic()
        summary = runner.run(config(tmp_path, scheduler=cluster.scheduler_address, no_worker_limit=3.0),
                             progress=False)
        assert time.monotonic() - t0 < 60
    assert summary.ran == summary.lost == 6
    assert all(r.status == CellStatus.LOST and "no live Dask worker" in r.reason for r in summary.records)
    again = runner.run(config(tmp_path), progress=False)  # the lost cells are redone
    assert again.ran == 6 and again.lost == 0


def test_record_time_limit_round_trips():
    r = Record(trial=1, goal=1, network="reg", solver="native-greedy", goal_label="x", status="solved",
               time_limit=2.5)
    assert Record.from_json(r.to_json()) == r
    with pytest.raises(ValueError):
        Record.from_json(r.to_json().replace("2.5", '"soon"'))
