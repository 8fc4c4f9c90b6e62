"""Where one unit's own nodes contradict each other about a container's contents: holders' rule 6 (`list_gaps`),
and the relation FOON states that the encoding does not hold (`attached_gaps`).

No plan can satisfy both words of such a pair, so the task reports them (`encode_relational`'s notes) and its
replay does not check that pair. Read from the unit alone, through the holders `relational_roles` read.
"""

from __future__ import annotations

from ..model.foon import FunctionalUnit
from ..model.places import describes_contents, listed, place_of, places
from .holder_words import newly_listed, unit_words
from .holders import Fate, on_parts, relational_roles, still_holds

__all__ = ["attached_gaps", "list_gaps"]


def list_gaps(unit: FunctionalUnit) -> tuple[tuple[str, str, str], ...]:
    """Rule 6: where the unit's own output nodes contradict each other about a container's contents.

    (container label, content label, message) for: an input node placed `in [C]` whose only C lists its
    contents without it (rule 2 binds it late); an output node placed `in [C]`/`on [C]` while C's output
    node describes its contents and does not list it (`salad (in [salad bowl])` and `carrot salad (in [salad
    bowl])` made, the bowl `contains {salad}`); and a label C's output node newly lists that no role of the
    unit is, nor is read as (rule 0), or that the unit leaves `attached to [C]` (the watermelon lemonade's
    `blender (with [cup])` beside `blender cup (attached to [blender])`: a relation, not in or on, that no holder
    fact holds); and a holder whose output node still lists an object that leaves it whole (rule 4: the mixer still
    `with [bowl]` as the blend's bowl leaves it). No plan can satisfy both words, so the task reports them and its replay
    does not check that pair. Names read through the unit's aliases; O(r^2) for r roles.
    """
    read = unit_words(unit)
    roles = read.roles
    labels = {r.label for r in roles}
    out = []
    outs = [(r.label, read.after[k]) for k, r in enumerate(roles) if r.after is not None]
    sides = [(r.label, read.after[k]) for k, r in enumerate(roles)]  # every role after the unit
    for label, node in outs:
        place = place_of(node)
        if place is None:
            continue
        holders = [n for lab, n in sides if lab == place[1] and describes_contents(n)]
        if holders and not any(label in listed(n) for n in holders):
            out.append((place[1], label, f"{label} is {place[0]} [{place[1]}], whose node after the unit does not "
                        "list it"))
    rels = relational_roles(unit)
    for k, r in enumerate(roles):  # rule 2: the only holder the unit has lists its contents without it
        src = rels[k].source
        mine = [j for j, x in enumerate(roles) if j != k and src is not None and x.label == src.holder
                and read.before[j] is not None]
        if r.before is not None and src is not None and src.role is None and mine and all(
                describes_contents(read.before[j]) for j in mine):
            out.append((src.holder, r.label, f"{r.label} is {src.relation} [{src.holder}], whose node before the "
                        "unit does not list it: which one holds it is left to the plan"))
    for k, x in enumerate(rels):  # rule 4: the whole, holding the unit's objects, leaves a holder that lists it still
        if x.fate is Fate.MOVES and x.source is not None and x.source.role is not None and still_holds(
                read.after[x.source.role], x.role.label) and any(y.source and y.source.role == k for y in rels):
            out.append((x.source.holder, x.role.label, f"{x.source.holder} lists {x.role.label} after the unit, which "
                        "leaves it whole with what is in it"))
    for node, holder in on_parts(unit):  # rule 2: placed on a part of another role (the bread of the sandwich)
        (rel, part), = places(node)[:1]
        out.append((holder, node.label, f"{node.label} is {rel} [{part}], which {holder} lists: read as {rel} the {holder}"))
    for r, new in zip(roles, newly_listed(unit), strict=True):
        out += [(r.label, x, f"{r.label} lists {x}, which no object of the unit is") for x in sorted(new - labels)]
        for label, node in outs:
            place = place_of(node)
            if label in new and place is not None and place[1] != r.label:
                out.append((r.label, label, f"{r.label} lists {label}, which the unit puts {place[0]} [{place[1]}]"))
    return tuple(dict.fromkeys(out + list(attached_gaps(unit))))


def attached_gaps(unit: FunctionalUnit) -> tuple[tuple[str, str, str], ...]:
    """The gaps of `list_gaps` that are no contradiction of FOON's words but a relation the encoding does not
    hold: a label C's output node newly lists while the unit leaves that object `attached to [C]` (FOON's labels
    agree; the task notes them as a relation not modelled, not as a label mismatch)."""
    read = unit_words(unit)
    outs = [(r.label, read.after[k]) for k, r in enumerate(read.roles) if r.after is not None]
    return tuple(dict.fromkeys(
        (r.label, label, f"{r.label} lists {label}, which the unit leaves attached to [{r.label}]: a relation the "
         "encoding does not hold (only in and on), so the replay does not check it")
        for r, new in zip(read.roles, newly_listed(unit), strict=True) for label, node in outs
        if label in new and place_of(node) is None
        and any(s.label == "attached to" and s.related == r.label for s in node.states)))
