"""When a WordNet noun names a class rather than a thing a recipe uses (the cook similarity's rules 3, 8 and 9).

Rule 8 counts a synset's kinds (`kinds`); rule 9 reads how its kinds are named (`named_kinds`): a bottle's
kinds are mostly called bottles (beer bottle, water bottle, wine bottle), a kitchen appliance's go by names of
their own (oven, toaster, food processor), as a drinking vessel's (mug, tankard) and flatware's (plate,
saucer) do. A tool whose kinds are named after it is a thing, and does its kinds' job; a tool whose kinds are
not is a class of tools with different jobs (`tool_class`). Counting also the kinds whose gloss's genus is the
noun (penne: "pasta in short tubes"), a food noun most of whose kinds are named or defined after it is a staple,
which rule 3's breadth limit does not reject with its kinds (`staple`: bread, pasta; not herb or sweetener); one
fewer than 10 % of whose kinds are is a class of foods (`food_class`: citrus, brew), which rule 8 reads for filed labels
and rule 9 for every label when its kinds are classes too (`food_class_of_classes`: salad green; not a flavorer such
as sweetening, a class WordNet defines by its job, `flavorer_class`).
Cost: one hyponym closure per synset, cached.
"""

from __future__ import annotations

import re
from functools import lru_cache

from .similarity import Evidence

#: Rule 9: an artifact sense with at least this many WordNet kinds, fewer than `NAMED_SHARE` of them named after
#: it, is a class of tools (kitchen appliance: 25 kinds, none named "... appliance"; bottle: 34, 35 % named so).
TOOL_CLASS_KINDS, NAMED_SHARE = 5, 0.1

#: Rule 3's exemption: a sense with at least `TOOL_CLASS_KINDS` kinds, at least `STAPLE_SHARE` of them named after
#: it or defined as it by their gloss's first `GENUS_WORDS` words, is a staple (bread 35 %, pasta 50 %).
STAPLE_SHARE, GENUS_WORDS = 0.3, 2

#: Rule 3's exemption is for a starch a meal is built on: no flavorer (a sauce's kinds are its flavours, as a herb's
#: are), no dish and no bake (their kinds are variants, rule 4) unless WordNet also files it as a starch (bread).
FLAVORER = "flavorer.n.01"
NOT_STAPLES, STARCH = frozenset({FLAVORER, "dish.n.02", "baked_goods.n.01"}), "starches.n.01"

#: Rule 9 for foods: a food class with at least this many levels of kinds below it has kinds that are classes too.
CLASS_LEVELS = 3

_WORD = re.compile(r"[a-z]+")


@lru_cache(maxsize=4096)
def kinds(reader, name: str) -> int:
    """How many WordNet kinds (hyponyms, transitively) synset `name` has (rule 8)."""
    return sum(1 for _ in reader.synset(name).closure(lambda s: s.hyponyms()))


@lru_cache(maxsize=4096)
def named_kinds(reader, name: str, gloss_words: int = 0) -> float:
    """Share of synset `name`'s WordNet kinds (hyponyms, transitively) with a lemma named after it: the lemma's
    last word ends with the last word of one of `name`'s lemmas (beer bottle under bottle; teaspoon under
    spoon), or, with `gloss_words`, whose gloss names it among its first `gloss_words` words (penne: "pasta in
    short tubes"). 1.0 without kinds."""
    s = reader.synset(name)
    heads = {x.name().lower().split("_")[-1] for x in s.lemmas()}
    found = list(s.closure(lambda y: y.hyponyms()))
    if not found:
        return 1.0

    def named(k) -> bool:
        if any(x.name().lower().split("_")[-1].endswith(h) for h in heads for x in k.lemmas()):
            return True
        return any(w in heads or w.removesuffix("s") in heads for w in _WORD.findall(k.definition().lower())[:gloss_words])
    return sum(map(named, found)) / len(found)


