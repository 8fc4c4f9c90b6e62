"""The category index of FOON-GEN: named groups of object labels, some refining others.

The index ships as `generalize/data/categories.json` (bootstrapped from WordNet
by `bootstrap_categories.py`, corrected by hand): `{"categories": {name:
{"parent": name | null, "description": text, "members": [label, ...]}}}`. An
object may belong to several categories or to none; a category may refine
another (`parent`), and its members are members of every ancestor too.

Generalizing needs one category per object (`CategoryIndex.choose`): the most
specific of the categories that list it (the deepest in the parent chain),
ties broken by the order of the categories in the file. PDDL typing needs a
single parent per type, which this rule also provides (see `lifted.py`).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources
from pathlib import Path

from ..errors import FoonInputError
from ..io.json_text import load_json
from ..io.parser import read_text
from ..model.foon import normalize_label


def index_path() -> Path:
    """The shipped category index."""
    return Path(str(resources.files("foon2pddl") / "generalize" / "data" / "categories.json"))


@dataclass(frozen=True)
class Category:
    """A named group of object labels, optionally refining a parent category."""

    name: str
    parent: str | None
    description: str
    members: tuple[str, ...]


@dataclass(frozen=True)
class CategoryIndex:
    """Categories in file order, with lookups by name and by member label."""

    categories: tuple[Category, ...]
    source: str = ""
    _by_name: dict[str, Category] = field(init=False, repr=False, compare=False)
    _of: dict[str, tuple[str, ...]] = field(init=False, repr=False, compare=False)
    _chosen: dict[str, str] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        by_name = {c.name: c for c in self.categories}
        of: dict[str, list[str]] = {}
        for c in self.categories:
            for m in c.members:
                of.setdefault(m, []).append(c.name)
        object.__setattr__(self, "_by_name", by_name)
        object.__setattr__(self, "_of", {m: tuple(v) for m, v in of.items()})
        order = {c.name: i for i, c in enumerate(self.categories)}
        chosen = {m: min(v, key=lambda n: (-self.depth(n), order[n])) for m, v in self._of.items()}
        object.__setattr__(self, "_chosen", chosen)

    def __len__(self) -> int:
        return len(self.categories)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(c.name for c in self.categories)

    def get(self, name: str) -> Category:
        return self._by_name[name]

    def is_category(self, label: str) -> bool:
        return label in self._by_name

    def of(self, label: str) -> tuple[str, ...]:
        """The categories that list `label`, in file order (ancestors not added)."""
        return self._of.get(label, ())

    def ancestors(self, name: str) -> tuple[str, ...]:
        """Parent, grandparent, ... of category `name`."""
        out = []
        parent = self._by_name[name].parent
        while parent is not None:
            out.append(parent)
            parent = self._by_name[parent].parent
        return tuple(out)

    def depth(self, name: str) -> int:
        return len(self.ancestors(name))

    def choose(self, label: str) -> str | None:
        """The one category `label` generalizes to: the deepest listing it, first in file order on ties."""
        return self._chosen.get(label)

    def members_of(self, name: str) -> frozenset[str]:
        """Labels in category `name` or in any category refining it."""
        out = set(self._by_name[name].members)
        for c in self.categories:
            if name in self.ancestors(c.name):
                out.update(c.members)
        return frozenset(out)


def parse_index(text: str, path: str) -> CategoryIndex:
    """Read and check an index: JSON shape, known parents, no cycles, no category named like an object."""
    data = load_json(text, path)  # located errors for bad JSON, deep nesting, huge integers
    cats = data.get("categories") if isinstance(data, dict) else None
    if not isinstance(cats, dict):
        raise FoonInputError(path, 0, 'expected {"categories": {name: {"parent", "description", "members"}}}')
    out = []
    for raw_name, body in cats.items():
        name = normalize_label(raw_name)
        if not name or not isinstance(body, dict):
            raise FoonInputError(path, 0, f"category {raw_name!r}: expected a non-empty name and an object")
        parent, members = body.get("parent"), body.get("members", [])
        if parent is not None and not isinstance(parent, str):
            raise FoonInputError(path, 0, f"category {name!r}: parent must be a name or null")
        if not isinstance(members, list) or not all(isinstance(m, str) and m.strip() for m in members):
            raise FoonInputError(path, 0, f"category {name!r}: members must be a list of labels")
        out.append(Category(name, normalize_label(parent) if parent else None, str(body.get("description", "")),
                            tuple(sorted({normalize_label(m) for m in members}))))
    names = [c.name for c in out]
    if len(set(names)) != len(names):
        raise FoonInputError(path, 0, "two categories have the same name")
    known = set(names)
    for c in out:
        if c.parent is not None and c.parent not in known:
            raise FoonInputError(path, 0, f"category {c.name!r}: unknown parent {c.parent!r}")
    parents = {c.name: c.parent for c in out}
    for c in out:
        seen, p = {c.name}, c.parent
        while p is not None:
            if p in seen:
                raise FoonInputError(path, 0, f"category {c.name!r}: parent chain has a cycle")
            seen.add(p)
            p = parents[p]
    clash = sorted(known & {m for c in out for m in c.members})
    if clash:
        raise FoonInputError(path, 0, f"category names used as object labels too: {', '.join(clash)}")
    return CategoryIndex(tuple(out), path)


def load_index(path: str | Path | None = None) -> CategoryIndex:
    """The index at `path`, or the shipped one."""
    if path is None:
        return shipped_index()
    p = Path(path)
    return parse_index(read_text(p), str(p))  # regular files only, UTF-8 errors located


@lru_cache(maxsize=1)
def shipped_index() -> CategoryIndex:
    p = index_path()
    return parse_index(p.read_text(encoding="utf-8"), str(p))


@dataclass(frozen=True)
class Coverage:
    """How many of some object labels the index puts in at least one category."""

    labels: tuple[str, ...]
    missing: tuple[str, ...]

    @property
    def covered(self) -> int:
        return len(self.labels) - len(self.missing)

    @property
    def percent(self) -> float:
        return 100.0 * self.covered / len(self.labels) if self.labels else 100.0


def coverage(labels: Iterable[str], index: CategoryIndex) -> Coverage:
    """Coverage of `labels` (normalized, deduplicated) by `index`."""
    all_labels = tuple(sorted({normalize_label(x) for x in labels}))
    return Coverage(all_labels, tuple(x for x in all_labels if not index.of(x)))
