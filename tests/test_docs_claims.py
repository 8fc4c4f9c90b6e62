"""What the docs say in prose about a transcript, and the files their commands read, hold for a new user's clone.

The transcripts themselves are checked line by line (test_docs_transcripts.py); these are the claims
around them that a reader acts on: the step a paragraph points to, and whether a command shown can be
run from a fresh clone as written (only the reader's own files may be missing).
"""

from __future__ import annotations

import functools
import re
import shlex
import subprocess
import sysconfig
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import ROOT

from bench.doc_commands import PAGES, blocks, documented_commands, missing_inputs
from foon2pddl.cli import main

#: A paragraph's pointer into the transcript under it: "... poured into the avocado's bowl at step 10".
_AT_STEP = re.compile(r"(pour\w*)[^.:]*? at step (\d+)", re.S)


def _pointed_steps() -> list[tuple[str, str, str, int]]:
    """(page, command, verb, step) for every "<verb> ... at step N" in the prose just above a transcript."""
    out = []
    for page in PAGES:
        lines = page.read_text().splitlines()
        for block in blocks("\n".join(lines)):
            if block.lang or not block.lines or not block.lines[0].startswith("$ foon2pddl "):
                continue
            before = "\n".join(lines[:block.start - 2]).rstrip().rsplit("\n\n", 1)[-1]  # the paragraph above it
            for m in _AT_STEP.finditer(before):
                out.append((page.name, block.lines[0][len("$ foon2pddl "):], m.group(1), int(m.group(2))))
    return out


POINTED = _pointed_steps()


def test_the_guacamole_pours_are_pointed_to():
    assert {(page, command) for page, command, _, _ in POINTED} >= {
        ("README.md", "plan --goal guacamole --skills --format recipe"),
        ("skills.md", "plan --goal guacamole --skills")}


@pytest.mark.parametrize(("page", "command", "verb", "step"), POINTED, ids=[f"{p}: {c}" for p, c, _, _ in POINTED])
def test_the_step_a_paragraph_points_to_is_that_step(page, command, verb, step, monkeypatch):
    monkeypatch.chdir(ROOT)
    result = CliRunner().invoke(main, shlex.split(command))
    assert result.exit_code == 0, result.stderr
    line = next((x for x in result.stdout.splitlines() if x.startswith(f"{step}. ")), "")
    assert line.split()[1:2] == [verb.removesuffix("ed")], f"{page} says step {step} is a {verb}; it is: {line!r}"


#: Files the docs name as the reader's own (their recipes, their robot, their planner), not shipped.
READERS_OWN = {"my_recipes/", "index.json", "my-robot.pddl", "my-motions.json", "./my-downward/fast-downward.py"}


def test_every_documented_command_runs_from_a_clone_as_written():
    """A command shown with a file a clone lacks sends a new user looking for it: name the shipped copy."""
    missing = {(c.where, path) for c in documented_commands() for path in missing_inputs(c.text)
               if path not in READERS_OWN}
    assert not missing


def test_skills_md_says_how_long_the_relational_try_takes_by_default():
    """skills.md said the merged subgraphs' black bean "solves under `instances` in ~2 s"; a new user running it
    waited 80 s, since the relational try takes its whole share of the default time limit first."""
    from foon2pddl.cli.plan_cmd import plan_ as plan_command
    from foon2pddl.skills.run import FIRST_SHARE

    default = next(p.default for p in plan_command.params if p.name == "time_limit")
    text = " ".join((ROOT / "docs" / "skills.md").read_text().split())
    assert f"after {default * FIRST_SHARE:g} s, a quarter of the default {default:g} s limit" in text


def _prose(page: str) -> str:
    return " ".join((ROOT / "docs" / page).read_text().split())


def test_pddl_md_says_one_count_of_the_dishes_instances_solves():
    """pddl.md's `state` note said "`instances` solves 88" while its figures table (bench.pddl_subgraphs)
    and the replay figures say 89: a reader comparing the encodings gets two answers."""
    text = _prose("pddl.md")
    table = re.search(r"\| `instances` \| (\d+) \| (\d+) \| (\d+) \|", text)
    assert table, "the figures table has an `instances` row"
    said = set(re.findall(r"`instances` solves (\d+)", text))
    assert said == {table.group(2)}, f"pddl.md says `instances` solves {sorted(said)}; its table: {table.group(2)}"


def test_pddl_md_native_tree_figures_are_what_the_bench_gives():
    """pddl.md quotes `python -m bench.physical_replay --native -v` (one object per kitchen item): its counts
    of executable, short and used-up trees must be what that bench gives on the shipped subgraphs."""
    from collections import Counter

    from bench.physical_replay import native_rows

    rows = native_rows(ROOT / "tests" / "data" / "foon-subgraphs")
    got = Counter(r.verdict for r in rows)
    text = _prose("pddl.md")
    m = re.search(r"--native -v`\), one object per kitchen item: (\d+) executable, (\d+) short .*? (\d+) used-up", text)
    assert m, "pddl.md quotes the native schedule's counts"
    assert (len(rows), *map(int, m.groups())) == (89, got["executable"], got["short"], got["used-up"])


