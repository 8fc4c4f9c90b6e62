"""Extending a category index to labels it does not know, through WordNet: `categories --extend`.

Each unknown object label joins the category of the known label it is nearest to:

1. head noun: a compound whose head (or a shorter tail of it) is a known label joins
   that label's category (`zucchini bread` -> the category of `bread`);
2. otherwise category name: a label that ends with a part of a category's name (the
   name split at " and ", words compared in the singular) and contains all its words
   joins that category (`banana pudding` -> `puddings and custards`, `enchilada sauce`
   -> `sauces`, `pizza sauce` -> `pasta and pizza sauces`, but `curry powder` not
   `allium powders`); among several, the longest part, then the shallowest category,
   then file order;
3. otherwise nearest member: the known label with the greatest value of the similarity
   given (`cook.filing_similarity`: the cook mode's role senses and deepest common
   ancestor; no breadth rejection, since a category is meant to be broad, and no category
   rule, which would read the index being extended), at least `min_similarity` (default
   0.65); ties broken by label order (the categories of the other members as near are
   listed, `Assignment.also`).

A whole WordNet term joins its head's category only when it is a kind of the head (`file_labels`, the one
way `categories --extend` and the cook mode's rule 5 file labels: chili pepper, a capsicum, is no kind of
the spice pepper, so it joins `peppers` by that category's name).

A label with no WordNet sense, no known head and no category-name head stays unassigned
(listed as such).
Every assignment is returned with its evidence for review (`Assignment`); the index
is otherwise unchanged. Cost: per unknown label, one similarity per known label.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

from ..analysis.check_labels import naive_singular
from ..model.foon import normalize_label
from .categories import Category, CategoryIndex

#: Least similarity to the nearest member for a WordNet assignment (measured: docs/generalization.md).
DEFAULT_MIN_SIMILARITY = 0.65


@dataclass(frozen=True)
class Assignment:
    """An unknown label, the category it joins (None: unassigned), through which known label, how similar."""

    label: str
    category: str | None
    via: str = ""
    similarity: float = 0.0
    how: str = ""  # head | name | wordnet | none
    also: tuple[str, ...] = ()  # the categories of other members as near (wordnet), in label order

    def describe(self) -> str:
        if self.category is None:
            return f"{self.label}\t-\t-\t-\tnone"
        return f"{self.label}\t{self.category}\t{self.via}\t{self.similarity:.4f}\t{self.how}"


def _tails(label: str) -> list[str]:
    words = label.split()
    return [" ".join(words[i:]) for i in range(1, len(words))]


def _name_parts(index: CategoryIndex) -> dict[str, list[tuple[str, frozenset[str]]]]:
    """Singular head word -> (category, the singular words of its name part) in file order (rule 2)."""
    out: dict[str, list[tuple[str, frozenset[str]]]] = {}
    for c in index.categories:
        for part in c.name.split(" and "):
            words = [naive_singular(w) for w in part.split()]
            if words:
                out.setdefault(words[-1], []).append((c.name, frozenset(words)))
    return out


def by_name(label: str, index: CategoryIndex, parts: dict[str, list[tuple[str, frozenset[str]]]] | None = None
            ) -> str | None:
    """The category a part of whose name `label` ends with and contains every word of (rule 2 of the module
    doc): the longest such part, then the shallowest category, then file order; None when there is none."""
    words = [naive_singular(w) for w in label.split()]
    if not words:
        return None
    candidates = [(name, part) for name, part in (parts if parts is not None else _name_parts(index)).get(words[-1], ())
                  if part <= set(words)]
    if not candidates:
        return None
    order = {name: i for i, name in enumerate(index.names)}
    return min(candidates, key=lambda c: (-len(c[1]), index.depth(c[0]), order[c[0]]))[0]


def assign(labels: Iterable[str], index: CategoryIndex, sim, min_similarity: float = DEFAULT_MIN_SIMILARITY,
           head_ok: Callable[[str, str], bool] | None = None) -> tuple[Assignment, ...]:
    """Assignments of the `labels` in no category of `index` (sorted by label); `sim(a, b)` ranks the known
    labels (`cook.filing_similarity`, which the cook mode's rule 5 also files unknown labels by). With
    `head_ok`, a head noun files a label only when `head_ok(label, head)` (the cook mode: a kind of it)."""
    known = sorted({m for c in index.categories for m in c.members})
    todo = sorted({normalize_label(x) for x in labels} - set(known) - set(index.names) - {""})
    if not todo:
        return ()
    parts = _name_parts(index)
    out = []
    for label in todo:
        head = next((t for t in _tails(label) if index.choose(t) is not None and (head_ok is None or head_ok(label, t))),
                    None)
        if head is not None:
            out.append(Assignment(label, index.choose(head), head, 1.0, "head"))
            continue
        named = by_name(label, index, parts)
        if named is not None:
            out.append(Assignment(label, named, named, 1.0, "name"))
            continue
        best, value, tied = "", 0.0, []
        for m in known:
            v = sim(label, m)
            if v > value:
                best, value, tied = m, v, []
            elif v == value and best:
                tied.append(m)
        if best and value >= min_similarity:
            first = index.choose(best)
            also = tuple(dict.fromkeys(c for c in map(index.choose, tied) if c not in (None, first)))
            out.append(Assignment(label, first, best, value, "wordnet", also))
        else:
            out.append(Assignment(label, None, best, value, "none"))
    return tuple(out)


def file_labels(labels: Iterable[str], index: CategoryIndex, files, min_similarity: float = DEFAULT_MIN_SIMILARITY
                ) -> tuple[Assignment, ...]:
    """How `categories --extend` and the cook mode's rule 5 file unknown labels, one way: `assign` with
    `files` (`cook.filing_similarity`) ranking the members and a head noun filing a whole WordNet term only
    as a kind of it (`files.kind_of_head`: chili pepper, a capsicum, is no kind of the spice pepper)."""
    return assign(labels, index, files, min_similarity, head_ok=files.kind_of_head)


def extended_index(index: CategoryIndex, assignments: Iterable[Assignment]) -> CategoryIndex:
    """`index` with each assigned label added to its category's members."""
    extra: dict[str, set[str]] = {}
    for a in assignments:
        if a.category is not None:
            extra.setdefault(a.category, set()).add(a.label)
    cats = tuple(Category(c.name, c.parent, c.description, tuple(sorted({*c.members, *extra.get(c.name, ())})))
                 for c in index.categories)
    return CategoryIndex(cats, index.source)


def index_json(index: CategoryIndex, comment: str = "") -> str:
    """The index in the shipped file's format (`categories.parse_index` reads it back)."""
    import json

    body = {c.name: {"parent": c.parent, "description": c.description, "members": list(c.members)}
            for c in index.categories}
    data = {"_comment": comment, "categories": body} if comment else {"categories": body}
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"
