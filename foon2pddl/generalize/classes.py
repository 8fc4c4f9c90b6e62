"""When a WordNet noun names a class rather than a thing a recipe uses (the cook similarity's rules 8 and 9).

Rule 8 counts a synset's kinds (`kinds`); rule 9 reads how its kinds are named (`named_kinds`): a bottle's
kinds are mostly called bottles (beer bottle, water bottle, wine bottle), a kitchen appliance's go by names of
their own (oven, toaster, food processor), as a drinking vessel's (mug, tankard) and flatware's (plate,
saucer) do. A tool whose kinds are named after it is a thing, and does its kinds' job; a tool whose kinds are
not is a class of tools with different jobs (`tool_class`). Cost: one hyponym closure per synset, cached.
"""

from __future__ import annotations

from functools import lru_cache

from .similarity import Evidence

#: Rule 9: an artifact sense with at least this many WordNet kinds, fewer than `NAMED_SHARE` of them named after
#: it, is a class of tools (kitchen appliance: 25 kinds, none named "... appliance"; bottle: 34, 35 % named so).
TOOL_CLASS_KINDS, NAMED_SHARE = 5, 0.1


@lru_cache(maxsize=4096)
def kinds(reader, name: str) -> int:
    """How many WordNet kinds (hyponyms, transitively) synset `name` has (rule 8)."""
    return sum(1 for _ in reader.synset(name).closure(lambda s: s.hyponyms()))


@lru_cache(maxsize=4096)
def named_kinds(reader, name: str) -> float:
    """Share of synset `name`'s WordNet kinds (hyponyms, transitively) with a lemma named after it: the lemma's
    last word ends with the last word of one of `name`'s lemmas (beer bottle under bottle; teaspoon under
    spoon). 1.0 without kinds."""
    s = reader.synset(name)
    heads = {x.name().lower().split("_")[-1] for x in s.lemmas()}
    found = list(s.closure(lambda y: y.hyponyms()))
    if not found:
        return 1.0
    return sum(any(x.name().lower().split("_")[-1].endswith(h) for h in heads for x in k.lemmas())
               for k in found) / len(found)


def tool_class(reader, found: Evidence) -> bool:
    """Rule 9: whether `found` is a kind pair (two senses, one the other's ancestor) whose generic is a class of
    tools: an artifact sense with at least `TOOL_CLASS_KINDS` kinds, fewer than `NAMED_SHARE` of them named after
    it (`named_kinds`)."""
    generic = found.ancestor
    if found.sense_a == found.sense_b or generic not in (found.sense_a, found.sense_b):
        return False
    if reader.synset(generic).lexname() != "noun.artifact" or kinds(reader, generic) < TOOL_CLASS_KINDS:
        return False
    return named_kinds(reader, generic) < NAMED_SHARE