#: Paragraphs quoting a bench's figures (page, words that open the paragraph or table row): a figure a later
#: change moves is only comparable when the text says which commit gave it.
BENCH_FIGURES = (
    ("pddl.md", "Figures (`python -m bench.physical_replay -v`"),
    ("pddl.md", "On the 89 native trees of the shared dishes (`python -m bench.physical_replay"),
    ("skills.md", "`python -m bench.skills` (also an area of `python -m bench`)"),
    ("planning.md", "(pyperplan's default search is blind breadth-first"),  # said 58 s; 10 s of CPU, 25 s wall
    ("pddl.md", "`instances` (`python -m bench.pddl_instances -v`"),
    ("README.md", "The `experiment` line is the quick one"),  # said "about 15 s ... 25 s", measured when?
    ("planning.md", "Which planners read and solve which encoding's PDDL"),  # a date, no commit, rows moved since
    ("planning.md", "Optimal planners on the universal FOON"),  # 55/59 on 2026-12-04, no commit; 56/59 later
    ("constraints.md", "`python -m bench --shared ../shared/data --only constraints"),  # no commit (issue 24 re-pass)
    ("planning.md", "**The translator kept warm.**"),  # 100 ms, 20 ms, 1.05 s -> 0.31 s: measured when? (issue 24 re-pass)
)


def _in_history(sha: str) -> bool:
    """Whether `sha` names exactly one commit HEAD descends from. Reachable, not merely present: a local
    clone copies every object, so a commit of an unmerged branch (e7c38b6, stop 46) resolved here and was
    missing from CI's clone of main."""
    return sum(full.startswith(sha) for full in _history()) == 1


@functools.cache
def _history() -> tuple[str, ...]:
    import subprocess

    return tuple(subprocess.run(["git", "-C", str(ROOT), "rev-list", "HEAD"], capture_output=True, text=True,
                                check=True).stdout.split())


@pytest.mark.parametrize(("page", "opening"), BENCH_FIGURES, ids=[f"{p}: {o[:40]}" for p, o in BENCH_FIGURES])
def test_bench_figures_name_the_commit_they_are_from(page, opening):
    """pddl.md's physical-replay figures were from before lanes (1,614 of 1,686 steps; the bench now gives
    1,759 of 1,800) and said nothing of when: the paragraph names the commit its figures are from."""

    text = (ROOT / page if page == "README.md" else ROOT / "docs" / page).read_text()
    start = text.index(opening)
    paragraph = text[start:text.find("\n\n", text.find("\n\n", start) + 2)]  # the paragraph and what follows
    commits = _COMMIT.findall(paragraph)
    assert commits, f"{page}: the figures after {opening!r} name no commit"
    for sha in commits:
        assert _in_history(sha), f"{page}: {sha} is no commit in the history of HEAD"


#: A time a bench measured: `0.074 s`, `146 ms`, `6 min`, quoted with how (median, load, wall, CPU).
_TIMED = re.compile(r"\d(?:\.\d+)? ?(?:s|ms|min)\b")
_HOW = re.compile(r"\b(?:medians?|load|wall|CPU)\b", re.I)
_BENCH = re.compile(r"python -m bench|make bench")
_COMMIT = re.compile(r"\b(?:[Aa]t|[Cc]ommit) ([0-9a-f]{7,40})\b")  # "At 6b607c6" slipped past a lower-case one


def _bench_paragraphs() -> list[tuple[str, str]]:
    """(page:line, paragraph) of every paragraph or table quoting a bench's times: it names a bench
    (`python -m bench ...`, `make bench`), or its section's heading does. docs/experiment.md is generated."""
    out = []
    for page in PAGES:
        if page.name == "experiment.md":
            continue
        text, heading = page.read_text(), ""
        for m in re.finditer(r"(?:^|\n\n)(.*?)(?=\n\n|\Z)", text, re.S):
            paragraph = m.group(1)
            if paragraph.startswith("#"):
                heading = paragraph.split("\n")[0]
            if paragraph.startswith("```") or not _BENCH.search(paragraph + heading):
                continue
            if _TIMED.search(paragraph) and _HOW.search(paragraph):
                out.append((f"{page.name}:{text.count(chr(10), 0, m.start()) + 2}", paragraph))
    return out


def test_every_paragraph_quoting_a_benchs_times_names_its_commit():
    """retrieval.md's batch figures, pddl.md's compile times and planning.md's run C/run B table named no
    commit (the last two were measured before most of today's code): a time is comparable only with the
    commit it was measured at. Each such paragraph names it (`at 3fbb13a`)."""

    paragraphs = _bench_paragraphs()
    unnamed = [where for where, paragraph in paragraphs if not _COMMIT.search(paragraph)]
    assert not unnamed, f"bench times with no commit: {unnamed}"
    named = sorted({(sha, where) for where, paragraph in paragraphs for sha in _COMMIT.findall(paragraph)})
    unknown = [f"{where}: {sha}" for sha, where in named if not _in_history(sha)]
    assert not unknown, f"bench times naming no commit in the history of HEAD: {unknown}"


def test_the_bench_paragraphs_are_found():
    """The oracle of the test above: the paragraphs it must read are among those it reads."""
    found = [(where.split(":")[0], paragraph) for where, paragraph in _bench_paragraphs()]
    for page, opening in [("retrieval.md", "Figures (`python -m bench --only batch`"),
                          ("pddl.md", "Universal FOON of the 100 subgraphs (1,845 units"),
                          ("planning.md", "| figure | run C, at c5b0b82"), ("planning.md", "**Equivalence** (run C, at c5b0b82)")]:
        assert any(p == page and paragraph.startswith(opening) for p, paragraph in found), (page, opening)


