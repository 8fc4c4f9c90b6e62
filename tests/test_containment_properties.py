"""Property tests of `--containment infer` on small random FOONs (hypothesis).

The oracle is written here from the definition in docs/format.md, not from the
package's code: a container `c (contains {X}, R...)` is available when every x in X
has an available node labelled x in state `in [c]`, and `c (R...)` is available
when R is not empty. Under that rule every tree found must execute step by step;
what strict semantics reaches stays reachable; and what the searches reach is
exactly what a naive closure with the rule reaches.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from foon2pddl.model.containment import is_inference, with_containment
from foon2pddl.model.dedupe import dedupe_units
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, ObjectNode, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.tasktree import validate
from foon2pddl.retrieval import retrieve


def node(label, *states):
    return make_node(label, [make_state(*s) if isinstance(s, tuple) else make_state(s) for s in states])


POOL = [
    node("bowl", ("contains", "", ["a"])), node("bowl", ("contains", "", ["a", "d"])),
    node("bowl", ("contains", "", ["a"]), ("in", "sink")), node("bowl", ("in", "sink")), node("bowl"),
    node("a", ("in", "bowl")), node("a", "cut", ("in", "bowl")), node("d", ("in", "bowl")), node("a"), node("d"),
    node("f", "mixed"), node("g"),
]
MOTIONS = ["pour", "mix", "stir"]


def oracle_holds(n: ObjectNode, have: set[ObjectNode]) -> bool:
    contents = {i for s in n.states if s.label == "contains" for i in s.ingredients}
    if not contents:
        return False
    rest = tuple(s for s in n.states if s.label != "contains")
    if rest and ObjectNode(n.label, rest) not in have:
        return False
    return all(any(h.label == x and any(s.label == "in" and s.related == n.label for s in h.states) for h in have)
               for x in contents)


def closure(units, kitchen, nodes) -> set[ObjectNode]:
    """Naive fixpoint of the units plus the rule over the network's container nodes."""
    have = set(kitchen)
    changed = True
    while changed:
        changed = False
        for c in nodes:
            if c not in have and oracle_holds(c, have):
                have.add(c)
                changed = True
        for u in units:
            if set(u.inputs) <= have and not set(u.outputs) <= have:
                have |= set(u.outputs)
                changed = True
    return have


def executes(units, kitchen, goal) -> bool:
    """Run the tree's real units in order, inferring a missing container by the oracle rule."""
    have = set(kitchen)
    for u in units:
        if is_inference(u):
            continue
        for i in u.inputs:
            if i not in have and oracle_holds(i, have):
                have.add(i)
        if not set(u.inputs) <= have:
            return False
        have |= set(u.outputs)
    return goal in have or oracle_holds(goal, have)


@st.composite
def problems(draw):
    ins = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    outs = st.lists(st.sampled_from(POOL), min_size=1, max_size=3, unique=True)
    units = draw(st.lists(st.tuples(ins, st.sampled_from(MOTIONS), outs), min_size=2, max_size=7))
    foon = Foon(dedupe_units(FunctionalUnit(tuple(i), Motion(m), tuple(o)) for i, m, o in units))
    kitchen = frozenset(draw(st.lists(st.sampled_from(POOL), max_size=5, unique=True)))
    goal = draw(st.sampled_from(sorted(foon.producers)))
    return foon, kitchen, Goal(GoalSpec(goal.label, goal.states), (goal,), 3)


@settings(max_examples=300, deadline=None)
@given(problems(), st.sampled_from(["complete", "greedy", "optimal"]))
def test_infer_trees_execute_under_the_rule_and_strict_goals_stay_reachable(problem, method):
    foon, kitchen, goal = problem
    aug = with_containment(foon, kitchen, "infer")
    strict = retrieve(foon, kitchen, goal, method)
    infer = retrieve(aug, kitchen, goal, method)
    if strict.tree is not None:
        assert infer.tree is not None
    reach = closure(foon.units, kitchen, foon.nodes)
    assert (infer.tree is not None) == (goal.candidates[0] in reach)
    if infer.tree is not None:
        assert executes(infer.tree.units, kitchen, infer.tree.goal)
        assert validate(infer.tree, kitchen, "infer").ok
        if any(is_inference(u) for u in infer.tree.units):
            assert not validate(infer.tree, kitchen, "strict").ok
