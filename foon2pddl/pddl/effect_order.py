"""An action's effects grouped by the parameters they name, in an order that does what the action does in one step
(`effect_parts`): what `split_actions` makes its `do` parts of. Conditions read the state before the action and an
add wins over a delete, so no group may change an atom a later group's conditions read, nor add an atom a later
group deletes (two atoms may be one when their predicates match and each pair of arguments may be one object, by
type); groups that must each come first are one part. O(effect groups^3 + (effect atoms)^2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .task import Action, Atom, Conditional

__all__ = ["EffectPart", "effect_parts", "variables"]


def variables(atoms) -> set[str]:
    """The variables (`?x`) the atoms name."""
    return {x for a in atoms for x in a.args if x.startswith("?")}


def _compatible(a: str, b: str, below: dict[str, set[str]]) -> bool:
    return a in below.get(b, {b}) or b in below.get(a, {a})


def _may_meet(one: tuple[Atom, dict[str, str]], other: tuple[Atom, dict[str, str]], below: dict[str, set[str]],
              kind: dict[str, str]) -> bool:
    """Whether two atoms, each with the types of its variables, may be one ground atom."""
    (a, at), (b, bt) = one, other
    if a.predicate != b.predicate or len(a.args) != len(b.args):
        return False
    for x, y in zip(a.args, b.args, strict=True):
        if x not in at and y not in bt:
            if x != y:
                return False
        elif not _compatible(at.get(x, kind.get(x, "object")), bt.get(y, kind.get(y, "object")), below):
            return False
    return True


@dataclass
class EffectPart:
    """Effects of an action that name the same parameters: unconditional adds and deletes, conditionals."""

    names: set[str]
    add: list[Atom] = field(default_factory=list)
    delete: list[Atom] = field(default_factory=list)
    conditional: list[Conditional] = field(default_factory=list)

    def scoped(self, params: dict[str, str], which: str) -> list[tuple[Atom, dict[str, str]]]:
        """The part's atoms of one kind ('add', 'delete', 'when') with the types of their variables."""
        out = [(a, params) for a in (self.add if which == "add" else self.delete if which == "delete" else ())]
        for c in self.conditional:
            scope = {**params, **dict(c.quantified)}
            out += [(a, scope) for a in (c.add if which == "add" else c.delete if which == "delete" else c.when)]
        return out


def effect_parts(action: Action, own: list[Atom], own_del: list[Atom], below, kind) -> list[EffectPart]:
    """The action's effects grouped by the parameters they name, in an order that does what the action does:
    no part changes an atom a later part's conditions read, none adds an atom a later part deletes (groups that
    must come before each other are one part)."""
    params = dict(action.params)
    parts: dict[frozenset[str], EffectPart] = {}
    for atoms, kind_ in ((own, "add"), (own_del, "delete")):
        for a in atoms:
            getattr(parts.setdefault(frozenset(variables((a,))), EffectPart(set(variables((a,))))), kind_).append(a)
    for c in action.conditional:
        names = variables(c.atoms()) - {v for v, _ in c.quantified}
        parts.setdefault(frozenset(names), EffectPart(set(names))).conditional.append(c)
    groups = list(parts.values())

    def meet(xs, ys) -> bool:
        return any(_may_meet(x, y, below, kind) for x in xs for y in ys)

    writes = [g.scoped(params, "add") + g.scoped(params, "delete") for g in groups]
    first = [[meet(writes[j], groups[i].scoped(params, "when"))  # i must come before j
              or meet(groups[j].scoped(params, "add"), groups[i].scoped(params, "delete")) for j in range(len(groups))]
             for i in range(len(groups))]
    n = len(groups)
    for k in range(n):  # transitive closure
        for i in range(n):
            if first[i][k]:
                first[i] = [x or y for x, y in zip(first[i], first[k], strict=True)]
    comp = [min(j for j in range(n) if j == i or first[i][j] and first[j][i]) for i in range(n)]
    order: list[int] = []
    todo = sorted(set(comp))
    while todo:  # the first component nothing left must come before
        c = next(c for c in todo if not any(first[d][c] and not first[c][d] for d in todo if d != c))
        todo.remove(c)
        order.append(c)
    out = []
    for c in order:
        merged = EffectPart(set())
        for g in (groups[i] for i in range(n) if comp[i] == c):
            merged.names |= g.names
            merged.add += g.add
            merged.delete += g.delete
            merged.conditional += g.conditional
        out.append(merged)
    return out
