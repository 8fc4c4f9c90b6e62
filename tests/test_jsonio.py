"""JSON export/import of a FOON: lossless round trip, deterministic text, errors that name the item."""

from __future__ import annotations

import json

import pytest
from conftest import ROOT
from foon_strategies import foons, full
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.errors import FoonSyntaxError
from foon2pddl.io.jsonio import FORMAT, VERSION, foon_from_dict, foon_to_dict, parse_json, read_json, write_json
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node
from foon2pddl.model.levels import project


@settings(max_examples=60, deadline=None)
@given(foon=foons(), level=st.sampled_from([1, 2, 3]))
def test_round_trip_keeps_everything(foon, level):
    foon = project(foon, level)
    text = write_json(foon)
    again = parse_json(text, "gen.json")
    assert full(again, sources=True) == full(foon, sources=True)
    assert write_json(again) == text
    assert foon_from_dict(json.loads(text)) == foon


def test_universal_round_trip_and_determinism(universal, tmp_path):
    foon, _ = universal
    text = write_json(foon)
    assert text == write_json(Foon(tuple(foon.units), foon.level))
    assert text.count("\n") == len(foon.units) + 2  # header line, one line per unit, closing line
    path = tmp_path / "u.json"
    path.write_text(text, encoding="utf-8")
    assert full(read_json(path), sources=True) == full(foon, sources=True)


def test_export_shape():
    unit = FunctionalUnit((make_node("cup", motion_flag=1),), Motion("fill", "0:01", "0:02", True),
                          (make_node("cup", dish=3, goal=True),), (Source("r.txt", 4, "http://x"),))
    data = foon_to_dict(Foon((unit,)))
    assert (data["format"], data["version"], data["level"]) == (FORMAT, VERSION, 3)
    assert data["units"] == [{
        "inputs": [{"label": "cup", "states": [], "motion_flag": 1}],
        "motion": {"label": "fill", "start": "0:01", "end": "0:02", "composite": True},
        "outputs": [{"label": "cup", "states": [], "goal": True, "dish": 3}],
        "sources": [{"path": "r.txt", "line": 4, "url": "http://x"}],
    }]


def test_schema_file_describes_the_export(universal):
    """docs/foon.schema.json stays in step with the exporter: every key written is declared there."""
    schema = json.loads((ROOT / "docs" / "foon.schema.json").read_text())
    defs = schema["$defs"]
    assert set(schema["required"]) == {"format", "version", "units"}
    assert schema["properties"]["format"]["const"] == FORMAT
    declared = {name: set(d["properties"]) for name, d in defs.items() if "properties" in d}
    unit = foon_to_dict(universal[0])["units"][0]
    assert set(unit) <= declared["unit"]
    assert {"label", "states", "motion_flag", "goal", "dish"} == declared["node"]
    assert {"label", "related", "ingredients"} == declared["state"]
    assert {"label", "start", "end", "composite"} == declared["motion"]
    assert {"path", "line", "url", "expanded_from"} == declared["source"]


GOOD = {"format": FORMAT, "version": 1, "units": [
    {"inputs": [{"label": "egg", "states": [{"label": "whole"}]}], "motion": {"label": "crack"},
     "outputs": [{"label": "egg", "states": [{"label": "cracked"}, {"label": "in", "related": "bowl"}]}]},
]}


def _broken(edit) -> str:
    data = json.loads(json.dumps(GOOD))
    edit(data)
    return json.dumps(data, indent=2)


def _set(path, value):
    def edit(data):
        target = data
        for step in path[:-1]:
            target = target[step]
        if value is KeyError:
            del target[path[-1]]
        else:
            target[path[-1]] = value
    return edit


@pytest.mark.parametrize(("edit", "where", "problem"), [
    (_set(("format",), "other"), "format", "not a foon2pddl FOON"),
    (_set(("version",), 2), "version", "unsupported version 2"),
    (_set(("version",), True), "version", "unsupported version"),
    (_set(("level",), 4), "level", "level must be 1, 2 or 3"),
    (_set(("units",), {}), "units", "units must be a list"),
    (_set(("units", 0, "motion"), KeyError), "units[0]", "lacks the required field 'motion'"),
    (_set(("units", 0, "inputs"), []), "units[0].inputs", "inputs is empty"),
    (_set(("units", 0, "outputs", 0, "label"), 3), "units[0].outputs[0].label", "non-empty string"),
    (_set(("units", 0, "outputs", 0, "label"), "  "), "units[0].outputs[0].label", "non-empty string"),
    (_set(("units", 0, "outputs", 0, "states", 1, "related"), ["bowl"]), "units[0].outputs[0].states[1].related",
     "must be a string"),
    (_set(("units", 0, "inputs", 0, "states", 0, "colour"), "red"), "units[0].inputs[0].states[0].colour",
     "unknown key 'colour' in state (expected one of label, related, ingredients)"),
    (_set(("units", 0, "inputs", 0, "motion_flag"), True), "units[0].inputs[0].motion_flag", "must be an integer"),
    (_set(("units", 0, "inputs", 0, "dish"), "3"), "units[0].inputs[0].dish", "must be an integer"),
    (_set(("units", 0, "motion", "label"), "pour*"), "units[0].motion.label", "composite"),
    (_set(("units", 0, "sources"), [{"path": "a", "line": -1}]), "units[0].sources[0].line", ">= 0"),
    (_set(("units", 0, "inputs", 0, "label"), "e\x00g"), "units[0].inputs[0].label", "control character"),
    (_set(("level",), 1), "units[0].inputs[0].states", "level-1 network"),
])
def test_errors_name_the_item_and_its_line(edit, where, problem):
    text = _broken(edit)
    with pytest.raises(FoonSyntaxError) as info:
        parse_json(text, "bad.json")
    err = info.value
    assert err.path == "bad.json"
    assert err.message.startswith(where + ": ") and problem in err.message, err.message
    lines = text.splitlines()
    units_line = next(i for i, row in enumerate(lines, start=1) if '"units"' in row)
    if where.startswith("units["):  # inside the offending unit, after the line that opens the list
        assert units_line < err.line <= len(lines)
    else:  # a top-level field: at or before the line of "units"
        assert 1 <= err.line <= units_line


def test_level_2_rejects_ingredients_and_reports_line():
    data = json.loads(json.dumps(GOOD))
    data["level"] = 2
    data["units"][0]["outputs"][0]["states"][1]["ingredients"] = ["salt"]
    text = json.dumps(data, indent=2)
    with pytest.raises(FoonSyntaxError, match=r"units\[0\]\.outputs\[0\]\.states\[1\]\.ingredients: ingredient list"):
        parse_json(text, "bad.json")


def test_invalid_json_names_line_and_column():
    with pytest.raises(FoonSyntaxError) as info:
        parse_json('{"format": "foon2pddl.foon",\n "version": 1,\n "units": [,]}', "bad.json")
    assert info.value.line == 3 and "invalid JSON" in info.value.message and "column" in info.value.message


def test_import_normalizes_labels_and_states():
    data = json.loads(json.dumps(GOOD))
    data["units"][0]["outputs"][0]["label"] = "  EGG "
    data["units"][0]["outputs"][0]["states"].reverse()
    assert parse_json(json.dumps(data)) == parse_json(json.dumps(GOOD))
