"""The cook's similarity, rules 5-8 (`cook.CookSimilarity` inherits them): which of two WordNet-close labels a
cook swaps, read from the category index and from what a filed label is a kind of.

5. Kin by the categories: a pair stands only if FOON-GEN's category index (`categories.json`,
   hand-made) puts the two labels in one category or one in a refinement of the other's (any of
   their categories), else 0 (`category`): siblings (microwave~oven, fork~spoon), two compounds of
   one head sense (bowl~food processor bowl), a kind and a narrower kind (cheese~parmesan). A label
   in no category joins one as `categories --extend` files it (`extend.assign`: its head's category,
   a category's name, else its nearest member's at >= `extend.DEFAULT_MIN_SIMILARITY`), but in the
   categories of all members as near, and by its head only when WordNet knows it as a kind of it
   (`kind_of_head`); a category's own name is in that category; each label on its own, so
   deterministic; a label still in none is not constrained. WordNet says how close two things are;
   the categories say which a cook swaps.
6. A filed label is a kind of its member (`sibling`): a label rule 5 files through one
   member (its head, or its nearest member other than a synonym, similarity < 1) stands
   only with a label whose sense is its own or a WordNet ancestor or descendant of it
   (runcible spoon~spoon), not with a sibling under a third ancestor (sugar spoon~wooden
   spoon, chestnut~walnut): the filing shows what the label is a kind of, not which of
   the category's members a cook swaps it with. A synonym of a member and a label filed
   by a category's name (hickory nut, "nuts and seeds") keep rule 5.
7. A kind of tool for another food is not its generic (`for_another_food`, `purpose.py`): in a pair
   with a label rule 6 holds to its kinds, the narrower kind (its sense below the other's, else the
   compound known by its head: rice cooker~cooker), when a tool, stands only if its name and gloss
   name no food its generic's do not: pot~urn ("a large pot for making coffee or tea"), spoon~tea
   maker, bowl~slop basin score 0; caldron~pot ("a very large pot that is used for boiling") stands.
   A vessel for liquids holds any (`purpose.held`): bottle~wine bottle, drinking glass~schooner stand.
   Labels of the category index keep rule 5 alone (spoon~teaspoon).
8. A filed class is not a substitute for its kinds (`kinds`): a label rule 6 holds to its kinds whose
   sense has at least `CLASS_KINDS` WordNet kinds (saltwater fish: 57) names a class, not a thing a
   recipe uses, and stands with none of its kinds (saltwater fish~tuna, mixed drink~bullshot score 0);
   chop~porkchop (3 kinds) and salad green~lettuce (18) stand. A label that is a category's own name
   and no category's member (cutlery) is a class too, and stands with no label (`bare_category`).
10. A stand-in is one member of its class (`stand_in`): a label WordNet does not know (neither as a whole nor
   by its head) that the overrides read as a class (virgin mojito as `soft_drink.n.01`, dashi as a broth, gyoza as
   a dumpling) is one member of that class: it stands with the class's label and its generics, and with a label
   of its own sense, but not with the class's other kinds (virgin mojito~tonic, dashi~chicken broth,
   gyoza~matzo ball score 0, "stand-in"), nor with a compound known by the class's head (dashi~soup broth, ~vegetable
   broth: kinds of broth, since stop 51). A label WordNet knows by its head (salad mix, a mix of salad greens)
   is read as WordNet reads it and keeps its kinds.
"""

from __future__ import annotations

from collections.abc import Callable

from ..model.foon import normalize_label
from .categories import CategoryIndex
from .classes import food_class, kinds
from .extend import Assignment, file_labels
from .senses import Overrides, resolve, role_senses
from .similarity import Evidence

#: No overrides: how WordNet alone reads a label (rule 10).
WORDNET_ONLY = Overrides({}, {})

#: WordNet kinds from which a label rule 6 holds to its kinds is a class, not a thing a recipe uses (rule 8).
CLASS_KINDS = 30


def kin(index: CategoryIndex, a: str, b: str, of: Callable[[str], tuple[str, ...]] | None = None) -> bool:
    """Whether `index` puts `a` and `b` in one category or one in a refinement of the other's (any of their
    categories, `of(label)`, by default `index.of`); True when either is in none (rule 5)."""
    of = of or index.of
    ca, cb = of(a), of(b)
    if not ca or not cb:
        return True
    return any(x == y or x in index.ancestors(y) or y in index.ancestors(x) for x in ca for y in cb)