def test_generalization_md_says_one_gen_unit_count(universal):
    """generalization.md's benchmark row said FOON-GEN of the shared subgraphs has "1,801 now" while its
    statistics table (what `generalize` prints) and its experiment table say 1,806: every figure is what
    FOON-GEN of the shipped subgraphs gives."""
    from foon2pddl.generalize.categories import shipped_index
    from foon2pddl.generalize.compress import compress

    foon, _ = universal
    units = len(compress(foon, shipped_index()).foon.units)
    text = " ".join((ROOT / "docs" / "generalization.md").read_text().split())
    table = re.search(r"\| GEN \| 3 \| \d+ \| (\d+) \|", text)
    now = re.search(r"FOON-GEN construction \| .*?; ([\d,]+) now", text)
    assert table and now
    assert {int(table.group(1)), int(now.group(1).replace(",", ""))} == {units}


def test_pddl_md_counts_the_instances_plans_steps_once():
    """pddl.md gave the 89 `instances` plans 1,840 unit steps (bench.pddl_instances, when lanes came) and 1,800
    (bench.physical_replay, the same plans now): both paragraphs quote the one count."""
    text = _prose("pddl.md")
    counted = re.search(r"([\d,]+) unit steps against `tree`'s", text)
    replayed = re.search(r"of their ([\d,]+) unit steps are followed", text)
    assert counted and replayed and counted.group(1) == replayed.group(1)


def _resolves(dotted: str) -> bool:
    """Whether `a.b.c` names a module, or an attribute of the longest module prefix that imports."""
    import importlib

    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:k]))
        except ImportError:
            continue
        for name in parts[k:]:
            if not hasattr(obj, name):
                return False
            obj = getattr(obj, name)
        return True
    return False


def test_every_dotted_name_the_docs_give_imports():
    """json-schema.md said `foon2pddl.jsonio` (it is `foon2pddl.io.jsonio`), planning.md
    `foon2pddl.pddl.solve.GoalReplanner` (then in `planners.solve`), retrieval.md `foon2pddl.tasktree.validate`
    (in `model.tasktree`): a reader who types them gets an ImportError. Every `foon2pddl.x.y` a page names,
    and every `pddl.x`, `planners.x`, ... it names inside the package, is importable."""
    subpackages = "model|io|analysis|retrieval|generalize|pddl|planners|skills|experiment|cli"
    named = re.compile(rf"`((?:foon2pddl|{subpackages})(?:\.[A-Za-z_]\w*)+)")
    wrong = []
    for page in PAGES:
        for number, line in enumerate(page.read_text().splitlines(), start=1):
            for m in named.finditer(line):
                dotted = m.group(1) if m.group(1).startswith("foon2pddl.") else "foon2pddl." + m.group(1)
                if dotted != "foon2pddl.foon" and not _resolves(dotted):  # the JSON format's name (json-schema.md)
                    wrong.append(f"{page.name}:{number}: {m.group(1)}")
    assert not wrong


def test_readme_says_what_make_bench_reads_in_a_clone():
    """README said `make bench` "needs `../shared/data`"; the Makefile runs it on the copy in tests/data when
    ../shared/data is not beside the checkout, so a new user's clone runs it as it is."""
    makefile = (ROOT / "Makefile").read_text()
    assert "SHARED ?= $(if $(wildcard ../shared/data),../shared/data,tests/data)" in makefile
    assert "bench: $(STAMP)\n\t$(PY) -m bench --shared $(SHARED)" in makefile
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert "needs `../shared/data`" not in readme
    assert "`make bench` (speed figures, medians over repeated runs, on `../shared/data` when it is beside the " \
           "checkout, else on the copy in `tests/data`)" in readme


def test_retrieval_md_gives_the_additions_search_its_bound():
    """retrieval.md said "When no set of up to 3 nodes works, the old list of missing nodes is printed"; the
    explanation tries sets of up to `MAX_ADDITIONS` (6) and prints "it needs more than 6 kitchen additions"."""
    from foon2pddl.retrieval.explain import MAX_ADDITIONS

    text = _prose("retrieval.md")
    said = {int(n) for n in re.findall(r"When no set of up to (\d+) nodes works", text)}
    assert said == {MAX_ADDITIONS}
    assert f"`it needs more than {MAX_ADDITIONS} kitchen additions`" in text


def test_skills_md_counts_and_lists_the_shipped_domains_actions():
    """skills.md said "Skills (46 actions, ...)" above a list of 47, the shipped domain's 47 actions: the count
    and the names listed are the domain's."""
    domain = (ROOT / "foon2pddl" / "data" / "skills" / "skills.pddl").read_text()
    actions = set(re.findall(r"\(:action ([\w-]+)", domain))
    text = _prose("skills.md")
    count = re.search(r"Skills \((\d+) actions, the first parameter always the hand\):(.*?)What FOON says", text)
    assert count, "skills.md introduces the skill list with its count"
    listed = set(re.findall(r"`([a-z-]+)`", count.group(2))) - {"tool", "graspable"}
    assert int(count.group(1)) == len(actions) and listed == actions, (count.group(1), listed ^ actions)


