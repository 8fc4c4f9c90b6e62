"""Memory and time bounded by input size: `check` on huge labels, `analyze` on large networks
(betweenness sampled, and said so), a sweep grid too large to run refused at once."""

from __future__ import annotations

import json
import time
import tracemalloc

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.analysis import check_labels
from foon2pddl.analysis.network import analyze
from foon2pddl.cli import main
from foon2pddl.errors import UsageError
from foon2pddl.experiment.params import MAX_POINTS, check_grid
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state


def _peak(fn) -> int:
    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def _check(path):
    result = CliRunner().invoke(main, ["check", str(path)])
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    return result


def _label_file(tmp_path, name: str, label: str):
    f = tmp_path / name
    f.write_text(f"O\t{label}\t1\nS\tempty\nM\tpour\nO\t{label}\t1\nS\tfull\n//\n"
                 f"O\t{label}x\t1\nS\tempty\nM\tstir\nO\tbowl\t1\nS\tfull {{{', '.join(['a'] * 2000)}}}\n//\n")
    return f


# ---------------------------------------------------------------- 16. check: memory linear in label length


def test_check_memory_does_not_grow_with_the_square_of_a_label(tmp_path):
    small = _peak(lambda: _check(_label_file(tmp_path, "s.txt", "mixing bowl")))
    huge = _peak(lambda: _check(_label_file(tmp_path, "h.txt", "bowl" * 5000)))  # a 20,000-character label
    assert huge - small < 20_000_000, (small, huge)


@settings(max_examples=200, deadline=None)
@given(st.text("abcde", max_size=12), st.text("abcde", max_size=12))
def test_distance_one_agrees_with_the_definition(a, b):
    def oracle(x, y):  # every string one edit away from x
        letters = set(x + y) | {"z"}
        near = {x[:i] + x[i + 1:] for i in range(len(x))}
        near |= {x[:i] + c + x[i + 1:] for i in range(len(x)) for c in letters}
        near |= {x[:i] + c + x[i:] for i in range(len(x) + 1) for c in letters}
        return y in near - {x}

    assert check_labels._distance_one(a, b) == oracle(a, b)


def test_long_labels_are_still_variants_by_their_normalized_form():
    long = "very " * 20 + "tomato"
    defects = check_labels.spelling_variants({long: [], long.replace("tomato", "tomatoes"): []})
    assert len(defects) == 1


# ---------------------------------------------------------------- 16. analyze: betweenness sampled on large networks


def _wide_foon(objects: int):
    units = []
    for i in range(objects):
        a, b = make_node(f"item {i}", [make_state("raw")]), make_node(f"item {i + 1}", [make_state("raw")])
        units.append(FunctionalUnit((a,), Motion(f"move {i % 7}"), (b,)))
    return Foon(tuple(units))


def test_betweenness_is_exact_within_its_budget_and_sampled_beyond(monkeypatch):
    from foon2pddl.analysis import network

    assert analyze(_wide_foon(50)).sampled == ()
    monkeypatch.setattr(network, "BETWEENNESS_WORK", 20_000)
    big = analyze(_wide_foon(400))  # 401 objects: exact would visit 401 * 801 edges and nodes
    assert big.sampled == (("objects", 24),)  # 20,000 // 801 sources
    assert analyze(_wide_foon(400)) == big  # the sample is seeded: deterministic
    monkeypatch.setattr(network, "BETWEENNESS_WORK", 10**12)
    truth = {r.name: r.betweenness for r in analyze(_wide_foon(400)).objects}
    guess = {r.name: r.betweenness for r in big.objects}
    middle = max(truth, key=truth.get)
    assert guess[middle] > 0.5 * truth[middle]  # an estimate of the same quantity, not noise


def test_analyze_says_when_betweenness_is_sampled(tmp_path, monkeypatch):
    from foon2pddl.analysis import network

    monkeypatch.setattr(network, "BETWEENNESS_WORK", 200)
    r = CliRunner().invoke(main, ["analyze"])
    assert r.exit_code == 0 and "betweenness of objects estimated from 10 sampled source nodes" in r.output, r.output
    r = CliRunner().invoke(main, ["analyze", "--json"])
    assert json.loads(r.output)["betweenness_sampled"] == {"objects": 10, "motions": 10}


# ---------------------------------------------------------------- 16. a sweep grid too large to run


def test_huge_sweep_grid_is_refused_at_once(tmp_path):
    values = ",".join(f"{i / 2001:.6f}" for i in range(1, 2001))
    t0 = time.perf_counter()
    r = CliRunner().invoke(main, ["experiment", "--trials", "1", "--goals", "1", "--solvers", "native-greedy",
                                  "--sweep", f"kitchen-fraction={values}", "--sweep", f"threshold={values}",
                                  "-o", str(tmp_path / "run"), "--no-progress"])
    assert r.exit_code == 2 and "4,000,000 points" in r.output, r.output
    assert time.perf_counter() - t0 < 30 and not (tmp_path / "run").exists()


def test_grid_bound():
    check_grid([("level", (1, 2, 3))])
    with pytest.raises(UsageError):
        check_grid([("a", tuple(range(MAX_POINTS))), ("b", (1, 2))])
