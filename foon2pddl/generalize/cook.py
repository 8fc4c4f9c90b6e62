"""The cook's similarity (mode `cook`, the default for substitutions): Wu-Palmer a cook would accept.

The paper's rule (`similarity.LabelSimilarity`, mode `paper`: best Wu-Palmer over all kitchen senses,
banana~cilantro 0.9 through their plant senses). This rule keeps the paper's composition (overrides,
head nouns and modifiers, `similarity.py`) and changes nine things:

1. Senses by role (`role_senses`): a label with a food sense is an ingredient and
   keeps only its food senses; otherwise a label with an artifact sense is a tool or
   container and keeps its artifact senses under `KITCHEN_ARTIFACTS` (all its
   artifact senses when none is); otherwise substances, then the other kitchen senses.
   A pair whose senses are a food and no food stands for nothing (`mixed_roles`: drying oil, a substance
   WordNet files under vegetable oil, is no olive oil).
2. The deepest common ancestor (`WupTable.deepest`): greatest `max_depth`, not NLTK's
   greatest `min_depth`, so lemon~lime as foods meet at `citrus.n.01` (0.917, NLTK 0.75).
3. Broad ancestors rejected: a sense pair whose common ancestor covers more than
   `breadth` of the breadth vocabulary (every label with a sense under it, counted
   once) names a category, not a substitute (container~spoon, baking tray~pot), and
   scores 0. Two labels with the same sense are never rejected. The breadth vocabulary
   is the shipped reference vocabulary (`data/reference_vocabulary.txt`: the object
   labels of the 100 public FOON subgraphs and the example network) plus the pair's own
   two labels, so a pair's value depends neither on how small a network is nor on how
   many kinds of one thing it happens to hold (a matrix of fourteen bottles does not make
   `bottle.n.01` broad). A staple (`staple`: bread, pasta, whose WordNet kinds are mostly
   named or defined after them, `classes.staple`) is never broad with its kinds, unless it is
   a dish, a bake or a flavorer (`classes.NOT_STAPLES`: sauce, cake) or a compound known by its head.

4. Variants (dish compounds) are not substitutes (`variant`); a stock (`INGREDIENTS`:
   `broth.n.01`, which WordNet files under soup but defines as the liquid soups and
   sauces are made from) is an ingredient, so vegetable broth~broth stands; a modifier
   WordNet tags mostly as an adjective (`senses.adjective`: green) is no food.
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
9. A class of tools is no tool (`tool_class`): a kind pair whose generic is an artifact sense with at least
   `TOOL_CLASS_KINDS` WordNet kinds, fewer than `NAMED_SHARE` of them named after it (`named_kinds`), scores 0:
   the kinds of kitchen appliance (oven, toaster, food processor), drinking vessel (mug, tankard) or flatware
   (plate, saucer) go by names of their own and do different jobs; a bottle's kinds are mostly called bottles
   (beer bottle, water bottle: 35 %) and a bottle stands for them. Every label, filed or in the index.

Senses are read as in the paper's rule, but a hyphenated WordNet lemma is read whole
(`senses.resolve(hyphens=True)`: iced-tea spoon is iced-tea_spoon, a kind of teaspoon).

The overrides (`data/cook_overrides.json`, `senses.parse_overrides` with `forbidden` pairs) fix
senses (mint the herb; pepper the spice, as the index files it) and forbid pairs WordNet puts close
that no cook swaps; a user file extends them. Cost: per sense pair one `deepest` call.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from functools import lru_cache
from importlib import resources
from pathlib import Path

from ..model.foon import normalize_label
from .cache import digest
from .categories import CategoryIndex, index_path, shipped_index
from .classes import food_class, kinds, staple, tool_class
from .extend import Assignment, file_labels
from .senses import Overrides, Resolution, adjective, mixed_roles, parse_overrides, resolve, role_senses
from .similarity import Evidence

#: Default share of the breadth vocabulary above which a common ancestor is a category (see docs).
DEFAULT_BREADTH = 0.02

#: WordNet kinds from which a label rule 6 holds to its kinds is a class, not a thing a recipe uses (rule 8).
CLASS_KINDS = 30

#: Dishes: their kinds are variants of them (rule 4), so no dish is a staple (rule 3's exemption).
DISH = "dish.n.02"

#: Prepared foods: a compound under one of these is a recipe's own dish, drink or bake (rule 4).
PREPARED: frozenset[str] = frozenset({DISH, "baked_goods.n.01", "beverage.n.01"})

#: Prepared foods that recipes use as ingredients (rule 4): stock and broth (under soup in WordNet).
INGREDIENTS: frozenset[str] = frozenset({"broth.n.01"})


def _data(name: str) -> Path:
    return Path(str(resources.files("foon2pddl") / "generalize" / "data" / name))


def cook_overrides_path() -> Path:
    return _data("cook_overrides.json")


@lru_cache(maxsize=1)
def cook_overrides() -> Overrides:
    """The shipped overrides of the cook's similarity."""
    p = cook_overrides_path()
    return parse_overrides(p.read_text(encoding="utf-8"), str(p))


