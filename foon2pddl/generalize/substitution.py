"""Excluded ingredients replaced by similar allowed ones, on the FOON-EXP and FOON-GEN networks.

- `--network exp`: FOON-EXP holds, beside each unit mentioning X, copies with X replaced
  by every label at least `threshold` similar. Banning X removes the originals; a copy
  survives when its substitute is allowed. `prefer_most_similar` keeps, for each banned
  X, only the copies of the most similar allowed substitute that still makes the goal
  (trying substitutes in decreasing similarity, then all of them): kale -> lettuce
  before kale -> spinach when both work.
- `--network gen`: the kitchen loses its banned objects *before* it is abstracted to
  categories, so a category in the tree is grounded by an allowed member.
`substitutions` says, for a found tree, which substitute replaced which banned label
and how similar they are (the default similarity mode, `modes.py`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace

from ..model.constraints import Constraint, Constraints, Kind, label_mentions, mentions
from ..model.foon import Foon, FunctionalUnit
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree
from .substitute import unit_labels


@dataclass(frozen=True, order=True)
class Substitution:
    """`replacement` stood in for the banned `original` (GEN: both in `category`)."""

    original: str
    replacement: str
    similarity: float
    category: str = ""

    def describe(self) -> str:
        via = f", both {self.category}" if self.category else ""
        return f"{self.original} -> {self.replacement} (Wu-Palmer {self.similarity:.3f}{via})"


def banned_labels(constraints: Constraints) -> tuple[str, ...]:
    return constraints.of(Kind.WITHOUT)


def allowed(label: str, constraints: Constraints) -> bool:
    return not any(label_mentions(label, x) for x in banned_labels(constraints))


def without_banned(kitchen: Kitchen, constraints: Constraints) -> Kitchen:
    """The kitchen without nodes mentioning a banned object (before GEN abstracts it)."""
    keep = frozenset(n for n in kitchen.nodes if not any(mentions(n, x) for x in banned_labels(constraints)))
    return Kitchen(keep, kitchen.level, kitchen.source)


def category_must_use(constraints: Constraints, index, name: str = "GEN") -> tuple[Constraints, tuple[str, ...]]:
    """The constraints as FOON-GEN (`index`: its categories) reads them, and a note per must-use it reads
    otherwise: a must-use object becomes its category, as a goal's label does (`compress.abstract_goal`), since
    the network's units name it so (`--must-use "mixing bowl"` -> `bowls`), unless a ban mentions it too; bans stay
    as given (the kitchen loses what they mention before it is abstracted)."""
    items: dict[Constraint, None] = {}
    notes = []
    for c in constraints.items:
        # a must-use the constraints also ban stays as written: as its category, other objects of the category
        # would satisfy it where REG and EXP report the contradiction (review rv47 finding 5)
        category = index.choose(c.value) if c.kind is Kind.MUST_USE and allowed(c.value, constraints) else None
        if category is not None and category != c.value:
            read = replace(c, value=category)
            notes.append(f"note: FOON-{name} reads `{c.detail()}` as its category: `{read.detail()}`")
            c = read
        items.setdefault(c)
    return replace(constraints, items=tuple(sorted(items))), tuple(notes)


def _copy_of(unit: FunctionalUnit, constraints: Constraints) -> str | None:
    """The banned label an EXP copy replaced, if it is one."""
    src = unit.sources[0].expanded_from if unit.sources else None
    return src if src is not None and not allowed(src, constraints) else None


def _substitute(unit: FunctionalUnit, original: str, sim: Callable[[str, str], float]) -> tuple[str, float]:
    """The label an EXP copy of `original` holds instead, with its similarity: the replacement the expansion
    recorded (`Source.expanded_to`); for a copy read from a file, which does not record it, the copy's
    label most similar to `original`."""
    recorded = unit.sources[0].expanded_to if unit.sources else None
    if recorded is not None:
        return recorded, sim(original, recorded)
    best = max(((label, sim(original, label)) for label in unit_labels(unit) if label != original),
               key=lambda x: (x[1], x[0]), default=("?", 0.0))
    return best


def prefer_most_similar(foon: Foon, constraints: Constraints, sim: Callable[[str, str], float],
                        works: Callable[[Foon], bool]) -> Foon:
    """The EXP network with, per banned label, only its most similar working substitute's copies (module doc)."""
    for original in sorted({o for u in foon.units if (o := _copy_of(u, constraints)) is not None}):
        choice: dict[int, str] = {}
        for i, u in enumerate(foon.units):
            if _copy_of(u, constraints) == original:
                choice[i] = _substitute(u, original, sim)[0]
        ranked = sorted(set(choice.values()), key=lambda y: (-sim(original, y), y))
        for y in ranked:
            trial = Foon(tuple(u for i, u in enumerate(foon.units) if choice.get(i, y) == y), foon.level)
            if works(trial):
                foon = trial
                break
    return foon


