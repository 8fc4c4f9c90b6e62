"""A run's wall time says what it covers: runs.jsonl's `seconds` time the cells only, so a run that built EXP from
an empty cache for 100 s reported '6,000 cells ... in 19.6 s wall time' where the command's own summary line said
118.7 s (newcomer pass nc46a, 7edb3f9). The log now also records `setup_seconds` (drawing the trials, reading the
cells already run, building the networks), and the report names both."""

from __future__ import annotations

import json
import time

from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.experiment import runner


def test_the_time_before_the_first_cell_is_logged_and_reported_apart(tmp_path, monkeypatch):
    build = runner.build_networks

    def slow_build(*args, **kwargs):
        time.sleep(0.5)
        return build(*args, **kwargs)

    monkeypatch.setattr(runner, "build_networks", slow_build)
    report = tmp_path / "report.md"
    r = CliRunner().invoke(main, ["experiment", "--trials", "1", "--goals", "2", "--networks", "reg",
                                  "--solvers", "native-greedy", "-o", str(tmp_path / "out"), "--report", str(report)])
    assert r.exit_code == 0, r.output
    (logged,) = [json.loads(line) for line in (tmp_path / "out" / "runs.jsonl").read_text().splitlines()]
    assert logged["setup_seconds"] >= 0.5  # the networks' building is not in the cells' seconds
    text = report.read_text()
    assert "s wall time running the cells" in text
    assert "s before them drawing the trials and building the networks" in text