@lru_cache(maxsize=1)
def reference_vocabulary() -> tuple[str, ...]:
    """The shipped breadth vocabulary, sorted."""
    text = _data("reference_vocabulary.txt").read_text(encoding="utf-8")
    return tuple(sorted({normalize_label(x) for x in text.splitlines()} - {""}))


@lru_cache(maxsize=1)
def _index_text() -> str:
    return index_path().read_text(encoding="utf-8")


def cache_tag(breadth: float, overrides: Overrides) -> str:
    """What a cook matrix depends on beyond its labels (with the shipped category index and reference
    vocabulary), computable without WordNet."""
    return "cook " + digest(repr(breadth), "\n".join(reference_vocabulary()), overrides.text, _index_text(), RULES)


#: The version of the rules, part of a cached matrix's key ("extended": rule 5 files unknown labels; rule 6).
RULES = ("rule 5 extended, rule 6, rule 7, rule 8, bare categories, hyphens, adjective modifiers, head kinds, ties,"
         " vessels hold liquids, breadth per pair, tool classes, staples, roles, regional senses, vessels named for food, food classes, starches")


def kin(index: CategoryIndex, a: str, b: str, of: Callable[[str], tuple[str, ...]] | None = None) -> bool:
    """Whether `index` puts `a` and `b` in one category or one in a refinement of the other's (any of their
    categories, `of(label)`, by default `index.of`); True when either is in none (rule 5)."""
    of = of or index.of
    ca, cb = of(a), of(b)
    if not ca or not cb:
        return True
    return any(x == y or x in index.ancestors(y) or y in index.ancestors(x) for x in ca for y in cb)


