"""Lifted FOON-GEN PDDL: atoms stand for nodes, plans ground to concrete kitchen objects and validate."""

from __future__ import annotations

import pytest
from foon_strategies import nodes
from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.generalize.categories import shipped_index
from foon2pddl.io.goal_files import parse_goal_spec
from foon2pddl.io.inputs import example_path
from foon2pddl.io.kitchen_files import read_kitchen
from foon2pddl.model.goal import Goal, resolve_goal, spec_of_node
from foon2pddl.model.tasktree import validate
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.encode_lifted import encode_lifted, generalizer, lift
from foon2pddl.pddl.lifted_atoms import Ordering, node_atom_labels, node_of, representations
from foon2pddl.planners.decode import PlanDecodeError, plan_units
from foon2pddl.planners.solve import plan

INDEX = shipped_index()
CATEGORIZED = sorted({m for c in INDEX.categories for m in c.members})


@pytest.fixture(scope="module")
def kitchen():
    return read_kitchen(example_path("example_kitchen.txt"))


def test_lemonade_plan_grounds_lime_and_validates(example, kitchen):
    goal = resolve_goal(parse_goal_spec("lemonade"), example.foon)
    out = plan(example.foon, kitchen, goal, "gen-lifted", category_index=INDEX, time_limit=60)
    assert out.status == "solved", out.message
    tree = out.tree
    assert validate(tree, kitchen.nodes).ok
    labels = {n.label for u in tree.units for n in u.inputs}
    assert "lime" in labels and "lemon" not in labels
    assert tree.goal.label == "lemonade"
    # what the lime made is named after it, in every unit and in the goal (as FOON-EXP names it)
    made = {n.label for u in tree.units for n in u.outputs}
    assert "lime juice" in made and "lemon juice" not in made and "lime juice" in tree.goal.ingredients
    grounded = [u for u in tree.units if u.sources and u.sources[0].expanded_from]
    assert grounded and all("lemon -> lime" in u.sources[0].expanded_from for u in grounded)


def test_every_example_dish_plan_maps_back_to_a_valid_tree(example, kitchen):
    dishes = sorted({n for u in example.foon.units for n in u.outputs if n.dish is not None})
    solved = 0
    for d in dishes:
        out = plan(example.foon, kitchen, Goal(spec_of_node(d), (d,), 3), "gen-lifted", category_index=INDEX,
                   time_limit=60)
        assert out.status in ("solved", "unsolvable"), (d.describe(), out.message)
        if out.status == "solved":
            solved += 1
            assert validate(out.tree, kitchen.nodes).ok
            # the dish itself, or the same dish made of what the kitchen's object gave (lime juice)
            assert out.tree.goal == d or (out.tree.goal.label == d.label and "lemon juice" in d.ingredients
                                          and out.tree.goal.ingredients == d.ingredients - {"lemon juice"}
                                          | {"lime juice"})
    assert solved >= 2


@settings(max_examples=80, deadline=None)
@given(nodes(pool=st.sampled_from(CATEGORIZED[:40] + ["zork", "lemonade"])))
def test_atoms_reconstruct_their_node(node):
    ordering = Ordering(INDEX)
    shape, labels = node_atom_labels(node, ordering)
    assert node_of(shape, labels) == node
    reps = representations(node, ordering, {shape})
    assert (shape, labels) in reps
    assert all(node_of(s, args) == node for s, args in reps)


def test_representations_of_a_node_with_many_objects_of_one_category_stay_small():
    """A node listing 10 seasonings: the orderings are drawn lazily, at most `MAX_REPRESENTATIONS`, and the same
    as `itertools.product`'s first ones. `product` read the 3.6 million permutations of the group in full first
    (a hypothesis example of the atoms test once grew a worker of the suite to 24 GB and had it killed)."""
    import itertools
    import tracemalloc

    from foon2pddl.model.foon import make_node, make_state
    from foon2pddl.pddl.lifted_atoms import MAX_REPRESENTATIONS, _orderings

    ordering = Ordering(INDEX)
    spices = sorted(m for m in CATEGORIZED if ordering.root(m) == "seasonings")[:10]
    node = make_node("bowl", [make_state("contains", "", spices)])
    shape, labels = node_atom_labels(node, ordering)
    tracemalloc.start()
    reps = representations(node, ordering, {shape})
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert (shape, labels) in reps and 1 <= len(reps) <= MAX_REPRESENTATIONS
    assert peak < 20_000_000, peak  # bytes: 3.6 million tuples of 10 would be hundreds of MB
    groups = [["a", "b", "c"], ["d", "e"]]
    assert list(_orderings(groups)) == list(itertools.product(*(itertools.permutations(g) for g in groups)))


def test_lifting_parameterizes_missing_objects_only(example, kitchen):
    have = kitchen.nodes
    lifted = lift(example.foon, INDEX, generalizer("missing", example.foon, have))
    params = {label for lu in lifted for label, _ in lu.params}
    assert "lemon" in params  # the recipes take it from the kitchen, which has none
    assert not params & {n.label for n in have}
    every = lift(example.foon, INDEX)
    assert len(every) < len(example.foon.units)  # units equal up to parameters become one action
    assert {label for lu in every for label, _ in lu.params} > params


