"""Universal FOON: file order never matters, duplicates go, provenance is joined, counts are right."""

from __future__ import annotations

import gc
import random
import shutil
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import SUBGRAPHS
from foon_strategies import foons, full, full_node
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.cli import main
from foon2pddl.errors import FoonInputError, FoonSyntaxError
from foon2pddl.io.files import expand_paths, load
from foon2pddl.io.jsonio import parse_json
from foon2pddl.io.parser import parse_file, parse_text
from foon2pddl.model.dedupe import dedupe_units, deduped
from foon2pddl.model.foon import (
    Foon,
    FunctionalUnit,
    Motion,
    Source,
    make_node,
    make_state,
)
from foon2pddl.model.levels import project
from foon2pddl.model.memo import per_network
from foon2pddl.model.merge import merge
from foon2pddl.model.node_table import node_table

FILES = expand_paths([SUBGRAPHS])


def _shuffled_copy(dest: Path, seed: int) -> dict[str, str]:
    """Copy the subgraphs under shuffled names (in two sub-directories); return new name -> original name."""
    names = list(range(len(FILES)))
    random.Random(seed).shuffle(names)
    renamed = {}
    for f, k in zip(FILES, names, strict=True):
        target = dest / ("a" if k % 2 else "b") / f"{k:03d}.txt"
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(f, target)
        renamed[str(target)] = f.name
    return renamed


def _canonical(foon: Foon, names: dict[str, str] | None = None):
    """Units as a set of keys, each with its provenance as (original file name, line) pairs."""
    def name(path: str) -> str:
        return names[path] if names else Path(path).name

    return {u.key: frozenset((name(s.path), s.line) for s in u.sources) for u in foon.units}


def test_result_does_not_depend_on_file_names_or_order(tmp_path, universal):
    foon, warnings = universal
    expected = _canonical(foon)
    for seed in (1, 2):
        names = _shuffled_copy(tmp_path / str(seed), seed)
        other, other_warnings = load([tmp_path / str(seed)])
        assert _canonical(other, names) == expected
        assert set(other.nodes) == set(foon.nodes)
        assert len(other_warnings) == len(warnings)
        for level in (1, 2):
            assert _canonical(project(other, level), names) == _canonical(project(foon, level))


def test_order_of_paths_given_does_not_matter():
    some = FILES[:12]
    forward, _ = load(some)
    backward, _ = load(list(reversed(some)) + [some[3]])
    assert full(backward, sources=True) == full(forward, sources=True)


def test_duplicate_files_dedupe_and_join_provenance(tmp_path):
    src = FILES[0]
    for name in ("x.txt", "y.foon"):
        shutil.copyfile(src, tmp_path / name)
    (tmp_path / "notes.md").write_text("ignored: not a FOON suffix\n")
    single, _ = load([src])
    double, _ = load([tmp_path])
    assert [u.key for u in double.units] == [u.key for u in single.units]
    for u in double.units:
        files = {Path(s.path).name for s in u.sources}
        assert files == {"x.txt", "y.foon"}
        assert len(u.sources) % 2 == 0


def test_units_repeated_inside_a_file_are_kept_once_with_both_lines():
    unit = "O\tbowl\nS\tempty\nM\tpour\nO\tbowl\nS\tcontains\t{water}\n//\n"
    other = "O\tbowl\nS\tcontains\t{water}\nM\tstir\nO\tbowl\nS\tcontains\t{water}\n//\n"
    foon = merge([parse_text(unit + other + unit.replace("pour", "pour*"), "r.foon").foon])
    assert [u.motion.label for u in foon.units] == ["pour", "stir"]
    assert [(s.path, s.line) for s in foon.units[0].sources] == [("r.foon", 1), ("r.foon", 13)]


def test_dedupe_keeps_the_first_unit_and_its_attributes():
    a = make_node("a", [make_state("x")])
    b = make_node("b")
    u1 = FunctionalUnit((a, b), Motion("m", "0:01", "0:02"), (b,), (Source("one", 1),))
    u2 = FunctionalUnit((b, make_node("a", [make_state("x")], motion_flag=1)), Motion("m", None, None, True), (b,),
                        (Source("two", 5),))
    u3 = FunctionalUnit((a,), Motion("m"), (b,), (Source("three", 2),))
    kept = dedupe_units([u1, u2, u3])
    assert len(kept) == 2
    assert kept[0].inputs == (a, b) and kept[0].motion.start == "0:01"
    assert [s.path for s in kept[0].sources] == ["one", "two"]
    assert kept[1].sources == (Source("three", 2),)