def test_the_tests_run_with_the_venvs_pytest_as_with_python_m_pytest():
    """`make test` runs `python -m pytest`, which puts the checkout on sys.path; the venv's `pytest` script (how
    a contributor runs one file) does not, and the test files that import `bench` failed to collect with
    "No module named 'bench'". pyproject's pytest `pythonpath` puts the checkout there for both."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    script = Path(sys.executable).parent / "pytest"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    run = subprocess.run([str(script), "--collect-only", "-q", "-p", "no:xdist", "-p", "no:cacheprovider",
                          "tests/test_docs_transcripts.py"], cwd=ROOT, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]


def test_generalization_md_statistics_name_the_network_they_are_of():
    """generalization.md's statistics of the 100 shared subgraphs said `foon2pddl expand --similarity paper` /
    `expand` / `generalize` print its rows: run as written (no PATHS) they print the embedded example's (101
    units). Each command shown names the subgraphs, and the REG rows are what `stats` of them prints."""
    text = (ROOT / "docs" / "generalization.md").read_text()
    section = text.split("## Statistics on the 100 shared subgraphs", 1)[1].split("\n## ", 1)[0]
    shown = re.findall(r"`(foon2pddl [^`]+)`", section.split("| network |", 1)[0])
    assert len(shown) == 3 and all(" tests/data/foon-subgraphs" in c for c in shown), shown
    stats = CliRunner().invoke(main, ["stats", str(ROOT / "tests" / "data" / "foon-subgraphs")]).stdout
    for level, objects, motions in re.findall(r"^\s+(\d)\s+(\d+)\s+(\d+)$", stats, re.M):
        assert f"| REG | {level} | {objects} | {motions} |" in section


def test_every_page_gives_the_current_exp_and_gen_unit_counts(universal):
    """retrieval.md said "EXP is now built with the cook similarity (8,448 units ...) and GEN has 1,801 units"
    while generalization.md's statistics (what `expand`/`generalize` of the subgraphs print) say 7,844 and
    1,806: a page's "now" count of EXP and GEN is the statistics table's, and GEN's is what FOON-GEN gives."""
    from foon2pddl.generalize.categories import shipped_index
    from foon2pddl.generalize.compress import compress

    gen = len(compress(universal[0], shipped_index()).foon.units)
    table = (ROOT / "docs" / "generalization.md").read_text()
    exp = int(re.search(r"^\| EXP \(cook, the default\) \| 3 \| \d+ \| (\d+) \|$", table, re.M).group(1))
    assert int(re.search(r"^\| GEN \| 3 \| \d+ \| (\d+) \|$", table, re.M).group(1)) == gen
    said = []
    for page in PAGES:
        text = " ".join(page.read_text().split())
        said += [(page.name, "EXP", int(n.replace(",", ""))) for n in
                 re.findall(r"EXP is now built with the cook similarity \(([\d,]+) units", text)]
        said += [(page.name, "GEN", int(n.replace(",", ""))) for n in re.findall(r"GEN has ([\d,]+) units", text)]
    assert said, "retrieval.md gives the current counts"
    assert [s for s in said if s[2] != {"EXP": exp, "GEN": gen}[s[1]]] == []


def test_skills_md_fallback_example_falls_back():
    """skills.md said the merged subgraphs' black bean times out under `relational` and solves under `instances`;
    since the relational readings of 8b11317 and later it solves under `relational` (21 macro steps): the page's
    example of the fallback is a command whose relational task finds no plan, run as written."""
    text = _prose("skills.md")
    m = re.search(r"`foon2pddl (plan tests/data/\S+ --goal \"[^\"]+\"(?: --kitchen \S+)? --skills --time-limit \d+)`\s+finds no plan "
                  r"under `relational`", text)
    assert m, "skills.md names a command whose relational task falls back to instances"
    r = CliRunner().invoke(main, shlex.split(m.group(1)))
    assert r.exit_code == 0, r.stderr
    assert "note: the relational encoding found no plan (" in r.stderr  # 0082 from the base kitchen: unsolvable at once
    assert "; planning with the instances encoding" in r.stderr
    assert "under the instances encoding" in r.stderr and "black bean times out" not in text


def test_readme_quotes_what_a_missing_file_prints(tmp_path):
    """README said a missing file prints `path: error: no such file`; a missing PATHS entry (a file or a
    directory) prints `... no such file or directory`. Each message the program prints is the one quoted."""
    readme = (ROOT / "README.md").read_text()
    missing = tmp_path / "nope.txt"
    for args in (("stats", missing), ("plan", "--goal", "guacamole", "--kitchen", missing)):
        r = CliRunner().invoke(main, [str(a) for a in args])
        assert r.exit_code == 2 and r.stderr.startswith(f"{missing}: error: "), r.stderr
        message = r.stderr.strip().removeprefix(f"{missing}: ")
        assert f"`path: {message}`" in readme, message


