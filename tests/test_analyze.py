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
