"""No command is silent for long (issue 24): the slow-step mechanism (`cli.progress`) and the commands
`python -m bench.silence` found silent. Nothing here depends on the machine's speed: a threshold of 0
makes every step say what it is, a command's silence budget is set by hand, and a threshold of an
hour keeps every step quiet."""

from __future__ import annotations

import re
import time

import pytest
from click.testing import CliRunner
from conftest import ROOT, SUBGRAPHS, substitution_lines_without_wordnet

from foon2pddl.cli import main, progress


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def said_steps(stderr: str) -> list[str]:
    """The progress lines of `stderr` (`step ...`, or `step ... 3 s` as it goes on), not a note's cut list, whose
    `... (N more)` (`words.first_of`) a `plan` prints whatever the budget."""
    return [line for line in stderr.splitlines() if re.search(r" \.\.\.(?= \d|$)", line)]


@pytest.fixture
def every_step_speaks(monkeypatch):
    monkeypatch.setattr(progress, "AFTER", 0.0)


# -- the mechanism -------------------------------------------------------------------------------


def steps_said(capsys, *names) -> str:
    for name in names:
        with progress.slow_step(name):
            pass
    return capsys.readouterr().err


def test_a_command_silent_past_its_budget_says_its_next_step_at_once(monkeypatch, capsys):
    monkeypatch.setattr(progress, "AFTER", 1.5)
    monkeypatch.setattr(progress, "_process_start", time.monotonic() - 60)  # the first command: since the process
    progress.begin()
    assert steps_said(capsys, "late step") == "late step ...\n"


def test_a_command_within_its_budget_stays_quiet(monkeypatch, capsys):
    monkeypatch.setattr(progress, "AFTER", 3600.0)
    progress.begin()
    assert steps_said(capsys, "one", "two") == ""


def test_short_steps_in_a_row_cannot_add_up_to_a_long_silence(monkeypatch, capsys):
    """The budget counts from the command's start, not from each step's: a step that begins once the
    command has been quiet for AFTER seconds speaks however short it is."""
    monkeypatch.setattr(progress, "AFTER", 3600.0)
    progress.begin()
    monkeypatch.setattr(progress, "_quiet_since", time.monotonic() - 3600.0)  # an hour of short silent steps
    assert steps_said(capsys, "the next one") == "the next one ...\n"


def test_a_step_that_spoke_restarts_the_budget(monkeypatch, capsys):
    monkeypatch.setattr(progress, "AFTER", 3600.0)
    progress.begin()
    with progress.slow_step("announced", after=0):
        pass
    assert progress._quiet_since is not None and time.monotonic() - progress._quiet_since < 60
    assert steps_said(capsys, "after it") == "announced ...\n"


def test_through_a_pipe_the_silence_after_a_step_counts_from_its_last_line(monkeypatch, capsys):
    """Stop 53's pass (nc53b): `check tests/data/foon-subgraphs` through a pipe went 2.2 s (load 10) from the last
    beat of `opening WordNet ...` to `checking ... for defects ...`: a log has no closing line, and the next step's
    budget counted from the WordNet step's end, up to BEAT + AFTER after its last line."""
    monkeypatch.setattr(progress, "AFTER", 0.2)
    progress.begin()
    with progress.slow_step("one long call", after=0):
        time.sleep(0.3)  # said at once, then silent past the budget before it ends
    assert steps_said(capsys, "the next step") == "one long call ...\nthe next step ...\n"


def test_a_step_inside_an_announced_one_counts_from_its_own_start(monkeypatch, capsys):
    monkeypatch.setattr(progress, "AFTER", 3600.0)
    monkeypatch.setattr(progress, "_quiet_since", time.monotonic() - 7200.0)
    with progress.slow_step("outer"):
        with progress.slow_step("inner"):
            pass
    assert capsys.readouterr().err == "outer ...\n"


def test_each_command_invocation_starts_its_own_budget(monkeypatch):
    monkeypatch.setattr(progress, "_quiet_since", time.monotonic() - 7200.0)
    monkeypatch.setattr(progress, "AFTER", 3600.0)
    assert said_steps(run("plan", "--goal", "guacamole").stderr) == []


def test_a_command_whose_modules_load_past_the_budget_says_so(monkeypatch):
    """Stop 51's pass (nc51b): `plan --network gen --goal beverages` said nothing for 2.0-3.4 s from the process's
    start at load 9-20: its first line, `looking up planner 'fd' ...`, comes once `plan`'s modules have loaded
    (0.2 s of CPU, seconds of wall time under load), and no step covered the loading. Loading a command's
    modules is a step: here the budget is spent before it (the process started a minute ago), so it speaks."""
    import sys

    monkeypatch.setattr(progress, "AFTER", 1.5)
    monkeypatch.delitem(main.commands, "stats", raising=False)  # as in a new process: the command's module not loaded yet
    monkeypatch.delitem(sys.modules, "foon2pddl.cli.stats_cmd", raising=False)
    monkeypatch.setattr(progress, "_process_start", time.monotonic() - 60)
    r = run("stats")
    assert r.exit_code == 0, r.stderr
    assert r.stderr.splitlines()[0] == "loading foon2pddl stats ...", r.stderr


@pytest.mark.parametrize(("args", "said"), [
    (("retrieve", "--goal", "lemonade", "--network", "exp"), "building FOON-EXP of 101 units"),
    (("retrieve", "--goal", "lemonade"), "checking whether FOON-EXP can make it: computing its WordNet similarity"),
    (("expand",), "opening WordNet for the similarities of 66 labels (once per set of labels, then cached)"),
], ids=["build FOON-EXP", "hint check", "expand"])
def test_a_step_known_to_be_slow_says_so_at_once(monkeypatch, tmp_path, args, said):
    """With an empty cache, FOON-EXP's WordNet matrix takes seconds: the step says so when it starts, not
    once the command's silence budget is spent (under load, that came 2.1-2.2 s after the start)."""
    monkeypatch.setattr(progress, "AFTER", 3600.0)  # no step may speak for having been quiet
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cold"))
    cold = run(*args)
    assert cold.exit_code in (0, 1), cold.stderr
    assert any(line.startswith(said) and line.endswith(" ...") for line in cold.stderr.splitlines()), cold.stderr
    warm = run(*args)  # the matrix is cached now: the step is quick and says nothing
    assert not any(line.startswith(said) for line in warm.stderr.splitlines()), warm.stderr


def test_a_unified_planning_engine_is_announced_before_its_import(monkeypatch):
    """`plan --planner pyperplan --optimal` said nothing for 2.0 s at load 15 (stop 48's pass): the line came
    once the silence budget was spent, then UP's import took seconds more. An engine name says so at once;
    Fast Downward, looked up without importing unified-planning, stays quiet."""
    monkeypatch.setattr(progress, "AFTER", 3600.0)  # no step may speak for having been quiet
    engine = run("plan", "--goal", "whipped cream", "--encoding", "tree", "--planner", "pyperplan", "--optimal")
    assert engine.exit_code == 0, engine.stderr
    assert engine.stderr.splitlines()[0] == "looking up planner 'pyperplan' among unified-planning's engines ..."
    assert "looking up planner" not in run("plan", "--goal", "whipped cream", "--encoding", "tree").stderr


# -- the commands found silent for seconds --------------------------------------------------------


