"""CLI: similarity, expand, generalize, and --network reg|exp|gen on retrieve, compile and plan."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from foon2pddl.cli import main
from foon2pddl.io.parser import parse_file


@pytest.fixture(scope="module")
def run():
    runner = CliRunner()
    return lambda *args: runner.invoke(main, list(args))


def test_similarity_floors(run):
    high = run("similarity", "onion", "chive", "--similarity", "paper")
    low = run("similarity", "onion", "knife", "--similarity", "paper")
    assert high.exit_code == 0 and float(high.stdout) >= 0.89
    assert low.exit_code == 0 and float(low.stdout) < 0.5


def test_cook_similarity_rejects_what_paper_accepts(run):
    assert run("similarity", "cilantro", "banana", "--similarity", "paper").stdout == "0.9000\n"
    cook = run("similarity", "cilantro", "banana", "--senses")
    assert cook.exit_code == 0 and cook.stdout.startswith("0.0000\n")
    assert "under matter.n.03 (rejected: the ancestor covers" in cook.stdout
    assert float(run("similarity", "lemon", "lime").stdout) >= 0.89


def test_user_overrides_extend_the_table(run, tmp_path):
    extra = tmp_path / "mine.json"
    extra.write_text(json.dumps({"forbidden": [["lemon", "lime"]], "pairs": [["cilantro", "banana", 0.5]]}))
    assert run("similarity", "lemon", "lime", "--overrides", str(extra)).stdout == "0.0000\n"
    assert run("similarity", "cilantro", "banana", "--overrides", str(extra)).stdout == "0.5000\n"
    extra.write_text('{"senses": {"lemon": ["nope.n.01"]}}')
    wrong = run("similarity", "lemon", "lime", "--overrides", str(extra))
    assert wrong.exit_code == 2 and wrong.stderr.startswith(f"{extra}: error: senses of 'lemon'")
    extra.write_text('{"forbidden": [["lemon"]]}')
    bad = run("similarity", "lemon", "lime", "--overrides", str(extra))
    assert bad.exit_code == 2 and f"{extra}:" in bad.stderr and "forbidden" in bad.stderr


def test_an_overrides_file_with_a_typo_or_a_key_given_twice_is_an_error(run, tmp_path):
    """Stop 46's pass: `--overrides` read its JSON with `json.loads`, so `"sensez"` (a typo) was ignored and
    a second `"pairs": []` dropped the first silently, where constraints.md says a key given twice is an error
    in every JSON input. Both are errors naming the file and line (exit 2); the shipped file's `_comment` stays."""
    extra = tmp_path / "mine.json"
    extra.write_text('{\n  "pairs": [["pot", "saucepan", 0.95]],\n  "sensez": {}\n}')
    typo = run("similarity", "pot", "saucepan", "--overrides", str(extra))
    assert typo.exit_code == 2 and typo.stderr.startswith(f"{extra}:3: error: unknown key 'sensez'"), typo.stderr
    extra.write_text('{\n  "pairs": [["pot", "saucepan", 0.95]],\n  "pairs": []\n}')
    twice = run("similarity", "pot", "saucepan", "--overrides", str(extra))
    assert twice.exit_code == 2 and twice.stderr.startswith(f"{extra}:3: error: duplicate key 'pairs'"), twice.stderr
    extra.write_text('{"_comment": "mine", "pairs": [["pot", "saucepan", 0.95]]}')
    assert run("similarity", "pot", "saucepan", "--overrides", str(extra)).stdout == "0.9500\n"


def test_expand_pairs_lists_every_substitution_with_its_evidence(run):
    tsv = run("expand", "--pairs")
    assert tsv.exit_code == 0, tsv.stderr
    lines = [line.split("\t") for line in tsv.stdout.splitlines()]
    assert lines[0] == ["label", "substitute", "similarity", "ancestor", "label_sense", "substitute_sense", "kind"]
    rows = {(r[0], r[1]): r for r in lines[1:]}
    assert rows[("lemon", "lime")][2:] == ["0.9167", "citrus.n.01", "lemon.n.01", "lime.n.06", "similar"]
    assert rows[("lemon juice", "lime juice")][-1] == "derived"
    as_json = json.loads(run("expand", "--pairs", "--format", "json").stdout)
    assert [(r["label"], r["substitute"]) for r in as_json] == [k for k in rows]
    paper = run("expand", "--pairs", "--similarity", "paper").stdout.splitlines()
    assert len(paper) > len(lines)  # the paper's rule substitutes more


def test_similarity_matrix_and_pairs(run):
    matrix = json.loads(run("similarity", "lemon", "lime", "knife", "--json").stdout)
    assert matrix["labels"] == ["lemon", "lime", "knife"]
    rows = matrix["matrix"]
    assert all(rows[i][j] == rows[j][i] for i in range(3) for j in range(3)) and rows[0][0] == 1.0
    pairs = run("similarity", "--pairs", "lemon", "lime", "onion", "knife")
    assert pairs.exit_code == 0 and len(pairs.stdout.splitlines()) == 2
    odd = run("similarity", "--pairs", "lemon", "lime", "onion")
    assert odd.exit_code == 2 and "even number" in odd.stderr


