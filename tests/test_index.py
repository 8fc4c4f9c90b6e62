"""The retrieval index (`analysis.index.build_index`) against a reference built from its definition.

The index is built on tuples or, for large networks, numpy arrays of (unit, node) pairs; the reference here follows each field's
definition with plain Python over the network's nodes (no node numbering, no arrays), so any slip in
the renumbering, the padded lexicographic sort or the pair sorts shows up as a difference.
"""

from __future__ import annotations

from unittest.mock import patch

from foon_strategies import foons, nodes
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.analysis import index
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state


def reference(foon: Foon) -> dict:
    """Every field of the index from its definition (FoonIndex's field comments)."""
    ordered = sorted({n for u in foon.units for n in (*u.inputs, *u.outputs)})  # the model's dataclass order
    node_id = {n: i for i, n in enumerate(ordered)}
    inputs = [tuple(sorted({node_id[n] for n in u.inputs})) for u in foon.units]
    outputs = [tuple(sorted({node_id[n] for n in u.outputs})) for u in foon.units]
    motions = [u.motion.label for u in foon.units]
    order = sorted(range(len(foon.units)), key=lambda u: (motions[u], inputs[u], outputs[u], u))
    rank = [order.index(u) for u in range(len(foon.units))]
    consumers = [tuple(u for u in order if i in inputs[u]) for i in range(len(ordered))]
    makers = [tuple(u for u in order if i in outputs[u] and i not in inputs[u]) for i in range(len(ordered))]
    return {"nodes": tuple(ordered), "node_id": node_id, "inputs": tuple(inputs), "outputs": tuple(outputs),
            "consumers": tuple(consumers), "makers": tuple(makers), "rank": tuple(rank), "order": tuple(order),
            "motions": tuple(motions)}


def assert_matches(foon: Foon) -> None:
    """Both ways of building (tuples for small networks, numpy arrays from `ARRAYS_FROM` units) give the reference."""
    want = reference(foon)
    for threshold in (0, len(foon.units) + 1):
        with patch.object(index, "ARRAYS_FROM", threshold):
            ix = index.build_index(foon)
        for name, value in want.items():
            got = getattr(ix, name)
            assert got == value, (name, threshold)
            assert type(got) is type(value), (name, threshold)
        assert list(ix.node_id) == list(ix.nodes)  # in id order
        for rows in (ix.inputs, ix.outputs, ix.consumers, ix.makers):
            assert all(type(x) is int for row in rows for x in row)


@st.composite
def crowded(draw):
    """Networks where units tie on motion and on inputs (two motions, a pool of four nodes, repeated nodes
    on a side, duplicate units): the content order's later keys and its unit-index tie-break decide."""
    pool = st.sampled_from([make_node("a"), make_node("a", [make_state("cut")]), make_node("b"),
                            make_node("c", [make_state("in", "a"), make_state("hot")])])
    side = st.lists(pool, min_size=0, max_size=4)
    units = draw(st.lists(st.tuples(side, st.sampled_from(["mix", "chop"]), side), max_size=9))
    return Foon(tuple(FunctionalUnit(tuple(i), Motion(m), tuple(o)) for i, m, o in units))


@settings(max_examples=150, deadline=None)
@given(crowded())
def test_index_matches_reference_on_crowded_networks(foon):
    assert_matches(foon)


@settings(max_examples=100, deadline=None)
@given(foons(min_units=0, max_units=8))
def test_index_matches_reference_on_random_networks(foon):
    assert_matches(foon)


@settings(max_examples=50, deadline=None)
@given(st.lists(nodes(), min_size=1, max_size=12))
def test_wide_units_sort_as_tuples(side):
    """A unit listing many nodes, beside units listing prefixes of them (a shorter tuple sorts first)."""
    units = [FunctionalUnit(tuple(side[:k]), Motion("m"), tuple(side[k:] or side[:1])) for k in range(len(side) + 1)]
    assert_matches(Foon(tuple(reversed(units))))


@settings(max_examples=60, deadline=None)
@given(crowded(), st.lists(st.integers(0, 15), min_size=1, max_size=30))
def test_kitchen_ids_answers_each_kitchen_by_value(foon, picks):
    """`kitchen_ids` keeps several kitchens by value: asked for kitchens in any order, equal ones built anew
    (another frozenset, a set) and more than it keeps, it answers what `ids` computes for each."""
    ix = index.build_index(foon)
    nodes_ = sorted({n for u in foon.units for n in (*u.inputs, *u.outputs)})
    for pick in picks:
        kitchen = frozenset(n for i, n in enumerate(nodes_) if pick >> i & 1)
        assert ix.kitchen_ids(kitchen) == tuple(ix.ids(kitchen)), pick
        assert ix.kitchen_ids(frozenset(set(kitchen))) == tuple(ix.ids(kitchen)), pick
