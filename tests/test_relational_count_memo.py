"""`plan` derives each distinct count once per call: its compiles of one goal share a memo (`compile_goal`'s `memo`,
`EncodeOptions.memo`), so the network is read once and the wide count, which every other count starts from
(`relational_objects.task_objects`), is derived once, not once per count. The omelette of
tests/test_relational_placed_gate.py is compiled six ways (small, through the stitches, with makers by holder reach,
wide, FOON's own plan unfolded, wide with those makers)."""

from __future__ import annotations

from collections import Counter

from relational_checks import compiled_counts
from test_relational_placed_gate import GOAL, omelette

from foon2pddl.pddl import relational_reading
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.render import render
from foon2pddl.planners.solve import plan


def _derived(monkeypatch) -> list[tuple]:
    """Each count derived from now on, by what it is derived from (the network's units, the plan's units, the
    kitchen, each unit's roles, the makers' rule, whether other makers' plans count)."""
    seen: list[tuple] = []
    real = relational_reading.derive_counts

    def recording(net, need, kitchen, candidates, **options):
        roles = tuple(options["roles_of"](u) for u in net.units)
        seen.append((net.units, tuple(need), kitchen, roles, options["placed"], options["other_makers"]))
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
    # the wide counts kept no other maker's plan (`InstanceCounts.other_maker`), so theirs are those (8 before)
    assert len(derived) == 6, len(derived)


def test_the_shared_memo_gives_the_tasks_each_count_gives_alone():
    foon, kitchen = omelette()
    memo: dict = {}
    for mode in ({"narrow": True}, {"narrow": True, "through": True}, {"narrow": True, "placed": True}, {},
                 {"own": True}, {"placed": True}):
        shared = compile_goal(foon, kitchen, GOAL, "relational", memo=memo, **mode)
        alone = compile_goal(foon, kitchen, GOAL, "relational", **mode)
        assert render(shared.task) == render(alone.task), mode
        assert (shared.notes, shared.narrowed) == (alone.notes, alone.narrowed), mode
