"""Issue 11 reproductions on planner processes: time limits that hold, no leaked processes or temporary
paths, bounded output, SIGTERM handled like SIGINT, a planner without a plan is not "unsolvable"."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import uuid
from pathlib import Path

import pytest
from conftest import ROOT

from foon2pddl.planners import external
from foon2pddl.planners.process import HEAD_BYTES, TAIL_BYTES, bounded_timeout, run_process

ENV = dict(os.environ, PYTHONPATH=str(ROOT))


def running_with(needle: str) -> list[int]:
    """Processes whose command line contains `needle`."""
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                cmdline = Path(f"/proc/{entry.name}/cmdline").read_bytes().replace(b"\0", b" ").decode()
            except OSError:
                continue
            if needle in cmdline and "pytest" not in cmdline:
                found.append(int(entry.name))
    return found


def unique_sleep() -> str:
    """A sleep duration no other process uses, to find the planner's children by command line."""
    return f"{40 + uuid.uuid4().int % 10**6 / 10**7:.7f}"


def cli(*args: str, tmpdir: Path, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "foon2pddl", *map(str, args)], capture_output=True, text=True,
                          env=dict(ENV, TMPDIR=str(tmpdir)), timeout=timeout)


# ---------------------------------------------------------------- 5. huge and infinite time limits


def test_bounded_timeout():
    assert bounded_timeout(None) is None and bounded_timeout(float("inf")) is None and bounded_timeout(1e7) is None
    assert bounded_timeout(2.5) == 2.5 and bounded_timeout(-1) == 0.001
    with pytest.raises(ValueError):
        bounded_timeout(float("nan"))


@pytest.mark.parametrize("limit", ["1e7", "inf"])
def test_huge_time_limits_plan_with_fd_and_a_command(tmp_path, limit):
    r = cli("plan", "--goal", "guacamole", "--time-limit", limit, tmpdir=tmp_path)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
    planner = f"{sys.executable} -c \"import sys; open(sys.argv[1], 'w').write('')\" {{plan}} {{time}}"
    r = cli("plan", "--goal", "guacamole", "--time-limit", limit, "--planner-cmd", planner, tmpdir=tmp_path)
    assert "OverflowError" not in r.stderr and "Traceback" not in r.stderr, r.stderr


def test_huge_time_limit_with_a_up_engine(tmp_path):
    r = cli("plan", "--goal", "guacamole", "--encoding", "tree", "--time-limit", "inf", "--planner", "pyperplan",
            tmpdir=tmp_path)  # pyperplan takes no conditional effects (relational's)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr


def test_nan_time_limit_is_a_usage_error(tmp_path):
    r = cli("plan", "--goal", "guacamole", "--time-limit", "nan", tmpdir=tmp_path)
    assert r.returncode == 2 and "--time-limit" in r.stderr and "Traceback" not in r.stderr


# ---------------------------------------------------------------- 6. daemon children and the time limit


def test_time_limit_holds_and_daemon_children_die(tmp_path):
    s1, s2 = unique_sleep(), unique_sleep()
    cmd = ["sh", "-c", f"setsid sleep {s1} & sleep {s2}"]
    t0 = time.monotonic()
    run = run_process(cmd, tmp_path, 1.0)
    elapsed = time.monotonic() - t0
    assert run.timed_out and elapsed < 20  # the former code waited for the daemon's 40 s
    assert running_with(f"sleep {s1}") == [] and running_with(f"sleep {s2}") == []


def test_daemon_left_by_a_planner_that_exits_is_killed(tmp_path):
    s = unique_sleep()
    run = run_process(["sh", "-c", f"setsid sleep {s} > /dev/null 2>&1 & echo started"], tmp_path, 30)
    assert run.returncode == 0 and "started" in run.output
    assert running_with(f"sleep {s}") == []


def test_planner_cmd_with_daemon_returns_at_the_limit(tmp_path):
    s1, s2 = unique_sleep(), unique_sleep()
    cmd = f"sh -c 'setsid sleep {s1} & sleep {s2}' {{domain}} {{problem}} {{plan}}"
    t0 = time.monotonic()
    r = cli("plan", "--goal", "guacamole", "--time-limit", "2", "--planner-cmd", cmd, tmpdir=tmp_path)
    assert time.monotonic() - t0 < 30 and r.returncode == 1 and "time limit" in r.stderr, r.stderr
    assert running_with(f"sleep {s1}") == [] and running_with(f"sleep {s2}") == []
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- 12. bounded output