def test_pddl_md_restore_figures_are_what_plan_gives():
    """pddl.md said `--restore` on 0013 (potato soup) gives "31 plan steps instead of 26" with "one knife washed
    twice": `plan` says 32 plan steps (31 units) instead of 27 (26 units), and the knife is washed three times."""
    import json

    m = re.search(r"On 0013 \(potato soup\)(?: at ([0-9a-f]{7,40}))?: (\d+) objects instead of (\d+), one knife "
                  r"washed (\w+(?: times)?) instead of (\w+) knives, (\d+) plan steps \((\d+) units\) instead of (\d+) \((\d+) units\)",
                  _prose("pddl.md"))
    assert m, "pddl.md quotes --restore's figures on 0013 with the plan steps and units of each run"
    words = {"once": 1, "twice": 2, "three times": 3, "thrice": 3, "four": 4, "two": 2, "three": 3, "five": 5}
    got = []
    for restore in ((), ("--restore",)):
        r = CliRunner().invoke(main, ["plan", str(ROOT / "tests/data/foon-subgraphs/0013-creamy_potato_soup.txt"),
                                      "--goal", "potato soup", "--encoding", "relational", *restore, "--format", "json"])
        assert r.exit_code == 0, r.stderr
        data = json.loads(r.stdout)
        objects = data["relational"]["initial"]
        got.append((len(objects), sum(o["label"] == "knife" for o in objects), len(data["plan"]),
                    data["tree"]["units"], sum(s["motion"] == "wash" and "knife" in s["text"]
                                                    for s in data["relational"]["steps"])))
    (plain, restored) = got
    said = (int(m[2]), int(m[3]), words[m[4]], words[m[5]], int(m[6]), int(m[7]), int(m[8]), int(m[9]))
    assert said == (restored[0], plain[0], restored[4], plain[1], restored[2], restored[3], plain[2], plain[3])


def test_pddl_md_gives_guacamole_restored_boards_as_plan_gives_them():
    """Guacamole with `--restore` planned with 4 cutting boards where the plain relational plan used 3 (README
    counts 3): a newcomer trying `--restore`, which plans "with the fewer objects they allow", was told
    nowhere why it took more. pddl.md says why the count is not the fewest, with the counts `plan` gives
    (3 and 3 since interchangeable objects are taken in one order, 801a1d5)."""
    import json

    m = re.search(r"guacamole on the example network \(`plan --goal guacamole --encoding relational --restore`\) "
                  r"plans with (\d+) cutting boards where the plain plan uses (\d+) of its (\d+)", _prose("pddl.md"))
    assert m, "pddl.md gives the boards guacamole's --restore plan and the plain one use"
    got = []
    for restore in ((), ("--restore",)):
        r = CliRunner().invoke(main, ["plan", "--goal", "guacamole", "--encoding", "relational", *restore,
                                      "--format", "json"])
        assert r.exit_code == 0, r.stderr
        rel = json.loads(r.stdout)["relational"]
        used = {b["object"] for s in rel["steps"] for b in s["bindings"] if (b["before"] or "").startswith("cutting board")}
        got.append((len(used), sum(o["label"] == "cutting board" for o in rel["initial"])))
    (plain_used, plain_has), (restored_used, _) = got
    assert (int(m[1]), int(m[2]), int(m[3])) == (restored_used, plain_used, plain_has)


def test_every_experiment_command_shown_says_how_long_it_runs():
    """README's sweep (`experiment ... --sweep ...`) gave no run time where the quick line under it did: a reader
    cannot tell a minute from an hour. The paragraph after each `foon2pddl experiment` a page shows in a block,
    and the paragraph holding each one shown inline, gives a wall time in seconds or minutes and the commit it was
    measured at."""
    shown = [c for c in documented_commands() if c.form in ("block", "inline")
             and c.text.startswith("foon2pddl experiment ")]
    assert len(shown) >= 3
    silent = []
    for command in shown:
        text = (ROOT / command.page).read_text()
        lines = text.splitlines()
        if command.form == "inline":  # the paragraph it is in (stop 45: constraints.md's 52,000-cell sweep)
            start = max((i for i in range(command.line) if not lines[i].strip()), default=-1) + 1
            paragraph = "\n".join(lines[start:]).split("\n\n")[0]
        else:  # the paragraph after the block it is in
            block = next(b for b in blocks(text) if b.start <= command.line < b.start + len(b.lines))
            paragraph = "\n".join(lines[block.start + len(block.lines):]).strip().split("\n\n")[0]
        if not (re.search(r"\d s\b|\d s wall|\d min\b", paragraph) and _COMMIT.search(paragraph)):
            silent.append(command.where)
    assert not silent, f"experiment commands with no run time (and commit) in the paragraph after them: {silent}"


#: The values an option named in retrieval.md's "refused with a batch" sentence takes, and the commands that have it.
_BATCH_REFUSED = {"--without-motion": (["pour"], ("retrieve", "compile", "plan")),
                  "--without": (["lime"], ("retrieve", "compile", "plan")),
                  "--must-use": (["lime"], ("retrieve", "compile", "plan")),
                  "--constraints": (["docs/examples/diet-no-egg.json"], ("retrieve", "compile", "plan")),
                  "--restore": ([], ("compile", "plan")), "--skills": ([], ("plan",))}