@pytest.mark.parametrize(("args", "said"), [
    (("similarity", "cilantro", "banana"), "comparing 2 labels in WordNet (cook similarity) ..."),
    (("expand", "--pairs"), "expanding 101 units onto similar objects: units 1-101 ..."),
    (("expand", "--pairs"), "listing the "),  # with the matrix cached, WordNet opens here
    (("retrieve", "--goal", "lemonade", "--network", "exp"), "building FOON-EXP of 101 units"),
    (("plan", "--goal", "whipped cream", "--encoding", "tree", "--planner", "pyperplan"),
     "looking up planner 'pyperplan' among unified-planning's engines ..."),
    (("plan", "--goal", "whipped cream", "--skills"),
     "planning 'whipped cream' (relational encoding, then instances if it finds no plan in 75 s) and each step's robot skills ..."),
    # stop 47's pass: --up-validate's validation (8-13 s at load 14-17) ran under a line naming only the planning
    (("plan", "--goal", "whipped cream", "--encoding", "tree", "--up-validate"),
     "planning 'whipped cream' (fd, tree encoding, planner time limit 300 s, then validating the plan with unified-planning) ..."),
    (("check", SUBGRAPHS), f"checking {SUBGRAPHS} for defects ..."),
    (("stats", SUBGRAPHS), f"reading {SUBGRAPHS} ..."),
    (("stats", SUBGRAPHS), "counting nodes and labels at each level ..."),  # 2.4 s silent at load 12
    (("expand",), "writing FOON-EXP (181 units) ..."),  # 4.4 s silent on the subgraphs (paper)
    (("generalize",), "writing FOON-GEN (95 units) ..."),
    (("generalize",), "generalizing 101 units to categories ..."),  # 2.0-2.1 s silent at load 13 (subgraphs)
    # 24 s at load 14; on a network with a label in no category (`dressing`): with none, WordNet is not opened
    (("categories", "--extend", ROOT / "tests/data/scene/dressed_lettuce.foon"),
     "filing the object labels in no category (through WordNet) ..."),
    # stop 58's pass: `goals tests/data/foon-subgraphs --network exp --dishes` said `building FOON-EXP ...`, then
    # nothing for 2.3-2.5 s while it ran the kitchen's fixpoint over FOON-EXP's 7,908 units and wrote its rows (load 8)
    (("goals", "--network", "exp", "--dishes"), "finding which of the 287 goal candidates of FOON-EXP the kitchen can make ..."),
    # and with --json, 2.3 s silent after that step while it wrote the 7,334 rows (load 9)
    (("goals", "--network", "exp", "--json"), "writing the 287 goal candidates as JSON ..."),
], ids=["similarity", "expand --pairs", "expand --pairs: senses", "retrieve --network exp", "plan --planner pyperplan", "plan --skills", "plan --up-validate",
        "check", "stats", "stats: its counts", "expand: its output", "generalize: its output",
        "generalize: compressing", "categories --extend", "goals --network exp", "goals --json"])
def test_a_slow_command_says_what_it_does(every_step_speaks, args, said):
    r = run(*args)
    assert r.exit_code in (0, 1), r.stderr
    assert any(line.startswith(said) for line in r.stderr.splitlines()), r.stderr


def test_a_batch_says_it_writes_its_tree_files(every_step_speaks, tmp_path):
    """Stop 58's pass: `goals --reachable | retrieve --goals - --format svg -o DIR` said nothing for 20.9 s after its
    retrieval (load 8), while it drew 171 trees with Graphviz; `plan`'s batch writes its trees the same way."""
    for command in ("retrieve", "plan"):
        out = tmp_path / command
        r = run(command, "--goal", "guacamole", "--goal", "whipped cream", "--format", "dot", "-o", out)
        assert r.exit_code == 0, r.stderr
        assert f"writing 2 task trees to {out} (dot) ..." in said_steps(r.stderr), r.stderr
        assert sorted(p.suffix for p in out.iterdir()) == [".dot", ".dot"]


def test_a_compile_batch_says_each_goal_and_its_files(every_step_speaks, tmp_path):
    """Stop 58's pass: `goals --reachable | compile --goals - -o DIR` compiled 171 goals and wrote 342 files
    2.2 s after its last line (load 8), where `plan`'s batch names each goal as it plans it."""
    r = run("compile", "--goal", "guacamole", "--goal", "whipped cream", "-o", tmp_path)
    assert r.exit_code == 0, r.stderr
    said = said_steps(r.stderr)
    assert "compiling goal 1 of 2: 'guacamole' ..." in said and "compiling goal 2 of 2: 'whipped cream' ..." in said
    assert f"writing the PDDL files of 2 goals to {tmp_path} ..." in said, r.stderr


def test_check_says_when_it_opens_wordnet_and_how_to_skip_it(every_step_speaks, monkeypatch):
    """`check tests/data/foon-subgraphs` said `checking ... for defects ...` and then nothing for 11.6 s (load 10),
    most of it opening WordNet for the spelling variants: the step says so, and names `--no-wordnet`. As in a new
    process, `check`'s module is not loaded yet (run alone, this test read `loading foon2pddl check ...` first)."""
    import sys

    monkeypatch.delitem(main.commands, "check", raising=False)
    monkeypatch.delitem(sys.modules, "foon2pddl.cli.check_cmd", raising=False)
    said = run("check", SUBGRAPHS).stderr.splitlines()
    opening = "opening WordNet (to tell spelling variants from different words; --no-wordnet: string rules only) ..."
    assert said[:4] == ["loading foon2pddl check ...", f"reading {SUBGRAPHS} ...", opening,
                        f"checking {SUBGRAPHS} for defects ..."], said[:4]
    assert opening not in run("check", SUBGRAPHS, "--no-wordnet").stderr.splitlines()


def test_analyze_says_it_draws_the_plot(every_step_speaks, tmp_path):
    r = run("analyze", "--plot", tmp_path / "central.png")
    assert r.exit_code == 0, r.stderr
    assert f"drawing {tmp_path / 'central.png'} ..." in r.stderr.splitlines()
    assert any(line.startswith("projecting 101 units") for line in r.stderr.splitlines())


def test_analyze_says_it_writes_the_graphml_files(every_step_speaks, tmp_path):
    """Stop 53's pass (nc53b): `analyze tests/data/foon-subgraphs --top 10 --plot central.png --graphml graphs/`
    (datasets.md) said nothing for 1.9 s at load 18 (2.2-2.4 s in bench.silence, stops 52-53) between betweenness's
    last line and `wrote graphs/foon.graphml`: the three graphs built and serialized, outside every step."""
    said = run("analyze", "--graphml", tmp_path / "graphs").stderr.splitlines()
    writing = f"writing the GraphML files to {tmp_path / 'graphs'} ..."
    assert writing in said and said.index(writing) < said.index(f"wrote {tmp_path / 'graphs' / 'foon.graphml'}"), said


def test_analyze_says_it_draws_the_plot_before_it_starts_at_the_default_threshold(tmp_path):
    """Drawing the plot (matplotlib's import, the figure) took 2.3 s at load 15 after a silent wait for the
    threshold: it is announced at once, not only after `AFTER` seconds of silence."""
    said = run("analyze", "--plot", tmp_path / "central.png").stderr.splitlines()
    drawing = f"drawing {tmp_path / 'central.png'} ..."
    assert drawing in said and said.index(drawing) < said.index(f"wrote {tmp_path / 'central.png'}")


