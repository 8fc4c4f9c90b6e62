"""Predicate arguments typed by their uses (`pddl.arg_types`): every atom still type-checks, types are tight."""

from __future__ import annotations

from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.generalize.categories import shipped_index
from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.model.goal import resolve_goal
from foon2pddl.pddl.arg_types import common_type, narrow_arguments
from foon2pddl.pddl.encode_lifted import ROOT_TYPE, encode_lifted
from foon2pddl.pddl.examples import GOALS
from foon2pddl.pddl.shared import share_domain
from foon2pddl.pddl.task import Atom, PlanningTask, Predicate, type_closure

INDEX = shipped_index()


def test_common_type_is_the_deepest_shared_ancestor():
    parent = {"food": "object", "fruit": "food", "citrus": "fruit", "apple": "fruit", "tool": "object"}
    assert common_type(parent, ["citrus", "apple"]) == "fruit"
    assert common_type(parent, ["citrus", "citrus"]) == "citrus"
    assert common_type(parent, ["citrus", "fruit"]) == "fruit"
    assert common_type(parent, ["citrus", "tool"]) == "object"
    assert common_type(parent, []) == "object"


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(0, 30), min_size=1, max_size=30), st.data())
def test_common_type_is_an_ancestor_of_each_and_no_child_of_it_is(parents, data):
    names = [f"t{i}" for i in range(len(parents) + 1)]  # t0's parent is object; t_k's parent has a smaller index
    parent = {names[0]: "object", **{names[k]: names[p % k] for k, p in enumerate(parents, start=1)}}
    types = data.draw(st.lists(st.sampled_from(names), min_size=1, max_size=5))

    def chain(t):
        out = [t]
        while out[-1] != "object":
            out.append(parent[out[-1]])
        return out

    found = common_type(parent, types)
    assert all(found in chain(t) for t in types)
    children = [c for c, p in parent.items() if p == found]
    assert not any(all(c in chain(t) for t in types) for c in children)


def _task(dish, example, kitchen):
    return encode_lifted(example.foon, kitchen, resolve_goal(parse_goal_spec(dish), example.foon), INDEX).task


@pytest.fixture(scope="module")
def kitchen():
    from foon2pddl.io.inputs import example_path
    from foon2pddl.io.kitchen_files import read_kitchen

    return read_kitchen(example_path("example_kitchen.txt"))


@pytest.mark.parametrize("dish", [*GOALS, "lemonade"])
def test_every_atom_fits_its_predicates_types_and_each_type_is_tight(example, kitchen, dish):
    task = _task(dish, example, kitchen)
    has = type_closure(task)
    parent = dict(task.types)
    declared = {p.name: [t for _, t in p.params] for p in task.predicates}
    seen: dict[tuple[str, int], set[str]] = {}
    for atoms, variables in [((*task.init, *task.goal), {}),
                             *(((*a.pre, *a.add), dict(a.params)) for a in task.actions)]:
        for atom in atoms:
            for k, arg in enumerate(atom.args):
                typ = variables.get(arg)
                kinds = has[arg] if typ is None else set(_chain(parent, typ))
                assert declared[atom.predicate][k] in kinds, (dish, atom, k)  # it type-checks
                seen.setdefault((atom.predicate, k), set()).add(typ or dict(task.objects + task.constants)[arg])
    for (name, k), uses in seen.items():  # no child of the declared type admits every use
        children = [c for c, p in parent.items() if p == declared[name][k]]
        assert not any(all(c in _chain(parent, u) for u in uses) for c in children), (dish, name, k)


def _chain(parent, t):
    out = [t]
    while out[-1] in parent:
        out.append(parent[out[-1]])
    return out


def test_narrowing_shrinks_the_ground_atoms_a_reader_enumerates(example, kitchen):
    task = _task("fruit salad", example, kitchen)
    rooted = replace(task, predicates=tuple(replace(p, params=tuple((v, ROOT_TYPE) for v, _ in p.params))
                                            for p in task.predicates))
    assert narrow_arguments(rooted) == task

    def ground_atoms(t: PlanningTask) -> int:
        has = type_closure(t)
        size = {typ: sum(typ in kinds for kinds in has.values()) for p in t.predicates for _, typ in p.params}
        total = 0
        for p in t.predicates:
            n = 1
            for _, typ in p.params:
                n *= size[typ]
            total += n
        return total

    assert ground_atoms(task) * 20 < ground_atoms(rooted)  # 451,020 before (UP enumerates them all)


def test_a_shared_domain_widens_an_argument_two_goals_type_differently():
    base = PlanningTask(domain="d", problem="p", encoding="gen-lifted", level=3, predicates=(), actions=(),
                        init=(), goal=(), types=(("food", "object"), ("fruit", "food"), ("nut", "food")))
    a = replace(base, predicates=(Predicate("ripe", (("?x", "fruit"),)),), objects=(("lime", "fruit"),),
                init=(Atom("ripe", ("lime",)),), goal=(Atom("ripe", ("lime",)),))
    b = replace(base, predicates=(Predicate("ripe", (("?x", "nut"),)),), objects=(("pecan", "nut"),),
                init=(Atom("ripe", ("pecan",)),), goal=(Atom("ripe", ("pecan",)),))
    shared = share_domain([("lime", a), ("pecan", b)])
    assert shared.domain.predicates == (Predicate("ripe", (("?x", "food"),)),)
