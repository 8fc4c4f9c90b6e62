"""The warm translator (`planners.translator`) does what a fresh `python -m fast_downward.translate`
does: the same SAS file byte for byte, the same exit codes and messages, the time limit; and it
recovers when its server dies, is busy, or this interpreter forked."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foon2pddl.io.inputs import load_network
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.render import render
from foon2pddl.planners import fd, translator


def _translate(tmp: Path, domain: str, problem: str, warm: bool, timeout: float | None = 60.0):
    tmp.mkdir(parents=True, exist_ok=True)
    (tmp / "domain.pddl").write_text(domain)
    (tmp / "problem.pddl").write_text(problem)
    os.environ[translator.SWITCH] = "1" if warm else "0"
    try:
        run = fd.translate(tmp / "domain.pddl", tmp / "problem.pddl", tmp / "output.sas", tmp, timeout)
    finally:
        os.environ.pop(translator.SWITCH, None)
    sas = tmp / "output.sas"
    return run, sas.read_bytes() if sas.exists() else None


@pytest.fixture(scope="module")
def example():
    net = load_network([])
    return net.foon, default_kitchen(net.foon)


@pytest.fixture(scope="module")
def goals(example):
    foon, _ = example
    return sorted({n for u in foon.units for n in u.outputs if n.dish is not None})


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data(), encoding=st.sampled_from(["instances", "tree", "state"]))
def test_warm_and_fresh_write_the_same_sas_file(example, goals, tmp_path_factory, data, encoding):
    foon, kitchen = example
    node = data.draw(st.sampled_from(goals))
    goal = resolve_goal(spec_of_node(node), foon)
    domain, problem = render(compile_goal(foon, kitchen, goal, encoding, 3).task)
    tmp = tmp_path_factory.mktemp("tr")
    fresh, fresh_sas = _translate(tmp / "fresh", domain, problem, warm=False)
    warm, warm_sas = _translate(tmp / "warm", domain, problem, warm=True)
    assert (warm.returncode, warm_sas) == (fresh.returncode, fresh_sas)
    assert fresh.returncode == 0 and fresh_sas


def test_input_error_has_the_fresh_translators_exit_code_and_message(tmp_path):
    fresh, _ = _translate(tmp_path / "fresh", "(define (domain d) (:predicates (p))", "(define", warm=False)
    warm, _ = _translate(tmp_path / "warm", "(define (domain d) (:predicates (p))", "(define", warm=True)
    assert warm.returncode == fresh.returncode != 0
    assert fresh.output.strip().splitlines()[-1] == warm.output.strip().splitlines()[-1]


def test_time_limit_kills_the_child_and_the_server_serves_the_next_task(example, goals, tmp_path):
    foon, kitchen = example
    domain, problem = render(compile_goal(foon, kitchen, resolve_goal(spec_of_node(goals[0]), foon),
                                          "instances", 3).task)
    run, _ = _translate(tmp_path / "late", domain, problem, warm=True, timeout=0.001)
    assert run.timed_out
    again, sas = _translate(tmp_path / "next", domain, problem, warm=True)
    assert again.returncode == 0 and sas


def test_a_dead_server_is_replaced(example, goals, tmp_path):
    foon, kitchen = example
    domain, problem = render(compile_goal(foon, kitchen, resolve_goal(spec_of_node(goals[0]), foon),
                                          "tree", 3).task)
    first, _ = _translate(tmp_path / "a", domain, problem, warm=True)
    server = translator._server
    assert first.returncode == 0 and server is not None
    os.killpg(server.proc.pid, signal.SIGKILL)
    server.proc.wait()
    second, sas = _translate(tmp_path / "b", domain, problem, warm=True)
    assert second.returncode == 0 and sas and translator._server is not server


def test_busy_server_falls_back_to_a_fresh_translator(tmp_path):
    assert translator._LOCK.acquire(blocking=False)
    try:
        assert translator.run([], tmp_path, 1.0, fd.bin_dir()) is None
    finally:
        translator._LOCK.release()


def test_switch_off_means_no_server(tmp_path, monkeypatch):
    monkeypatch.setenv(translator.SWITCH, "0")
    assert translator.run([], tmp_path, 1.0, fd.bin_dir()) is None


def test_a_forked_interpreter_starts_its_own_server(example, goals, tmp_path):
    foon, kitchen = example
    domain, problem = render(compile_goal(foon, kitchen, resolve_goal(spec_of_node(goals[0]), foon),
                                          "tree", 3).task)
    _translate(tmp_path / "parent", domain, problem, warm=True)
    parent_server = translator._server.proc.pid
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child reports through the pipe
        ok = 0
        try:
            run, sas = _translate(tmp_path / "child", domain, problem, warm=True)
            ok = int(run.returncode == 0 and bool(sas) and translator._server.proc.pid != parent_server)
        finally:
            os.write(write, bytes([ok]))
            os._exit(0)
    os.close(write)
    assert os.read(read, 1) == b"\x01"
    os.waitpid(pid, 0)
    time.sleep(0.05)
    # the parent's server still answers
    run, sas = _translate(tmp_path / "after", domain, problem, warm=True)
    assert run.returncode == 0 and sas and translator._server.proc.pid == parent_server


def test_prestart_starts_the_server_that_the_next_translation_uses(example, goals, tmp_path, monkeypatch):
    foon, kitchen = example
    domain, problem = render(compile_goal(foon, kitchen, resolve_goal(spec_of_node(goals[0]), foon),
                                          "instances", 3).task)
    translator._drop()
    monkeypatch.setenv(translator.SWITCH, "0")
    fd.prestart_translator()
    assert translator._server is None  # switched off: nothing starts
    monkeypatch.delenv(translator.SWITCH)
    fd.prestart_translator()
    server = translator._server
    assert server is not None and server.usable()
    fd.prestart_translator()
    assert translator._server is server  # a running server is kept
    run, sas = _translate(tmp_path / "t", domain, problem, warm=True)
    assert run.returncode == 0 and sas and translator._server is server


def test_the_server_has_imported_every_module_a_translation_imports(example, goals, tmp_path):
    """`translate_server.LATE_IMPORTS` is complete: after importing what the server imports, translating a FOON
    goal's task (delete-free and with deletes) imports nothing more (else each child imports it again)."""
    import subprocess
    import sys

    from foon2pddl.planners import translate_server

    foon, kitchen = example
    goal = resolve_goal(spec_of_node(goals[0]), foon)
    for k, encoding in enumerate(("tree", "instances")):
        domain, problem = render(compile_goal(foon, kitchen, goal, encoding).task)
        (tmp_path / f"domain{k}.pddl").write_text(domain)
        (tmp_path / f"problem{k}.pddl").write_text(problem)
    script = (
        "import importlib, io, contextlib, sys\n"
        "from fast_downward.translate import main, options, pddl_parser\n"
        f"for name in {translate_server.LATE_IMPORTS!r}: importlib.import_module(name)\n"
        "before = set(sys.modules)\n"
        "for k in (0, 1):\n"
        "    sys.argv = ['translate', f'domain{k}.pddl', f'problem{k}.pddl', '--sas-file', 'out.sas']\n"
        "    options.set_options()\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        main.main()\n"
        "print(sorted(set(sys.modules) - before))\n")
    env = {**os.environ, "PYTHONPATH": str(fd.bin_dir())}
    out = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=env, capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]", out.stdout