def test_what_retrieval_md_says_a_batch_refuses_it_refuses(tmp_path, monkeypatch):
    """Stop 44's re-pass: retrieval.md said `--network gen` is refused with a batch; `retrieve`, `compile` and
    `plan` all run a GEN batch (issue 24 item 9 made them). Every option the sentence names is refused (exit 2)
    by every command that has it, and what it says takes a batch runs one."""
    monkeypatch.chdir(ROOT)
    text = " ".join((ROOT / "docs" / "retrieval.md").read_text().split())
    (refused,) = [s for s in re.split(r"(?<=\.) ", text) if "refused with a batch" in s]
    named = [m for m in re.findall(r"`(--[^`]+)`", refused)]
    assert set(_BATCH_REFUSED) <= set(named), refused
    wrong = []
    for option in named:
        values, commands = _BATCH_REFUSED.get(option, (option.split()[1:], ("retrieve", "compile", "plan")))
        for command in commands:
            out = ["-o", str(tmp_path / command)] if command == "compile" else []
            r = CliRunner().invoke(main, [command, "--goal", "guacamole", "--goal", "lemonade",
                                          option.split()[0], *values, *out])
            if r.exit_code != 2:
                wrong.append(f"{command} {option}: exit {r.exit_code}")
    assert not wrong, f"retrieval.md says these are refused with a batch; they are not: {wrong}"
    (takes,) = [s for s in re.split(r"(?<=\.) ", text) if "take a batch" in s]
    for network in re.findall(r"`--network (\w+)`", takes):
        r = CliRunner().invoke(main, ["retrieve", "--goal", "guacamole", "--goal", "lemonade", "--network", network])
        assert r.exit_code in (0, 1) and "2 goals:" in r.stdout, (network, r.output)


def test_extending_md_says_the_experiment_takes_a_new_network_kinds_name_only(tmp_path, monkeypatch):
    """Stop 45's pass: extending.md said that after `register(...)` "the CLI, the Python API and the experiment"
    accept the new planner's, network kind's, method's or encoding's name. The experiment takes a network kind's
    (`--networks`); its `--solvers` are its own registry (`experiment/solvers.py`), so a new planner is no solver."""
    from foon2pddl.generalize.network import NETWORKS, NetworkKind, register
    from foon2pddl.planners.registry import PLANNERS, Planner
    from foon2pddl.planners.registry import register as register_planner

    monkeypatch.setitem(NETWORKS, "asread", NETWORKS["reg"])  # placeholder: replaced by register below
    register(NetworkKind("asread", "ASREAD", "the network as read", NETWORKS["reg"].build, ""))
    monkeypatch.setitem(PLANNERS, "toy", PLANNERS["fd"])
    register_planner(Planner("toy", "Fast Downward again", PLANNERS["fd"].solve, lambda name: None))
    common = ["experiment", "--trials", "1", "--goals", "1", "--no-progress", "-o", str(tmp_path / "x")]
    assert CliRunner().invoke(main, [*common, "--networks", "asread", "--solvers", "native-complete"]).exit_code == 0
    assert CliRunner().invoke(main, [*common, "--networks", "reg", "--solvers", "toy"]).exit_code == 2
    intro = (ROOT / "docs/extending.md").read_text().split("\n\n")[1]
    said = re.search(r"then accept[^.]*\.", intro, re.S)
    assert said and "experiment" in said.group(0) and "--networks" in said.group(0), intro
    assert "solvers.py" in intro  # where the experiment's own names are


#: A page's word on which encoding a command takes by default: "`relational` is not the default of `plan`",
#: a heading "### `tree` (the default of `compile`)".
_DEFAULT_SAID = re.compile(r"`([a-z-]+)` is (not )?the default of `(\w+)`|^#+ `([a-z-]+)` \(([^)]*default[^)]*)\)", re.M)


def test_what_the_docs_say_an_encoding_default_is_the_commands_default():
    """Stop 45's pass: docs/pddl.md said "`relational` is not the default of `plan`" and headed the `tree`
    section "(default)", while `plan` takes `relational` unless --encoding says otherwise (`compile`: `tree`).
    Every such sentence names the command and says what its --encoding option defaults to."""
    from foon2pddl.cli import main as cli

    def default(command):
        return next(p.default for p in cli.get_command(None, command).params if p.name == "encoding")

    said = []
    for page in PAGES:
        for m in _DEFAULT_SAID.finditer(page.read_text()):
            if m.group(1):
                said.append((page.name, m.group(0), (default(m.group(3)) == m.group(1)) != bool(m.group(2))))
            else:
                named = re.fullmatch(r"the default of `(\w+)`", m.group(5))
                said.append((page.name, m.group(0), bool(named) and default(named.group(1)) == m.group(4)))
    assert said and not [s for s in said if not s[2]], said


def test_the_instances_physical_note_pddl_md_quotes_is_the_one_plan_prints(monkeypatch):
    """Stop 45's pass: docs/pddl.md quoted the note `plan --encoding instances` adds as '... first:
    07-guacamole.foon:28: step 4: scoop ...'; the guacamole plan puts every board to use first and scoops at
    step 12. The quote (its `...` any text) is a line of that command's stderr."""
    quote = re.search(r"`(note: not checked physically by the encoding:[^`]*)`",
                      " ".join((ROOT / "docs/pddl.md").read_text().split()))
    assert quote and "07-guacamole.foon" in quote.group(1)
    monkeypatch.chdir(ROOT)
    r = CliRunner().invoke(main, ["plan", "--goal", "guacamole", "--encoding", "instances"])
    assert r.exit_code == 0, r.stderr
    pattern = re.compile(".*".join(re.escape(part) for part in quote.group(1).split("...")))
    assert any(pattern.fullmatch(line) for line in r.stderr.splitlines()), (quote.group(1), r.stderr)
    # like every other note, it names the unit's file alone, not where the package is installed (stop 45's pass)
    assert "first: 07-guacamole.foon:" in r.stderr, r.stderr