def expansion_substitutions(tree: TaskTree, sim: Callable[[str, str], float]) -> tuple[Substitution, ...]:
    """The substitutions an EXP tree relies on: for each FOON-EXP copy among its units, the label it
    replaced and the label standing in (as recorded at expansion, `_substitute`), sorted."""
    found = set()
    for u in tree.units:
        original = u.sources[0].expanded_from if u.sources else None
        if original is not None:
            label, value = _substitute(u, original, sim)
            found.add(Substitution(original, label, value))
    return tuple(sorted(found))


def substitutions(tree: TaskTree, constraints: Constraints, sim: Callable[[str, str], float], *,
                  kitchen_labels: Iterable[str] = (), category_of: Callable[[str], str | None] | None = None
                  ) -> tuple[Substitution, ...]:
    """What stood in for banned labels in `tree`: EXP copies (by their sources), or with `category_of`
    (GEN) the most similar allowed kitchen label of a banned label's category when the tree uses it."""
    found: set[Substitution] = set()
    if category_of is None:
        for u in tree.units:
            original = _copy_of(u, constraints)
            if original is not None:
                label, value = _substitute(u, original, sim)
                found.add(Substitution(original, label, value))
        return tuple(sorted(found))
    used = set().union(*(unit_labels(u) for u in tree.units)) if tree.units else set()
    kitchen_labels = sorted(set(kitchen_labels))
    for x in banned_labels(constraints):
        cat = category_of(x)
        if cat is None or cat not in used:
            continue
        members = [y for y in kitchen_labels if category_of(y) == cat and allowed(y, constraints)]
        if members:
            y = max(members, key=lambda m: (sim(x, m), m))
            found.add(Substitution(x, y, sim(x, y), cat))
    return tuple(sorted(found))


def retrieve_substituted(kind: str, foon: Foon, kitchen: Kitchen, goal: Goal, constraints: Constraints,
                         method: str = "complete", *, concrete_labels: Iterable[str] = (),
                         sim: Callable[[str, str], float] | None = None, index=None, rates=None, **limits):
    """Retrieval under `constraints` on the network of `kind` (EXP: the most similar allowed objects are
    preferred; GEN: `index` its categories, substitutes from the same category), ranked by similarity;
    (ConstrainedRetrieval, substitutions made)."""
    from ..retrieval.constrained import retrieve_constrained
    from .network import NETWORKS, Substitutes

    substitutes = NETWORKS[kind].substitutes

    if not banned_labels(constraints):
        return retrieve_constrained(foon, kitchen, goal, constraints, method, rates=rates, **limits), ()
    if sim is None:
        from .modes import make_similarity

        sim = make_similarity()  # the default mode (cook)
    if substitutes is Substitutes.SIMILAR:
        foon = prefer_most_similar(foon, constraints, sim, lambda f: retrieve_constrained(
            f, kitchen, goal, constraints, "complete").result.tree is not None)
    done = retrieve_constrained(foon, kitchen, goal, constraints, method, rates=rates, **limits)
    if done.result.tree is None:
        return done, ()
    category_of = index.choose if substitutes is Substitutes.CATEGORY and index is not None else None
    return done, substitutions(done.result.tree, constraints, sim, kitchen_labels=concrete_labels,
                               category_of=category_of)
