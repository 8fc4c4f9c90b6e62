"""Label and written-form defects: spelling variants, state order, duplicated states.

Spelling variants: two labels are variants when they are equal after removing
spaces, hyphens and apostrophes and reducing the last word to its singular
(`tomato` / `tomatoes`, `green onion` / `greenonion`), or when they differ by
one edit (insertion, deletion or substitution; both at least `MIN_EDIT_LENGTH`
long: `raman` / `ramen`) unless the lexicon knows both as different words
(`rice` / `mice`). The lexicon is WordNet when the CLI can open it; the
pure-string fallback singularizes by English suffix rules and knows no words.
Edit pairs are found with one-deletion neighbourhoods: O(length^2) characters per
label, so only labels of at most `MAX_EDIT_LENGTH` characters are compared by one
edit (a longer label is still compared by its normalized form); memory and time stay
linear in the total label length however long one label is.
"""

from __future__ import annotations

import re
from collections import Counter, defaultdict
from collections.abc import Callable, Iterable

from ..io.raw_objects import RawObject
from ..model.foon import Source
from .defects import Defect, DefectKind, Place, defect

#: Shortest labels compared by edit distance (short words differ by one letter too often).
MIN_EDIT_LENGTH = 5
#: Longest labels compared by edit distance (a label's one-deletion neighbourhood holds length^2 characters).
MAX_EDIT_LENGTH = 64

#: `lemma(word)`: the dictionary form of a known word, or None for an unknown one.
Lemma = Callable[[str], "str | None"]


def naive_singular(word: str) -> str:
    """English plural rules without a dictionary: berries -> berry, tomatoes -> tomato, dishes -> dish, eggs -> egg."""
    for plural, single in (("ies", "y"), ("oes", "o"), ("ches", "ch"), ("shes", "sh"), ("xes", "x"), ("sses", "ss")):
        if word.endswith(plural) and len(word) > len(plural) + 1:
            return word[: -len(plural)] + single
    if word.endswith("s") and not word.endswith(("ss", "us", "is")) and len(word) > 3:
        return word[:-1]
    return word


def _key(label: str, lemma: Lemma | None) -> str:
    words = label.split(" ")
    last = words[-1]
    single = (lemma(last) if lemma else None) or naive_singular(last)
    return re.sub(r"[\s\-']", "", " ".join([*words[:-1], single]))


def _one_edit_pairs(keys: Iterable[str]) -> set[tuple[str, str]]:
    """Pairs of keys at edit distance 1 (both MIN_EDIT_LENGTH to MAX_EDIT_LENGTH long)."""
    by_deletion: dict[str, set[str]] = defaultdict(set)
    keys = [k for k in set(keys) if MIN_EDIT_LENGTH <= len(k) <= MAX_EDIT_LENGTH]
    for k in keys:
        by_deletion[k].add(k)
        for i in range(len(k)):
            by_deletion[k[:i] + k[i + 1:]].add(k)
    pairs = set()
    for group in by_deletion.values():
        if len(group) > 1:
            ordered = sorted(group)
            pairs.update((a, b) for i, a in enumerate(ordered) for b in ordered[i + 1:] if _distance_one(a, b))
    return pairs


def _distance_one(a: str, b: str) -> bool:
    if len(a) == len(b):
        return sum(x != y for x, y in zip(a, b, strict=True)) == 1
    if abs(len(a) - len(b)) != 1:
        return False
    short, long_ = sorted((a, b), key=len)
    i = next((j for j, (x, y) in enumerate(zip(short, long_, strict=False)) if x != y), len(short))  # first difference
    return long_[i + 1:] == short[i:]


def spelling_variants(mentions: dict[str, list[Source]], lemma: Lemma | None = None) -> list[Defect]:
    """Groups of labels (keys of `mentions`: label -> where it occurs) that are spelling variants."""
    parent: dict[str, str] = {}

    def find(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    keys: dict[str, list[str]] = defaultdict(list)
    for label in sorted(mentions):
        keys[_key(label, lemma)].append(label)
    for labels in keys.values():
        for other in labels[1:]:
            parent[find(other)] = find(labels[0])
    for a, b in sorted(_one_edit_pairs(keys)):
        la, lb = keys[a][0], keys[b][0]
        if lemma is not None and lemma(la) and lemma(lb):
            continue  # two words the lexicon knows: different words, not a misspelling
        parent[find(lb)] = find(la)
    groups: dict[str, list[str]] = defaultdict(list)
    for label in sorted(mentions):
        groups[find(label)].append(label)
    return [defect(DefectKind.SPELLING_VARIANT, "labels differ only in spelling, spacing or plural: "
                   + " / ".join(g), (s for label in g for s in mentions[label]), g)
            for g in sorted(groups.values()) if len(g) > 1]


def written_form(objects: Iterable[RawObject]) -> list[Defect]:
    """Objects written with a state twice, and one node written with its states in different orders."""
    duplicated: dict[tuple[str, str], list[Place]] = defaultdict(list)
    orders: dict[tuple[str, tuple[str, ...]], dict[tuple[str, ...], list[Place]]] = defaultdict(lambda: defaultdict(list))
    for o in objects:
        seen = set()
        for s in o.states:
            if s in seen:
                duplicated[(o.label, s)].append(Place(o.path, o.line))
            seen.add(s)
            for body in re.findall(r"\{([^{}]*)\}", s):
                counts = Counter(i.strip() for i in body.split(",") if i.strip())
                for item in sorted(i for i, n in counts.items() if n > 1):
                    duplicated[(o.label, f"{s} (item {item!r} listed twice)")].append(Place(o.path, o.line))
        orders[(o.label, tuple(sorted(set(o.states))))][tuple(dict.fromkeys(o.states))].append(Place(o.path, o.line))
    out = []
    for (label, state), places in sorted(duplicated.items()):
        out.append(defect(DefectKind.DUPLICATE_STATE, f"{label}: state {state!r} written twice on one object" if "listed twice" not in state
                          else f"{label}: {state}",
                          (Source(p.path, p.line) for p in places), [label]))
    for (label, _states), variants in sorted(orders.items()):
        if len(variants) > 1:
            forms = sorted(variants)
            out.append(defect(DefectKind.STATE_ORDER, f"{label} written with the same states in {len(forms)} "
                              "orders: " + " / ".join("(" + ", ".join(f) + ")" for f in forms[:3]),
                              (Source(p.path, p.line) for v in variants.values() for p in v), [label]))
    return out
