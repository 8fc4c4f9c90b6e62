"""Ground instances of the lifted FOON-GEN network (`generalize.grounding`) and the relevance pruning built on them."""

from __future__ import annotations

import itertools

import pytest

from foon2pddl.generalize.categories import shipped_index
from foon2pddl.generalize.grounding import ground, unit_params
from foon2pddl.generalize.relevance import image_relevant, relevant
from foon2pddl.generalize.substitute import substitute_node, unit_labels
from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.constraints import node_labels
from foon2pddl.model.goal import resolve_goal
from foon2pddl.model.levels import project
from foon2pddl.pddl.encode_lifted import encode_lifted, generalizer
from foon2pddl.pddl.examples import GOALS
from foon2pddl.pddl.render import render

INDEX = shipped_index()


@pytest.fixture(scope="module")
def setting(example):
    kitchen = read_kitchen(example_path("example_kitchen.txt"))
    foon = project(example.foon, 3)
    return foon, kitchen, kitchen.project(3).nodes


def _naive(foon, kitchen_nodes, generalize):
    """Every binding of every unit over every object of a fitting category, fired until nothing changes."""
    labels = sorted(set().union(*map(unit_labels, foon.units), *map(node_labels, kitchen_nodes)))

    def fits(cat, x):
        own = INDEX.choose(x)
        return own is not None and (own == cat or cat in INDEX.ancestors(own))

    bindings = []
    for ui, u in enumerate(foon.units):
        ps = unit_params(u, generalize, INDEX)
        for values in itertools.product(*([y for y in labels if fits(c, y)] for c in ps.values())):
            b = {k: v for k, v in zip(ps, values, strict=True) if k != v}
            bindings.append((ui, frozenset(substitute_node(n, b) for n in u.inputs),
                             tuple(substitute_node(n, b) for n in u.outputs)))
    reached, fired, changed = set(kitchen_nodes), set(), True
    while changed:
        changed = False
        for ui, ins, outs in bindings:
            if (ui, ins) not in fired and ins <= reached:
                fired.add((ui, ins))
                reached.update(outs)
                changed = True
    return reached, fired


@pytest.mark.parametrize("policy", ["absent", "missing", "all"])
def test_ground_instances_are_those_a_brute_force_fixpoint_fires(setting, policy):
    foon, _, held = setting
    generalize = generalizer(policy, foon, held)
    grounded = ground(foon, held, generalize, INDEX)
    reached, fired = _naive(foon, held, generalize)
    assert set(grounded.nodes) == reached
    found = {(u, frozenset(grounded.nodes[i] for i in ins)) for u, ins in zip(grounded.units, grounded.inputs,
                                                                              strict=True)}
    assert found == fired


def test_an_instance_makes_only_outputs_that_are_not_among_its_inputs(setting):
    foon, _, held = setting
    grounded = ground(foon, held, generalizer("absent", foon, held), INDEX)
    for n, makers in enumerate(grounded.makers):
        for i in makers:
            assert n not in grounded.inputs[i]
    assert all(grounded.kitchen[grounded.node_id[n]] for n in held)


def test_past_the_step_limit_there_are_no_instances(setting):
    foon, _, held = setting
    assert ground(foon, held, generalizer("all", foon, held), INDEX, limit=10) is None


@pytest.mark.parametrize("dish", [*GOALS, "lemonade"])
def test_ground_relevance_keeps_a_subset_of_the_image_relevance(setting, example, dish):
    foon, _, held = setting
    generalize = generalizer("absent", foon, held)
    candidates = resolve_goal(parse_goal_spec(dish), example.foon).candidates
    tight = relevant(foon, held, candidates, generalize, INDEX, ground(foon, held, generalize, INDEX))
    loose = image_relevant(foon, held, tuple(candidates), generalize, INDEX)
    assert tight and set(tight) <= set(loose)
    assert relevant(foon, held, candidates, generalize, INDEX, None) == loose  # too many instances: the image


@pytest.mark.parametrize("policy", ["absent", "all"])
@pytest.mark.parametrize("dish", ["fruit salad", "guacamole", "lemonade", "pancake"])
def test_pruned_and_unpruned_tasks_get_the_same_answer(setting, example, policy, dish):
    from foon2pddl.planners import fd

    foon, kitchen, _ = setting
    goal = resolve_goal(parse_goal_spec(dish), example.foon)
    tasks = [encode_lifted(foon, kitchen, goal, INDEX, prune=p, policy=policy).task for p in (True, False)]
    kept, whole = (sum(a.unit is not None for a in t.actions) for t in tasks)
    assert kept < whole and (policy != "absent" or 2 * kept < whole)
    answers = [fd.solve(*render(t), time_limit=60).status for t in tasks]
    assert answers[0] == answers[1] == "solved", (dish, policy, answers)
