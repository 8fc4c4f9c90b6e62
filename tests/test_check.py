"""`foon2pddl check`: every defect class on the shared subgraphs, and one planted defect of each class found."""

from __future__ import annotations

import json
import shutil

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS

from foon2pddl.analysis.check import DefectKind, check
from foon2pddl.analysis.check_labels import naive_singular, spelling_variants
from foon2pddl.cli import main
from foon2pddl.io.parser import parse_text
from foon2pddl.io.raw_objects import scan_text
from foon2pddl.model.foon import Source

# One defect of each class, with labels no shared file uses.
PLANTED = """//
O1\tzorb bowl\t0
S1\tcontains\t{zorbflour}
S2\tin\t[zmixer]
O2\tspoon\t1
M1\tmix\tAssumed\tAssumed
O1\tzorb bowl\t0
S1\tcontains\t{zorbflour}
S2\tin\t[zmixer]
O3\tzorbdough\t1
S2\tin\t[zorb bowl]
//
O4\tzqa\t1
S3\thot
M2\theat\tAssumed\tAssumed
O5\tzqb\t1
S3\thot
//
O5\tzqb\t1
S3\thot
M2\theat\tAssumed\tAssumed
O4\tzqa\t1
S3\thot
//
O6\tzqx\t1
S4\twet
M3\twipe\tAssumed\tAssumed
O6\tzqx\t1
S4\twet
//
O7\tzqpepper\t1
S5\tground
M4\tpour\tAssumed\tAssumed
O8\tzqpot\t0
S1\tcontains\t{zqsalt}
O7\tzqpepper\t1
S2\tin\t[zqpot]
//
O9\tzqtomatoes\t1
S2\tin\t[zqnowhere]
M5\tslice\tAssumed\tAssumed
O10\tzqtomato\t1
S6\tsliced
//
O11\tzqcarrot\t1
S7\twhole
S8\twashed
M6\tpeel\tAssumed\tAssumed
O12\tzqegg\t1
S9\traw
S9\traw
//
O12\tzqegg\t1
S9\traw
O11\tzqcarrot\t1
S8\twashed
S7\twhole
M7\tcrack\tAssumed\tAssumed
O12\tzqegg\t1
S10\tcracked
//
"""


def test_every_planted_defect_is_found_at_its_place(tmp_path):
    data = tmp_path / "subgraphs"
    shutil.copytree(SUBGRAPHS, data)
    planted = data / "zz-planted.txt"
    planted.write_text(PLANTED)
    r = CliRunner().invoke(main, ["check", str(data), "--json", "--no-wordnet"])
    assert r.exit_code == 1, r.output
    report = json.loads(r.stdout)
    here = {d["kind"] for d in report["defects"] if any(p.startswith(str(planted) + ":") for p in d["places"])}
    assert here == {str(k) for k in DefectKind}
    lines = {d["kind"]: d["places"] for d in report["defects"] if d["places"][0].startswith(str(planted))}
    assert f"{planted}:13" in lines["no-entry-cycle"] and f"{planted}:19" in lines["no-entry-cycle"]
    assert lines["identity-unit"] == [f"{planted}:25"]
    assert lines["duplicate-state"] == [f"{planted}:49"]


def test_shared_subgraphs_report_every_class_with_counts():
    r = CliRunner().invoke(main, ["check", str(SUBGRAPHS), "--no-wordnet"])
    assert r.exit_code == 1
    summary = r.stdout.splitlines()[-1]
    assert summary.startswith("defects: ") and all(f"{k} " in summary for k in DefectKind)
    assert "self-supporting 8" in summary
    assert "bowl (contains {banana pudding mix, condensed milk, cream cheese}, in [mixer])" in r.stdout


def test_clean_network_exits_0():
    foon = parse_text("//\nO1\tonion\t1\nS1\twhole\nM1\tchop\t0:01\t0:02\nO1\tonion\t1\nS2\tchopped\n//\n", "c").foon
    assert check(foon) == []


@pytest.mark.parametrize("plural, single", [("berries", "berry"), ("tomatoes", "tomato"), ("dishes", "dish"),
                                            ("eggs", "egg"), ("glass", "glass"), ("asparagus", "asparagus")])
def test_naive_singular(plural, single):
    assert naive_singular(plural) == single


def test_spelling_variants_string_rules_and_lexicon_veto():
    where = {label: [Source("f", i)] for i, label in enumerate(["raman", "ramen", "tomato", "tomatoes", "green onion",
                                                                "green-onion", "batter", "butter", "pan", "pen"])}
    groups = {tuple(d.subjects) for d in spelling_variants(where)}
    assert groups == {("raman", "ramen"), ("tomato", "tomatoes"), ("green onion", "green-onion"), ("batter", "butter")}
    known = {"batter": "batter", "butter": "butter", "tomato": "tomato", "tomatoes": "tomato"}
    vetoed = {tuple(d.subjects) for d in spelling_variants(where, known.get)}
    assert ("batter", "butter") not in vetoed and ("raman", "ramen") in vetoed


def test_raw_scan_keeps_written_order():
    (obj,) = list(scan_text("O1\tEgg\t1\r\nS1\traw\r\nS2\tin\t[bowl]\r\n", "f"))
    assert (obj.label, obj.states, obj.line) == ("egg", ("raw", "in [bowl]"), 1)
