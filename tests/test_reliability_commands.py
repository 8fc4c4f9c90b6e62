"""Reliability of the commands' inputs and outputs: duplicate JSON keys, optional hints, plan files,
GraphML text, batch outputs all or nothing, a full standard output, plot sizes, extreme costs, goal
text. Each was a reproduced defect: a wrong answer, a half-written output or a traceback."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import ROOT, SUBGRAPHS

from foon2pddl.cli import main
from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.constraints_file import parse_constraints
from foon2pddl.io.json_text import load_json

HOOKS = ROOT / "tests" / "hooks"  # sitecustomize simulating missing optional dependencies


def cli(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert "Traceback" not in result.output
    return result


def foon2pddl(*args, env: dict | None = None, **kw) -> subprocess.CompletedProcess:
    """The CLI in a subprocess, with the missing-dependency hooks available (off unless `env` sets them)."""
    full = dict(os.environ, PYTHONPATH=os.pathsep.join((str(ROOT), str(HOOKS))), **(env or {}))
    streams = {"stdout": subprocess.PIPE, "stderr": subprocess.PIPE, **kw}
    return subprocess.run([sys.executable, "-m", "foon2pddl", *map(str, args)], text=True, env=full, timeout=600,
                          **streams)


# ---------------------------------------------------------------- 2. duplicate keys in JSON inputs


def test_duplicate_key_in_a_constraints_file_is_a_located_error(tmp_path):
    f = tmp_path / "c.json"
    f.write_text('{"without_motions": ["pour"],\n "without_motions": []}\n')
    r = cli("retrieve", "--goal", "guacamole", "--constraints", f)
    assert r.exit_code == 2 and f"{f}:2: error: " in r.stderr and "without_motions" in r.stderr, r.output


@pytest.mark.parametrize("text, line", [
    ('{"a": 1,\n"a": 2}', 2),
    ('{"x": {"b": 1,\n\n "b": 1}}', 3),
    ('[{"u": 1}, {"u": 2},\n {"v": 1, "v": 1}]', 2),
    ('{"k\\u0041": 1,\n"kA": 2}', 2),  # the same key, escaped differently
])
def test_load_json_rejects_duplicate_keys_with_their_line(text, line):
    with pytest.raises(FoonSyntaxError) as err:
        load_json(text, "f.json")
    assert err.value.line == line and "duplicate key" in err.value.message


def test_same_key_in_different_objects_is_fine():
    assert load_json('[{"a": 1}, {"a": 2}, {"b": {"a": 3}}]', "f.json")[2]["b"]["a"] == 3


def test_duplicate_key_in_a_kitchen_and_a_foon_json(tmp_path):
    k = tmp_path / "k.json"
    k.write_text('[\n{"label": "bowl", "label": "avocado"}\n]\n')
    r = cli("retrieve", "--goal", "guacamole", "--kitchen", k)
    assert r.exit_code == 2 and f"{k}:2: error: " in r.stderr, r.output
    src = tmp_path / "w.json"
    assert cli("merge", "--format", "json", "-o", src, SUBGRAPHS / "0001-whipped_cream.txt").exit_code == 0
    lines = src.read_text().split("\n")
    lines[2] = lines[2].replace('"motion": {', '"motion": {"label": "x", ', 1)
    src.write_text("\n".join(lines))
    r = cli("stats", src)
    assert r.exit_code == 2 and f"{src}:3: error: " in r.stderr and "duplicate key" in r.stderr, r.output


# ---------------------------------------------------------------- 4. an optional hint never turns an answer into an error


def test_unreachable_goal_without_wordnet_exits_1(tmp_path):
    r = foon2pddl("retrieve", "--goal", "lemonade",
                  env={"FOON2PDDL_TEST_NO_WORDNET": "1", "FOON2PDDL_CACHE": str(tmp_path)})
    assert r.returncode == 1 and "cannot make 'lemonade'" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr and "error" not in r.stderr.lower().replace("cannot make", "")


# ---------------------------------------------------------------- 5. only validated plans reach --plan-file


def _fake_planner(tmp_path: Path, plan: str) -> str:
    script = tmp_path / "planner.py"
    script.write_text(f"import sys\nopen(sys.argv[3], 'w').write({plan!r})\n")
    return f"{sys.executable} {script} {{domain}} {{problem}} {{plan}}"


@pytest.mark.parametrize("plan", ["(bogus-action a b)\n; cost = 1 (unit cost)\n", "; cost = 0 (unit cost)\n"])
def test_rejected_plan_is_not_written_to_the_plan_file(tmp_path, plan):
    out = tmp_path / "sas_plan"
    r = cli("plan", "--goal", "guacamole", "--planner-cmd", _fake_planner(tmp_path, plan), "--plan-file", out)
    assert r.exit_code == 2, r.output
    assert not out.exists()


def test_plan_file_kept_when_a_later_plan_is_rejected(tmp_path):
    out = tmp_path / "sas_plan"
    assert cli("plan", "--goal", "guacamole", "--plan-file", out).exit_code == 0
    good = out.read_text()
    r = cli("plan", "--goal", "guacamole", "--planner-cmd", _fake_planner(tmp_path, "(nope)\n"), "--plan-file", out)
    assert r.exit_code == 2 and out.read_text() == good


# ---------------------------------------------------------------- 6. GraphML that parses


def test_graphml_with_noncharacters_parses(tmp_path):
    pytest.importorskip("networkx")
    import networkx as nx

    f = tmp_path / "odd.txt"
    f.write_text("O\tbowl\uffff\t1\nS\tempty\nM\tpour\uFFFE\nO\tbowl\uffff\t1\nS\tfull\n//\n", encoding="utf-8")
    r = cli("analyze", f, "--graphml", tmp_path / "g")
    assert r.exit_code == 0, r.output
    for name in ("foon", "objects", "motions"):
        path = tmp_path / "g" / f"{name}.graphml"
        ET.parse(path)
        nx.read_graphml(path)


# ---------------------------------------------------------------- 7. batch -o: all files or none


def test_retrieve_batch_writes_nothing_when_one_file_cannot_be_written(tmp_path):
    d = tmp_path / "D"
    (d / "greek-salad.txt").mkdir(parents=True)
    r = cli("retrieve", "--goal", "guacamole", "--goal", "greek salad", "-o", d)  # the embedded example
    assert r.exit_code == 2, r.output
    assert sorted(p.name for p in d.iterdir()) == ["greek-salad.txt"]


def test_compile_batch_leaves_no_empty_directory(tmp_path):
    d = tmp_path / "D"
    d.mkdir()
    (d / "greek-salad").write_text("in the way\n")
    r = cli("compile", "--goal", "guacamole", "--goal", "greek salad", "-o", d)
    assert r.exit_code == 2, r.output
    assert sorted(p.name for p in d.iterdir()) == ["greek-salad"]
    (d / "greek-salad").unlink()
    (d / "greek-salad" / "problem.pddl").mkdir(parents=True)
    r = cli("compile", "--goal", "guacamole", "--goal", "greek salad", "-o", d)
    assert r.exit_code == 2, r.output
    assert sorted(p.name for p in d.iterdir()) == ["greek-salad"]
    assert [p.name for p in (d / "greek-salad").iterdir()] == ["problem.pddl"]


# ---------------------------------------------------------------- 13. a full standard output


@pytest.mark.parametrize("args", [("stats",), ("retrieve", "--goal", "guacamole"), ("stats", "--json")])
def test_full_stdout_is_an_error_not_a_traceback(args):
    with open("/dev/full", "w") as full:
        r = foon2pddl(*args, stdout=full)
    assert r.returncode == 2 and "Traceback" not in r.stderr and "No space left" in r.stderr, r.stderr


# ---------------------------------------------------------------- 14. the plot's size comes from what it shows


def test_plot_with_a_huge_top_is_sized_by_the_items(tmp_path):
    pytest.importorskip("matplotlib")
    png = tmp_path / "x.png"
    r = cli("analyze", "--top", "100000", "--plot", png)
    assert r.exit_code == 0, r.output
    height = int.from_bytes(png.read_bytes()[20:24], "big")  # the PNG IHDR's height
    assert height < 10_000


# ---------------------------------------------------------------- 17. any finite cost the schema allows


@pytest.mark.parametrize("cost", [800, 1e300, 745.2])
def test_huge_costs_are_accepted(cost):
    cons = parse_constraints(json.dumps({"costs": {"slice": cost}}), "c.json")
    (motion, rate), = cons.rates
    assert motion == "slice" and 0.0 < rate < 1e-300


def test_huge_cost_makes_the_motion_a_last_resort(tmp_path):
    f = tmp_path / "c.json"
    f.write_text('{"costs": {"slice": 800}}')
    r = cli("retrieve", "--goal", "guacamole", "--constraints", f)
    assert r.exit_code == 0, r.output


# ---------------------------------------------------------------- 18. goal text is label text


@pytest.mark.parametrize("goal", ["guaca\0mole", "guacamole\x1b[2J", "\x7f"])
def test_control_characters_in_goals_are_rejected(goal):
    r = cli("retrieve", "--goal", goal, "--goal", "lemonade")
    assert r.exit_code == 2 and "control character" in r.stderr, r.output
    r = cli("retrieve", "--goal", goal)
    assert r.exit_code == 2 and "control character" in r.stderr, r.output


def test_control_characters_in_a_goal_list_file_are_located(tmp_path):
    f = tmp_path / "goals.txt"
    f.write_text("guacamole\nlemon\x00ade\n")
    r = cli("retrieve", "--goals", f)
    assert r.exit_code == 2 and f"{f}:2: error: " in r.stderr and "control character" in r.stderr, r.output


# ---------------------------------------------------------------- 12. a damaged WordNet corpus


def _damage(corpus: Path, case: str) -> None:
    data = corpus / "data.noun"
    if case == "no data.noun":
        data.unlink()
    elif case == "truncated data.noun":
        data.write_bytes(data.read_bytes()[: data.stat().st_size // 2])
    elif case == "garbage data.noun":
        data.write_bytes(os.urandom(100_000))
    elif case == "truncated index.noun":
        index = corpus / "index.noun"
        index.write_bytes(index.read_bytes()[:100_000])
    elif case == "bad lexnames":
        (corpus / "lexnames").write_text("garbage\n")
    elif case == "empty lexnames":
        (corpus / "lexnames").write_text("")


@pytest.mark.parametrize("case", ["no data.noun", "truncated data.noun", "garbage data.noun", "truncated index.noun",
                                  "bad lexnames", "empty lexnames", "bad zip", "zip without data.noun"])
def test_damaged_wordnet_is_a_located_error(tmp_path, case):
    import shutil
    import zipfile

    from foon2pddl.generalize import wordnet

    source = wordnet.locate()[1]
    root = tmp_path / "nltk_data"
    corpus = root / "corpora" / "wordnet"
    if source.suffix == ".zip":
        with zipfile.ZipFile(source) as zf:
            zf.extractall(root / "corpora")
    else:
        shutil.copytree(source, corpus)
    if case == "bad zip":
        shutil.rmtree(corpus)
        (root / "corpora" / "wordnet.zip").write_bytes(b"not a zip\n")
    elif case == "zip without data.noun":
        (corpus / "data.noun").unlink()
        with zipfile.ZipFile(root / "corpora" / "wordnet.zip", "w") as zf:
            for f in sorted(corpus.iterdir()):
                zf.write(f, f"wordnet/{f.name}")
        shutil.rmtree(corpus)
    else:
        _damage(corpus, case)
    env = {"NLTK_DATA": str(root), "FOON2PDDL_CACHE": str(tmp_path / "cache")}
    for args in (("similarity", "lemon", "lime"), ("expand", "-o", tmp_path / "x.txt")):
        r = foon2pddl(*args, env=env)
        assert r.returncode == 2 and "Traceback" not in r.stderr, r.stderr
        assert ": error: damaged WordNet corpus" in r.stderr and "reinstall" in r.stderr, r.stderr
    assert not (tmp_path / "x.txt").exists()
