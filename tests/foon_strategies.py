"""hypothesis strategies for FOON model objects, and a full-attribute view for comparisons.

Model equality deliberately ignores attributes (motion flag, goal and dish marks,
times, composite flag, provenance); `full` exposes them so that round-trip tests
check that nothing is lost.
"""

from __future__ import annotations

from hypothesis import strategies as st

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_node, make_state, normalize_label

# Characters the FOON text format can carry inside labels (no tab, newline, brackets, braces or commas).
_ALPHABET = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 -'()&/.:éü"

labels = st.text(_ALPHABET, min_size=1, max_size=12).map(normalize_label).filter(bool)
motion_labels = labels.filter(lambda s: not s.endswith("*"))
times = st.sampled_from(["Assumed", "assumed", "Assume", "0:10", "1:02:03", "3:0s7", "1:116", "0:4:50"])


@st.composite
def states(draw):
    related = draw(st.one_of(st.just(""), labels))
    ingredients = draw(st.lists(labels, max_size=3))
    return make_state(draw(labels), related, ingredients)


@st.composite
def nodes(draw, pool=None):
    label = draw(pool) if pool is not None else draw(labels)
    return make_node(
        label,
        draw(st.lists(states(), max_size=3)),
        motion_flag=draw(st.integers(0, 1)),
        goal=draw(st.booleans()),
        dish=draw(st.one_of(st.none(), st.integers(0, 29))),
    )


@st.composite
def motions(draw):
    label = draw(motion_labels)
    timed = draw(st.booleans())
    start = draw(times) if timed else None
    end = draw(times) if timed else None
    return Motion(label, start, end, draw(st.booleans()))


@st.composite
def units(draw, pool=None):
    """A level-3 unit: each node once per side, as the readers keep them (a line written twice is one object)."""
    node = nodes(pool)
    return FunctionalUnit(
        tuple(draw(st.lists(node, min_size=1, max_size=4, unique=True))),
        draw(motions()),
        tuple(draw(st.lists(node, min_size=1, max_size=4, unique=True))),
        (Source("gen.foon", draw(st.integers(0, 500))),),
    )


@st.composite
def foons(draw, min_units=1, max_units=6):
    """A level-3 network; node labels drawn from a small pool so that units share nodes."""
    pool = st.sampled_from(draw(st.lists(labels, min_size=1, max_size=6, unique=True)))
    return Foon(tuple(draw(st.lists(units(pool), min_size=min_units, max_size=max_units))))


def full_node(n):
    return (n.label, n.states, n.motion_flag, n.goal, n.dish)


def full_unit(u, sources: bool = False):
    m = u.motion
    view = (tuple(map(full_node, u.inputs)), (m.label, m.start, m.end, m.composite), tuple(map(full_node, u.outputs)))
    return view + (u.sources,) if sources else view


def full(foon: Foon, sources: bool = False):
    """Everything a network holds, attributes included (sources only on request)."""
    return (foon.level, tuple(full_unit(u, sources) for u in foon.units))