def test_the_experiment_says_its_set_up_and_its_report(every_step_speaks, tmp_path):
    args = ("experiment", "--trials", "1", "--goals", "2", "--networks", "reg,gen", "--solvers", "native-greedy",
            "-o", tmp_path)
    r = run(*args)
    assert r.exit_code == 0, r.stderr
    lines = r.stderr.splitlines()
    assert "building the networks (REG, GEN) before the first of 4 cells ..." in lines
    drawing = "drawing the trials (kitchens and goals) and reading the cells already run ..."
    assert drawing in lines and lines.index(drawing) < lines.index(  # README's experiment: 2.8 s silent first
        "building the networks (REG, GEN) before the first of 4 cells ...")
    assert f"writing the report and plots ({tmp_path / 'report.md'}) ..." in lines
    # stop 53 (nc53b): the README's quick run said nothing for 1.7-2.0 s after its bar's last line, every record
    # parsed again from results.jsonl (6,000 cells)
    reading = f"reading the results back ({tmp_path / 'results.jsonl'}) ..."
    assert reading in lines and max(k for k, line in enumerate(lines) if line.startswith("experiment: ")) < \
        lines.index(reading) < lines.index(f"writing the report and plots ({tmp_path / 'report.md'}) ...")
    assert lines.index("building the networks (REG, GEN) before the first of 4 cells ...") < next(
        k for k, line in enumerate(lines) if line.startswith("experiment: "))  # before the progress line
    quiet = run(*args, "--no-progress", "--fresh")
    assert quiet.exit_code == 0 and said_steps(quiet.stderr) == []  # --no-progress: no line at all


def test_the_experiment_says_it_checks_its_scheduler(every_step_speaks, tmp_path):
    """Stop 58's pass: `experiment --scheduler tcp://10.255.255.1:8786`, a host that never answers, waited out the
    10 s handshake without a line (11.4 s, then exit 2). The check is a step (here a port nothing listens on:
    refused at once, the step said first)."""
    import socket

    with socket.create_server(("127.0.0.1", 0)) as server:
        port = server.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    r = run("experiment", "--scheduler", address, "--trials", "1", "--goals", "1", "-o", tmp_path / "exp")
    assert r.exit_code == 2, r.stderr
    assert f"checking the Dask scheduler {address} (its handshake, within 10 s) ..." in said_steps(r.stderr), r.stderr
    assert "cannot reach the Dask scheduler" in r.stderr and not (tmp_path / "exp").exists()


def test_the_experiment_says_it_stops_its_dask_workers(every_step_speaks, tmp_path):
    """README's `experiment ... --jobs 2` went 2.3 s without a line after its bar reached 100 % (bench.silence,
    load 15, stop 49's pass): the local cluster's workers were being stopped. That step says so."""
    r = run("experiment", "--trials", "1", "--goals", "2", "--networks", "reg", "--solvers", "native-greedy",
            "--jobs", "2", "-o", tmp_path)
    assert r.exit_code == 0, r.stderr
    assert "stopping the 2 Dask workers ..." in r.stderr.splitlines(), r.stderr


def test_a_resumed_experiment_says_it_builds_the_networks_for_its_report(every_step_speaks, tmp_path, monkeypatch):
    """Run again with every cell reused, the experiment ran no cell, so it built its networks only for the report's
    sizes table: 12 s with nothing on stderr between the drawing of the trials and the report (found by the
    newcomer re-pass, stop 43)."""
    args = ("experiment", "--trials", "1", "--goals", "2", "--networks", "reg,gen", "--solvers", "native-greedy",
            "-o", tmp_path)
    first = run(*args)
    assert first.exit_code == 0
    assert "for the report ..." not in first.stderr  # its cells ran in this process: its networks are built
    from foon2pddl.experiment import worker

    monkeypatch.setitem(worker._CACHE, "views", {})  # a new process
    again = run(*args)
    assert again.exit_code == 0, again.stderr
    lines = again.stderr.splitlines()
    building = "building the networks (REG, GEN) for the report ..."
    assert building in lines
    assert lines.index(building) < lines.index(f"writing the report and plots ({tmp_path / 'report.md'}) ...")


def test_the_report_is_drawn_with_the_runs_objects_frozen_and_no_full_collection(tmp_path, monkeypatch):
    """The silence floor's last miss (stop 42: 2.9 s at load 20, at the experiment's end): full garbage collections
    during the report walked every object of the run (its networks, records, views: 0.12-0.22 s of CPU each, 1.2-2.5 s
    of wall at load 20, holding the lock the step's ticking line needs). The run froze them while its cells ran
    (`experiment.collector`) and unfroze them before the report; they stay frozen until the report is written.
    With them frozen, a full collection during the report still walked what the report makes (matplotlib's modules,
    fonts and figures): 1.46 s in one pass at load 16 (nc53a's pass, README's `experiment ... --jobs 2`, a
    `gc.callbacks` log), during which the step's beat waited for the lock: 2.7 s between its lines through a pipe.
    The report is drawn with full collections held back (`model.bulk.full_gc_paused`), as they were after."""
    import gc

    from foon2pddl.experiment import report

    seen = []
    real = report.write_report
    before = gc.get_threshold()

    def spy(*args, **kwargs):
        seen.append((gc.get_freeze_count() > 0, gc.get_threshold()[2] > 10 ** 9 or not gc.isenabled()))
        return real(*args, **kwargs)

    monkeypatch.setattr(report, "write_report", spy)
    r = run("experiment", "--trials", "1", "--goals", "2", "--networks", "reg", "--solvers", "native-greedy",
            "-o", tmp_path)
    assert r.exit_code == 0, r.stderr
    assert seen == [(True, True)]
    assert gc.get_freeze_count() == 0  # and unfrozen after: a long-lived process keeps collecting them
    assert gc.isenabled() and gc.get_threshold() == before


def test_a_step_says_what_it_does_when_it_speaks(monkeypatch, capsys):
    """A step's message may be a callable, read when the line is printed (here at once: AFTER 0)."""
    monkeypatch.setattr(progress, "AFTER", 0.0)
    progress.begin()
    doing = ["first plan"]
    with progress.slow_step(lambda: doing[0]):
        pass
    assert capsys.readouterr().err == "first plan ...\n"


def test_skills_say_the_step_they_are_in_after_the_fallback(monkeypatch):
    """Stop 48's newcomer pass: `plan 0082-... --kitchen base --skills --time-limit 40` printed `note: the relational
    encoding found no plan ...; planning with the instances encoding`, and only then `planning 'cheese pizza'
    (relational encoding, then instances if it finds no plan in 10 s) ...`: the step, once the command had been
    silent long enough, announced what it had set out to do before the note, not what it was doing. The step's
    message is read when it is printed: before the fallback it is the first plan, after it the fallback."""
    from contextlib import contextmanager
    from types import SimpleNamespace

    from foon2pddl.cli import skills_cli
    from foon2pddl.pddl.constraints import GoalExcluded
    from foon2pddl.skills import run as skills_run

    said = []

    @contextmanager
    def step(what):
        said.append(what())
        try:
            yield
        finally:
            said.append(what())

    def fake(*args, on_fallback, **kwargs):
        on_fallback(SimpleNamespace(status="unsolvable", result=SimpleNamespace(message="no reachable state")))
        raise GoalExcluded("stop here")

    monkeypatch.setattr(skills_cli, "slow_step", step)
    monkeypatch.setattr(skills_run, "plan_skills", fake)
    r = run("plan", "--goal", "whipped cream", "--skills")
    assert "note: the relational encoding found no plan" in r.stderr
    assert said == ["planning 'whipped cream' (relational encoding, then instances if it finds no plan in 75 s) "
                    "and each step's robot skills",
                    "planning 'whipped cream' (instances encoding) and each step's robot skills"]


# -- a series of steps (issue 24: `analyze --level 3` left ~25 finished share lines on a terminal) --------------