class KinRules:
    """Rules 5-8 of the cook's similarity, a mixin of `cook.CookSimilarity` (which sets `reader`, `overrides`,
    `categories`, `extend`, `_filed`, `_filer`, `_wup`, `resolution` and `filer`)."""

    def categories_of(self, label: str) -> tuple[str, ...]:
        """The categories rule 5 reads for `label`: the index's, else the one `categories --extend` would
        file it in (`extend.assign` with this similarity's reader and overrides), else none."""
        assert self.categories is not None
        label = normalize_label(label)
        found = self.categories.of(label)
        if found or not self.extend:
            return found
        if self.categories.is_category(label):  # a category's own name (cutlery), no member of any: that category
            return (label,)
        filed = self.filing(label)
        return (filed.category, *filed.also) if filed is not None and filed.category is not None else ()

    def filing(self, label: str) -> Assignment | None:
        """How rule 5 files `label` (`extend.assign`); None for a label of the index, a member's or a category's
        name (`assign` files neither), or with `extend=False`."""
        assert self.categories is not None
        label = normalize_label(label)
        if self.categories.of(label) or self.categories.is_category(label) or not self.extend:
            return None
        if label not in self._filed:
            if self._filer is None:
                self._filer = self.filer()
            self._filed[label] = file_labels([label], self.categories, self._filer)[0]
        return self._filed[label]

    def kind_of_head(self, label: str, head: str) -> bool:
        """Whether rule 5 may file `label` by its head noun `head`: a whole WordNet term only as a kind of a head
        sense (chili pepper, a capsicum, is no kind of pepper the spice); a label known by its head always."""
        mine = self.resolution(label)
        if mine.modifier is not None or not mine.senses:
            return True
        heads = set(self.resolution(head).senses)
        return any(self._wup.ancestors(s) & heads for s in mine.senses)

    def bare_category(self, label: str) -> bool:
        """Whether `label` is a category's own name and no category's member (cutlery): a class (rule 8)."""
        assert self.categories is not None
        label = normalize_label(label)
        return self.categories.is_category(label) and not self.categories.of(label)

    def kind_only(self, label: str) -> bool:
        """Whether rule 6 holds `label` to its kinds: filed through its head or a nearest member it is not a
        synonym of."""
        filed = self.filing(label) if self.categories is not None else None
        return filed is not None and filed.category is not None and (
            filed.how == "head" or (filed.how == "wordnet" and filed.similarity < 1.0))

    def _kinds(self, a: str, b: str, found: Evidence) -> str:
        """Why rules 6-8 reject a pair with a label rule 6 holds to its kinds ("" when they do not)."""
        if found.ancestor not in (found.sense_a, found.sense_b):
            return "sibling"
        if self.for_another_food(a, b, found):
            return "purpose"
        general = a if found.sense_a == found.ancestor else b
        if found.sense_a != found.sense_b and self.kind_only(general) and (
                kinds(self.reader, found.ancestor) >= CLASS_KINDS
                or (self.filing(general).how == "wordnet" and food_class(self.reader, found.ancestor))):
            return "class"
        return ""

    def for_another_food(self, a: str, b: str, found: Evidence) -> bool:
        """Rule 7: whether the narrower of the kind pair `a`, `b` (`a`'s sense first in `found`) is a tool
        whose name or gloss names a food its generic's does not (`purpose.for_another_food`). The narrower
        is the label whose sense is below the common ancestor, else a compound known by its head (rice
        cooker, a kind of cooker); two synonyms or two compounds of one head have none."""
        from .purpose import for_another_food

        ra, rb = self.resolution(a), self.resolution(b)
        if found.sense_a != found.sense_b:
            narrow_a = found.sense_b == found.ancestor
        elif (ra.modifier is None) != (rb.modifier is None):
            narrow_a = ra.modifier is not None
        else:
            return False
        kind, generic = ((a, found.sense_a), (b, found.sense_b)) if narrow_a else ((b, found.sense_b), (a, found.sense_a))
        if self.reader.synset(kind[1]).lexname() != "noun.artifact":
            return False
        return for_another_food(self.reader, kind[1], generic[1], kind[0], generic[0])

    def stand_in(self, label: str) -> bool:
        """Rule 10: whether the overrides read `label`, which WordNet alone gives no sense (as a whole term or by its
        head), as a class it is one member of (virgin mojito as a soft drink)."""
        if self.resolution(label).source != "override":
            return False
        return not resolve(self.reader, normalize_label(label), WORDNET_ONLY, role_senses, hyphens=True).senses

    def member_as_class(self, a: str, b: str, found: Evidence) -> bool:
        """Rule 10: whether the kind pair `a`, `b` (`a`'s sense first in `found`) puts a stand-in as the generic of
        another kind of its class (virgin mojito~tonic); a label of the stand-in's own sense is no other kind, unless
        a compound known by its head (dashi~soup broth: a kind of broth, as chicken broth is)."""
        if found.sense_a == found.sense_b:
            return (self.stand_in(a) and self.resolution(b).modifier is not None) or (
                self.stand_in(b) and self.resolution(a).modifier is not None)
        return (found.ancestor == found.sense_a and self.stand_in(a)) or (
            found.ancestor == found.sense_b and self.stand_in(b))

