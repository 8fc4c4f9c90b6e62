"""The delete-free plan `instance_counts` unfolds: back from the goal candidate made in the fewest rounds, each
needed node's first achiever (`relational`: `count_together`'s makers; or a maker the plan has, `in_plan`), in firing
order; and the plans with one needed node made by another of its makers (`_other_makers`), which
`instance_counts.derive_counts` counts too."""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Mapping, Sequence

from ..analysis.reachability import Reachability, reachable
from ..model.foon import Foon, ObjectNode
from .count_together import AT_HAND, made_in_plan, makers_together, needs

__all__ = ["Score", "delete_free_plan", "delete_free_plans"]

#: Objects a plan (unit indexes in firing order) for a target node counts, unfolded as it is (`derive_counts`).
Score = Callable[[tuple[int, ...], ObjectNode], int]


def delete_free_plan(foon: Foon, kitchen: frozenset[ObjectNode], candidates: Sequence[ObjectNode],
                     together: bool = False, first: bool = False, placed: bool = False, in_plan: bool = False
                     ) -> tuple[tuple[int, ...], ObjectNode] | None:
    """A delete-free plan (unit indexes in firing order) for the candidate made in the fewest rounds.

    Each needed node is made by its first achiever (`reachability`): following first achievers back never meets a
    cycle and never pulls in another recipe's units the way crediting the latest maker can. None when no candidate
    can be made. `together` (`relational`): a container's node and the node of what is in it that one unit takes are
    made by one unit that makes both, when their first achievers differ and such a unit fires before it and needs
    neither (`count_together`; `first`, `placed`: `makers_together`'s; `in_plan`: `_chosen`'s)."""
    return delete_free_plans(foon, kitchen, candidates, together, ((first, in_plan),), placed)[0]


def delete_free_plans(foon: Foon, kitchen: frozenset[ObjectNode], candidates: Sequence[ObjectNode], together: bool,
                      ways: Sequence[tuple[bool, bool]], placed: bool = False,
                      others: list[tuple[int, ...]] | None = None, score: Score | None = None
                      ) -> tuple[tuple[tuple[int, ...], ObjectNode] | None, ...]:
    """`delete_free_plan` for each of `ways` (`first`, `in_plan`) over one fixpoint; `placed`: `makers_together`'s;
    `others` gets the plans with needed nodes made by other makers that count fewer objects by `score`
    (`_other_makers`)."""
    reach = reachable(foon, kitchen, candidates)
    made = [c for c in candidates if reach.can_make(c)]
    if not made:
        return (None,) * len(ways)
    target = min(made, key=lambda c: (reach.round_of(c), c))
    if others is not None and score is not None:
        others.extend(_other_makers(reach, target, together, placed, score))
    return tuple((_chosen(reach, target, together, first, placed, in_plan), target) for first, in_plan in ways)


def _chosen(reach: Reachability, target: ObjectNode, together: bool, first: bool, placed: bool = False,
            in_plan: bool = False, preset: Mapping[int, int] | None = None, made_by: dict[int, int] | None = None,
            most: int | None = None) -> tuple[int, ...] | None:
    """The units of `delete_free_plan`'s plan for `target`, in firing order; `in_plan`: a node waits till the stack
    empties (`count_together.made_in_plan`); `preset`: node id -> the unit that makes it whatever the rules say
    (`_other_makers`); `made_by` gets node id -> the unit chosen to make it; `most`: None as soon as the plan has
    more units than that (`_other_makers` keeps no longer plan: the walk stops there)."""
    ix = reach.index
    chosen: set[int] = set()
    seen: set[int] = set()
    maker: dict[int, int] = dict(preset or {})  # node id -> the unit chosen to make it (`together`, `preset`)
    stack = [(ix.node_id[target], -1)] if target in ix.node_id else []  # (node id, the unit taking it)
    waiting: deque[tuple[int, int]] = deque()  # `in_plan`: nodes decided once the stack is empty, in the order met
    size = 0  # the units chosen that fire: the plan's length
    while stack or waiting:
        n, by = waiting.popleft() if (late := not stack) else stack.pop()  # `late`: a node that waited, decided now
        if n in seen or reach.node_round[n] == 0:
            continue
        if late and n not in maker:  # decided now; a maker `together` chose stands (then it never waits below)
            maker[n] = made_in_plan(reach, chosen, n, by)
        elif in_plan and n not in maker and by >= 0 and len(ix.makers[n]) > 1 and reach.achiever[n] not in chosen:
            waiting.append((n, by))
            continue
        u = maker[n] = maker.get(n, reach.achiever[n])
        if u == AT_HAND:  # a kitchen container holds it (`count_together.kitchen_held`): the kitchen's
            continue
        seen.add(n)
        if u not in chosen:
            chosen.add(u)
            if most is not None and (size := size + (reach.unit_round[u] >= 0)) > most:  # the units it lists
                return None
            if together:
                maker.update({k: v for k, v in makers_together(reach, u, first, placed).items()
                              if k not in seen and k not in (preset or ())})
            stack.extend((i, u) for i in ix.inputs[u])
    made = {n: u for n, u in maker.items() if n in seen}
    if made_by is not None:
        made_by.update(made)
    return _in_order(reach, chosen, made)