def staple(reader, name: str) -> bool:
    """Whether synset `name` is a staple, not a class (rule 3's exemption): at least `TOOL_CLASS_KINDS` kinds,
    at least `STAPLE_SHARE` of them named after it or whose gloss's genus, among its first `GENUS_WORDS` words,
    is it (`named_kinds`: penne is "pasta in short tubes"; herb 10 %, sweetening 0 %), and under none of
    `NOT_STAPLES` unless a `STARCH` (sauce, a flavorer, and cake, a bake, are no staples; bread is)."""
    above = {x.name() for x in reader.synset(name).closure(lambda s: s.hypernyms())} | {name}
    if above & NOT_STAPLES and STARCH not in above:
        return False
    return kinds(reader, name) >= TOOL_CLASS_KINDS and named_kinds(reader, name, GENUS_WORDS) >= STAPLE_SHARE


def likened(reader, a: str, b: str) -> bool:
    """Rule 3's second exemption: whether WordNet defines synset `a` by likeness to `b` or `b` to `a`: the gloss
    of one names a lemma of the other as "X-like" (coriander.n.03, "parsley-like herb used as seasoning or
    garnish"). WordNet's own definition says the two do one job, whatever their ancestor covers. Cost: two glosses."""
    for x, y in ((a, b), (b, a)):
        gloss = reader.synset(x).definition().lower()
        if any(re.search(r"\b" + re.escape(n.name().lower().replace("_", " ")) + r"-like\b", gloss)
               for n in reader.synset(y).lemmas()):
            return True
    return False


def food_class(reader, name: str) -> bool:
    """Rule 8: whether food synset `name` is a class of foods, the converse of a staple: at least `TOOL_CLASS_KINDS`
    kinds, fewer than `NAMED_SHARE` of them named after it or defined as it by their gloss's genus (`named_kinds`
    with `GENUS_WORDS`: citrus, whose kinds are lemon, lime, orange; brew, whose kinds are ale and beer)."""
    if reader.synset(name).lexname() != "noun.food" or kinds(reader, name) < TOOL_CLASS_KINDS:
        return False
    return named_kinds(reader, name, GENUS_WORDS) < NAMED_SHARE


@lru_cache(maxsize=4096)
def levels(reader, name: str) -> int:
    """How many levels of WordNet kinds synset `name` has below it (0 for a leaf; sweetening 4: sugar, brown sugar, ...)."""
    below = reader.synset(name).hyponyms()
    return 1 + max(levels(reader, x.name()) for x in below) if below else 0


def flavorer_class(reader, name: str) -> bool:
    """Whether WordNet files synset `name` as a flavorer (`FLAVORER` or below it: sweetening, condiment), a class it
    defines by what it does to food ("something added to foods to make them taste sweeter"), not by what a food is
    (vegetable, salad green, poultry): its kinds all do its job (rule 9 for foods spares it, stop 54)."""
    return FLAVORER in {x.name() for x in reader.synset(name).closure(lambda s: s.hypernyms())} | {name}


def food_class_of_classes(reader, found: Evidence) -> bool:
    """Rule 9 for foods: whether `found` is a kind pair whose generic is a class of foods (`food_class`) whose kinds are
    classes of their own (at least `CLASS_LEVELS` levels of kinds below it): salad green (lettuce, cress); not a
    chicken's or a beefsteak's kinds (capon, strip steak: two levels), nor, since stop 54, a class defined by its job
    (`flavorer_class`: sweetening, whose kinds sugar and syrup all sweeten)."""
    generic = found.ancestor
    if found.sense_a == found.sense_b or generic not in (found.sense_a, found.sense_b):
        return False
    return food_class(reader, generic) and levels(reader, generic) >= CLASS_LEVELS and not flavorer_class(reader, generic)


def tool_class(reader, found: Evidence) -> bool:
    """Rule 9: whether `found` is a kind pair (two senses, one the other's ancestor) whose generic is a class of
    tools: an artifact sense with at least `TOOL_CLASS_KINDS` kinds, fewer than `NAMED_SHARE` of them named after
    it (`named_kinds`); or, since stop 51, two kinds that meet only under such a class (knife~scissors under edge
    tool, scraper~spatula under hand tool): kinds of a class of tools do different jobs."""
    generic = found.ancestor
    if found.sense_a == found.sense_b or generic is None:
        return False
    if reader.synset(generic).lexname() != "noun.artifact" or kinds(reader, generic) < TOOL_CLASS_KINDS:
        return False
    return named_kinds(reader, generic) < NAMED_SHARE