def test_generalization_md_cook_successes_are_the_experiment_reports():
    """Stop 45's pass: generalization.md gave GEN 72.4 successes per trial under the default protocol, where
    docs/experiment.md (the default protocol's own report) and a run at f8303c2 give 72.6. Its `--similarity
    cook` row is the report's `native-complete` row (same protocol: 10 x 100 goals, fraction 0.9, seed 0)."""
    row = re.search(r"^\| native-complete \| 100 \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$",
                    (ROOT / "docs/experiment.md").read_text(), re.M)
    cook = re.search(r"^\| mean successes per trial, `--similarity cook` \(min-max\) \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$",
                     (ROOT / "docs/generalization.md").read_text(), re.M)
    assert row and cook
    assert [g.strip() for g in cook.groups()] == [g.strip() for g in row.groups()]


class _Parsed(Exception):
    """Raised in place of running a benchmark once its command line has parsed."""


def test_every_bench_command_the_docs_show_parses(monkeypatch):
    """Stop 45's pass: generalization.md showed `python -m bench.similarity_lemmas --split lemmas2`, which exits 2
    (its BLIND and KEY files are required). Every `python -m bench...` a page shows in prose (a synopsis with
    `[...]` or `a|b` aside) parses with that module's own argument parser; nothing is run."""
    import argparse
    import runpy
    import sys

    spans = {m.group(1) for page in PAGES for m in re.finditer(r"`python -m (bench[^`]*)`", page.read_text())}
    spans = sorted(s for s in spans if "[" not in s and "|" not in s)
    assert len(spans) >= 10
    parse = argparse.ArgumentParser.parse_args

    def parsed(self, args=None, namespace=None):
        parse(self, args, namespace)
        raise _Parsed

    monkeypatch.setattr(argparse.ArgumentParser, "parse_args", parsed)
    refused = []
    for span in spans:
        module, *args = shlex.split(span)
        monkeypatch.setattr(sys, "argv", [module, *args])
        try:
            runpy.run_module(module if module != "bench" else "bench.__main__", run_name="__main__")
        except _Parsed:
            continue
        except SystemExit:
            pass
        refused.append(span)
    assert not refused, refused


def test_generalization_md_counts_the_labelled_pairs_the_file_holds():
    """Stop 47's pass: generalization.md said its precision figures rest on "1,279 pairs ... in five batches",
    the count before `lemmas3`, `lemmas4` and `lemmas5` were labelled; bench/similarity_pairs.tsv holds 1,944
    in eight. The count the page gives is the file's, and every split of the file is named on the page."""
    page = " ".join((ROOT / "docs" / "generalization.md").read_text().split())
    said = re.search(r"([\d,]+) pairs, labelled good/marginal/bad", page)
    assert said, "the sentence counting the labelled pairs is gone"
    rows = [line.split("\t") for line in (ROOT / "bench" / "similarity_pairs.tsv").read_text().splitlines()[1:]
            if line.strip() and not line.startswith("#")]
    assert int(said.group(1).replace(",", "")) == len(rows)
    assert not [split for split in sorted({r[-1] for r in rows}) if f"`{split}`" not in page]


def _installed(path: str) -> bool:
    """Whether `path`, a file in a directory (`driver/returncodes.py`, Fast Downward's), is one of an installed
    package (a bare name, `hash.py`, is in some package or other)."""
    site = Path(sysconfig.get_paths()["purelib"])
    return "/" in path.strip("./") and any(str(f).endswith("/" + path.lstrip("./")) for f in site.rglob(Path(path).name))


def test_the_pages_name_no_file_outside_the_checkout():
    """Stop 47's pass: generalization.md's lemmas6 paragraph ran its bench with `--shared /work/shared/data`, the
    development machine's path; pddl.md named a scratch tool, `/tmp/obj46/over.py` (not kept), and `hash.py`, a
    script no clone has. A page names paths a reader's clone has (`../shared/data` is the project's layout
    beside it, which the benches explain), and every `x.py` it names is a file of the repository."""
    files = subprocess.run(["git", "-C", str(ROOT), "ls-files"], capture_output=True, text=True, check=True)
    names = {Path(f).name for f in files.stdout.splitlines()}
    outside, unknown = [], []
    for page in PAGES:
        text = page.read_text()
        outside += [f"{page.name}: {m.group()}" for m in re.finditer(r"(?<![\w.])/(?:work|tmp|home|root)/\S*", text)]
        unknown += [f"{page.name}: {m.group(1)}" for m in re.finditer(r"`(?:[\w./-]*/)?([\w-]+\.py)\b[^`]*`", text)
                    if m.group(1) not in names and not _installed(m.group(0).strip("`").split()[0])]
    assert not outside and not unknown, (outside, unknown)


def test_every_documented_command_parses():
    """Stop 49's pass: generalization.md showed `foon2pddl similarity --pairs --senses` as a command; run as written
    it exits 2 (`Missing argument 'LABELS...'`). Every command the pages show (not a synopsis; each `foon2pddl` of a
    pipeline) parses: its command exists and its arguments and options are ones the command takes (nothing is run)."""
    import click

    refused = []
    for c in documented_commands():
        parts: list[list[str]] = [[]]
        for word in shlex.split(c.text, comments=True):
            parts[-1:] = [parts[-1], []] if word in ("|", "&&", ";") else [[*parts[-1], word]]
        for part in (p for p in parts if p[:1] == ["foon2pddl"]):
            args = part[1:]
            try:
                with main.make_context("foon2pddl", args) as ctx:
                    name, command, rest = main.resolve_command(ctx, [*ctx.protected_args, *ctx.args])
                    command.make_context(name, rest, parent=ctx).close()
            except click.exceptions.Exit:
                pass  # --help, --version
            except click.UsageError as exc:
                refused.append(f"{c.where}: {c.text}: {exc.format_message()}")
    assert not refused, "\n".join(refused)