def test_expand_writes_a_readable_network_with_marked_copies(run, tmp_path):
    out = tmp_path / "exp.foon"
    r = run("expand", "--provenance", "-o", str(out))
    assert r.exit_code == 0, r.stderr
    assert "| EXP | 3 |" in r.stderr
    text = out.read_text()
    assert "(expanded from lemon)" in text
    parsed = parse_file(out).foon
    assert any(n.label == "lime" and any(s.label == "squeezed" for s in n.states)
               for u in parsed.units for n in u.outputs)
    guard = run("expand", "--max-units", "10", "-o", str(tmp_path / "no.foon"))
    assert guard.exit_code == 2 and "exceed 10 units" in guard.stderr
    assert not (tmp_path / "no.foon").exists()


def test_generalize_writes_category_network(run, tmp_path):
    out = tmp_path / "gen.foon"
    r = run("generalize", "-o", str(out))
    assert r.exit_code == 0, r.stderr
    labels = {n.label for u in parse_file(out).foon.units for n in u.inputs}
    assert "lemons and limes" in labels and "lemon" not in labels
    # a name read as its unit's object is generalized as it, and the reading is a note at the unit's file:line
    r = run("generalize", "tests/data/foon-subgraphs/0086-apple_turnover.txt", "--readings", "-o", str(out))
    assert r.exit_code == 0, r.stderr
    assert "note: category reading: tests/data/foon-subgraphs/0086-apple_turnover.txt:195: pan read as cooking " \
           "pan, so cookware\n" in r.stderr


def test_generalize_counts_its_category_readings_in_one_line_and_lists_them_with_readings(run, tmp_path):
    """The 100 subgraphs have 204 readings: one a line drowned the table; one line counts them, --readings lists."""
    r = run("generalize", "tests/data/foon-subgraphs", "-o", str(tmp_path / "gen.foon"))
    assert r.exit_code == 0, r.stderr
    notes = [line for line in r.stderr.splitlines() if "category reading" in line]
    assert notes == ["note: 204 category readings (a name a node uses read as its unit's object, and generalized as "
                     "it); --readings lists each at its unit's file:line"]
    listed = run("generalize", "tests/data/foon-subgraphs", "--readings", "-o", str(tmp_path / "gen.foon"))
    assert sum(line.startswith("note: category reading: ") for line in listed.stderr.splitlines()) == 204


def test_network_option_on_retrieve(run):
    assert run("retrieve", "--goal", "lemonade").exit_code == 1
    exp = run("retrieve", "--goal", "lemonade", "--network", "exp")
    assert exp.exit_code == 0 and "lime (whole)" in exp.stdout
    gen = run("retrieve", "--goal", "lemonade", "--network", "gen")
    assert gen.exit_code == 0 and "lemons and limes (whole)" in gen.stdout


def test_network_option_on_plan(run):
    assert run("plan", "--goal", "lemonade").exit_code == 1
    gen = run("plan", "--goal", "lemonade", "--network", "gen")
    assert gen.exit_code == 0, gen.stderr
    assert "lime (whole)" in gen.stdout and "valid" in gen.stderr
    exp = run("plan", "--goal", "lemonade", "--network", "exp")
    assert exp.exit_code == 0 and "lime" in exp.stdout
    bad = run("plan", "--goal", "lemonade", "--network", "gen", "--encoding", "state")
    assert bad.exit_code == 2 and "lifted" in bad.stderr


def test_compile_gen_writes_typed_pddl_that_parses(run, tmp_path):
    from pddl import parse_domain, parse_problem

    r = run("compile", "--goal", "lemonade", "--network", "gen", "-o", str(tmp_path))
    assert r.exit_code == 0, r.stderr
    domain = parse_domain(tmp_path / "domain.pddl")
    problem = parse_problem(tmp_path / "problem.pddl")
    assert any(t == "lemons_and_limes" for t in domain.types)
    assert any(a.parameters for a in domain.actions)
    declared = {o.name: o.type_tag for o in (*problem.objects, *domain.constants)}
    assert declared["lime"] == declared["lemon"] == "lemons_and_limes"


def test_exp_tree_names_its_substitutions_and_similarity_is_an_option(run):
    cook = run("retrieve", "--goal", "lemonade", "--network", "exp")
    assert cook.exit_code == 0 and "FOON-EXP (cook similarity, threshold 0.89)" in cook.stderr
    assert "substitution: lemon juice -> lime juice (Wu-Palmer 0.875)" in cook.stderr
    paper = run("retrieve", "--goal", "lemonade", "--network", "exp", "--similarity", "paper")
    assert paper.exit_code == 0 and "FOON-EXP (threshold 0.89): 101 -> 282 units" in paper.stderr
    assert paper.stdout == cook.stdout  # the same tree: lime stands in for lemon either way
    plain = run("retrieve", "--goal", "guacamole")
    assert "substitution:" not in plain.stderr
    planned = run("plan", "--goal", "lemonade", "--network", "exp")
    assert planned.exit_code == 0 and "substitution: lemon juice -> lime juice" in planned.stderr


def test_exp_names_a_product_renamed_along_that_neither_the_network_nor_the_kitchen_holds(run):
    """The lemonade recipe alone with the example kitchen's limes: the EXP copy that pours the juice records
    `lemon juice -> lime juice`, a label outside the vocabulary the EXP view's matrix covers (network and
    kitchen labels); naming it raised KeyError: 'lime juice' (a traceback) once the notes read that matrix."""
    from foon2pddl.io.inputs import example_path

    lemonade = str(example_path() / "01-lemonade.foon")
    kitchen = str(example_path("example_kitchen.txt"))
    r = run("retrieve", "--goal", "lemonade", "--network", "exp", "--kitchen", kitchen, lemonade)
    assert r.exit_code == 0, r.stderr
    assert "substitution: lemon juice -> lime juice (Wu-Palmer 0.875)" in r.stderr
