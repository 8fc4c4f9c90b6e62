"""Why a goal cannot be made, in words a user can act on: the smallest kitchen additions.

Computed only when an answer is printed (not inside the timed retrievals, which
keep the cheap `complete.unreachable_detail`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ..analysis.additions import first_additions
from ..analysis.reachability import blocker_words, reachable
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal
from ..model.kitchen import default_kitchen
from ..model.words import count, prose_list
from .complete import none_can_be_made


def additions_text(sets, shown: int = 3) -> str:
    """`add 'a' and 'b'; or add 'c'` (backquoted node names): the first `shown` sets, and how many more there are."""
    def one(nodes) -> str:
        names = [f"`{n.describe()}`" for n in nodes]
        return "add " + prose_list(names)

    text = "; or ".join(one(s) for s in sets[:shown])
    return text + (f" (or {len(sets) - shown} more ways of that size)" if len(sets) > shown else "")


#: Largest kitchen-addition sets the explanation searches, tried in growing sizes.
MAX_ADDITIONS = 6


@dataclass(frozen=True)
class Unreachable:
    """Why a goal cannot be made: the words `retrieve` and `plan` print, and the kitchen additions they name
    (each a set of nodes that, added to the kitchen, makes the goal; none when no small set was found)."""

    text: str
    additions: tuple[tuple[ObjectNode, ...], ...] = ()


def explain_unreachable(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal,
                        max_size: int = MAX_ADDITIONS) -> str:
    """The words of `why_unreachable`."""
    return why_unreachable(foon, kitchen_nodes, goal, max_size).text


def why_unreachable(foon: Foon, kitchen_nodes: Iterable[ObjectNode], goal: Goal,
                    max_size: int = MAX_ADDITIONS) -> Unreachable:
    """Why no candidate of `goal` can be made from the kitchen: the smallest sets of nodes a kitchen
    could hold (the network's default kitchen) that make it.

    Sizes 3, then 4 up to `max_size` are tried (a larger bound only costs when the smaller
    finds nothing). When none is found the words say which limit was reached, and list
    the unmakeable leaves only when no limit cut the search (then they are what the
    kitchen lacks; otherwise they can be leaves of other recipes, a wrong list): the first
    `SUMMARY` in node order (`blocker_words`), then how many more (a cut list must not read as the whole).
    """
    reach = reachable(foon, kitchen_nodes, goal.candidates)
    if reach.makes_any(goal.candidates):
        return Unreachable(f"{goal.describe()!r} can be made from the kitchen")
    addable = default_kitchen(foon).nodes
    head = none_can_be_made(goal)
    fixes = first_additions(reach, goal.candidates, addable, sorted({min(3, max_size), *range(4, max_size + 1)}))
    if fixes.sets:
        return Unreachable(f"{head}; smallest kitchen additions that make it: " + additions_text(fixes.smallest),
                           fixes.smallest)
    if not fixes.possible:  # the nodes no unit makes a kitchen lacks too would not help: the cycle is the reason
        return _cycle(reach, goal, max_size, head)
    exact = fixes.exact
    if exact:
        leaves = blocker_words(reach, goal.candidates)
        if not leaves:
            return _cycle(reach, goal, max_size, head)
        return Unreachable(f"{head}; it needs more than {max_size} kitchen additions (no set of up to {max_size} "
                           "makes it); nodes no unit makes, each needed on some way to it: " + leaves)
    return Unreachable(f"{head}; no set of up to {max_size} kitchen additions was found to make it (the search "
                       "keeps the 16 smallest sets per node, so it may have missed one; the goal may need more "
                       "additions)")


def _cycle(reach, goal: Goal, max_size: int, head: str) -> Unreachable:
    """Every way to the goal needs a node that itself needs it, so no node no unit makes helps; a kitchen that
    holds a node of the cycle breaks it (the converter's pour water gives back the empty cup its fill takes):
    the smallest such sets, among the nodes the goal depends on (the goal's own nodes excluded)."""
    text = (f"{head}; no set of up to {count(max_size, 'node')} no unit makes gives it: every way to make it needs a "
            "node that itself needs it (`foon2pddl check` names the cycle)")
    fixes = first_additions(reach, goal.candidates, None, range(1, min(3, max_size) + 1))
    if fixes.smallest:
        text += "; a kitchen that holds one of the cycle's nodes breaks it: " + additions_text(fixes.smallest)
    return Unreachable(text, fixes.smallest)
