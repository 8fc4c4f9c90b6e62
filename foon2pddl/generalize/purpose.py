"""What a kind of tool is for, in WordNet's own words (the cook similarity's rule 7, `cook.py`).

WordNet's hierarchy files an urn ("a large pot for making coffee or tea"), a tea maker and a
slop basin ("a bowl into which the dregs of teacups and coffee cups are emptied") as kinds of
pot, spoon and bowl; what sets them apart is in their names and glosses: the food they are
for. `foods` reads the foods a synset names: the words of its label (the FOON label, or the
synset's first lemma) and of its gloss whose most frequent noun sense (WordNet's first) is a
food (`noun.food`), a two-word compound first ("iced tea", then "tea"), each as that sense.
A kind for another food is one whose foods are not all among its generic's: `for_another_food`.
Cost: a few WordNet lookups per synset, cached.
"""

from __future__ import annotations

import re
from functools import lru_cache

_WORD = re.compile(r"[a-z]+")


def _food(reader, term: str) -> str | None:
    """The first noun sense of `term` when it is a food, else None."""
    found = reader.synsets(term, "n")
    return found[0].name() if found and found[0].lexname() == "noun.food" else None


def foods(reader, synset: str, label: str = "") -> frozenset[str]:
    """The food senses the label (else the synset's first lemma) and the gloss of `synset` name (module doc)."""
    return _foods(reader, synset, label)


@lru_cache(maxsize=4096)
def _foods(reader, synset: str, label: str) -> frozenset[str]:
    s = reader.synset(synset)
    name = label or s.lemmas()[0].name()
    out: set[str] = set()
    for text in (name.replace("_", " "), s.definition()):
        words = _WORD.findall(text.lower())
        i = 0
        while i < len(words):
            pair = _food(reader, f"{words[i]}_{words[i + 1]}") if i + 1 < len(words) else None
            if pair is not None:
                out.add(pair)
                i += 2
                continue
            single = _food(reader, words[i])
            if single is not None:
                out.add(single)
            i += 1
    return frozenset(out)


def for_another_food(reader, kind: str, generic: str, kind_label: str = "", generic_label: str = "") -> bool:
    """Whether tool synset `kind` (a WordNet kind of `generic`) names a food its generic does not name."""
    return bool(foods(reader, kind, kind_label) - foods(reader, generic, generic_label))
