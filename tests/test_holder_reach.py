"""`pddl.holder_reach`: actions no reachable state applies (a holder and its content in states no plan has together).

Two oracles: the apple turnover's pour of experiment REG trial 1 goal 12 (each node reachable alone, the two in one
pan not: unsolvable, said at once with the unit's file:line, where Fast Downward searched until its time limit),
and exhaustive search of small random tasks written as the relational encoding writes them (one state per object,
one holder per object): no action applicable in a reachable state is dropped.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from node_words import contains, inside, n
from task_search import explore

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.pddl.holder_reach import drop_unreachable, unreachable
from foon2pddl.pddl.task import Action, Atom, Conditional, PlanningTask, Predicate, type_closure
from foon2pddl.planners.solve import plan

BUTTER_PAN = n("cooking pan", contains("butter"))
MELTED = n("butter", "melted", inside("pan"))


def _turnover_units() -> tuple[FunctionalUnit, ...]:
    # 0050-scrambled_eggs_with_bacon-cheese.txt:135 and :153, 0086-apple_turnover.txt:195: the scoop fills the pan,
    # the only heat that melts butter in a pan leaves it greased, and the pour takes the pan of butter with the
    # melted butter in it (0086's own heat, which keeps the pan as it is, needs a spatula the trial's kitchen lacks)
    scoop = FunctionalUnit((n("cooking pan", "heated"), n("bowl", contains("butter")), n("butter", inside("bowl"))),
                           Motion("scoop and pour"), (BUTTER_PAN, n("butter", "cubed", inside("pan"))))
    heat = FunctionalUnit((BUTTER_PAN, n("butter", "cubed", inside("pan"))), Motion("heat"),
                          (n("cooking pan", "greased"), MELTED))
    pour = FunctionalUnit((n("bowl", contains("apple")), n("apple", inside("bowl")), BUTTER_PAN, MELTED),
                          Motion("pour"), (n("cooking pan", contains("apple", "butter")), n("apple", inside("cooking pan"))))
    return scoop, heat, pour


def test_a_holder_and_its_content_in_states_no_plan_has_together_make_the_goal_unsolvable_at_once():
    kitchen = Kitchen(frozenset({n("cooking pan", "heated"), n("bowl", contains("butter")), n("butter", inside("bowl")),
                                 n("bowl", contains("apple")), n("apple", inside("bowl"))}))
    goal_node = n("apple", inside("cooking pan"))
    outcome = plan(Foon(_turnover_units()), kitchen, Goal(GoalSpec("apple"), (goal_node,)), "relational")
    assert outcome.status == "unsolvable"
    assert outcome.message == ("no reachable state applies what the goal needs: pour at ? needs cooking pan "
                               "(contains {butter}) holding butter (in [pan], melted)")
    assert "search" not in outcome.timings and "translate" not in outcome.timings  # no planner ran
    # FOON's semantics makes it (the nodes are there, each alone): the tree encoding still plans it
    assert plan(Foon(_turnover_units()), kitchen, Goal(GoalSpec("apple"), (goal_node,)), "tree").status == "solved"


def test_a_goal_out_of_reach_with_no_holder_pair_on_the_way_is_left_to_the_planner():
    # nothing makes the pour's apple in a bowl: relaxed reachability answers, as before holder reachability
    # (found in review: the 11 unreachable subgraph dishes said "holder reachability: no reachable state
    # applies what the goal needs" and named no unit, where Fast Downward says the cause)
    kitchen = Kitchen(frozenset({n("cooking pan", "heated"), n("bowl", contains("butter")), n("butter", inside("bowl"))}))
    goal_node = n("apple", inside("cooking pan"))
    outcome = plan(Foon(_turnover_units()), kitchen, Goal(GoalSpec("apple"), (goal_node,)), "relational")
    assert outcome.status == "unsolvable" and outcome.result.planner != "holder reachability", outcome.message


OBJECTS = (("a", "bowl"), ("b", "bowl"), ("c", "egg"), ("d", "egg"))
STATES = ("s0", "s1", "s2")


@st.composite
def tasks(draw) -> PlanningTask:
    """Two bowls and two eggs, each in one state, each egg in at most one bowl, and actions as the relational
    encoding writes them: a state changes from the one the precondition names, an egg moves out of whatever
    holds it into a bowl, the eggs in a bowl change state with it (quantified conditional effects)."""
    init = [Atom("is", (o, draw(st.sampled_from(STATES)))) for o, _ in OBJECTS]
    init += [Atom("in", (draw(st.sampled_from("ab")), egg)) for egg in "cd" if draw(st.booleans())]
    actions = []
    for k in range(draw(st.integers(1, 5))):
        params = tuple(p for p in (("?p", "bowl"), ("?q", "egg")) if draw(st.booleans())) or (("?p", "bowl"),)
        pre, add, delete, cond = [], [], [], []
        for v, _ in params:
            if draw(st.booleans()):
                was = draw(st.sampled_from(STATES))
                pre.append(Atom("is", (v, was)))
                if draw(st.booleans()):
                    delete.append(Atom("is", (v, was)))
                    add.append(Atom("is", (v, draw(st.sampled_from(STATES)))))
        names = {v for v, _ in params}
        if names == {"?p", "?q"}:
            move = draw(st.sampled_from(("none", "read", "into")))
            if move == "read":
                pre.append(Atom("in", ("?p", "?q")))
            elif move == "into":
                cond.append(Conditional((Atom("in", ("?h", "?q")),), delete=(Atom("in", ("?h", "?q")),),
                                        var="?h", type="bowl"))
                add.append(Atom("in", ("?p", "?q")))
        for _ in range(draw(st.integers(0, 2)) if "?p" in names else 0):  # two may change one variable from two states
            was, now = draw(st.sampled_from(STATES)), draw(st.sampled_from(STATES))
            cond.append(Conditional((Atom("in", ("?p", "?y")), Atom("is", ("?y", was))),
                                    add=(Atom("is", ("?y", now)),), delete=(Atom("is", ("?y", was)),),
                                    var="?y", type="egg"))
        actions.append(Action(f"act{k}", tuple(pre), tuple(add), tuple(delete), params=params,
                              conditional=tuple(cond)))
    preds = (Predicate("is", (("?x", "thing"), ("?s", "state"))), Predicate("in", (("?h", "thing"), ("?x", "thing"))))
    return PlanningTask("d", "p", "relational", 3, preds, tuple(actions), tuple(sorted(set(init))), (),
                        types=(("bowl", "thing"), ("egg", "thing")), objects=OBJECTS,
                        constants=tuple((s, "state") for s in STATES))


def _applied(task: PlanningTask) -> set[str]:
    """The actions some state reachable from `task.init` applies (exhaustive search)."""
    return explore(task, type_closure(task))[1]


@settings(max_examples=500, deadline=None)
@given(tasks())
def test_no_action_some_reachable_state_applies_is_dropped(task):
    assert not _applied(task) & {a.name for a in unreachable(task)}


@settings(max_examples=300, deadline=None)
@given(tasks())
def test_the_task_without_what_never_applies_or_fires_reaches_the_same_states(task):
    # the conditional effects no reachable state fires are dropped too (less for the planner to ground): same states
    assert explore(drop_unreachable(task)[0], type_closure(task))[0] == explore(task, type_closure(task))[0]


def test_an_action_whose_holder_and_content_states_never_meet_is_dropped():
    # the egg turns e1 only in bowl a, which turns b1 with it; nothing has a bowl in b0 holding an egg in e1
    turn = Action("turn", (Atom("is", ("?p", "b0")), Atom("is", ("?q", "e0")), Atom("in", ("?p", "?q"))),
                  (Atom("is", ("?p", "b1")), Atom("is", ("?q", "e1"))),
                  (Atom("is", ("?p", "b0")), Atom("is", ("?q", "e0"))), params=(("?p", "bowl"), ("?q", "egg")))
    need = Action("need", (Atom("is", ("?p", "b0")), Atom("is", ("?q", "e1")), Atom("in", ("?p", "?q"))), (),
                  params=(("?p", "bowl"), ("?q", "egg")))
    init = (Atom("in", ("a", "c")), Atom("is", ("a", "b0")), Atom("is", ("b", "b0")), Atom("is", ("c", "e0")),
            Atom("is", ("d", "e0")))
    preds = (Predicate("in", (("?h", "thing"), ("?x", "thing"))),)
    task = PlanningTask("d", "p", "relational", 3, preds, (turn, need), init, (), objects=OBJECTS)
    assert [a.name for a in unreachable(task)] == ["need"]
    # with the egg taken from no named bowl, it may be in any bowl as it turns: bowl b, still b0, may hold it
    loose = Action("turn", (Atom("is", ("?p", "b0")), Atom("is", ("?q", "e0"))), turn.add, turn.delete,
                   params=turn.params)
    assert unreachable(PlanningTask("d", "p", "relational", 3, preds, (loose, need), init, (),
                                    objects=OBJECTS)) == ()


def test_two_conditional_changes_of_one_quantified_holder_each_keep_their_own_state_before():
    # encode_relational writes one conditional per state a holder the action empties may be in (`empties`): here a
    # bowl holding the egg goes s0 -> s1 or s2 -> s0 as the egg leaves it. Bowl a (s2) holding egg c turns s0, and
    # bowl a then holds egg d in s0: `need` applies. Reading both conditionals as changes from the first one's s0
    # lost that way (found in review: it dropped an action a plan applies in 0050 and in GEN trial 1 goal 64).
    leave = Atom("in", ("?f", "?q"))
    take = Action("take", (Atom("is", ("?q", "s0")),), (Atom("is", ("?q", "s1")),), (Atom("is", ("?q", "s0")),),
                  params=(("?q", "egg"),),
                  conditional=(Conditional((leave,), delete=(leave,), var="?f", type="bowl"),
                               Conditional((leave, Atom("is", ("?f", "s0"))), add=(Atom("is", ("?f", "s1")),),
                                           delete=(Atom("is", ("?f", "s0")),), var="?f", type="bowl"),
                               Conditional((leave, Atom("is", ("?f", "s2"))), add=(Atom("is", ("?f", "s0")),),
                                           delete=(Atom("is", ("?f", "s2")),), var="?f", type="bowl")))
    need = Action("need", (Atom("is", ("?p", "s0")), Atom("is", ("?q", "s0")), Atom("in", ("?p", "?q"))), (),
                  params=(("?p", "bowl"), ("?q", "egg")))
    init = (Atom("in", ("a", "c")), Atom("in", ("a", "d")), Atom("is", ("a", "s2")), Atom("is", ("b", "s2")),
            Atom("is", ("c", "s0")), Atom("is", ("d", "s0")))
    preds = (Predicate("is", (("?x", "thing"), ("?s", "state"))), Predicate("in", (("?h", "thing"), ("?x", "thing"))))
    task = PlanningTask("d", "p", "relational", 3, preds, (take, need), init, (),
                        types=(("bowl", "thing"), ("egg", "thing")), objects=OBJECTS,
                        constants=tuple((s, "state") for s in STATES))
    assert _applied(task) == {"take", "need"}
    assert unreachable(task) == ()


def test_a_conditional_change_whose_condition_no_reachable_state_meets_makes_nothing():
    # 0068-apple_cake.txt:357's scrape moves the cake batter it finds in a bowl in whatever state it is: a cake batter
    # state only it "makes" (from that very state) is out of reach, and so is the pour that needs it (odd universal
    # half, chocolate cake: counting the move as firing kept the counted units' task, out of reach, for the planner)
    batter = Atom("is", ("?y", "s1"))
    move = Action("move", (), (), params=(("?p", "bowl"), ("?q", "bowl")),
                  conditional=(Conditional((Atom("in", ("?q", "?y")), batter),
                                           add=(batter, Atom("in", ("?p", "?y"))), delete=(Atom("in", ("?q", "?y")),),
                                           var="?y", type="egg"),))
    need = Action("need", (Atom("is", ("?q", "s1")),), (), params=(("?q", "egg"),))
    init = (Atom("in", ("a", "c")), Atom("is", ("c", "s0")), Atom("is", ("d", "s0")))
    preds = (Predicate("is", (("?x", "thing"), ("?s", "state"))), Predicate("in", (("?h", "thing"), ("?x", "thing"))))
    task = PlanningTask("d", "p", "relational", 3, preds, (move, need), init, (),
                        types=(("bowl", "thing"), ("egg", "thing")), objects=OBJECTS,
                        constants=tuple((s, "state") for s in STATES))
    assert _applied(task) == {"move"}
    assert [a.name for a in unreachable(task)] == ["need"]


def test_a_conditional_effect_no_reachable_state_fires_is_left_out_of_the_task_for_the_planner():
    # as above: the scrape's move of a cake batter in a state nothing makes never fires; the one that may is kept
    # (the odd universal half's chocolate cake: Fast Downward grounded such effects over every bowl pair and batter)
    there = Atom("in", ("?q", "?y"))
    never, may = ((Conditional((there, Atom("is", ("?y", s))), add=(Atom("in", ("?p", "?y")),), delete=(there,),
                               var="?y", type="egg")) for s in ("s1", "s0"))
    move = Action("move", (), (), params=(("?p", "bowl"), ("?q", "bowl")), conditional=(never, may))
    init = (Atom("in", ("a", "c")), Atom("is", ("c", "s0")), Atom("is", ("d", "s0")))
    preds = (Predicate("is", (("?x", "thing"), ("?s", "state"))), Predicate("in", (("?h", "thing"), ("?x", "thing"))))
    task = PlanningTask("d", "p", "relational", 3, preds, (move,), init, (),
                        types=(("bowl", "thing"), ("egg", "thing")), objects=OBJECTS,
                        constants=tuple((s, "state") for s in STATES))
    kept, why = drop_unreachable(task)
    assert why is None and [a.conditional for a in kept.actions] == [(may,)]