class CookSimilarity:
    """The cook's label similarity (module doc); same interface as `similarity.LabelSimilarity`."""

    mode = "cook"

    def __init__(self, reader=None, overrides: Overrides | None = None, *, breadth: float = DEFAULT_BREADTH, categories: bool | CategoryIndex = True, extend: bool = True
                 ) -> None:
        """`categories=False` drops rule 5 (extending the category index must not read the index it extends);
        an index replaces the shipped one; `extend=False` leaves a label in no category unconstrained."""
        from . import wordnet
        from .wup import WupTable

        self.reader = reader if reader is not None else wordnet.reader()
        self.overrides = overrides if overrides is not None else cook_overrides()
        self.breadth = breadth
        self.vocabulary = reference_vocabulary()
        self._reference = frozenset(self.vocabulary)
        self.tag = cache_tag(breadth, self.overrides)
        self._wup = WupTable(self.reader)
        self._resolved: dict[str, Resolution] = {}
        self._evidence: dict[tuple[str, str], Evidence] = {}
        self._modifier_evidence: dict[tuple[str, str], Evidence] = {}
        self._cover: dict[str, int] | None = None
        self.categories: CategoryIndex | None = (
            categories if isinstance(categories, CategoryIndex) else shipped_index() if categories else None)
        self._filed: dict[str, Assignment] = {}
        self._filer: CookSimilarity | None = None
        self.extend = extend

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
                self._filer = filing_similarity(self.reader, self.overrides)
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

    def resolution(self, label: str) -> Resolution:
        label = normalize_label(label)
        found = self._resolved.get(label)
        if found is None:
            found = self._resolved[label] = resolve(self.reader, label, self.overrides, role_senses, hyphens=True)
        return found

    def coverage(self, ancestor: str, labels: Iterable[str] = ()) -> float:
        """Share of the breadth vocabulary, the reference vocabulary joined by `labels` (the pair's own), with a
        sense under synset `ancestor` (itself included)."""
        if self._cover is None:
            counts: dict[str, int] = {}
            for label in self.vocabulary:
                for x in self._under(label):
                    counts[x] = counts.get(x, 0) + 1
            self._cover = counts
        extra = {normalize_label(x) for x in labels} - self._reference
        return (self._cover.get(ancestor, 0) + sum(ancestor in self._under(x) for x in extra)) / (
            len(self.vocabulary) + len(extra))

    def _under(self, label: str) -> frozenset[str]:
        """Every synset some sense of `label` is, or is below."""
        return frozenset().union(*(self._wup.ancestors(s) for s in self.resolution(label).senses))

    def variant(self, r: Resolution) -> bool:
        """Whether a label known by its head noun is a recipe's preparation (rule 4): a food whose head is a
        prepared food (`PREPARED`), or whose modifier ends in a food (garlic-parmesan chicken) or a past
        participle (barbecued ribs); never a stock or broth (`INGREDIENTS`: vegetable broth). A modifier WordNet
        tags more often as an adjective (`adjective`: green) describes the food and is no food itself."""
        if not r.senses or not all(k == "noun.food" for k in r.lexnames):
            return False
        if any(self._wup.ancestors(x) & INGREDIENTS for x in r.senses):
            return False
        last = (r.modifier or "").split()[-1:]
        if last and last[0].endswith("ed") and self.reader.morphy(last[0], "v") not in (None, last[0]):
            return True
        if last and not adjective(self.reader, last[0]) and any(
                s.lexname() == "noun.food" for s in self.reader.synsets(last[0], "n")):
            return True
        return any(self._wup.ancestors(x) & PREPARED for x in r.senses)

    def __call__(self, a: str, b: str) -> float:
        return self.explain(a, b).similarity

    def explain(self, a: str, b: str) -> Evidence:
        """The similarity of `a` and `b` with the sense pair and ancestor it comes from (symmetric)."""
        a, b = sorted((normalize_label(a), normalize_label(b)))
        if a == b:
            return Evidence(1.0, rejected="same")
        found = self._evidence.get((a, b))
        if found is None:
            found = self._compute(a, b)
            if found.similarity and not found.rejected and self.categories is not None:
                if mixed_roles(self.reader, found.sense_a, found.sense_b):  # rule 1: an ingredient and no ingredient
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "role")
                elif self.bare_category(a) or self.bare_category(b):  # rule 8: a class stands with nothing
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "class")
                elif not kin(self.categories, a, b, self.categories_of):
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "category")
                elif self.kind_only(a) or self.kind_only(b):
                    why = self._kinds(a, b, found)
                    if why:
                        found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, why)
            if found.similarity and not found.rejected and self.categories is not None and tool_class(self.reader, found):
                found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "tool class")
            self._evidence[(a, b)] = found
        return found

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

    def staple(self, sense: str, other: str, lcs: str, label: str) -> bool:
        """Rule 3's exemption: whether the kind pair `sense`~`other` (`lcs` one of them) has a generic that is a
        staple, not a class: `label` (the generic's) a whole WordNet term and `classes.staple` (bread, pasta; no
        dish, bake or flavorer: a dish's kinds are variants of it, rule 4)."""
        if lcs not in (sense, other) or self.resolution(label).modifier is not None:
            return False
        return staple(self.reader, lcs)

    def _modifiers(self, a: str, b: str) -> Evidence:
        """The similarity of two modifiers (rules 1-4: a modifier is no object label, so no categories)."""
        a, b = sorted((a, b))
        if a == b:
            return Evidence(1.0, rejected="same")
        found = self._modifier_evidence.get((a, b))
        if found is None:
            found = self._modifier_evidence[(a, b)] = self._compute(a, b)
        return found

    def _compute(self, a: str, b: str) -> Evidence:
        fixed = self.overrides.pair(a, b)
        if fixed is not None:
            return Evidence(fixed, rejected="fixed")
        if self.overrides.forbids(a, b):
            return Evidence(0.0, rejected="forbidden")
        ra, rb = self.resolution(a), self.resolution(b)
        if not ra.senses or not rb.senses:
            return Evidence(0.0, rejected="unknown")
        if ra.modifier is None and rb.modifier is None:
            return self._best(ra.senses, rb.senses, 0, (a, b))
        if (ra.modifier is None) != (rb.modifier is None) and self.variant(ra if ra.modifier is not None else rb):
            return Evidence(0.0, rejected="variant")
        if ra.modifier is not None and rb.modifier is not None:
            heads = self._best(ra.senses, rb.senses, 0, (a, b))
            mod = self._modifiers(ra.modifier, rb.modifier)
            if mod.rejected not in ("", "fixed", "same") and heads.similarity:  # same modifier: the heads decide
                return Evidence(0.0, mod.ancestor, mod.sense_a, mod.sense_b, mod.breadth, mod.rejected)
            return Evidence(heads.similarity * mod.similarity, heads.ancestor, heads.sense_a, heads.sense_b,
                            heads.breadth, heads.rejected)
        return self._best(ra.senses, rb.senses, 1, (a, b))

    def _best(self, senses_a: tuple[str, ...], senses_b: tuple[str, ...], extra: int, labels: tuple[str, str]
              ) -> Evidence:
        """Greatest accepted value over sense pairs (then first in WordNet order); the best rejected one
        explains a 0. `extra` links are added below one side (a compound under its head); `labels` (the
        pair's) join the breadth vocabulary."""
        best = Evidence(0.0)
        broad = None
        for s in senses_a:
            for t in senses_b:
                found = self._wup.deepest(*sorted((s, t)))
                if found is None:
                    continue
                lcs, depth, la, lb = found
                value = 2.0 * depth / (la + lb + 2 * depth + extra)
                share = self.coverage(lcs, labels)
                if s != t and share > self.breadth and not self.staple(s, t, lcs, labels[0] if lcs == s else labels[1]):
                    if broad is None or value > broad.similarity:
                        broad = Evidence(value, lcs, s, t, share, "broad")
                elif value > best.similarity:
                    best = Evidence(value, lcs, s, t, share)
        if best.similarity == 0.0 and broad is not None:
            return Evidence(0.0, broad.ancestor, broad.sense_a, broad.sense_b, broad.breadth, "broad")
        return best


def filing_similarity(reader=None, overrides: Overrides | None = None) -> CookSimilarity:
    """The similarity unknown labels are filed by (`extend.assign`, `categories --extend`, rule 5): the cook
    mode's senses and deepest common ancestor, no breadth rejection (a category is meant to be broad) and no
    category rule (it would read the index being extended)."""
    return CookSimilarity(reader, overrides, breadth=1.0, categories=False)
