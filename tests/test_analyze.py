"""`foon2pddl analyze`: projections and centralities checked against brute force, GraphML, PNG, JSON."""

from __future__ import annotations

import json

import networkx as nx
from click.testing import CliRunner

from foon2pddl.analysis.network import analyze, bipartite, motion_projection, object_projection
from foon2pddl.cli import main


def test_object_projection_degree_is_the_number_of_distinct_partners(example):
    g = object_projection(example.foon)
    partners: dict[str, set[str]] = {}
    for u in example.foon.units:
        labels = {n.label for n in (*u.inputs, *u.outputs)}
        for a in labels:
            partners.setdefault(a, set()).update(labels - {a})
    assert {n: g.degree(n) for n in g} == {a: len(p) for a, p in partners.items()}
    shared = sum(1 for u in example.foon.units if {"bowl", "spoon"} <= {n.label for n in (*u.inputs, *u.outputs)})
    assert g["bowl"]["spoon"]["weight"] == shared


def test_motion_projection_links_a_maker_to_a_consumer(example):
    g = motion_projection(example.foon)
    foon = example.foon
    for n, makers in list(foon.producers.items())[:50]:
        for c in foon.consumers.get(n, ()):
            a, b = foon.units[makers[0]].motion.label, foon.units[c].motion.label
            if a != b:
                assert g.has_edge(a, b)


def test_rankings_and_components(example):
    a = analyze(example.foon)
    top = a.top("objects", "degree_centrality", 3)
    assert [r.degree_centrality for r in top] == sorted((r.degree_centrality for r in a.objects), reverse=True)[:3]
    b = bipartite(example.foon)
    assert sum(a.components) == b.number_of_nodes()
    assert len(a.components) == nx.number_weakly_connected_components(b)
    assert analyze(example.foon, 3).object_count == len(set(example.foon.nodes))


def test_cli_json_graphml_and_png(tmp_path):
    r = CliRunner().invoke(main, ["analyze", "--top", "5", "--json", "--graphml", str(tmp_path / "g"),
                                  "--plot", str(tmp_path / "c.png")])
    assert r.exit_code == 0, r.output
    data = json.loads(r.stdout)
    assert len(data["top"]["objects"]["betweenness"]) == 5 and len(data["top"]["motions"]["degree_centrality"]) == 5
    objects = nx.read_graphml(tmp_path / "g" / "objects.graphml")
    best = data["top"]["objects"]["degree_centrality"][0]
    assert abs(objects.nodes[best["name"]]["degree_centrality"] - best["degree_centrality"]) < 1e-6
    assert {d["kind"] for _, d in nx.read_graphml(tmp_path / "g" / "foon.graphml").nodes(data=True)} == {"object",
                                                                                                      "motion"}
    assert (tmp_path / "c.png").read_bytes().startswith(b"\x89PNG")
    text = CliRunner().invoke(main, ["analyze", "--top", "3"])
    assert text.exit_code == 0 and "top 3 objects by degree centrality:" in text.stdout


def _graphs():
    """Random graphs with an isolated node, two components, a path and a star, and the degenerate sizes."""
    for seed in range(4):
        g = nx.gnm_random_graph(40, 70 + 20 * seed, seed=seed)
        g.add_node("alone")
        yield g
    yield nx.disjoint_union(nx.path_graph(7), nx.star_graph(5))
    yield from (nx.empty_graph(0), nx.empty_graph(1), nx.path_graph(2), nx.path_graph(3))


def test_batched_betweenness_is_networkx_betweenness(monkeypatch):
    """`analyze --level 3` of the shared subgraphs ran networkx's per-source betweenness for minutes in silence;
    the batched Brandes that replaces it gives networkx's values, exact and sampled (same seeded sample)."""
    from foon2pddl.analysis import betweenness

    monkeypatch.setattr(betweenness, "BATCH", 3)  # batches that split the sources unevenly
    for g in _graphs():
        want = nx.betweenness_centrality(g, normalized=True)
        got = betweenness.betweenness(g)
        assert got.keys() == want.keys() and all(abs(got[v] - want[v]) < 1e-9 for v in g), g
        if len(g) > 3:
            k = len(g) // 3
            want = nx.betweenness_centrality(g, k=k, normalized=True, seed=0)
            got = betweenness.betweenness(g, k=k, seed=0)
            assert all(abs(got[v] - want[v]) < 1e-9 for v in g), g


def test_analyze_says_how_far_betweenness_is(monkeypatch, example):
    """Each share of the source nodes is a step: a long betweenness says how far it is on stderr, a line at a
    time, rather than one line for minutes; the figures on stdout do not change."""
    from foon2pddl.analysis import betweenness
    from foon2pddl.cli import progress

    quiet = CliRunner().invoke(main, ["analyze", "--level", "3"])
    monkeypatch.setattr(progress, "AFTER", 0.0)  # every step counts as slow: each says what it is
    monkeypatch.setattr(betweenness, "STEP_WORK", 1)  # one batch of sources a step
    monkeypatch.setattr(betweenness, "BATCH", 64)
    r = CliRunner().invoke(main, ["analyze", "--level", "3"])
    assert r.exit_code == 0 and r.stdout == quiet.stdout
    n = analyze(example.foon, 3).object_count
    lines = [line for line in r.stderr.splitlines() if line.startswith("betweenness of ")]
    assert lines[0] == f"betweenness of {n:,} objects: source nodes 1-64 of {n:,} ..."
    assert lines[-2].endswith(f"-{n:,} of {n:,} ...") and lines[-1].startswith("betweenness of ")
    assert len([line for line in lines if " objects: " in line]) == -(-n // 64)


def test_cli_plot_refuses_a_name_that_is_no_png(tmp_path):
    """`analyze --plot x.svg` wrote PNG bytes into a file named .svg (newcomer pass nc50b): the name is
    refused as a usage error naming --plot, before any work, and no file is written."""
    r = CliRunner().invoke(main, ["analyze", "--plot", str(tmp_path / "x.svg")])
    assert r.exit_code == 2 and "Invalid value for '--plot'" in r.stderr and ".png" in r.stderr, r.output
    assert not (tmp_path / "x.svg").exists()
    ok = CliRunner().invoke(main, ["analyze", "--top", "2", "--plot", str(tmp_path / "X.PNG")])
    assert ok.exit_code == 0 and (tmp_path / "X.PNG").read_bytes().startswith(b"\x89PNG"), ok.output
