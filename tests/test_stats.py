"""`foon2pddl stats`: Table 1 layout, label counts, units per file, warnings; text and --json."""

from __future__ import annotations

import json
import re

from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.cli import main

# Two recipes. Level 3: the bowls with {salt} and {salt, pepper} differ, so no unit is shared;
# level 2 ignores ingredients, so the 'stir' units merge and so do the 'pour' units ('*' is no
# identity); level 1 keeps only labels: bowl, spoon, water.
RECIPE_A = """# Source:\thttp://example.org/a
//
O1\tbowl\t1
S1\tcontains\t{salt}
O2\tspoon\t1
M1\tstir\tAssumed\tAssumed
O1\tbowl\t0
S2\tmixed
S1\tcontains\t{salt}
//
O3\twater\t1
O1\tbowl\t0
S2\tmixed
S1\tcontains\t{salt}
M2\tpour*\t0:01\t0:03
O1\tbowl\t0
S1\tcontains\t{salt,water}
//
O1\tbowl\t0
S4\tempty
M3\tpour
//
"""

RECIPE_B = """O1\tbowl\t1
S1\tcontains\t{salt,pepper}
O2\tspoon\t1
M1\tstir
O1\tbowl\t0
S2\tmixed
S1\tcontains\t{salt,pepper}
//
O3\twater\t1
O1\tbowl\t0
S2\tmixed
S1\tcontains\t{pepper,salt}
M2\tpour
O1\tbowl\t0
S1\tcontains\t{salt,water,pepper}
"""


def _write(tmp_path):
    (tmp_path / "a.txt").write_text(RECIPE_A)
    (tmp_path / "b.foon").write_text(RECIPE_B)
    return tmp_path


def _stats(*args):
    result = CliRunner().invoke(main, ["stats", *map(str, args)])
    assert result.exit_code == 0, result.output
    return result.stdout


def test_stats_json_counts_each_level(tmp_path):
    data = json.loads(_stats(_write(tmp_path), "--json"))
    rows = {r["level"]: (r["object_nodes"], r["motion_nodes"], r["units"]) for r in data["levels"]}
    # level 3: bowl{salt}, spoon, bowl(mixed){salt}, water, bowl{salt,water} + 3 pepper bowls -> 8 nodes
    # level 2: bowl(contains), spoon, bowl(mixed, contains), water -> 4 nodes
    assert rows == {3: (8, 4, 4), 2: (4, 2, 2), 1: (3, 2, 2)}
    assert (data["object_labels"], data["state_labels"], data["motion_labels"]) == (3, 2, 2)
    assert data["composite_units"] == 1
    assert data["units_per_file"] == {str(tmp_path / "a.txt"): 2, str(tmp_path / "b.foon"): 2}
    assert len(data["warnings"]) == 1 and data["warnings"][0].startswith(f"{tmp_path / 'a.txt'}:19: warning:")


def test_stats_text_has_the_table_and_the_same_figures(tmp_path):
    folder = _write(tmp_path)
    text = _stats(folder)
    data = json.loads(_stats(folder, "--json"))
    table = re.findall(r"^\s+(\d)\s+(\d+)\s+(\d+)$", text, flags=re.MULTILINE)
    assert [tuple(map(int, row)) for row in table] == [
        (r["level"], r["object_nodes"], r["motion_nodes"]) for r in data["levels"]]
    assert text.splitlines()[0].split() == ["level", "object", "nodes", "motion", "nodes"]
    assert f"distinct object labels: {data['object_labels']}" in text
    assert "units per source file (2 files):" in text
    assert "warnings (1):" in text and "no output objects" in text


def test_stats_of_the_shared_subgraphs(tmp_path):
    data = json.loads(_stats(SUBGRAPHS, "--json"))
    assert [r["level"] for r in data["levels"]] == [1, 2, 3]
    objects = [r["object_nodes"] for r in data["levels"]]
    assert objects == sorted(objects) and len(set(objects)) == 3
    assert len(data["units_per_file"]) == 100
    _stats(SUBGRAPHS, "--json", "-o", tmp_path / "s.json")
    assert json.loads((tmp_path / "s.json").read_text()) == data


def test_stats_help_is_complete():
    text = CliRunner().invoke(main, ["stats", "--help"]).stdout
    for word in ("PATHS", "--json", "--output"):
        assert word in text
