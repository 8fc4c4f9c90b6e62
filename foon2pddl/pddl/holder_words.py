"""FOON's words about a unit's holders read by another name: rule 0 of `holders` (`model.aliases.unit_aliases`, and
`aliased`, a node read through them), and those readings as the relational task reports and reads them: per unit
(`mismatches`, the `label mismatch:` notes) and across a task (`task_aliases`, which its replay reads); `reported`
gives a task's report lines with their units' file:line."""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from functools import lru_cache

from ..model.aliases import unit_aliases
from ..model.foon import FunctionalUnit, ObjectNode, make_node, make_state
from ..model.pairing import Role, unit_roles
from ..model.places import listed, places
from ..model.where import short_path, unit_where

__all__ = ["UnitWords", "aliased", "listed_as", "mismatches", "newly_listed", "part_of", "read_names", "renamed", "reported",
           "takers", "task_aliases", "unit_words"]


@dataclass(frozen=True)
class UnitWords:
    """A unit's roles with their nodes read through its names (rule 0 of `holders`)."""

    roles: tuple[Role, ...]
    before: tuple[ObjectNode | None, ...]  # input nodes read through the unit's aliases
    after: tuple[ObjectNode | None, ...]  # output nodes (input node when the unit gives none), read likewise


@lru_cache(maxsize=1 << 14)
def unit_words(unit: FunctionalUnit) -> UnitWords:
    """The unit's roles and their nodes, read through `unit_aliases`."""
    roles = unit_roles(unit)
    alias = dict(unit_aliases(unit))
    before = tuple(aliased(r.before, alias) for r in roles)
    after = tuple(aliased(r.after, alias) if r.after is not None else before[k] for k, r in enumerate(roles))
    return UnitWords(roles, before, after)


@lru_cache(maxsize=1 << 14)
def newly_listed(unit: FunctionalUnit) -> tuple[frozenset[str], ...]:
    """Per role, the labels its output node lists and its input node does not (none without an output node),
    read through the unit's aliases: what the unit puts into it."""
    read = unit_words(unit)
    return tuple(listed(read.after[k]) - listed(read.before[k]) if r.after is not None else frozenset()
                 for k, r in enumerate(read.roles))


def takers(unit: FunctionalUnit, label: str, but: int) -> list[int]:
    """The roles other than `but` whose output node newly lists `label`, in role order, but those whose output
    node is in or on another of them first: the label is in the inner one, and the outer holds it through that
    (the whipped cream the scoop and pour leaves listed by both the baking tray and the pudding in it,
    `0071-banana_pudding.txt:245`, is on the pudding)."""
    read, into = unit_words(unit), [j for j, new in enumerate(newly_listed(unit)) if j != but and label in new]
    inner = [j for j in into if {c for _, c in places(read.after[j])} & {read.roles[i].label for i in into if i != j}]
    return inner + [j for j in into if j not in inner]


def renamed(was: ObjectNode | None, now: ObjectNode | None, label: str, labels: Iterable[str]) -> bool:
    """A holder's list renamed to `label`: its node after a unit (`now`) lists `label` and nothing its node before
    (`was`) lists, none of which is one of the unit's `labels` (the cook's `cooking pan (contains {egg mixture})`
    becomes `contains {omelette}`: the omelette the mix made there from the egg mixture, the list not saying so)."""
    before, after = listed(was), listed(now)
    return bool(before) and label in after and not before & after and not before & set(labels)


def part_of(labels: Sequence[str], before: Sequence[ObjectNode | None], after: Sequence[ObjectNode | None], k: int,
            holder: str) -> int | None:
    """The one role (of a unit's `labels`, with nodes `before` and `after` it; not `k`, existing before and given an
    output, and no place the unit's nodes name) whose node after lists role `k`'s label and `holder`, when no role
    is a `holder`: placed at a `holder` that is part of that role (the bacon `on [bread]` beside the sandwich that
    lists bread and bacon; FOON-GEN's sandwich listed its sausages and cured meats, the ham, before the bacon came
    too). A container the unit's nodes place things in lists what is in it, not what it is made of: the salt
    sprinkled `on [bean mix]` in the bowl that lists both is on the bean mix. Else None."""
    if holder in labels:
        return None
    named = {c for n in (*before, *after) for _, c in places(n)}
    takers = [j for j in range(len(labels)) if j != k and before[j] is not None and after[j] is not None
              and labels[j] not in named and {labels[k], holder} <= listed(after[j])]
    return takers[0] if len(takers) == 1 else None


def read_names(names: Iterable[str], alias: Mapping[str, str]) -> frozenset[str]:
    """`names` read through the task's aliases (`task_aliases`): `salad` as `carrot salad`."""
    return frozenset(alias.get(x, x) for x in names)


