"""Rule 0 of the relational reading (docs/pddl.md): the names a unit's lists and places use for one of its
objects under another label (`oil (in [pan])` in a unit whose pan is the `cooking pan`). In the model, below
the encodings, so that the networks (`generalize`, which comes before `pddl`) can read a unit as the encoding
does; FOON-GEN's `generalize/readings.py` still reads names by its own narrower rule."""

from __future__ import annotations

from functools import lru_cache

from .foon import FunctionalUnit
from .pairing import unit_roles
from .places import head_of, listed, places

__all__ = ["unit_aliases"]


@lru_cache(maxsize=1 << 14)
def unit_aliases(unit: FunctionalUnit) -> tuple[tuple[str, str], ...]:
    """Rule 0: names the unit's lists and places use for one of its objects under another label.

    A name a `contains`/`with` list or an `in [C]`/`on [C]` place of the unit uses that is the label of no
    role of the unit, and that exactly one role's label matches by the head-noun rule (`head_of`), not counting
    a role whose own nodes list it (`fried rice (contains {rice})` lists an ingredient, not itself), means
    that role: `salad bowl (contains {salad})` beside `carrot salad (in [salad bowl])`, `oil (in [pan])` in a
    unit whose pan is `cooking pan`. A name only places use (an output node's among them), matching no label
    so, where the unit's nodes put objects one other role's node on that side lists, means that role (the
    drinking glass that lists the lemonade `in [cup]`; the skillet of `bread (in [pan])`). Not a name a
    container lists before and after the unit while the unit's nodes list the role's label itself: the bowl's
    `brown sugar`, there before the `sugar` is poured in, is no other name for it. A name only an input's place
    uses, of an object the unit leaves in or on one role whose input node's `contains` list names it, means that
    role (the sprinkle's pie `on [baking try]`, left `on [baking tray]` beside `baking tray (contains {apple
    pie})`, `0086-apple_turnover.txt:523`). Not a name only input nodes' places use, of objects the role's
    output node newly lists (`_source`): the unit moves them out of it into the role (the water ice `in [glass]`
    poured into the highball glass, `0076-bloody_mary.txt:25`). Sorted; O(n r^2).
    """
    roles = unit_roles(unit)
    labels = {r.label for r in roles}
    users: dict[str, set[str]] = {}  # name -> labels of the nodes that use it
    listers: dict[str, set[str]] = {}  # name -> labels of the nodes that list it
    for r, n in ((role, n) for role in roles for n in (role.before, role.after)):
        for x in listed(n):
            listers.setdefault(x, set()).add(r.label)
        for x in (*listed(n), *(c for _, c in places(n))):
            users.setdefault(x, set()).add(r.label)
    # a name a container lists before and after the unit, while the unit's nodes also list the role's own label,
    # is what was there before under its own name (the bowl's `brown sugar` beside the `sugar` poured in)
    stays = {x for r in roles if r.before is not None and r.after is not None for x in listed(r.before) & listed(r.after)}
    out = {}
    for name in sorted(set(users) - labels):
        if len(match := [lab for lab in sorted(labels) if head_of(name, lab) and lab not in listers.get(name, ())]) == 1:
            if not (name in stays and match[0] in listers) and not _source(roles, name, match[0]):
                out[name] = match[0]
    lists = {x for r in roles for n in (r.before, r.after) if n for s in n.states if s.label != "with"  # not a place
             for x in (*s.ingredients, s.related if s.label == "contains" else "")} - {""}
    sides = [(r.before, r) for r in roles if r.before], [(r.after, r) for r in roles if r.after]
    for name in sorted(set(users) - labels - lists - set(out)):  # a place only: the one role listing what is there
        takers = set()
        for side in sides:
            put = {r.label for n, r in side if name in (c for _, c in places(n))}
            takers |= {r.label for n, r in side if r.label not in put and listed(n) & put}
        if len(takers) == 1 and any(name in (c for _, c in places(n)) for n, _ in sides[1]):
            out[name] = takers.pop()
    for name in sorted(set(users) - labels - lists - set(out)):  # an input's place only: where the unit leaves it
        held = {(r.label, c) for r in roles if r.after is not None and name in (c for _, c in places(r.before))
                for _, c in places(r.after)[:1]}
        if len(held) == 1 and (x := next(iter(held)))[1] in labels and any(  # a `contains` list, no wrapping
                r.label == x[1] and r.before is not None and any(s.label == "contains" and x[0] in s.ingredients
                                                                 for s in r.before.states) for r in roles):
            out[name] = x[1]
    return tuple(sorted(out.items()))


def _source(roles, name: str, label: str) -> bool:
    """`name` is used by input nodes' places only (no list, no output node names it), and the output node of a
    role of `label` newly lists every object placed there (its input node does not): where the unit moves them
    from, not that role. O(r)."""
    moved = [r.label for r in roles if r.before is not None and name in (c for _, c in places(r.before))]
    if not moved or any(name in listed(n) or n is r.after and name in (c for _, c in places(n))
                        for r in roles for n in (r.before, r.after) if n is not None):
        return False
    return any(r.label == label and r.before is not None and r.after is not None
               and all(x in listed(r.after) and x not in listed(r.before) for x in moved) for r in roles)
