"""Items a container's list drops while a later unit takes them out of that container: the list left them out.

`holders` rule 5 reads a label a container's output node drops, with no role of the unit of that label, as part
of a mixture made there (`Flow.into` None: consumed). The gyoza's scrape (0070-gyoza.txt:87) gives `pot (contains
{cabbage, ground pork, scallion, soy sauce, sesame oil, garlic})`, without the rice beer poured in at :63; but the
mix at :113 takes `rice beer (in [pot])` (the pour's node) from the pot the scrape's output becomes (the pour of
corn starch between takes that node and gives the mix's). Read from those units, the scrape's list left the rice
beer out: it stays in the pot, and the mix takes it from there.

Rule (`kept_in_place`): a flow of label L out of the container role of label C into nothing is not applied when,
following that role's output node forward through the task's units that take it (each unit's pairing,
`pairing.unit_roles`, gives the node it becomes), each later in the same recipe file, a unit takes a node of
label L placed in C (its place read through that unit's names) that a unit of the network makes; or when a unit
of the task later in the same recipe file takes a node of label L placed in C that a unit making this unit's node
of C makes too, with a node of C listing L or with no node of C (`_still_there`): FOON describes the object still
there, in the node it had before. 0012's spray (0012-grilled-grilled_cheese_sandwich.txt:123) leaves `grill (on,
contains {bread})`, without the spatula of cheese the pick-and-place put on it; the heat at :142, after it in the
video, takes `grill spatula (contains {cheese}, on [grill])` and `grill (on, contains {grill spatula})`: the spatula
stayed on the grill. 0010's pick-and-place (0010-cheesy_garlic_bread.txt:229) leaves `baking tray (contains {bread})`
without the foil the place at :218 put on it, and the wrap at :243 takes `aluminium foil (sheet, on [baking tray])`,
the place's node, with no node of the tray: the foil stayed on the tray, for the wrap (read as part of the bread,
it left the wrap needing a second sheet on a second tray). What stays ambiguous: the container's nodes between the
two units do not list L, so the pair (C, L) is one the replay does not check (`PlanningTask.gaps`), and the
reading is reported once with the unit's file:line. O(d r) per dropped label for a path of d units of r roles (d at
most `DEPTH`), and O(u n) for the later units of the recipe.

An ingredient role consumed out of the unit's own container role is read the same way (`kept_in_place`): when a
unit on the container's path (`path_taker`) takes the role's very input node again, placed in that container, the
object stayed there, as `instances` reads it. The shrimp mango salad's vinaigrette mix
(`0048-shrimp-mango_salad.txt:76`) takes `olive oil (in [bowl])` and `lemon juice (in [bowl])` and leaves no node of
them; the mix at `:254`, on the bowl's path, takes both nodes again: read as consumed, FOON's plan as counted fired
the oil's pour (`:4`) and the lemon's chain (`:16` to `:50`) twice (35 objects in the problem, `instances` 34; 28
read so), unless a unit between them makes that node again (`_made_between`: the egg noodles' pour at
`0044-egg_noodles_from_scratch.txt:155` brings new flour for the stir at `:162`). The pair is reported and left
unchecked like a dropped flow's: the replay checks it nowhere in the task (where this reading fires on the four
sets, FOON's own contradiction at the taker left it unchecked already).

Likewise a container a unit empties because an earlier unit filled it (`relational_plan`) is kept whole when a
later unit the unit's outputs lead to takes its input node again (`taken_again`): what left it was a portion.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import replace

from ..model.aliases import unit_aliases
from ..model.foon import Foon, FunctionalUnit, ObjectNode
from ..model.pairing import unit_roles
from ..model.places import listed, place_of
from ..model.where import short_path, unit_where
from .holders import Fate
from .relational_plan import UnitPlan

__all__ = ["DEPTH", "kept_in_place", "path_taker", "placed_at", "taken_again"]

#: How many units the container's node is followed through.
DEPTH = 12


def _order(foon: Foon, u: int) -> tuple[str, int]:
    """Where unit `u` is in its recipe: (file, line) of its first source, else (``, index)."""
    src = foon.units[u].source
    return (src.path, src.line) if src is not None else ("", u)


def path_taker(foon: Foon, units: frozenset[int], u: int, start: ObjectNode, label: str,
               made: bool = True) -> FunctionalUnit | None:
    """The first unit of `units` on the path of `start`'s object (unit `u`'s output) that takes a node of `label`
    placed in or on it, when a unit of the network makes that node (`made`; else when none does): breadth-first,
    `DEPTH` units, each later in the same recipe file than the one before (a universal FOON shares nodes between
    recipes, and one recipe's nodes may come round again: no path runs into another recipe or back)."""
    frontier, seen = [(start, _order(foon, u))], {start}
    for _ in range(DEPTH):
        nxt = []
        for node, (path, line) in frontier:
            for v in foon.consumers.get(node, ()):
                here = _order(foon, v)
                if v not in units or here[0] != path or here[1] <= line:
                    continue
                unit = foon.units[v]
                if any((n in foon.producers) == made for n in placed_at(unit, label, start.label)):
                    return unit
                nxt += [(r.after, here) for r in unit_roles(unit) if r.before == node and r.after is not None
                        and r.after not in seen]
        seen.update(n for n, _ in nxt)
        frontier = nxt
        if not frontier:
            return None
    return None


def placed_at(unit: FunctionalUnit, label: str, holder: str) -> list[ObjectNode]:
    """The unit's inputs of `label` placed in or on `holder` (the place read through the unit's names)."""
    names = dict(unit_aliases(unit))
    return [n for n in unit.inputs if n.label == label and (w := place_of(n)) is not None
            and names.get(w[1], w[1]) == holder]


def _in_recipes(foon: Foon, units: Iterable[int]) -> dict[str, list[tuple[tuple[str, int], int]]]:
    """recipe file -> [(where, unit)] of `units` in that file, in recipe order (`_order`; ties as `units` gives
    them): read once per task, not once per flow."""
    out: dict[str, list[tuple[tuple[str, int], int]]] = {}
    for at, v in sorted(((_order(foon, v), v) for v in units), key=lambda p: p[0]):
        out.setdefault(at[0], []).append((at, v))
    return out


def _still_there(foon: Foon, recipes: dict[str, list[tuple[tuple[str, int], int]]], u: int, before: ObjectNode,
                 label: str) -> FunctionalUnit | None:
    """The first unit of the task (`recipes`, `_in_recipes`) later in unit `u`'s recipe file that takes a node of
    `label` placed in or on the container `before` is (unit `u`'s input), made by a unit that made `before` too,
    together with a node of that container listing `label`, or with no node of that container (one not listing it
    says it left): FOON describes the object still there, in the node it had before `u` (0012's heat takes the
    spatula of cheese on the grill, which the pick-and-place made with the grill the spray takes, and the grill
    listing it, after the spray's `grill (contains {bread})`; 0010's wrap takes the foil on the tray with no node
    of the tray). The shared maker, not the file, ties the two: a universal FOON written as one file has all its
    recipes in it."""
    makers = set(foon.producers.get(before, ()))
    if not makers:  # a kitchen node: no unit made the object's earlier node beside it
        return None
    path, line = _order(foon, u)
    for at, v in recipes.get(path, ()):
        if at[1] <= line:
            continue
        unit = foon.units[v]
        names = dict(unit_aliases(unit))
        mine = [n for n in unit.inputs if n.label == before.label]
        if (any(makers.intersection(foon.producers.get(n, ())) for n in placed_at(unit, label, before.label))
                and (not mine or any(label in {names.get(x, x) for x in listed(n)} for n in mine))):
            return unit
    return None


def kept_in_place(foon: Foon, units: Iterable[int], plans: dict[int, UnitPlan]
                  ) -> tuple[dict[int, UnitPlan], list[tuple[str, str, str, FunctionalUnit]]]:
    """`plans` without the flows, and with the roles consumed out of the unit's container, that a later unit's input
    says did not happen (module doc), and the readings as (container label, content label, message, unit) gaps, in
    unit order."""
    task = frozenset(units)
    recipes = _in_recipes(foon, task)  # `_still_there`'s later units
    out, gaps = dict(plans), []
    for u in sorted(task & plans.keys()):
        plan = plans[u]
        keep = []
        for f in plan.flows:
            role = plan.slots[f.holder].rel.role
            taker = path_taker(foon, task, u, role.after, f.label) if f.into is None and role.after is not None else None
            if taker is None and f.into is None and role.before is not None:
                taker = _still_there(foon, recipes, u, role.before, f.label)
            if taker is None:
                keep.append(f)
                continue
            rel = next((place_of(n)[0].value for n in placed_at(taker, f.label, role.label)), "in")
            gaps.append((role.label, f.label, f"{role.label} leaves {f.label} out of its list, which {taker.motion.label} at "
                         f"{unit_where(taker, short_path)} takes {rel} [{role.label}]: read as still in it",
                         plan.unit))
        if len(keep) < len(plan.flows):
            out[u] = replace(plan, flows=tuple(keep))
        slots = list(out[u].slots)
        for k, s in enumerate(slots):  # consumed out of a holder role whose path takes its node again: still there
            src = s.rel.source
            if s.fate is not Fate.CONSUMED or src is None or src.role is None or s.rel.role.before is None:
                continue
            holder = plan.slots[src.role].rel.role
            after = plan.after_of(src.role) or holder.before
            taker = path_taker(foon, task, u, after, s.rel.role.label) if after is not None else None
            if taker is None or s.rel.role.before not in taker.inputs or _made_between(foon, task, s.rel.role.before,
                                                                                     u, taker):
                continue
            slots[k] = replace(s, fate=Fate.STAYS, after=None)
            gaps.append((holder.label, s.rel.role.label, f"{holder.label} leaves {s.rel.role.label} out of its list, "
                         f"which {taker.motion.label} at {unit_where(taker, short_path)} takes again: read as still in it",
                         plan.unit))
        if slots != list(out[u].slots):
            out[u] = replace(out[u], slots=tuple(slots))
    return out, gaps


def _made_between(foon: Foon, units: frozenset[int], node: ObjectNode, u: int, taker: FunctionalUnit) -> bool:
    """Whether a unit of `units` makes `node` again after unit `u` and before `taker` in their recipe file: then
    `taker` takes that unit's object, not the one `u` had (the egg noodles' pour at `:155` between the stirs)."""
    path, line = _order(foon, u)
    end = (taker.source.path, taker.source.line) if taker.source is not None else ("", line)
    return any(v in units and (at := _order(foon, v))[0] == path and line < at[1] and at < end
               for v in foon.producers.get(node, ()))


def _downstream(foon: Foon, units: frozenset[int], u: int) -> frozenset[int]:
    """The units of `units` on a path from unit `u`'s outputs, at most `DEPTH` units on: each is the next unit of
    `units` after the one before it (`_order`: later in the same recipe file) to take a node that one makes, with no
    unit of `units` making that node again between them. The next taker of the node that unit made, not every
    later one: a universal FOON shares nodes between recipes, and written as one file, every later recipe's unit
    taking a node another recipe makes is later in that file (the grilled shrimp's cooked shrimp on a plate, made
    again by the shrimp mango salad, whose pour of shrimp out of its bowl is no evidence for the grilled shrimp's)."""
    path, line = _order(foon, u)
    frontier, seen = [(u, line)], {u}
    for _ in range(DEPTH):
        nxt = []
        for w, at in frontier:
            for node in dict.fromkeys(foon.units[w].outputs):
                later = [(here, v) for v in (*foon.consumers.get(node, ()), *foon.producers.get(node, ()))
                         if v in units and (here := _order(foon, v))[0] == path and here[1] > at]
                if not later or (v := min(later)[1]) in seen or node not in foon.units[v].inputs:
                    continue  # made again before it is taken next: the next taker takes that unit's node
                seen.add(v)
                nxt.append((v, _order(foon, v)[1]))
        frontier = nxt
        if not frontier:
            break
    return frozenset(seen - {u})


def taken_again(foon: Foon, units: Iterable[int], plans: dict[int, UnitPlan], fired: Sequence[int] = ()
                ) -> tuple[dict[int, UnitPlan], dict[int, tuple[FunctionalUnit, str]]]:
    """`plans` with a container kept whole where a unit of the task on a path from the unit's outputs (`_downstream`)
    takes its input node again: the unit emptied it only because an earlier unit filled its label with what left it (`relational_plan`:
    a container FOON never empties, the whole leaves it), and FOON's later input says the container still holds
    what that node lists, so what left it was a portion (`Fate.SPLITS`, as holders read it). The blueberry muffin's
    pour (`ACT-0003-blueberry_muffin.txt:182`) leaves `bowl (contains {flour mixture})` out of its outputs, and the
    pour at `:207`, which takes the batter the mix of the bowl poured into made, takes that node again: read as emptied, the flour mixture's mix and the pours before it fired
    once more per taking. Only when every object leaving the container is such a portion (no flow, nothing
    consumed out of it), and only units a recipe file gives (`FunctionalUnit.source`): "a later unit of the same
    file" alone read a universal FOON written as one file as one recipe. Also unit index -> (unit, note) per unit so
    read, the note naming the taker FOON's plan fires first (`fired`: its units in firing order, as counted); of
    takers it does not fire, the first in the file. O(u r) per recipe of u units, and a path of `DEPTH` units per
    unit that empties a container."""
    task = frozenset(units)
    recipes = _in_recipes(foon, task)
    at = {v: k for k, v in enumerate(dict.fromkeys(fired))}
    takers: dict[ObjectNode, list[int]] = {}  # input node -> the task's units of a recipe file taking it, in order
    for path, steps in recipes.items():
        for _, v in (steps if path else ()):  # units of no recipe file: not known to be one recipe's
            for x in dict.fromkeys(foon.units[v].inputs):
                takers.setdefault(x, []).append(v)
    for vs in takers.values():  # fired first, then the file's order (a stable sort)
        vs.sort(key=lambda v: at.get(v, len(at)))
    later: dict[tuple[int, ObjectNode], FunctionalUnit] = {}  # (unit, input node) -> the first later taker
    for u in sorted(task & plans.keys()):
        if not plans[u].emptied or not _order(foon, u)[0]:
            continue
        after = _downstream(foon, task, u)
        for x in dict.fromkeys(foon.units[u].inputs):
            v = next((v for v in takers.get(x, ()) if v in after), None)
            if v is not None:
                later[(u, x)] = foon.units[v]
    out, said = dict(plans), {}
    for u in sorted(task & plans.keys()):
        plan = plans[u]
        emptied = dict(plan.emptied)
        keep = {k for k in emptied if (u, plan.slots[k].rel.role.before) in later
                and not any(f.holder == k for f in plan.flows)
                and all(s.fate is Fate.MOVES and s.rel.fate is Fate.SPLITS for s in plan.slots
                        if s.rel.source is not None and s.rel.source.role == k and s.fate is not Fate.SPLITS)}
        if not keep:
            continue
        slots = tuple(replace(s, fate=Fate.SPLITS, after=None, portion=s.rel.after)
                      if s.rel.source is not None and s.rel.source.role in keep and s.fate is Fate.MOVES else s
                      for s in plan.slots)
        out[u] = replace(plan, slots=slots, emptied=tuple((k, x) for k, x in plan.emptied if k not in keep))
        k = min(keep)
        node, taker = plan.slots[k].rel.role.before, later[(u, plan.slots[k].rel.role.before)]
        said[u] = (plan.unit, f"{plan.unit.motion.label} leaves {node.describe()} out of its outputs, which "
                              f"{taker.motion.label} at {unit_where(taker, short_path)} takes again: read as a portion taken "
                              "out of it, the rest still in it")
    return out, said