def _other_makers(reach: Reachability, target: ObjectNode, together: bool, placed: bool,
                  score: Score) -> tuple[tuple[int, ...], ...]:
    """The plans `_chosen` makes for `target` with one needed node made by another of its makers that count fewer
    objects by `score` (unfolded as they are) and have fewer units, or swap the one unit for the other and keep the
    rest where the other takes only some of the one's inputs (`_fewer_units`), one plan per (node, maker): a maker
    that fires in the fixpoint and does not need the node through first achievers (`count_together.needs`), in node
    then FOON order; then those swaps together, each kept when it counts fewer again (greedy, in that order), when
    that is another plan. The universal FOON's baked garlic bread: its first achiever of `bread (contains {garlic
    butter}, on [cutting board])` is the spread at `0010-cheesy_garlic_bread.txt:176`, taking 0016's bowl of garlic
    butter and 0010's garlic butter in the food processor bowl, so both garlic-butter chains were counted; the spread
    at `0016-easy_garlic_bread-one-pot-chef.txt:125` makes that node from 0016's chain alone. `derive_counts` counts
    (with `other_makers`: every relational count but FOON's own plan unfolded, `EncodeOptions.own`)
    each (its ways back and orders, which cost most) after its other plans, and keeps the fewest-counting (the first
    on a tie). A swap that trades units for as many others is left: the odd universal half's shrimp mango salad, 33
    units either way (2 for 2), counted 49 objects against 50 but had 35 in the problem against 34; so is one unit for
    one taking other inputs (the shared universal's macaroni and cheese with bacon and chives: 40 objects in the
    problem against 39). The shared universal's 0050 omelette needs two swaps at once: its plan peels the onion at
    `0013-creamy_potato_soup.txt:105`, taking a clean knife it leaves dirty beside the one the chop at
    `0059-best_black_beans.txt:12` reads (the peel at `0026-cheddar_frittata.txt:79` takes the onion alone), and
    makes the mixture's egg by a second crack (`0026-cheddar_frittata.txt:246`). O(n x m) plans for n needed nodes
    of m makers, each O(plan) to choose and score."""
    ix, made = reach.index, {}
    plan = _chosen(reach, target, together, False, placed, made_by=made)
    least = score(plan, target)
    out: dict[tuple[int, ...], None] = {}
    kept: list[tuple[int, int]] = []  # the (node, maker) swaps that count fewer alone
    for n, u in sorted(made.items()):
        for m in sorted(ix.makers[n], key=lambda k: ix.rank[k]):
            if m != u and reach.unit_round[m] >= 0 and not needs(reach, m, {n}):
                other = _chosen(reach, target, together, False, placed, preset={n: m}, most=len(plan))
                if other not in (None, plan) and _fewer_units(reach, other, plan, u, m) and score(other, target) < least:
                    out[other] = None
                    kept.append((n, m))
    preset: dict[int, int] = {}
    best, fewest = plan, least
    for n, m in kept if len(kept) > 1 else ():  # together: each swap counted on the plan with those kept before
        both = _chosen(reach, target, together, False, placed, preset={**preset, n: m}, most=len(best) + 2)
        if both is not None and (len(both) < len(best) or len(set(both) ^ set(best)) <= 2) and (
                k := score(both, target)) < fewest:
            preset, best, fewest = {**preset, n: m}, both, k
    if best not in out and best != plan:
        out[best] = None
    return tuple(out)


def _fewer_units(reach: Reachability, alt: Sequence[int], plan: Sequence[int], u: int, m: int) -> bool:
    """Whether the plan `alt`, `plan` with unit `m` making a node of unit `u`'s, has fewer units, or swaps `u` for
    `m` alone, `m` taking only some of `u`'s inputs (the peel that takes no knife): it pulls in nothing new."""
    ix = reach.index
    return len(alt) < len(plan) or (len(alt) == len(plan) and set(alt) ^ set(plan) == {u, m}
                                    and set(ix.inputs[m]) < set(ix.inputs[u]))


def _in_order(reach: Reachability, chosen: set[int], made_by: dict[int, int]) -> tuple[int, ...]:
    """`chosen` in firing order, each after the units chosen to make its inputs (`made_by`: node id -> unit): a unit
    `together` picks may fire in the round of the unit it makes a node for (the tomato soup's turn on)."""
    out: list[int] = []
    placed: set[int] = set()
    waiting = [u for u in reach.fired if u in chosen]
    while waiting:
        ready = [u for u in waiting if all(made_by.get(n, u) in placed or made_by.get(n, u) == u
                                           for n in reach.index.inputs[u])]
        step = ready or waiting[:1]  # a cycle none of the rules makes: firing order
        out.extend(step)
        placed.update(step)
        waiting = [u for u in waiting if u not in placed]
    return tuple(out)
