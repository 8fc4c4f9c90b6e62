"""What a kind of tool is for, in WordNet's own words (the cook similarity's rule 7, `cook.py`).

WordNet's hierarchy files an urn ("a large pot for making coffee or tea"), a tea maker and a
slop basin ("a bowl into which the dregs of teacups and coffee cups are emptied") as kinds of
pot, spoon and bowl; what sets them apart is in their names and glosses: the food they are
for. `foods` reads the foods a synset names: the words of its label (the FOON label, or the
synset's first lemma) and of its gloss whose most frequent noun sense (WordNet's first) is a
food (`noun.food`), a two-word compound first ("iced tea", then "tea"), each as that sense.
A kind for another food is one whose foods are not all among its generic's: `for_another_food`.
But a vessel named for what it holds is still a vessel: when the generic is a container whose name or
gloss names a substance it holds (a bottle "for storing drinks or other liquids", a drinking glass "for
holding liquids"), a food that is a WordNet kind of that substance (wine, beer, soft drink: liquids) is
not another food (`held`), so bottle~wine bottle and drinking glass~schooner stand; a pot for making
coffee does not (a pot's gloss names no substance). A container whose label says which food it holds is that
container for it (`named_for_food`): a cookie jar is "a jar in which cookies are kept", a jar still.
Cost: a few WordNet lookups per synset, cached.
"""

from __future__ import annotations

import re
from functools import lru_cache

_WORD = re.compile(r"[a-z]+")


#: The synset whose kinds are containers: only a container's gloss says what it holds (`held`).
CONTAINER = "container.n.01"

#: What a container may be said to hold (`held`): liquids (a drink is a liquid in WordNet).
LIQUID = "liquid.n.01"


def _first(reader, term: str, lexname: str) -> str | None:
    """The first noun sense of `term` when it is in WordNet's file `lexname`, else None."""
    found = reader.synsets(term, "n")
    return found[0].name() if found and found[0].lexname() == lexname else None


def foods(reader, synset: str, label: str = "") -> frozenset[str]:
    """The food senses the label (else the synset's first lemma) and the gloss of `synset` name (module doc)."""
    return _named(reader, synset, label, "noun.food")


def held(reader, synset: str, label: str = "") -> frozenset[str]:
    """The liquids (`LIQUID` or its kinds, read as `foods` reads foods, in `noun.substance`) the label and
    gloss of container `synset` name; none for a synset that is no WordNet kind of a container."""
    if CONTAINER not in _ancestors(reader, synset):
        return frozenset()
    return frozenset(x for x in _named(reader, synset, label, "noun.substance")
                     if x == LIQUID or LIQUID in _ancestors(reader, x))


@lru_cache(maxsize=8192)
def _named(reader, synset: str, label: str, lexname: str) -> frozenset[str]:
    s = reader.synset(synset)
    name = label or s.lemmas()[0].name()
    out: set[str] = set()
    for text in (name.replace("_", " "), s.definition()):
        words = _WORD.findall(text.lower())
        i = 0
        while i < len(words):
            pair = _first(reader, f"{words[i]}_{words[i + 1]}", lexname) if i + 1 < len(words) else None
            if pair is not None:
                out.add(pair)
                i += 2
                continue
            single = _first(reader, words[i], lexname)
            if single is not None:
                out.add(single)
            i += 1
    return frozenset(out)


def named_for_food(reader, generic: str, kind_label: str, generic_label: str) -> bool:
    """Whether `kind_label` is container `generic_label` (synset `generic`, a WordNet kind of a container) named
    for a food it holds: the compound's head is that label and its modifier names a food (read as `foods` reads
    words: cookie jar, beer mug, soup ladle; not milk can beside tin can, whose heads only are shared)."""
    modifier = kind_label.removesuffix(" " + generic_label)
    if not generic_label or modifier in ("", kind_label) or CONTAINER not in _ancestors(reader, generic):
        return False
    words = _WORD.findall(modifier.lower())
    return bool(words) and (_first(reader, "_".join(words), "noun.food") is not None
                            or _first(reader, words[-1], "noun.food") is not None)


def for_another_food(reader, kind: str, generic: str, kind_label: str = "", generic_label: str = "") -> bool:
    """Whether tool synset `kind` (a WordNet kind of `generic`) names a food its generic does not name and
    that is no WordNet kind of a substance the generic holds (`held`); never a container named for the food
    it holds (`named_for_food`: a cookie jar is a jar)."""
    if named_for_food(reader, generic, kind_label, generic_label):
        return False
    holds = held(reader, generic, generic_label)
    return any(not (_ancestors(reader, f) & holds)
               for f in foods(reader, kind, kind_label) - foods(reader, generic, generic_label))


@lru_cache(maxsize=4096)
def _ancestors(reader, synset: str) -> frozenset[str]:
    """`synset`'s WordNet ancestors (hypernyms, transitively)."""
    return frozenset(x.name() for x in reader.synset(synset).closure(lambda s: s.hypernyms()))
