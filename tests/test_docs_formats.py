"""What the input-format pages (docs/json-schema.md, docs/format.md) say about a file's fields and forms holds
for the reader and the shipped JSON Schema (issue 24: a newcomer writes files from these pages)."""

from __future__ import annotations

import json
import re

from conftest import ROOT

from foon2pddl.io.jsonio import parse_json

SCHEMA_PAGE = ROOT / "docs" / "json-schema.md"


def _optional_in_schema() -> set[str]:
    schema = json.loads((ROOT / "docs" / "foon.schema.json").read_text())
    parts = [schema, *schema["$defs"].values()]
    return {key for part in parts for key in part.get("properties", {}) if key not in part.get("required", ())}


def test_json_schema_md_lists_every_field_that_may_be_left_out():
    """json-schema.md said "Only `motion_flag`, ... and `expanded_from` may be left out" where the reader and the
    schema also take a document without `level`, a unit without `sources` and a source without `line` (each with
    the default the page's tables give)."""
    sentence = re.search(r"Only (.*?) may be left out", SCHEMA_PAGE.read_text(), re.S).group(1)
    said = set(re.findall(r"`(\w+)`", sentence))
    assert said == _optional_in_schema()


def test_a_document_without_the_optional_fields_reads_with_their_defaults():
    """The oracle for the list: a unit with no `sources`, a source with no `line`, a document with no `level`."""
    node = {"label": "onion", "states": []}
    doc = {"format": "foon2pddl.foon", "version": 1, "units": [
        {"inputs": [node], "motion": {"label": "chop"}, "outputs": [{"label": "onion", "states": [
            {"label": "chopped"}]}]},
        {"inputs": [node], "motion": {"label": "peel"}, "outputs": [node], "sources": [{"path": "r.txt"}]}]}
    foon = parse_json(json.dumps(doc), "doc.json")
    assert foon.level == 3 and foon.units[0].sources == () and foon.units[1].sources[0].line == 0