class _Terminal:
    """A fake terminal for stderr: what was written, and the screen's lines after the cursor moves and clears."""

    def __init__(self) -> None:
        self.written = ""

    def isatty(self) -> bool:
        return True

    def write(self, text: str) -> int:
        self.written += text
        return len(text)

    def flush(self) -> None:
        pass

    def screen(self) -> list[str]:
        """The lines left on screen: `\\x1b[A` moves up a line, `\\r` to its start, `\\x1b[K` clears the rest."""
        lines, row, col = [""], 0, 0
        for token in re.split(r"(\x1b\[A|\x1b\[K|\r|\n)", self.written):
            if token == "\x1b[A":
                row = max(0, row - 1)
            elif token == "\x1b[K":
                lines[row] = lines[row][:col]
            elif token == "\r":
                col = 0
            elif token == "\n":
                row, col = row + 1, 0
                lines += [""] * (row + 1 - len(lines))
            else:
                lines[row] = lines[row][:col] + token + lines[row][col + len(token):]
                col += len(token)
        return [line for line in lines if line]


def on_terminal(monkeypatch) -> _Terminal:
    """stderr a fake terminal, from here on (pytest's capture sets sys.stderr when the test's body starts)."""
    screen = _Terminal()
    monkeypatch.setattr("sys.stderr", screen)
    progress.begin()
    return screen


def test_a_series_of_steps_is_one_redrawn_line_on_a_terminal(every_step_speaks, monkeypatch):
    terminal = on_terminal(monkeypatch)
    for first in (1, 33, 65):
        with progress.slow_step(f"betweenness of 96 objects: source nodes {first}-{first + 31} of 96",
                                series="betweenness of 96 objects"):
            pass
    with progress.slow_step("drawing the plot"):
        pass
    shown = terminal.screen()
    assert len(shown) == 2, shown  # was a finished line per share
    assert re.fullmatch(r"betweenness of 96 objects: source nodes 65-96 of 96: \d+\.\d s", shown[0]), shown
    assert re.fullmatch(r"drawing the plot: \d+\.\d s", shown[1]), shown


def test_a_series_starts_a_new_line_after_another_step_spoke(every_step_speaks, monkeypatch):
    terminal = on_terminal(monkeypatch)
    """Another step's line below the series's: the series's next step may not redraw over it."""
    for what in ("a: share 1", "other", "a: share 2"):
        with progress.slow_step(what, series="a" if what.startswith("a") else None):
            pass
    assert [line.split(": ")[:-1] for line in terminal.screen()] == [["a", "share 1"], ["other"], ["a", "share 2"]]


def test_a_series_in_a_log_is_a_line_per_step(every_step_speaks, capsys):
    for k in (1, 2):
        with progress.slow_step(f"s: share {k}", series="s"):
            pass
    assert capsys.readouterr().err == "s: share 1 ...\ns: share 2 ...\n"


def test_analyze_level_3_keeps_one_betweenness_line_per_projection_on_a_terminal(every_step_speaks, monkeypatch):
    """What `analyze` runs, with the command's step: a line per projection, the last share's, not one per share."""
    terminal = on_terminal(monkeypatch)
    from foon2pddl.analysis import betweenness
    from foon2pddl.analysis.network import analyze
    from foon2pddl.io.inputs import load_network

    monkeypatch.setattr(betweenness, "STEP_WORK", 1)  # a share of BATCH sources: several shares on the example
    analyze(load_network(()).foon, 3, step=progress.slow_step)
    assert terminal.written.count("betweenness of ") > 4  # several shares of each projection spoke
    shown = [line for line in terminal.screen() if line.startswith("betweenness of ")]
    assert len(shown) == 2 and {line.split(" ")[3].rstrip(":") for line in shown} == {"objects", "motions"}, shown
    assert all(re.search(r"source nodes [\d,]+-([\d,]+) of \1: \d+\.\d s$", line) for line in shown), shown


@pytest.mark.parametrize(("args", "said"), [
    (("expand",), ["expanding 101 units onto similar objects: units 1-16 ...",
                   "expanding 101 units onto similar objects: units 97-101 ...",
                   "substituting the products renamed along into the units that use them ...",
                   "removing duplicates among 187 units ...",
                   "counting the nodes of REG and EXP at each level: REG (101 units) at level 1 ...",
                   "counting the nodes of REG and EXP at each level: EXP (181 units) at level 3 ..."]),
    (("generalize",), ["counting the nodes of REG and GEN at each level: REG (101 units) at level 1 ...",
                       "counting the nodes of REG and GEN at each level: GEN (95 units) at level 3 ..."]),
], ids=["expand", "generalize"])
def test_expand_and_generalize_say_how_far_they_are(every_step_speaks, monkeypatch, args, said):
    """`expand tests/data/foon-subgraphs` said one line at 1.8 s and nothing for 37.8 s more; `generalize` was silent
    3.6 s after its header while the statistics table was computed (stop 48's pass): both now say each share."""
    from foon2pddl.generalize import expand

    monkeypatch.setattr(expand, "SHARE", 16)
    r = run(*args)
    assert r.exit_code == 0, r.stderr
    lines = r.stderr.splitlines()
    assert all(line in lines for line in said), r.stderr
    assert [lines.index(line) for line in said] == sorted(lines.index(line) for line in said)


def test_a_warm_exp_retrieval_scores_its_substitutions_without_opening_wordnet(monkeypatch, tmp_path):
    """`retrieve --goal lemonade --network exp` (docs/generalization.md's transcript) opened WordNet on every run to
    score its one substitution: 10.6 s after `scoring the tree's FOON-EXP substitutions in WordNet ...` with a warm
    cache (load 7-9). The scores come from the mode's disk-cached matrix over the labels compared."""
    said = substitution_lines_without_wordnet(monkeypatch, tmp_path, "retrieve", "--goal", "lemonade", "--network",
                                              "exp")
    assert said == ["substitution: lemon juice -> lime juice (Wu-Palmer 0.875)"]


def test_the_similarity_matrix_is_computed_in_a_series_of_steps(monkeypatch):
    """`expand tests/data/foon-subgraphs` on an empty cache said `expanding ... (WordNet similarities: once, then
    cached) ...` and nothing for 88.5 s (load 6-9): the matrix's 117,000 pairs. They are computed in shares of
    rows of about SHARE_PAIRS pairs, each a step of one series; every pair is computed once, as before."""
    from contextlib import contextmanager

    from foon2pddl.generalize import similarity

    monkeypatch.setattr(similarity, "SHARE_PAIRS", 10)
    said = []

    @contextmanager
    def step(what, *, series=None):
        said.append((what, series))
        yield

    labels = tuple(f"l{i:02d}" for i in range(12))
    m = similarity.compute_matrix(labels, lambda a, b: int(a[1:]) * int(b[1:]) / 1000, step=step)
    assert all(m(a, b) == int(a[1:]) * int(b[1:]) / 1000 for a in labels for b in labels if a != b)
    assert {series for _, series in said} == {"WordNet similarities of 12 labels"}
    assert [what.rsplit(": rows ", 1)[1] for what, _ in said] == [
        "1-1 of 12", "2-2 of 12", "3-4 of 12", "5-6 of 12", "7-9 of 12", "10-12 of 12"]


def test_a_cold_expand_says_it_opens_wordnet_and_how_far_the_matrix_is(every_step_speaks, monkeypatch, tmp_path):
    from foon2pddl.generalize import similarity

    monkeypatch.setattr(similarity, "SHARE_PAIRS", 1000)
    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cold"))
    r = run("expand")
    assert r.exit_code == 0, r.stderr
    lines = r.stderr.splitlines()
    assert "opening WordNet for the similarities of 66 labels (once per set of labels, then cached) ..." in lines
    rows = [line for line in lines if line.startswith("WordNet similarities of 66 labels (once per set of labels, then cached): rows ")]
    assert len(rows) == 3 and rows[0].endswith(": rows 1-18 of 66 ...") and rows[-1].endswith(" of 66 ..."), rows