def test_planner_output_is_capped_in_memory(tmp_path):
    size = 8 * (HEAD_BYTES + TAIL_BYTES)
    code = f"import sys; sys.stdout.write('x' * {size}); sys.stdout.write('THE END')"
    run = run_process([sys.executable, "-c", code], tmp_path, 60)
    assert run.output_bytes == size + 7
    assert len(run.output) < HEAD_BYTES + TAIL_BYTES + 200
    assert run.output.endswith("THE END") and "bytes of output omitted" in run.output


# ---------------------------------------------------------------- 13. no plan, no claim: an error


def _fake(tmp_path: Path, body: str) -> str:
    script = tmp_path / "planner.py"
    script.write_text(body)
    return f"{sys.executable} {script} {{domain}} {{problem}} {{plan}}"


def test_planner_exiting_without_plan_is_an_error(tmp_path):
    result = external.solve(_fake(tmp_path, "print('segfault-ish silence')\n"), "(define)", "(define)")
    assert result.status == "error" and "did not say" in result.message


def test_planner_saying_unsolvable_is_unsolvable(tmp_path):
    result = external.solve(_fake(tmp_path, "print('Search stopped without finding a solution.')\n"),
                            "(define)", "(define)")
    assert result.status == "unsolvable"


# ---------------------------------------------------------------- 7. leaked temporary paths and processes


def test_up_engine_timeout_leaves_no_temporary_directory(tmp_path, monkeypatch):
    import tempfile

    from foon2pddl.io.inputs import load_goal, load_kitchen, load_network
    from foon2pddl.pddl.compile import compile_task
    from foon2pddl.planners import up_engine

    net = load_network([])
    foon = net.at(3)
    task = compile_task(foon, load_kitchen(None, net, 3), load_goal("guacamole", None, foon), "state", 3, True,
                        None, None)
    private = tmp_path / "tmp"
    private.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(private))
    # 0.01 s cannot hold the engine's start, so the timeout path (the one that leaked) is taken
    result = up_engine.solve(task, "pyperplan", time_limit=0.01)
    assert result.status == "timeout"
    assert list(private.iterdir()) == []


def test_up_engine_timeout_cli_leaves_nothing(tmp_path):
    r = cli("plan", "--goal", "guacamole", "--planner", "pyperplan", "--encoding", "state", "--time-limit", "0.5",
            tmpdir=tmp_path)
    assert r.returncode in (0, 1) and "Traceback" not in r.stderr, r.stderr
    assert list(tmp_path.iterdir()) == []