def test_lifted_task_types_and_objects(example, kitchen):
    goal = resolve_goal(parse_goal_spec("lemonade"), example.foon)
    lt = encode_lifted(example.foon, kitchen, goal, INDEX)
    types = dict(lt.task.types)
    assert types["lemons_and_limes"] == "citrus_fruits" and types["citrus_fruits"] == "fruits"
    assert types["fruits"] == "kitchen-object"
    declared = dict(lt.task.objects + lt.task.constants)
    assert declared["lime"] == "lemons_and_limes" and declared["lemon"] == "lemons_and_limes"
    squeeze = next(a for a in lt.task.actions if a.name.startswith("squeeze"))
    assert [t for _, t in squeeze.params] == ["lemons_and_limes"]  # only the missing lemon is a parameter


def test_bad_plan_step_is_a_decode_error(example, kitchen):
    goal = resolve_goal(parse_goal_spec("lemonade"), example.foon)
    compiled = compile_goal(example.foon, kitchen, goal, "gen-lifted", category_index=INDEX)
    with pytest.raises(PlanDecodeError):
        plan_units(compiled, ["no-such-action lime"])
    squeeze = next(a for a in compiled.task.actions if a.name.startswith("squeeze"))
    with pytest.raises(PlanDecodeError):
        plan_units(compiled, [squeeze.name])  # missing arguments
    with pytest.raises(PlanDecodeError, match="unknown object"):
        plan_units(compiled, [squeeze.name + " no-such-object"])
    (unit,) = plan_units(compiled, [squeeze.name + " lime"])
    assert "lime" in {n.label for n in unit.inputs} and "lemon" not in {n.label for n in unit.inputs}


def test_no_ground_precondition_is_true_from_the_start_and_never_deleted(example, kitchen):
    for dish in ("lemonade", "guacamole", "whipped cream"):
        lt = encode_lifted(example.foon, kitchen, resolve_goal(parse_goal_spec(dish), example.foon), INDEX)
        init, deleted = set(lt.task.init), {d.predicate for a in lt.task.actions for d in a.delete}
        static = [(a.name, p) for a in lt.task.actions for p in a.pre
                  if not any(x.startswith("?") for x in p.args) and p in init and p.predicate not in deleted]
        assert static == [], dish


def test_a_predicate_keeps_as_arguments_only_positions_some_action_binds_to_a_parameter(example, kitchen):
    arities = []
    for dish in ("lemonade", "guacamole", "fruit salad"):
        lt = encode_lifted(example.foon, kitchen, resolve_goal(parse_goal_spec(dish), example.foon), INDEX)
        shape = {name: family[0] for name, family in lt.families.items()}
        bound = {(shape[x.predicate], k) for a in lt.task.actions for x in (*a.pre, *a.add) if x.predicate in shape
                 for k, arg in enumerate(x.args) if arg.startswith("?")}
        for p in lt.task.predicates:  # (the same position of every predicate of one node shape)
            assert all((shape[p.name], k) in bound for k in range(len(p.params))), (dish, p.name)
        arities.extend(len(p.params) for p in lt.task.predicates)
    assert max(arities) <= 3  # the objects at the other positions are part of the predicate
    task = encode_lifted(example.foon, kitchen, resolve_goal(parse_goal_spec("lemonade"), example.foon), INDEX).task
    squeeze = next(a for a in task.actions if a.name.startswith("squeeze") and a.params)
    assert any(x.args == (squeeze.params[0][0],) for x in squeeze.add)  # the lemon's squeezed node: one argument


def test_action_costs_are_the_units_costs_and_fast_downward_plans_with_them(example, kitchen):
    from foon2pddl.pddl.render import render

    goal = resolve_goal(parse_goal_spec("guacamole"), example.foon)
    compiled = compile_goal(example.foon, kitchen, goal, "gen-lifted", category_index=INDEX, costs="unit")
    units = [a for a in compiled.task.actions if a.unit is not None]
    assert units and all(a.cost == 1 for a in units)
    assert all(a.cost == 0 for a in compiled.task.actions if a.unit is None)
    domain, problem = render(compiled.task)
    assert ":action-costs" in domain and "(:metric minimize (total-cost))" in problem
    out = plan(example.foon, kitchen, goal, "gen-lifted", category_index=INDEX, costs="unit", time_limit=60)
    assert out.status == "solved" and validate(out.tree, kitchen.nodes).ok, out.message


@pytest.mark.parametrize("dish", ["lemonade", "whipped cream", "fruit salad", "greek salad"])
def test_pruning_keeps_fewer_units_and_the_same_answer(example, kitchen, dish):
    from foon2pddl.pddl.render import render
    from foon2pddl.planners import fd

    goal = resolve_goal(parse_goal_spec(dish), example.foon)
    pruned, whole = (encode_lifted(example.foon, kitchen, goal, INDEX, prune=p).task for p in (True, False))
    units = [sum(a.unit is not None for a in t.actions) for t in (pruned, whole)]
    assert units[0] < units[1]
    answers = [fd.solve(*render(t), time_limit=60).status for t in (pruned, whole)]
    assert answers[0] == answers[1] == "solved", (dish, answers)