def test_a_new_exp_goal_scores_its_substitutions_from_the_views_matrix(monkeypatch, tmp_path):
    """A goal whose tree relies on other substitutions than the last run's (`bowl -> mixing bowl`, not lemonade's
    `lemon juice -> lime juice`) reopened WordNet (4.9 s against 0.5 s) for a matrix over the tree's labels beside
    the one the EXP view had just read from the cache: the scores come from the view's matrix."""
    from foon2pddl.generalize import wordnet

    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    first = run("retrieve", "--goal", "lemonade", "--network", "exp")
    assert first.exit_code == 0, first.stderr

    def no_wordnet():
        raise AssertionError("WordNet opened for a new goal on a warm cache")

    monkeypatch.setattr(wordnet, "reader", no_wordnet)
    other = run("retrieve", "--goal", "avocado: in [mixing bowl], scooped", "--network", "exp")
    assert other.exit_code == 0, other.stderr
    said = [line for line in other.stderr.splitlines() if line.startswith("substitution: ")]
    assert said == ["substitution: bowl -> mixing bowl (Wu-Palmer 0.957)"]


def test_a_hint_check_that_finds_nothing_says_so(every_step_speaks, tmp_path):
    """`checking which other network makes it (for a hint) ...` was the last line of a run whose check found
    nothing: the reader could not tell a finished check from a hung one. It closes with what it found, and no
    `hint:` line (README: none when neither network would make it)."""
    kitchen = tmp_path / "k.txt"
    kitchen.write_text("knife\n")
    r = run("retrieve", "--goal", "guacamole", "--kitchen", kitchen)
    assert r.exit_code == 1
    lines = r.stderr.splitlines()
    assert "checking which other network makes it (for a hint) ..." in lines, r.stderr
    assert lines[-1] == "neither --network exp nor --network gen makes it", r.stderr
    assert "hint:" not in r.stderr


def test_analyze_says_what_it_does_before_its_slow_imports(every_step_speaks, monkeypatch):
    """`analyze` was silent 2.1 s from its start (bench.silence, load 16): numpy and networkx load (1.1 s at load
    15) before its first step; a step around them speaks first, after the command's own modules' step. As in a new
    process, `analyze`'s module is not loaded yet: whether an earlier test of this worker loaded it must not decide
    the first line (rv51: run alone, this test failed on `loading foon2pddl analyze ...` once 46b61d2 made that a step)."""
    import sys

    monkeypatch.delitem(main.commands, "analyze", raising=False)
    monkeypatch.delitem(sys.modules, "foon2pddl.cli.analyze_cmd", raising=False)
    r = run("analyze", "--level", "3", "--json")
    assert r.exit_code == 0, r.stderr
    assert r.stderr.splitlines()[:2] == ["loading foon2pddl analyze ...",
                                         "loading the network analysis (numpy, networkx) ..."], r.stderr


class _Said:
    """Stands in for `progress.click`: records the lines a step says, and signals each one."""

    def __init__(self):
        import threading

        self.lines: list[str] = []
        self.new = threading.Condition()

    def echo(self, text, err=False, nl=True):
        with self.new:
            self.lines.append(text)
            self.new.notify_all()

    def wait_for(self, count: int) -> bool:
        with self.new:
            return self.new.wait_for(lambda: len(self.lines) >= count, timeout=60)


def test_every_said_step_beats_through_a_pipe(monkeypatch):
    """Through a pipe a step said its line once, and only a step marked as one long call (opening WordNet) added its
    seconds every `BEAT` seconds: stop 54's pass (a fresh clone, stderr through a pipe, load 12-22) found steps said
    once then silent for their whole length: `goals --dishes | retrieve --goals - --network exp`'s `retrieving trees
    for 100 goals (complete) ...` 16.1 s, `expand --similarity paper`'s `counting the nodes of REG and EXP at each
    level: EXP (19,423 units) at level 2 ...` 5.5 s, `analyze --level 3`'s `loading the network analysis (numpy,
    networkx) ...` 2.1 s. A log has no line that counts: every said step adds its seconds every `BEAT` seconds."""
    said = _Said()
    monkeypatch.setattr(progress, "click", said)
    monkeypatch.setattr(progress, "AFTER", 0.0)
    monkeypatch.setattr(progress, "BEAT", 0.01)
    with progress.slow_step("counting the nodes"):
        assert said.wait_for(3), said.lines  # the line, then two beats: the step ends only once they are said
    assert said.lines[0] == "counting the nodes ..."
    assert all(re.fullmatch(r"counting the nodes \.\.\. \d+ s", line) for line in said.lines[1:]), said.lines


def test_a_hint_check_that_skips_a_network_too_large_to_build_says_so(every_step_speaks):
    """The ramen on the subgraphs (docs/format.md): the check closed with `--network gen does not make it
    either`, while FOON-EXP of a 1,845-unit network is never built for a hint: the reader took EXP for checked too;
    the closing line says whose units it counts (the network's, not FOON-EXP's 7,799: rv51's review)."""
    r = run("retrieve", SUBGRAPHS, "--goal", "ramen")
    assert r.exit_code == 1
    lines = r.stderr.splitlines()
    assert lines[-1] == ("--network gen does not make it either; --network exp is not checked (FOON-EXP of a"
                         " 1,845-unit network is too large to build for a hint: run it to see)"), r.stderr


#: Runs the console script with `foon2pddl.cli`'s import slowed down (as under heavy load), then a quick command.
_SLOW_CLI_IMPORT = """
import sys, time
from importlib.abc import MetaPathFinder

DELAY, BUDGET = float(sys.argv[1]), float(sys.argv[2])

class Slow(MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name == "foon2pddl.cli":
            time.sleep(DELAY)
        return None

sys.meta_path.insert(0, Slow())
sys.argv = ["foon2pddl", "--version"]
import foon2pddl.__main__ as console
console.LOADING_AFTER = BUDGET
console.run()
"""


@pytest.mark.parametrize(("delay", "budget", "said"), [(2.5, 1.5, ["loading foon2pddl ..."]), (0.0, 3600.0, [])],
                         ids=["slow", "quick"])