def _naive_counts(results, level: int) -> tuple[int, int]:
    """Object nodes and units at `level`, from plain tuples (no model equality, no projection code)."""
    def node_id(n):
        if level == 1:
            return n.label
        if level == 2:
            return (n.label, frozenset((s.label, s.related) for s in n.states))
        return (n.label, frozenset((s.label, s.related, frozenset(s.ingredients)) for s in n.states))

    nodes, units = set(), set()
    for res in results:
        for u in res.foon.units:
            ins = frozenset(map(node_id, u.inputs))
            outs = frozenset(map(node_id, u.outputs))
            nodes |= ins | outs
            units.add((u.motion.label, ins, outs))
    return len(nodes), len(units)


def test_level_counts_match_a_naive_computation(universal):
    results = [parse_file(f) for f in FILES]
    foon, _ = universal
    for level in (1, 2, 3):
        at = project(foon, level)
        assert (len(at.nodes), len(at.units)) == _naive_counts(results, level)
        loaded = load([SUBGRAPHS], level)[0]
        assert (loaded.level, len(loaded.nodes), len(loaded.units)) == (level, len(at.nodes), len(at.units))


def test_merge_lowers_the_level_to_the_lowest_input():
    text = "O\tbowl\nS\tcontains\t{salt}\nM\tm\nO\tbowl\nS\tcontains\t{salt, water}\n"
    full3 = parse_text(text).foon
    low = project(full3, 1)
    merged = merge([full3, low])
    assert merged.level == 1
    assert all(not n.states for n in merged.nodes)
    assert len(merged.units) == 1


def test_expand_paths_sorts_filters_and_reports_problems(tmp_path):
    (tmp_path / "d" / "sub").mkdir(parents=True)
    for name in ("d/b.txt", "d/sub/a.FOON", "d/c.json", "d/readme.md", "e.data"):
        (tmp_path / name).write_text("x")
    found = expand_paths([tmp_path / "e.data", tmp_path / "d"])
    assert found == sorted([tmp_path / "d/b.txt", tmp_path / "d/sub/a.FOON", tmp_path / "e.data"])
    with pytest.raises(FoonInputError, match="no such file"):  # a missing path is an input error, not a syntax error
        expand_paths([tmp_path / "nope"])
    (tmp_path / "empty").mkdir()
    with pytest.raises(FoonSyntaxError, match="no FOON files"):
        expand_paths([tmp_path / "empty"])


def test_load_reads_json_exports_named_directly(tmp_path):
    text_foon, _ = load(FILES[:3])
    result = CliRunner().invoke(main, ["merge", *map(str, FILES[:3]), "--format", "json", "-o", str(tmp_path / "u.json")])
    assert result.exit_code == 0, result.output
    again, _ = load([tmp_path / "u.json"])
    assert full(again, sources=True) == full(text_foon, sources=True)


# ---------------------------------------------------------------- the merge command


def _merge(*args: str) -> str:
    result = CliRunner().invoke(main, ["merge", *args])
    assert result.exit_code == 0, result.output
    return result.stdout


def test_merge_command_writes_idless_universal_foon_that_reparses(universal):
    foon, warnings = universal
    result = CliRunner().invoke(main, ["merge", str(SUBGRAPHS)])
    assert result.exit_code == 0
    text = result.stdout
    assert not any(line[:1] in "OSM" and line[1:2].isdigit() for line in text.splitlines())
    assert full(parse_text(text, "u.foon").foon) == full(foon)
    assert [ln for ln in result.stderr.splitlines()] == [str(w) for w in warnings]


def test_merge_command_is_deterministic_and_order_free(tmp_path):
    a = _merge(*map(str, FILES[:20]))
    b = _merge(*map(str, reversed(FILES[:20])))
    assert a == b
    _merge(*map(str, FILES[:20]), "-o", str(tmp_path / "u.foon"))
    assert (tmp_path / "u.foon").read_text() == a