def aliased(node: ObjectNode | None, alias: Mapping[str, str]) -> ObjectNode | None:
    """`node` with the names of its lists and places read through `alias` (the node itself when none apply): the
    related objects of `contains`, `with`, `in` and `on`, and the ingredients of every state (`cooking pan (greased
    {butter})` lists the butter as `contains` would, `places.listed`). O(names of the node)."""
    if node is None or not alias or not any(st.related in alias or any(i in alias for i in st.ingredients)
                                            for st in node.states):
        return node
    states = []
    for st in node.states:
        related = alias.get(st.related, st.related) if st.label in ("contains", "in", "on", "with") else st.related
        if related != st.related or any(i in alias for i in st.ingredients):
            st = make_state(st.label, related, [alias.get(i, i) for i in st.ingredients])
        states.append(st)
    return make_node(node.label, states)


def listed_as(node: ObjectNode | None, alias: Mapping[str, str]) -> frozenset[str]:
    """The labels `node` lists (`places.listed`) read through `alias`, a unit's (`unit_aliases`, as `unit_words`
    reads its nodes) or a task's (`task_aliases`): the one reading of a list by other names, `greased {butter}` as
    the unit's `unsalted butter` (reread60's F5: the task's readings read the names `listed` gives, the unit's the
    lists of its renamed nodes, which kept other states' names; they differed there). O(names of the node)."""
    return listed(aliased(node, alias))


def mismatches(unit: FunctionalUnit) -> tuple[str, ...]:
    """Names an output node newly lists that no role has (`bowl lists olive oil, read as green olive oil` by
    rule 0, else `..., which no object of the unit is`), or places by another: `oil is in [pan], read as ...`; and
    a label an input-only role has that two roles newly list, one in or on the other (`takers`): `baking tray and
    pudding both list whipped cream, and pudding is in [baking tray]: read as held by the pudding, ...`."""
    roles = unit_roles(unit)
    labels = {r.label for r in roles}
    alias = dict(unit_aliases(unit))
    out = []
    for r in roles:
        if r.after is None:
            continue
        new = listed(r.after) - (listed(r.before) if r.before is not None else frozenset())
        out += [f"{r.label} lists {x}, " + (f"read as {alias[x]}" if x in alias else "which no object of the unit is")
                for x in sorted(new - labels)]
        out += [f"{r.label} is {rel} [{c}], read as {alias[c]}" for rel, c in places(r.after) if c in alias]
    read = unit_words(unit)
    for k, r in enumerate(roles):  # `takers`: listed by a holder and by what is in or on it, it is with the latter
        into = takers(unit, r.label, k) if r.after is None and r.before is not None else []
        for rel, c in places(read.after[into[0]]) if len(into) > 1 else ():
            if c in {roles[j].label for j in into[1:]}:
                out.append(f"{c} and {roles[into[0]].label} both list {r.label}, and {roles[into[0]].label} is {rel} "
                           f"[{c}]: read as held by the {roles[into[0]].label}, which the {c} holds")
    return tuple(dict.fromkeys(out))


def task_aliases(units: Iterable[FunctionalUnit], labels: Iterable[str],
                 starts: Iterable[ObjectNode | None] = ()) -> tuple[tuple[str, str], ...]:
    """The units' aliases (rule 0) for a whole task, for its replay, plus those of the objects' start nodes
    (`starts`: `bowl (contains {rice})` in a kitchen whose only rice is `white rice`, read against all the
    task's `labels`; a place only where a start node of the label it reads lists the object: the kitchen's
    `oil (in [pan])` beside `cooking pan (contains {oil})`, not the bloody mary's `water ice (in [glass])`
    beside an empty highball glass). A name that is itself the label of an object of the task, or that is read as different
    labels, is no alias. Sorted pairs."""
    have = set(labels)
    seen: dict[str, set[str]] = {}
    for u in units:
        for name, label in unit_aliases(u):
            seen.setdefault(name, set()).add(label)
    tails: dict[str, set[str]] = {}  # the labels by each of their ends after a blank: `salad` -> `carrot salad`
    for lab in have:
        for k, ch in enumerate(lab):
            if ch == " ":
                tails.setdefault(lab[k + 1:], set()).add(lab)
    matches: dict[str, list[str]] = {}  # a name's labels by the head-noun rule (`head_of`), read once per name
    starts = [x for x in starts if x is not None]
    for node in starts:
        for name in (*listed(node), *(c for _, c in places(node))):
            if name not in matches:
                ends = {name[k + 1:] for k, ch in enumerate(name) if ch == " "} & have
                matches[name] = sorted((tails.get(name, set()) | ends) - {name})
            if name not in have and len(matches[name]) == 1 and (name in listed(node) or any(
                    x.label == matches[name][0] and node.label in listed(x) for x in starts)):
                seen.setdefault(name, set()).add(matches[name][0])
    return tuple((n, next(iter(ls))) for n, ls in sorted(seen.items()) if len(ls) == 1 and n not in have)


def reported(found: Iterable[tuple[FunctionalUnit, str]]) -> tuple[list[str], list[str]]:
    """A task's report lines, each once, after its unit's file:line: for the notes (the path as given) and for
    the PDDL comments (the file name only: no checkout path in generated files)."""
    found = list(found)
    return (sorted({f"{unit_where(u)}: {m}" for u, m in found}),
            sorted({f"{unit_where(u, short_path)}: {m}" for u, m in found}))
