"""`plan` derives each distinct count once per call: its compiles of one goal share a memo (`compile_goal`'s `memo`,
`EncodeOptions.memo`), so the network is read once and the wide count, which every other count starts from
(`relational_objects.task_objects`), is derived once, not once per count. The omelette of
tests/test_relational_placed_gate.py is compiled six ways (small, through the stitches, with makers by holder reach,
wide, FOON's own plan unfolded, wide with those makers). A count is derived again only when a unit it read has other
roles now (`relational_reading._asking`): the lemonade of `0072-old-fashioned_lemonade.txt` reads its units again with
the same roles (4 counts derived, 3 distinct)."""

from __future__ import annotations

from collections import Counter

from conftest import SUBGRAPHS
from relational_checks import alone_roles, compiled_counts
from test_relational_placed_gate import GOAL, omelette
from test_relational_reuse_filled import BATTER, MIX, PANTRY, SIFT

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon
from foon2pddl.model.goal import Goal, GoalSpec, resolve_goal, spec_of_node
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl import relational_reading
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.instance_counts import derive_counts
from foon2pddl.pddl.render import render
from foon2pddl.planners.solve import plan


def _derived(monkeypatch) -> list[tuple]:
    """Each count derived from now on, by what it is derived from (the network's units, the plan's units, the
    kitchen, each unit's roles, the makers' rule, whether other makers' plans count, whether a filled container is
    taken again)."""
    seen: list[tuple] = []
    real = relational_reading.derive_counts

    def recording(net, need, kitchen, candidates, **options):
        roles = tuple(options["roles_of"](u) for u in net.units)
        seen.append((net.units, tuple(need), kitchen, roles, options["placed"], options["other_makers"],
                     options["refill"]))
        return real(net, need, kitchen, candidates, **options)

    monkeypatch.setattr(relational_reading, "derive_counts", recording)
    return seen


def test_each_distinct_count_is_derived_once_per_plan(monkeypatch):
    derived = _derived(monkeypatch)
    names = compiled_counts(monkeypatch)
    plan(*omelette(), GOAL, "relational", time_limit=60)
    assert names == ["small", "small through", "small placed", "wide", "wide own", "wide placed"]
    assert [k for k, n in Counter(derived).items() if n > 1] == []
    # FOON's plan and the stitched one, from first makers and by holder reach (4); small (1); through the stitches
    # (1); FOON's own plan unfolded and the stitched one, no other makers' plans (the wide task had no plan), none:
    # the wide counts kept no other maker's plan (`InstanceCounts.other_maker`), so theirs are those (8 before); the
    # small and the through count each once more, without the kitchen nodes their plans make anyway
    # (`relational_objects._made_anyway`, kept when fewer and the same units fire)
    assert len(derived) == 8, len(derived)


def test_a_count_read_again_with_the_same_roles_is_derived_once(monkeypatch):
    foon, _ = load([SUBGRAPHS / "0072-old-fashioned_lemonade.txt"])
    goal = resolve_goal(spec_of_node(min(n for n in foon.nodes if n.dish is not None)), foon)
    modes = ({"narrow": True}, {"narrow": True, "through": True}, {"narrow": True, "placed": True}, {}, {"own": True},
             {"placed": True})
    derived, memo = _derived(monkeypatch), {}
    tasks = [compile_goal(foon, default_kitchen(foon), goal, "relational", memo=memo, **mode) for mode in modes]
    assert [k for k, n in Counter(derived).items() if n > 1] == []
    # one more than 3d97747 counted: the small count once more, without the kitchen nodes its plan makes anyway
    # (`relational_objects._made_anyway`, 9923ed2: a distinct count; here not kept, the lemon on the board stays)
    assert len(derived) == 4, len(derived)
    for mode, shared in zip(modes, tasks, strict=True):  # each as counted afresh, with a memo of its own
        assert render(shared.task) == render(compile_goal(foon, default_kitchen(foon), goal, "relational",
                                                          **mode).task), mode


def test_the_shared_memo_gives_the_tasks_each_count_gives_alone():
    foon, kitchen = omelette()
    memo: dict = {}
    tasks = []
    for mode in ({"narrow": True}, {"narrow": True, "through": True}, {"narrow": True, "placed": True}, {},
                 {"own": True}, {"placed": True}):
        shared = compile_goal(foon, kitchen, GOAL, "relational", memo=memo, **mode)
        alone = compile_goal(foon, kitchen, GOAL, "relational", **mode)
        assert render(shared.task) == render(alone.task), mode
        assert (shared.notes, shared.narrowed) == (alone.notes, alone.narrowed), mode
        tasks.append(shared)
    # small with makers by holder reach (not kept), FOON's own plan unfolded (no other maker's plan) and wide with
    # makers by holder reach (the first makers') count as the wide count does: its task, encoded once
    assert all(t.task is tasks[3].task for t in tasks[2:]), [len(t.task.instances) for t in tasks]


def test_the_counts_without_a_filled_container_taken_again_come_with_those_with_it(monkeypatch):
    # the muffin's shape (tests/test_relational_reuse_filled.py): counted wide, the bowl the pour fills serves the
    # mix; the small count's kitchen is read with and without that, and the counts without it are the same
    # derivation less its last step (`derive_counts`' `unfilled`): none is derived for them alone
    foon, kitchen = Foon((SIFT, MIX)), frozenset(PANTRY)
    unfilled: list = []
    counts = derive_counts(foon, range(2), kitchen, (BATTER,), roles_of=alone_roles(kitchen), together=True,
                           stitched=True, reuse=True, unfilled=unfilled)
    assert counts.refilled and unfilled == [derive_counts(foon, range(2), kitchen, (BATTER,),
                                                        roles_of=alone_roles(kitchen), together=True, stitched=True,
                                                        reuse=True, refill=False)]
    assert unfilled[0].total > counts.total
    derived = _derived(monkeypatch)
    small = compile_goal(foon, Kitchen(kitchen), Goal(GoalSpec("batter"), (BATTER,)), "relational", narrow=True)
    assert small.narrowed and [d for d in derived if not d[-1]] == []
    assert derived  # the wide count, the small ones
