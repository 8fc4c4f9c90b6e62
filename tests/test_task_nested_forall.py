"""A conditional effect quantified over two variables (`Conditional.more`): what is on what is on a consumed
object. Rendered as one `forall` over both, applied over every pair, converted to unified-planning and kept by the
untyped rewrite."""

from __future__ import annotations

from foon2pddl.pddl.render import render
from foon2pddl.pddl.task import Action, Atom, Conditional, PlanningTask, Predicate, apply_action, type_closure
from foon2pddl.pddl.untyped import untyped
from foon2pddl.pddl.up_problem import to_up_problem

HOLD = (("?h", "object"), ("?x", "object"))
# consume the bread; whatever bean mix is on it, and whatever salt is on such a bean mix, is consumed too
SWEEP = Conditional((Atom("on", ("?bread", "?m")), Atom("on", ("?m", "?s"))), add=(Atom("gone", ("?s",)),),
                    delete=(Atom("on", ("?m", "?s")),), var="?s", type="salt", more=(("?m", "mix"),))
FOLD = Action("fold", pre=(Atom("on", ("board", "?bread")),), add=(Atom("gone", ("?bread",)),),
              params=(("?bread", "bread"),), conditional=(SWEEP,))
TASK = PlanningTask(
    domain="d", problem="p", encoding="test", level=3,
    predicates=(Predicate("on", HOLD), Predicate("gone", (("?x", "object"),))), actions=(FOLD,),
    init=(Atom("on", ("board", "bread1")), Atom("on", ("bread1", "mix1")), Atom("on", ("mix1", "salt1")),
          Atom("on", ("mix2", "salt2"))),
    goal=(Atom("gone", ("salt1",)),), types=(("bread", "object"), ("mix", "object"), ("salt", "object")),
    objects=(("board", "object"), ("bread1", "bread"), ("mix1", "mix"), ("mix2", "mix"), ("salt1", "salt"),
             ("salt2", "salt")))


def test_a_two_variable_forall_renders_as_one_forall_over_both():
    domain, _ = render(TASK)
    assert "(forall (?s - salt ?m - mix) (when (and (on ?bread ?m) (on ?m ?s))" in domain


def test_it_applies_to_every_pair_that_meets_its_condition_and_no_other():
    after = apply_action(set(TASK.init), FOLD, {"?bread": "bread1"}, type_closure(TASK))
    assert Atom("gone", ("salt1",)) in after and Atom("on", ("mix1", "salt1")) not in after
    assert Atom("on", ("mix2", "salt2")) in after and Atom("gone", ("salt2",)) not in after


def test_unified_planning_and_the_untyped_rewrite_keep_both_variables():
    action = to_up_problem(TASK).action("fold")
    forall = [e for e in action.conditional_effects if e.forall]
    assert forall and {v.name for e in forall for v in e.forall} == {"s", "m"}
    plain = untyped(TASK).actions[0].conditional[0]
    assert plain.more == (("?m", "object"),) and plain.type == "object"
    assert {a.args for a in plain.when if a.args in (("?s",), ("?m",))} == {("?s",), ("?m",)}