def test_pddl_md_quotes_what_compile_prints_for_a_missing_file(tmp_path):
    """pddl.md's `compile` paragraph quoted only `nope.json: error: no such file`; `compile --goal guacamole
    nope.json` (a missing PATHS entry) prints `... no such file or directory`. Each message compile prints for a
    missing file, as a network path and as a kitchen, is the one the paragraph quotes."""
    text = _prose("pddl.md")
    for args in (("nope.json",), ("--kitchen", "nope.json")):
        r = CliRunner().invoke(main, ["compile", "--goal", "guacamole", "-o", str(tmp_path), *args])
        assert r.exit_code == 2 and r.stderr.startswith("nope.json: error: "), r.stderr
        assert f"`{r.stderr.strip()}`" in text, r.stderr


def test_extending_md_names_what_the_guacamole_pours():
    """extending.md's network-kind example says the guacamole cannot be made without pour units because `its salt
    is poured`; the tree sprinkles its salt and pours its lime juice (issue 24's tried-again pass). The thing the
    comment names is what the guacamole's tree pours."""
    text = (ROOT / "docs" / "extending.md").read_text()
    poured = re.search(r"network_kind=\"nopour\"\).reason\s+# its (.+?) is poured", text)
    assert poured, "the nopour example's comment"
    r = CliRunner().invoke(main, ["retrieve", "--goal", "guacamole"])
    assert r.exit_code == 0, r.stderr
    pours = [line for line in r.stdout.splitlines() if re.match(r"\d+\. pour ", line)]
    assert pours and any(line.split(". ", 1)[1].startswith(f"pour {poured.group(1)}") for line in pours), pours


def test_readme_lists_every_sweepable_parameter():
    """README's sweep paragraph listed six parameters; `--sweep` takes seven (`objects-per-item` too, as its own
    error message says: `expected one of kitchen-fraction, ..., objects-per-item, ...`): issue 24's tried-again
    pass. The list is the registry's."""
    from foon2pddl.experiment.params import PARAMS

    text = (ROOT / "README.md").read_text()
    listed = re.search(r"runs the grid at every combination of values\s*\(([^)]*)\)", text)
    assert listed, "README's sweep paragraph"
    assert set(re.findall(r"`([a-z-]+)`", listed.group(1))) == set(PARAMS)


def test_retrieval_md_quotes_the_breakfast_pizza_as_retrieve_says_it():
    """retrieval.md quoted `spread sour cream from the scraper into the pizza dough (...)` after 14727fa made the step
    say `onto the pizza dough` (issue 24's tried-again pass). Every quote of the breakfast pizza's steps there (a
    quote naming its sour cream or its bacon) is what `retrieve` prints, up to its `...`."""
    text = " ".join((ROOT / "docs" / "retrieval.md").read_text().split())
    quotes = re.findall(r"`([a-z]+ (?:sour cream|onion \(peeled, sliced\) and bacon)[^`]*)`", text)
    assert len(quotes) >= 3, quotes
    r = CliRunner().invoke(main, ["retrieve", str(ROOT / "tests/data/foon-subgraphs/0085-mini_bacon_egg_breakfast_pizza.txt"),
                                  "--goal", "eggs and bacon pizza"])
    assert r.exit_code == 0, r.stderr
    said = " ".join(r.stdout.split())
    for q in quotes:
        assert " ".join(q.split(" (...)")[0].split(" ...")[0].split()) in said, q


def test_planning_md_says_what_the_time_limit_bounds(monkeypatch):
    """planning.md said `plan --time-limit 3` returns within about the limit plus a second; on the shared subgraphs
    `plan --goal "black bean" --time-limit 2` returned after 10 s, 7.5 s of them encoding, while stderr counted
    `planning 'black bean' (fd, relational encoding, time limit 2 s) ... 7 s` (stop 60's newcomer pass). The limit
    is the planner's (translation and search, as `--help` says): the page and the progress line say so, and a task
    whose encoding outlasts the limit still gets the whole limit for its planner."""
    import time

    from foon2pddl.cli import progress
    from foon2pddl.planners import solve

    text = " ".join((ROOT / "docs" / "planning.md").read_text().split())
    claim = re.search(r"so the planner ends within about the limit plus a second\. (.*?) A run with", text)
    assert claim and "not the reading of the network and the encoding" in claim.group(1), "what the limit bounds"
    real = solve.compile_goal

    def slow(*args, **kwargs):
        time.sleep(1.5)
        return real(*args, **kwargs)

    monkeypatch.setattr(solve, "compile_goal", slow)
    monkeypatch.setattr(progress, "AFTER", 0.0)  # every step says what it does (a test's stderr is no terminal)
    r = CliRunner().invoke(main, ["plan", "--goal", "whipped cream", "--encoding", "tree", "--time-limit", "1"])
    assert r.exit_code == 0 and "solved (" in r.stderr, r.stderr
    assert "planning 'whipped cream' (fd, tree encoding, planner time limit 1 s) ..." in r.stderr, r.stderr
    assert float(re.search(r"encode ([0-9.]+) s", r.stderr).group(1)) >= 1.5, r.stderr
