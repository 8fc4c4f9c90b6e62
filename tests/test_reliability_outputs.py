"""Issue 11 reproductions on output: special files and links (`-o`), modes, pairs written as a unit."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading

import pytest
from click.testing import CliRunner
from conftest import ROOT, SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.io import atomic
from foon2pddl.io.atomic import atomic_write, atomic_write_many, read_locked
from foon2pddl.io.interrupts import Terminated

WHIPPED = SUBGRAPHS / "0001-whipped_cream.txt"
ENV = dict(os.environ, PYTHONPATH=str(ROOT))


def foon2pddl(*args: str, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "foon2pddl", *map(str, args)], capture_output=True, text=True,
                          env=ENV, timeout=300, **kw)


def test_output_to_dev_stdout_writes_through():
    proc = foon2pddl("stats", WHIPPED, "-o", "/dev/stdout")
    assert proc.returncode == 0, proc.stderr
    assert "units per file" in proc.stdout or "0001-whipped_cream.txt" in proc.stdout


def test_output_into_a_fifo_writes_through(tmp_path):
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    got: list[bytes] = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    atomic_write(fifo, "hello\n")
    reader.join(30)
    assert got == [b"hello\n"] and stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.fifo"]


def test_symlink_to_a_device_stays_a_symlink(tmp_path):
    link = tmp_path / "null"
    link.symlink_to("/dev/null")
    r = CliRunner().invoke(main, ["stats", str(WHIPPED), "-o", str(link)])
    assert r.exit_code == 0, r.output
    assert link.is_symlink() and stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_symlink_target_is_written_and_the_link_kept(tmp_path):
    target = tmp_path / "real" / "stats.txt"
    target.parent.mkdir()
    target.write_text("old\n")
    link = tmp_path / "stats-link.txt"
    link.symlink_to(target)
    atomic_write(link, "new\n")
    assert link.is_symlink() and target.read_text() == "new\n"
    assert sorted(p.name for p in target.parent.iterdir()) == ["stats.txt"]


def test_existing_file_keeps_its_mode(tmp_path):
    out = tmp_path / "secret.txt"
    out.write_text("old\n")
    out.chmod(0o600)
    r = CliRunner().invoke(main, ["stats", str(WHIPPED), "-o", str(out)])
    assert r.exit_code == 0, r.output
    assert stat.S_IMODE(out.stat().st_mode) == 0o600 and "whipped" in out.read_text()


def test_new_file_follows_umask(tmp_path):
    old = os.umask(0o027)
    try:
        atomic_write(tmp_path / "new.txt", "x")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "new.txt").stat().st_mode) == 0o640


def test_interrupted_pair_leaves_no_hidden_file_and_no_mixed_pair(tmp_path, monkeypatch):
    d, p = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    atomic_write_many({d: "domain A", p: "problem A"})
    calls = []
    real_replace = os.replace

    def interrupted(src, dst):
        calls.append(dst)
        if len(calls) == 2:
            raise Terminated()
        real_replace(src, dst)

    monkeypatch.setattr(atomic.os, "replace", interrupted)
    with pytest.raises(Terminated):
        atomic_write_many({d: "domain B", p: "problem B"})
    monkeypatch.undo()
    assert sorted(x.name for x in tmp_path.iterdir()) == ["domain.pddl", "problem.pddl"]


def test_concurrent_pairs_are_never_mixed(tmp_path):
    """8 writers of (domain i, problem i) into one directory and a locked reader: every pair read matches."""
    d, p = tmp_path / "domain.pddl", tmp_path / "problem.pddl"
    atomic_write_many({d: "0", p: "0"})
    stop = threading.Event()
    mixed: list[tuple[bytes, bytes]] = []

    def writer(i: int) -> None:
        for k in range(40):
            atomic_write_many({d: f"{i}.{k}", p: f"{i}.{k}"})

    def reader() -> None:
        while not stop.is_set():
            a, b = read_locked([d, p])
            if a != b:
                mixed.append((a, b))

    threads = [threading.Thread(target=writer, args=(i,)) for i in range(8)]
    watcher = threading.Thread(target=reader)
    watcher.start()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    stop.set()
    watcher.join()
    assert mixed == [] and d.read_bytes() == p.read_bytes()
    assert sorted(x.name for x in tmp_path.iterdir()) == ["domain.pddl", "problem.pddl"]


def test_concurrent_compile_runs_end_with_one_goals_pair(tmp_path):
    goals = ["guacamole", "lemonade", "tomato soup", "whipped cream"]
    out = tmp_path / "out"
    procs = [subprocess.Popen([sys.executable, "-m", "foon2pddl", "compile", "--goal", g, "-o", str(out)],
                              env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for g in goals]
    for proc in procs:
        proc.wait(300)
    domain, problem = read_locked([out / "domain.pddl", out / "problem.pddl"])
    goal_of = [line for line in domain.decode().splitlines() if line.startswith("; goal: ")]
    assert goal_of and goal_of[0].encode() in problem
    assert sorted(x.name for x in out.iterdir()) == ["domain.pddl", "problem.pddl"]


@pytest.mark.parametrize("many", [False, True], ids=["one file", "a set"])
def test_a_failed_write_removes_the_directories_it_made(tmp_path, monkeypatch, many):
    target = tmp_path / "new" / "dir" / "tree.txt"

    def full(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(atomic.os, "replace", full)
    with pytest.raises(OSError):
        atomic_write_many({target: "x"}) if many else atomic_write(target, "x")
    assert list(tmp_path.iterdir()) == []
    monkeypatch.undo()
    atomic_write(target, "x")  # and a write that succeeds keeps them
    assert target.read_text() == "x"