def test_the_console_script_says_so_when_its_own_modules_load_past_the_budget(delay, budget, said):
    """The first step that can speak, `loading foon2pddl CMD`, exists once `foon2pddl.cli` (click, the command
    group) has loaded: at load 23 the interpreter and that import took 2.05 s of wall time for 0.09 s of CPU
    (stop 51's pass), a silence no step covered. The console script itself says `loading foon2pddl ...` once
    the budget is spent (`--version` has no step of its own); a start within the budget says nothing. The
    quick case sets the budget to an hour, so that no wall-clock race under load decides it (rv52's review)."""
    import subprocess
    import sys

    r = subprocess.run([sys.executable, "-c", _SLOW_CLI_IMPORT, str(delay), str(budget)], capture_output=True, text=True,
                       timeout=120, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("foon2pddl, version"), r.stdout
    assert r.stderr.splitlines() == said, r.stderr


def test_the_console_scripts_budget_is_the_clis(monkeypatch):
    from foon2pddl.__main__ import LOADING_AFTER

    monkeypatch.undo()  # conftest's budget of an hour off: the CLI's own
    assert LOADING_AFTER == progress.AFTER


def test_a_beat_leaves_the_floor_a_margin(monkeypatch):
    """Through a pipe a step that is one long call (the WordNet matrix of a hint check) added a line every 2.0 s,
    the floor itself (issue 24: no 2 s without a line): at load 16-19 a wake-up came 0.1-0.2 s late, gaps of
    2.1-2.2 s between its lines (nc52a's pass, `retrieve --goal lemonade` on an empty cache). At 1.5 s a beat left
    0.5 s, and stop 58's pass saw one come 0.88 s late (`retrieve --goal "greek salad" --network exp`, `building
    FOON-EXP ... 2 s` then 2.38 s without a line, load 8.7): a wake-up waits for the interpreter lock, which a long
    call in C (a collection, a module's `dlopen`) holds however short the beat. A beat, and the first line of a step
    (`AFTER`), come with a margin of a second, more than any late wake-up seen; the first line is as late as a
    beat, so the console script's own (`LOADING_AFTER`) is too."""
    from bench.silence import LIMIT
    from foon2pddl.__main__ import LOADING_AFTER

    monkeypatch.undo()  # conftest's beat of an hour off: the CLI's own
    assert progress.BEAT == progress.AFTER == LOADING_AFTER <= LIMIT - 1.0


def test_a_unified_planning_engine_lookup_beats_through_a_pipe(monkeypatch):
    """`plan --planner foo` said `looking up planner 'foo' among unified-planning's engines ...` and then nothing
    for 15.0 s through a pipe (nc52a's pass, load 19: importing unified-planning, one long call, as opening
    WordNet is): the step beats as WordNet's does."""
    from dataclasses import replace

    from foon2pddl.cli import plan_cmd
    from foon2pddl.planners import registry

    def slow_check(name):
        time.sleep(0.3)
        return registry.UP_ENGINE.check(name)

    slow = replace(registry.UP_ENGINE, check=slow_check)
    monkeypatch.setattr(plan_cmd, "UP_ENGINE", slow)
    monkeypatch.setattr(plan_cmd, "lookup", lambda planner, planner_cmd: slow)
    monkeypatch.setattr(progress, "BEAT", 0.05)
    r = run("plan", "--goal", "whipped cream", "--planner", "foo")
    assert r.exit_code == 2, r.stderr
    beats = [line for line in r.stderr.splitlines()
             if re.fullmatch(r"looking up planner 'foo' among unified-planning's engines \.\.\. \d+ s", line)]
    assert beats, r.stderr


def _beats_while(monkeypatch, module, name: str, *args, code: int = 0) -> list[str]:
    """Runs the command `args` (exit status `code`) with `module.name` (its one long call) slowed until the step's
    line and two beats have been said; returns every line said."""
    said = _Said()
    monkeypatch.setattr(progress, "click", said)
    monkeypatch.setattr(progress, "AFTER", 0.0)
    monkeypatch.setattr(progress, "BEAT", 0.01)
    long_call = getattr(module, name)

    def slow(*a, **kw):
        assert said.wait_for(len(said.lines) + 3), said.lines  # the step's line, then beats while it runs
        return long_call(*a, **kw)

    monkeypatch.setattr(module, name, slow)
    r = run(*args)
    assert r.exit_code == code, r.output
    return said.lines


def test_expand_pairs_beats_while_it_reads_the_senses(monkeypatch):
    """Stop 52's pass (nc52b): `expand --pairs` (generalization.md) on an empty cache said `listing the 10
    substitutions with their WordNet senses ...` once, then nothing for 34.5 s through a pipe (load 20): the senses
    open WordNet, one long call, and the step had no beat, unlike the other long calls."""
    from foon2pddl.generalize import pairs

    lines = _beats_while(monkeypatch, pairs, "substitution_pairs", "expand", "--pairs")
    listing = [line for line in lines if line.startswith("listing the 10 substitutions")]
    assert len(listing) >= 3 and re.fullmatch(r"listing .* \.\.\. \d+ s", listing[-1]), lines


def test_analyze_beats_while_it_draws_the_plot(monkeypatch, tmp_path):
    """Stop 52's pass (nc52b): `analyze ... --plot central.png` (datasets.md) said `drawing central.png ...` once,
    then nothing for 15.1 s through a pipe (load 20): matplotlib's import and the figure, one long call."""
    from foon2pddl.analysis import network_report

    lines = _beats_while(monkeypatch, network_report, "plot_png", "analyze", "--plot", tmp_path / "central.png")
    drawing = [line for line in lines if line.startswith(f"drawing {tmp_path / 'central.png'}")]
    assert len(drawing) >= 3 and re.fullmatch(r"drawing .* \.\.\. \d+ s", drawing[-1]), lines


def test_similarity_beats_while_it_opens_wordnet(monkeypatch):
    """Stop 53's pass (nc53b): `similarity cilantro banana --senses` (generalization.md) said `comparing 2 labels
    in WordNet (cook similarity) ...` once, then nothing for 26.1 s through a pipe (load 10): opening WordNet, one
    long call, and the step had no beat, unlike the other long calls."""
    from foon2pddl.generalize import modes

    lines = _beats_while(monkeypatch, modes, "make_similarity", "similarity", "cilantro", "banana", "--senses")
    comparing = [line for line in lines if line.startswith("comparing 2 labels in WordNet")]
    assert len(comparing) >= 3 and re.fullmatch(r"comparing .* \.\.\. \d+ s", comparing[-1]), lines


def test_the_experiment_beats_while_it_writes_its_report(monkeypatch, tmp_path):
    """Stop 53's pass (nc53b): the tiny experiment (`--trials 1 --goals 5`) said `writing the report and plots
    (...) ...` once, then nothing for 9.4 s through a pipe (load 15): matplotlib's import and the plots."""
    from foon2pddl.experiment import report

    lines = _beats_while(monkeypatch, report, "write_report", "experiment", "--trials", "1", "--goals", "2",
                         "--networks", "reg", "--solvers", "native-greedy", "-o", tmp_path)
    writing = [line for line in lines if line.startswith("writing the report and plots")]
    assert len(writing) >= 3 and re.fullmatch(r"writing .* \.\.\. \d+ s", writing[-1]), lines


def test_after_a_beating_step_the_silence_counts_from_its_last_line(monkeypatch):
    """Through a pipe, `plan --goal guacamole --planner pyperplan` beat while it looked the engine up, then planned
    without a line: 2.2 s between the lookup's last beat and the result (nc53a's pass, load 17). The step after a
    beating one counted its budget from that step's end, which may come up to `BEAT` seconds after its last
    line: `BEAT` + `AFTER` of silence. It counts from the last line said."""
    said = _Said()
    monkeypatch.setattr(progress, "click", said)
    monkeypatch.setattr(progress, "AFTER", 0.0)
    with progress.slow_step("looking up planner 'pyperplan'"):  # BEAT: an hour, no beat comes
        assert said.wait_for(1)
        time.sleep(0.3)  # the long call goes on after the step's last line
    monkeypatch.setattr(progress, "AFTER", 0.2)
    with progress.slow_step("planning 'guacamole'"):
        pass  # a quick step: quiet within its budget, but the budget was spent while the lookup ended
    assert said.lines == ["looking up planner 'pyperplan' ...", "planning 'guacamole' ..."]


def test_after_a_step_said_on_a_terminal_the_silence_counts_from_its_end(monkeypatch, capsys):
    """On a terminal a step's line counts its seconds and ends with its time as the step ends: the next step's
    budget counts from there."""
    monkeypatch.setattr(progress.sys.stderr, "isatty", lambda: True, raising=False)
    monkeypatch.setattr(progress, "AFTER", 0.0)
    with progress.slow_step("opening WordNet"):
        time.sleep(0.3)
    monkeypatch.setattr(progress, "AFTER", 0.2)  # spent since the step's first line, not since its last
    with progress.slow_step("next"):
        pass
    assert "next" not in capsys.readouterr().err


def test_the_experiment_beats_while_it_builds_its_networks(monkeypatch, tmp_path):
    """Stop 53's re-check (nc53b, a fresh clone, empty cache, load 16): the tiny experiment said `building the
    networks (REG, EXP, GEN) before the first of 30 cells ...` once, then nothing for 38.7 s through a pipe
    (FOON-EXP's WordNet matrix, one long call): the run's steps beat as the report's does."""
    from foon2pddl.experiment import runner

    lines = _beats_while(monkeypatch, runner, "build_networks", "experiment", "--trials", "1", "--goals", "2",
                         "--networks", "reg", "--solvers", "native-greedy", "-o", tmp_path)
    building = [line for line in lines if line.startswith("building the networks (REG)")]
    assert len(building) >= 3 and re.fullmatch(r"building .* \.\.\. \d+ s", building[-1]), lines


def test_the_report_step_covers_what_the_report_is_made_of(monkeypatch, tmp_path):
    """README's `experiment ... --jobs 2` on a terminal (bench.silence, stop 54's pass, load 25): 2.1 s between
    `stopping the 2 Dask workers: 0.4 s` and the report's line. A stack sampler showed the main thread reading the
    results back (its step, within the budget), then 0.6 s in the report's network sizes (the node tables of FOON-EXP
    and FOON-GEN) outside every step. What the report is made of (sizes, provenance, the machine) is gathered under
    the report's step."""
    from foon2pddl.cli import experiment_cmd

    said = _Said()
    monkeypatch.setattr(progress, "click", said)
    monkeypatch.setattr(progress, "AFTER", 0.0)
    report = f"writing the report and plots ({tmp_path / 'report.md'}) ..."
    seen = []
    real = experiment_cmd.machine

    def spy():
        with said.new:  # the report's line is said by its watcher thread: wait a moment for it
            seen.append(said.new.wait_for(lambda: report in said.lines, timeout=5))
        return real()

    monkeypatch.setattr(experiment_cmd, "machine", spy)
    r = run("experiment", "--trials", "1", "--goals", "2", "--networks", "reg", "--solvers", "native-greedy",
            "-o", tmp_path)
    assert r.exit_code == 0, r.stderr
    assert seen == [True], said.lines


def test_the_hint_check_beats_while_it_builds_the_other_networks(monkeypatch):
    """nc54a's pass: `retrieve tests/data/foon-subgraphs --goal ramen` (docs/format.md) said `checking which other
    network makes it (for a hint) ...` once, then nothing for 12.4 s through a pipe (load 12): building FOON-GEN and
    planning its lifted task, one long call, and the step had no beat unless WordNet was to open."""
    from foon2pddl.generalize import hints

    lines = _beats_while(monkeypatch, hints, "networks_that_reach", "retrieve", SUBGRAPHS, "--goal", "ramen", code=1)
    checking = [line for line in lines if line.startswith("checking which other network makes it (for a hint)")]
    assert len(checking) >= 3 and re.fullmatch(r"checking .* \.\.\. \d+ s", checking[-1]), lines


def _asked_inside_a_step(monkeypatch, steps, owner, name: str) -> list[bool]:
    """Wraps `steps.slow_step` (the one the code under test calls) to know when a step is open, and `owner.name` to
    note at each call whether one is: returns those notes, filled as the command runs."""
    from contextlib import contextmanager

    inside: list[bool] = []
    real_step, real = steps.slow_step, getattr(owner, name)

    @contextmanager
    def step(*args, **kwargs):
        inside.append(True)
        try:
            with real_step(*args, **kwargs) as said:
                yield said
        finally:
            inside.pop()

    asked: list[bool] = []

    def spy(*args, **kwargs):
        asked.append(bool(inside))
        return real(*args, **kwargs)

    monkeypatch.setattr(steps, "slow_step", step)
    monkeypatch.setattr(owner, name, spy)
    return asked

def test_a_batch_plan_explains_each_goal_inside_its_step(monkeypatch, tmp_path):
    """The known leftover of stop 53's pass, reproduced by stop 54's (bench.silence's pty, empty cache, load 16):
    `goals ... --dishes --kitchen default | plan ... --goals - --kitchen default --network gen` went 2.1 s from goal 1's
    closing line to `planning goal 4 of 100 ...`; a stack sampler showed goals 2 and 3 planned within the budget, then
    the reason goal 3 is unsolvable (`failure_reason`: the kitchen additions' search, 0.6 s) outside every step. A
    goal's reason is found inside its step."""
    from foon2pddl.cli import batch_pddl

    asked = _asked_inside_a_step(monkeypatch, batch_pddl, batch_pddl, "failure_reason")
    goals = tmp_path / "goals.txt"
    goals.write_text("guacamole\nlemonade\n")
    r = run("plan", "--goals", goals, "--encoding", "tree")
    assert r.exit_code == 1, r.stderr  # the lemonade: unreachable
    assert asked == [True, True], r.stderr


def test_plan_beats_while_it_plans(monkeypatch):
    """nc54a's pass: `plan --goal guacamole --optimal` said `planning 'guacamole' (fd, relational encoding, ...) ...`
    once, then nothing for 2.6 s through a pipe (load 15; `--planner pyperplan --optimal --encoding tree` 2.2 s):
    encoding, translating and searching, one long call for the command (every said step beats since 749ac1e)."""
    from foon2pddl.cli import plan_cmd

    lines = _beats_while(monkeypatch, plan_cmd, "plan", "plan", "--goal", "whipped cream", "--encoding", "tree")
    planning = [line for line in lines if line.startswith("planning 'whipped cream' (fd, tree encoding")]
    assert len(planning) >= 3 and re.fullmatch(r"planning .* \.\.\. \d+ s", planning[-1]), lines


def test_plan_skills_beats_while_it_plans_and_decomposes(monkeypatch):
    """nc54a's pass: `plan tests/data/foon-subgraphs/0082-homemade_cheese_pizza.txt --goal "cheese pizza" --kitchen
    base --skills --time-limit 40` (docs/skills.md) said `planning 'cheese pizza' (relational encoding, then
    instances ...) and each step's robot skills ...`, then its fallback note, then nothing for 29.1 s through a
    pipe (load 20): the instances plan and 61 steps' skills (every said step beats since 749ac1e)."""
    from foon2pddl.skills import run as skills_run

    lines = _beats_while(monkeypatch, skills_run, "plan_skills", "plan", "--goal", "whipped cream", "--skills")
    planning = [line for line in lines if line.startswith("planning 'whipped cream' (relational encoding")]
    assert len(planning) >= 3 and re.fullmatch(r"planning .* robot skills \.\.\. \d+ s", planning[-1]), lines


def test_reading_the_network_beats(monkeypatch):
    """nc54a's pass (load 21): `merge tests/data/foon-subgraphs --format json -o out/net.json` (json-schema.md) said
    `reading tests/data/foon-subgraphs ...`, then nothing for 2.4 s through a pipe; `stats out/net.json` 2.2 s:
    reading and merging the files, one long call (every said step beats since 749ac1e)."""
    from foon2pddl.io import inputs

    lines = _beats_while(monkeypatch, inputs, "load_network", "stats", SUBGRAPHS)
    reading = [line for line in lines if line.startswith(f"reading {SUBGRAPHS}")]
    assert len(reading) >= 3 and re.fullmatch(r"reading .* \.\.\. \d+ s", reading[-1]), lines


def test_a_networks_kitchen_strays_are_found_inside_its_step(monkeypatch):
    """Stop 54's re-check (a fresh clone, stderr through a pipe, load 14): `goals ... --dishes --kitchen default |
    retrieve ... --goals - --kitchen default --network exp` (generalization.md) went 1.8-2.0 s from the last beat of
    `building FOON-EXP of 1,845 units ...` to its next line; a stack sampler showed the kitchen's strays (FOON-EXP's
    node table, 0.3-0.5 s) looked for after the step, outside every step. They are looked for inside it."""
    from foon2pddl.generalize.network import NetworkView

    asked = _asked_inside_a_step(monkeypatch, progress, NetworkView, "kitchen_strays")
    r = run("retrieve", "--goal", "guacamole", "--kitchen", "default")
    assert r.exit_code == 0, r.stderr
    assert asked == [True], r.stderr


def test_a_batch_reads_its_goal_list_inside_a_step(monkeypatch, tmp_path):
    """Stop 54's re-check (through a pipe, load 14): `goals ... --dishes | retrieve ... --goals - --network exp` said
    `loading foon2pddl retrieve ...`, then nothing for 2.0 s: a stack sampler showed `retrieve` waiting for its goal
    list on standard input (the `goals` before it still reading the network) outside every step. Reading the list
    is a step: it says what it waits for."""
    from foon2pddl.cli import batch

    asked = _asked_inside_a_step(monkeypatch, progress, batch, "read_goal_list")
    goals = tmp_path / "goals.txt"
    goals.write_text("guacamole\n")
    r = run("retrieve", "--goals", goals)
    assert r.exit_code == 0, r.stderr
    assert asked == [True], r.stderr


def test_retrieve_looks_for_the_kitchen_additions_inside_a_step(monkeypatch, tmp_path):
    """Stop 55's pass (nc55b): `retrieve ../shared/data/foon-subgraphs --goal 'whipped cream' --kitchen
    foon-search-inputs/utensils.txt` (a list of utensils given as a kitchen) said `retrieving a tree for ...` and then
    nothing for 23.2 s through a pipe (load 20-30): the search for the smallest kitchen additions
    (`explain_unreachable`, now `why_unreachable`, 'no set of up to 6 kitchen additions was found') ran after the step, outside every step."""
    from foon2pddl.cli import retrieve_cmd

    asked = _asked_inside_a_step(monkeypatch, retrieve_cmd, retrieve_cmd, "why_unreachable")
    r = run("retrieve", "--goal", "lemonade")
    assert r.exit_code == 1, r.stderr  # the example kitchen has no lemon
    assert asked == [True], r.stderr


def test_plan_finds_why_there_is_no_plan_inside_a_step(monkeypatch):
    """The same search behind `plan`'s `reason:` line (`failure_reason`) ran after the planning step."""
    from foon2pddl.cli import plan_cmd

    asked = _asked_inside_a_step(monkeypatch, plan_cmd, plan_cmd, "failure_reason")
    r = run("plan", "--goal", "lemonade", "--encoding", "tree")
    assert r.exit_code == 1, r.stderr
    assert asked == [True], r.stderr


def test_compile_checks_the_goal_can_be_made_inside_a_step(monkeypatch, tmp_path):
    """... and behind `compile`'s `unreachable` error (`unreachable_reason`), before the compiling step."""
    from foon2pddl.cli import compile_cmd, reasons

    asked = _asked_inside_a_step(monkeypatch, compile_cmd, reasons, "unreachable_reason")
    r = run("compile", "--goal", "lemonade", "-o", tmp_path)
    assert r.exit_code == 1, r.stderr
    assert asked and all(asked), r.stderr


def test_a_solved_plan_never_says_it_is_finding_why_there_is_no_plan(monkeypatch):
    """`failure_reason` runs after every `plan`, also a solved one (it returns at once then): its step's words
    (`finding why there is no plan for ...`) were said on a solved plan whenever the command had been silent
    for `AFTER` seconds by then (a large plan rendered under load). The step wraps the search only when there is
    no plan; the command's silence is set here as a loaded machine leaves it."""
    from foon2pddl.cli import plan_cmd

    real = plan_cmd.render_tree

    def rendered_late(*args, **kwargs):
        progress._quiet_since = time.monotonic() - 10 * progress.AFTER  # silent since long before
        return real(*args, **kwargs)

    monkeypatch.setattr(plan_cmd, "render_tree", rendered_late)
    r = run("plan", "--goal", "guacamole")
    assert r.exit_code == 0, r.stderr
    assert "solved" in r.stderr and "finding why there is no plan" not in r.stderr


def test_expand_reads_the_cached_similarity_matrix_inside_a_step(monkeypatch, tmp_path):
    """Stop 55's pass: `expand --similarity paper` went 5.6 s without a line at load 30. With the matrix cached,
    reading it (numpy's import and the file: 0.43 s of 9.8 at load 8 on the subgraphs, the one stretch of the
    command outside every step) ran between the reading of the network and the expansion, where nothing could
    speak; the silence since the network's step added to it."""
    from foon2pddl.cli import expand_cmd
    from foon2pddl.generalize import modes

    monkeypatch.setenv("FOON2PDDL_CACHE", str(tmp_path / "cache"))
    assert run("expand", "--similarity", "paper").exit_code == 0  # fills the cache
    asked = _asked_inside_a_step(monkeypatch, expand_cmd, modes, "cached_matrix")
    r = run("expand", "--similarity", "paper")
    assert r.exit_code == 0, r.stderr
    assert asked == [True], r.stderr


def test_wordnet_opens_with_full_collections_held_back(monkeypatch):
    """`similarity cilantro banana --senses` from an empty cache (stop 57's newcomer pass, load 8-10): gaps of 2.0,
    2.2 and 2.5 s between the lines of `comparing 2 labels in WordNet ...`, over the 2 s floor, with a beat every
    1.5 s. Full garbage collections while NLTK builds WordNet's maps (millions of long-lived objects) held the
    interpreter lock: a 0.25 s ticker beside `reader()` woke up to 0.76 s late (0.08 s beside a busy pure-Python
    loop). The reader is built with full collections held back (`model.bulk.full_gc_paused`): 0.13-0.18 s."""
    import gc

    from foon2pddl.generalize import wordnet

    seen = []
    real = wordnet.check_corpus

    def spy(wn):  # inside the build, as the maps are made
        seen.append(gc.get_threshold()[2] > 10 ** 9 or not gc.isenabled())
        return real(wn)

    monkeypatch.setattr(wordnet, "check_corpus", spy)
    before = gc.get_threshold()
    wordnet.reader.cache_clear()
    assert wordnet.reader().synsets("cilantro")  # built anew: the cached reader is this one from now on
    assert seen == [True]
    assert gc.isenabled() and gc.get_threshold() == before


def test_a_plan_without_a_plan_says_its_outcome_before_searching_why(every_step_speaks):
    """Stop 58's note: `plan --goal guacamole --time-limit 0.01` printed `finding why there is no plan for ...`
    before its `timeout (...)` line, so the search for a reason read as part of the planning. The outcome comes
    first, then the step that finds why, then the reason it found."""
    r = run("plan", "--goal", "guacamole", "--time-limit", "0.01")
    assert r.exit_code != 0, r.stderr
    lines = r.stderr.splitlines()
    outcome = next(k for k, line in enumerate(lines) if line.startswith("timeout ("))
    finding = next(k for k, line in enumerate(lines) if line.startswith("finding why there is no plan"))
    reason = next(k for k, line in enumerate(lines) if line.startswith("reason: "))
    assert outcome < finding < reason, r.stderr