def test_merge_command_ids_provenance_level_and_json(universal):
    foon, _ = universal
    some = list(map(str, FILES[:10]))
    small, _ = load(some)
    with_ids = _merge(*some, "--ids")
    assert any(line.startswith("O0\t") for line in with_ids.splitlines())
    assert full(parse_text(with_ids).foon) == full(small)

    prov = _merge(*some, "--provenance")
    comments = [ln[len("# from "):] for ln in prov.splitlines() if ln.startswith("# from ")]
    assert comments == [f"{s.path}:{s.line}" for u in small.units for s in u.sources]

    level1 = parse_text(_merge(*some, "--level", "1")).foon
    assert {u.key for u in level1.units} == {u.key for u in project(small, 1).units}
    assert all(not n.states for n in level1.nodes)

    as_json = parse_json(_merge(*some, "--format", "json", "--level", "2"))
    assert as_json.level == 2
    assert full(as_json, sources=True) == full(project(small, 2), sources=True)


def test_merge_command_without_paths_uses_the_example(example):
    assert full(parse_text(_merge()).foon) == full(example.foon)


def test_merge_help_lists_every_option():
    text = CliRunner().invoke(main, ["merge", "--help"]).stdout
    for word in ("PATHS", "--level", "--ids", "--provenance", "--format", "--output"):
        assert word in text
    assert "merge" in CliRunner().invoke(main, ["--help"]).stdout


# -- node numbers (`Foon.table`) and the passes built on them, against plain definitions over the units --


def _first_seen(units, sides=("inputs", "outputs")) -> dict:
    """Node -> the first object listed for it (on the given sides, unit by unit): what a dict of nodes keeps."""
    seen: dict = {}
    for u in units:
        for side in sides:
            for n in getattr(u, side):
                seen.setdefault(n, n)
    return seen


@settings(max_examples=80, deadline=None)
@given(foon=foons(max_units=8), flags=st.lists(st.integers(0, 1), min_size=40, max_size=40))
def test_node_table_and_network_indexes_match_their_definitions(foon, flags):
    """Nodes equal in identity but not in attributes (motion flags differ here) keep the first object listed,
    per side for producers and consumers; the numbering, duplicate removal and dictionaries agree with
    plain passes over the units."""
    marks = iter(flags)
    units = tuple(FunctionalUnit(tuple(replace(n, motion_flag=next(marks, 0)) for n in u.inputs), u.motion,
                                 tuple(replace(n, motion_flag=next(marks, 0)) for n in u.outputs), u.sources)
                  for u in foon.units)
    table = node_table(units)
    first = _first_seen(units)
    assert table.nodes == tuple(first)
    assert [[n is first[n] for n in table.nodes]] == [[True] * len(table.nodes)]
    assert [[table.nodes[i] for i in ids] for ids in table.inputs] == [list(u.inputs) for u in units]
    assert [[table.nodes[i] for i in ids] for ids in table.outputs] == [list(u.outputs) for u in units]
    net = deduped(units + units[:2])  # duplicates join their sources into the first unit
    assert [u.key for u in net.units] == [u.key for u in dedupe_units(units + units[:2])]
    assert full(net, sources=True) == full(Foon(dedupe_units(units + units[:2])), sources=True)
    for name, side in (("producers", "outputs"), ("consumers", "inputs")):
        got = getattr(Foon(units), name)
        want = _first_seen(units, (side,))
        assert [(full_node(n), v) for n, v in got.items()] == [
            (full_node(want[n]), tuple(i for i, u in enumerate(units) if n in getattr(u, side))) for n in want]
    by_label: dict = {}
    for n in _first_seen(units, ("outputs",)).values():
        by_label.setdefault(n.label, []).append(full_node(n))
    assert {k: [full_node(n) for n in v] for k, v in Foon(units).produced_by_label.items()} == by_label


def test_results_per_network_object_are_built_once_and_dropped_with_it():
    calls = []

    @per_network
    def count(foon, extra=0):
        calls.append(foon)
        return len(foon.units) + extra

    foon = parse_text("O\ta\nM\tm\nO\tb\n").foon
    assert count(foon) == count(foon) == 1 and len(calls) == 1
    assert count(foon, 1) == 2 and count(foon, 1) == 2 and len(calls) == 3  # more arguments: not remembered
    key = id(foon)
    del foon, calls[:]
    gc.collect()
    assert key not in count.cache