def _warm_fake(tmp_path, main: str, timeout: float, cpu: float | None = None):
    """A warm run of a fake translator whose `main` is `main` (source of translate/main.py)."""
    fake = tmp_path / "bin" / "fast_downward" / "translate"
    fake.mkdir(parents=True)
    (fake.parent / "__init__.py").write_text("")
    (fake / "__init__.py").write_text("")
    (fake / "options.py").write_text("def set_options():\n    pass\n")
    (fake / "pddl_parser.py").write_text("class ParseError(Exception):\n    pass\n")
    (fake / "main.py").write_text(main)
    translator._drop()
    try:
        return translator.run(["domain.pddl"], tmp_path, timeout, tmp_path / "bin", cpu=cpu)
    finally:
        translator._drop()


LIMITS = "def main():\n    print(open('/proc/self/limits').read())\n"


def test_the_warm_translators_child_has_the_cpu_limit_of_a_fresh_one(tmp_path):
    # a fresh translator gets its CPU limit before exec (`process.limited`); the warm server's forked child had
    # none, so a caller killed mid-translation left it translating unbounded (the server ends, its child does not)
    from foon2pddl.planners.process import CPU_LIMIT_FACTOR

    run = _warm_fake(tmp_path, LIMITS, 3.0)
    assert run is not None and run.returncode == 0, run
    line = next(x for x in run.output.splitlines() if x.startswith("Max cpu time"))
    assert line.split()[3:5] == [str(CPU_LIMIT_FACTOR * 3 + 1), str(CPU_LIMIT_FACTOR * 3 + 2)], line


def test_the_warm_translators_child_gets_the_cpu_budget_and_reports_its_cpu(tmp_path):
    run = _warm_fake(tmp_path, LIMITS, 60.0, cpu=2.0)
    assert run is not None and run.returncode == 0, run
    line = next(x for x in run.output.splitlines() if x.startswith("Max cpu time"))
    assert line.split()[3:5] == ["2", "3"], line  # soft, then hard a second later
    assert run.cpu is not None and run.cpu >= 0


def test_the_warm_translator_past_its_cpu_budget_exits_with_the_translators_time_limit_code(tmp_path):
    run = _warm_fake(tmp_path, "def main():\n    while True:\n        pass\n", 60.0, cpu=1.0)
    assert run is not None and run.returncode == 21, run  # the server child's SIGXCPU handler, as FD's __main__
    assert run.cpu is not None and run.cpu >= 0.5
    assert fd.translation_failure(run, "fd").status == "timeout"
