"""Relational tasks' search time and size: readings of FOON that made a task unsolvable in a state space too large
for the planner to prove it (it searched to the time limit), and objects no plan needs."""

from __future__ import annotations

from node_words import contains, n

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen
from foon2pddl.model.pairing import RoleKind, unit_roles
from foon2pddl.pddl.compile import compile_task
from foon2pddl.planners.physical_replay import replay
from foon2pddl.planners.solve import plan


def test_the_container_that_keeps_what_no_role_moves_is_the_one_that_receives():
    # 0002 (bacon mac and cheese, line 409): the bacon is scooped out of its skillet into the white sauce's.
    # Both skillets share one ingredient and two states with the output; FOON marks the bacon as the object in
    # motion (identifier 1) and nothing moves the white sauce: its skillet is the one that holds both after.
    place = make_state("on", "stove")
    bacon_pan = n("skillet", contains("bacon"), "hot", place)
    sauce_pan = n("skillet", contains("white sauce"), "hot", place)
    both = n("skillet", contains("white sauce", "bacon"), "hot", place)
    scoop = FunctionalUnit((bacon_pan, sauce_pan, make_node("bacon", [make_state("fried"), make_state("in", "skillet")], motion_flag=1)),
                           Motion("scoop and pour"), (n("skillet", "dirty", place), both))
    roles = {r.before: r for r in unit_roles(scoop)}
    assert roles[sauce_pan].after == both and roles[bacon_pan].after == n("skillet", "dirty", place)
    # unmarked, FOON's order still decides (as before)
    a, b = n("bowl", contains("a")), n("bowl", contains("b"))
    kinds = {r.before: r.kind for r in unit_roles(FunctionalUnit((b, a), Motion("pour"), (n("bowl", contains("a", "b")),)))}
    assert kinds == {b: RoleKind.MOVED, a: RoleKind.READ_ONLY}


def test_two_objects_on_holders_the_unit_does_not_name_may_be_on_two_of_them():
    # 0005 (chipotle bean sandwich, line 457): two breads, each `on [cutting board]`, each put on a clean board
    # of its own; the unit that makes the sandwich names no board. Binding both to one board parameter made
    # the task unsolvable (lama-first searched to the limit); the sandwich is where the first bread was.
    board = n("cutting board", "clean")
    on = make_state("on", "cutting board")
    units = [FunctionalUnit((n("bread", s), board), Motion("place"), (n("bread", s, on), n("cutting board", contains("bread"))))
             for s in ("buttered", "toasted")]
    sandwich = n("sandwich", on)
    units.append(FunctionalUnit((n("bread", "buttered", on), n("bread", "toasted", on)), Motion("assemble"), (sandwich,)))
    kitchen = Kitchen(frozenset({n("bread", "buttered"), n("bread", "toasted"), board}))
    out = plan(Foon(tuple(units)), kitchen, Goal(GoalSpec("sandwich"), (sandwich,)), "relational", time_limit=30)
    assert out.status == "solved", out.message
    assert replay(out.trace).ok
    placed = out.trace.after(1)  # both breads placed, one board each as the place units say
    boards = {placed[b].holder for b in ("bread_1", "bread_2")}
    assert len(boards) == 2 and None not in boards
    assert out.trace.final["sandwich_1"].holder in boards


def test_portions_poured_into_the_state_they_come_from_need_one_source_object():
    # 0012 (grilled cheese, line 34): each of two firings pours a portion of the grated cheese out of its bowl
    # into the bowl of mustard; the portion's node is the source's own (`cheese (grated, in [bowl])`, a kitchen
    # node). The unfolding charged both later mixes to the kitchen (two cheeses in the bowl, never used) on top
    # of the two portions: 4 objects where one that stays and two portions do, and the pour's groundings grow
    # with the product of such counts (32,504 operators on 0012, 4,504 now).
    inb = make_state("in", "bowl")
    mbowl, mustard = n("bowl", contains("mustard")), n("mustard", "ground", inb)
    cbowl, cheese = n("bowl", contains("cheese")), n("cheese", "grated", inb)
    both, spread = n("bowl", contains("cheese", "mustard")), n("spread", inb)
    on_bread, on_cracker = n("bread", "toasted", contains("spread")), n("cracker", contains("spread"))
    units = (FunctionalUnit((mbowl, mustard, cbowl, cheese), Motion("pour"), (both,)),
             FunctionalUnit((both, mustard, cheese), Motion("mix"), (n("bowl", contains("spread")), spread)),
             FunctionalUnit((spread, n("bread", "toasted")), Motion("spread"), (on_bread,)),
             FunctionalUnit((spread, n("cracker", "plain")), Motion("spread"), (on_cracker,)),
             FunctionalUnit((on_bread, on_cracker), Motion("serve"), (n("snack", "plated"),)))
    kitchen = Kitchen(frozenset({mbowl, mustard, cbowl, cheese, n("bread", "toasted"), n("cracker", "plain")}))
    goal = Goal(GoalSpec("snack"), (n("snack", "plated"),))
    task = compile_task(Foon(units), kitchen, goal, "relational")
    cheeses = [x for x in task.instances if x.label == "cheese"]
    assert len(cheeses) == 3 and sum(x.start is None for x in cheeses) == 2  # one in its bowl, two portions
    out = plan(Foon(units), kitchen, goal, "relational", time_limit=30)
    assert out.status == "solved", out.message
    assert replay(out.trace).ok
