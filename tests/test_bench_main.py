"""`python -m bench`: what a reader of the docs meets running a benchmark area (stop 47's newcomer pass)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import types
from pathlib import Path

import pytest

import bench.__main__ as bench_main

ROOT = Path(__file__).resolve().parents[1]


def test_each_area_says_on_stderr_what_runs_before_it_runs(monkeypatch, capsys, tmp_path):
    """`python -m bench --shared ../shared/data --only constraints --repeat 1` (constraints.md) printed nothing
    for minutes: an area prints its figures once measured, 200 pairs later. As a command's slow step does, each
    area says on stderr which runs and what it measures (its module's first line) before it runs."""
    said = []

    def run(ctx):
        said.append(capsys.readouterr().err)

    fake = types.ModuleType("bench.fake")
    fake.__doc__ = "A fake area: what it measures.\n\nMore text."
    fake.run = run
    monkeypatch.setitem(sys.modules, "bench.fake", fake)
    monkeypatch.setattr(bench_main, "AREAS", [*bench_main.AREAS, "fake"])
    (tmp_path / "foon-subgraphs").mkdir()
    monkeypatch.setattr(sys, "argv", ["bench", "--shared", str(tmp_path), "--only", "fake",
                                      "--save", str(tmp_path / "out.json")])
    bench_main.main()
    assert said == ["bench fake: A fake area: what it measures. (its figures follow as each is measured) ...\n"]


def test_a_bench_module_run_alone_says_what_it_measures_once_its_arguments_are_read(monkeypatch, capsys,
                                                                                       tmp_path):
    """`python -m bench.pddl_subgraphs -v` (pddl.md), `bench.pddl_instances -v`, `bench.physical_replay -v` and
    `bench.gen_pruning --fd -v` (generalization.md) printed nothing for their first 15 s and more: a row comes
    once a whole subgraph is measured. Every bench module with `--shared` reads it through
    `harness.shared_data` (tests/test_bench_shared.py), which now says what the module run measures."""
    from bench.harness import shared_data

    (tmp_path / "foon-subgraphs").mkdir()
    run_alone = types.ModuleType("__main__")
    run_alone.__doc__ = "Each shared subgraph alone: what it measures.\n\nMore text."
    run_alone.__spec__ = types.SimpleNamespace(name="bench.fake")
    monkeypatch.setitem(sys.modules, "__main__", run_alone)
    shared_data(tmp_path)
    assert capsys.readouterr().err == "python -m bench.fake: Each shared subgraph alone: what it measures. ...\n"
    run_alone.__spec__ = types.SimpleNamespace(name="bench.__main__")  # `python -m bench`: said per area
    shared_data(tmp_path)
    assert capsys.readouterr().err == ""


def _interrupt_once_running(args: list[str], tmp_path) -> subprocess.CompletedProcess:
    """Run `python -m ARGS` from the repository, send SIGINT once its first stderr line (what it measures) is out
    (the bench is running by then, minutes from its end), and return how it ended."""
    proc = subprocess.Popen([sys.executable, "-m", *args], cwd=ROOT, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, start_new_session=True,
                            env=dict(os.environ, PYTHONPATH=str(ROOT)))
    first = proc.stderr.readline()
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    rest = proc.stderr.read()
    proc.wait(timeout=120)
    return subprocess.CompletedProcess(args, proc.returncode, "", first + rest)


@pytest.mark.parametrize("args", [
    ["bench", "--shared", "tests/data", "--only", "pddl_compile", "--repeat", "1"],
    ["bench.pddl_subgraphs", "-v", "--shared", "tests/data"],
])
def test_ctrl_c_stops_a_bench_with_one_line_and_status_130_as_the_cli_does(args, tmp_path):
    """Ctrl-C in `python -m bench ...` printed a KeyboardInterrupt traceback from wherever the bench was; the CLI
    says `interrupted` and exits 130 (cli/__init__.py): a bench does the same, after the same cleanup."""
    if args[0] == "bench":
        args = [*args, "--save", str(tmp_path / "latest.json")]
    done = _interrupt_once_running(args, tmp_path)
    assert "Traceback" not in done.stderr, done.stderr[-3000:]
    assert (done.returncode, done.stderr.strip().splitlines()[-1]) == (130, "interrupted"), done.stderr[-3000:]


def test_help_lists_each_area_with_what_it_measures_and_where_the_data_is(capsys, monkeypatch):
    """`python -m bench --help` (README: `make bench`; docs: "area `similarity`") listed the area names only, and
    `--shared` as "shared data directory", absent in a clone. It says what each area measures (its module's first
    line, read without importing it: help stays fast) and where the default data is."""
    monkeypatch.setattr(sys, "argv", ["bench", "--help"])
    monkeypatch.setenv("COLUMNS", "200")
    with pytest.raises(SystemExit):
        bench_main.main()
    text = " ".join(capsys.readouterr().out.split())
    for area in bench_main.AREAS:
        module = __import__(f"bench.{area}", fromlist=["run"])
        assert f"{area}: {bench_main.what_it_measures(module)}" in text, area
    assert "default ../shared/data (beside the checkout; a clone has a copy: --shared tests/data)" in text


def test_pddl_subgraphs_summary_says_statuses_in_words():
    """`python -m bench.pddl_subgraphs` (pddl.md) printed `status {<PlanStatus.SOLVED: 'solved'>: 89, ...}`: Python
    reprs where a reader expects the words the table uses."""
    from bench.pddl_subgraphs import Outcome, summary
    from foon2pddl.status import PlanStatus

    rows = [Outcome("a.txt", "tree", PlanStatus.SOLVED, "", "", True, 0.1),
            Outcome("b.txt", "tree", PlanStatus.UNSOLVABLE, "search: unsolvable", "", False, 0.2)]
    first = summary(rows).splitlines()[0]
    assert first == ("tree: 1/2 solved, 2/2 accepted by FD, agrees with native on 2; status solved 1, unsolvable 1; "
                     "median 0.20 s per file (compile + FD)")


def test_pddl_md_figures_table_has_a_row_per_encoding_the_bench_runs():
    """pddl.md's `bench.pddl_subgraphs` table listed four encodings; the bench runs six (`relational`, `ocp`
    too): a reader running it met rows the docs do not have."""
    import re

    from bench.pddl_subgraphs import ENCODINGS

    text = (ROOT / "docs" / "pddl.md").read_text()
    table = text[text.index("| encoding | PDDL accepted by FD |"):]
    rows = re.findall(r"^\| `([a-z-]+)` \| \d+ \| \d+ \| \d+ \| \d+ \|$", table.split("\n\n", 1)[0], re.M)
    assert sorted(rows) == sorted(ENCODINGS)


def test_pddl_subgraphs_says_which_file_it_plans(monkeypatch, capsys):
    """`python -m bench.pddl_subgraphs --shared tests/data` printed its first line and then nothing for 307 s (load
    10-18; `-v` prints its rows only at the end too): each file is a step that says which, and how far the run is."""
    from bench.pddl_subgraphs import ENCODINGS, check_all
    from foon2pddl.cli import progress

    monkeypatch.setattr(progress, "AFTER", 0.0)  # every step counts as slow: each says what it is
    outcomes = check_all(ROOT / "tests" / "data" / "foon-subgraphs", limit=1)
    first = outcomes[0].file
    assert capsys.readouterr().err.splitlines() == [f"{first} (1 of 1): {len(ENCODINGS)} encodings, Fast Downward ..."]