def _wait_for(predicate, timeout: float = 60) -> bool:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return False


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_signal_during_planner_kills_it_and_cleans_up(tmp_path, sig):
    s = unique_sleep()
    cmd = f"sh -c 'setsid sleep {s} & sleep {s}' {{domain}} {{problem}} {{plan}}"
    proc = subprocess.Popen([sys.executable, "-m", "foon2pddl", "plan", "--goal", "guacamole", "--planner-cmd", cmd],
                            env=dict(ENV, TMPDIR=str(tmp_path)), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    assert _wait_for(lambda: len(running_with(f"sleep {s}")) >= 3)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == (143 if sig == signal.SIGTERM else 130), err
    assert "Traceback" not in err
    assert running_with(f"sleep {s}") == [] and list(tmp_path.iterdir()) == []


def test_sigterm_during_fd_translation_kills_the_translator(tmp_path):
    proc = subprocess.Popen([sys.executable, "-m", "foon2pddl", "plan", "--goal", "guacamole", "--no-prune"],
                            env=dict(ENV, TMPDIR=str(tmp_path)), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    started = _wait_for(lambda: bool(running_with(str(tmp_path))) or proc.poll() is not None)
    assert started
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode in (0, 143), err  # 0 when the plan was already done
    assert "Traceback" not in err
    assert running_with(str(tmp_path)) == [] and list(tmp_path.iterdir()) == []


def test_a_planner_whose_caller_is_killed_ends_at_its_cpu_limit(tmp_path):
    # a pool worker killed with SIGKILL cannot kill its planner: the run's CPU limit ends it
    mark = f"busy_{uuid.uuid4().hex}"
    child = f"{mark} = 1\nwhile True: pass"
    caller = ("import sys; from pathlib import Path; from foon2pddl.planners.process import run_process; "
              f"run_process([sys.executable, '-c', {child!r}], Path({str(tmp_path)!r}), timeout=3)")
    proc = subprocess.Popen([sys.executable, "-c", caller], env=ENV)
    assert _wait_for(lambda: bool(running_with(mark)))
    # the caller sets the limit just after the child starts: kill it once it has (a fresh clone's run at
    # f601743 killed it in between, on a loaded machine, and the child ran on unlimited)
    assert _wait_for(lambda: all(_cpu_limited(pid) for pid in running_with(mark)))
    proc.kill()
    proc.wait()
    assert running_with(mark), "the child ended with its caller: nothing was tested"
    assert _wait_for(lambda: not running_with(mark), timeout=120)  # 2 x 3 + 1 s of CPU at most


def _cpu_limited(pid: int) -> bool:
    """Whether process `pid` has a CPU time limit (`/proc/PID/limits`)."""
    try:
        text = Path(f"/proc/{pid}/limits").read_text()
    except OSError:
        return False
    line = next((x for x in text.splitlines() if x.startswith("Max cpu time")), "")
    return bool(line) and "unlimited" not in line


def _limits_of(pid: int) -> dict[str, str]:
    """`/proc/PID/limits` as {name: soft limit}."""
    rows = Path(f"/proc/{pid}/limits").read_text().splitlines()[1:]
    return {row[:26].strip(): row[26:47].strip() for row in rows}


def test_a_planner_has_its_limits_even_when_its_caller_dies_right_after_starting_it(tmp_path):
    # the caller is SIGKILLed the moment Popen returns: anything it does after that never happens,
    # so the planner must already carry its CPU and memory limits (set before exec)
    s = unique_sleep()
    caller = ("import os, signal, subprocess, sys; from pathlib import Path; "
              "from foon2pddl.planners.process import run_process\n"
              "real = subprocess.Popen\n"
              "class Dying(real):\n"
              "    def __init__(self, *a, **k):\n"
              "        super().__init__(*a, **k)\n"
              "        os.kill(os.getpid(), signal.SIGKILL)\n"
              "subprocess.Popen = Dying\n"
              f"run_process(['sleep', '{s}'], Path({str(tmp_path)!r}), timeout=3, memory_limit_mb=512)")
    proc = subprocess.run([sys.executable, "-c", caller], env=ENV, timeout=60)
    assert proc.returncode == -signal.SIGKILL
    assert _wait_for(lambda: bool(running_with(f"sleep {s}")), timeout=10)
    (pid,) = running_with(f"sleep {s}")
    try:
        assert _wait_for(lambda: Path(f"/proc/{pid}/comm").read_text().strip() == "sleep", timeout=10)
        limits = _limits_of(pid)
        assert limits["Max cpu time"] == "7"  # 2 x 3 s + 1
        assert limits["Max address space"] == str(512 * 1024 * 1024)
    finally:
        os.kill(pid, signal.SIGKILL)


def test_a_planner_without_limits_runs_unwrapped_and_a_missing_one_is_an_oserror(tmp_path):
    run = run_process(["sh", "-c", "ulimit -t; ulimit -v; cat /proc/$$/comm"], tmp_path)
    assert run.returncode == 0 and run.output.split() == ["unlimited", "unlimited", "sh"]
    run = run_process(["sh", "-c", "ulimit -t; ulimit -v"], tmp_path, 5, memory_limit_mb=300)
    assert run.returncode == 0 and run.output.split() == ["11", str(300 * 1024)]
    with pytest.raises(FileNotFoundError):
        run_process(["no-such-planner-x7"], tmp_path, 5)
    (tmp_path / "not-executable").write_text("#!/bin/sh\n")
    with pytest.raises(PermissionError):
        run_process(["./not-executable"], tmp_path, 5)
