"""The cook's similarity (mode `cook`, the default for substitutions): Wu-Palmer a cook would accept.

The paper's rule (`similarity.LabelSimilarity`, mode `paper`: best Wu-Palmer over all kitchen senses,
banana~cilantro 0.9 through their plant senses). This rule keeps the paper's composition (overrides,
head nouns and modifiers, `similarity.py`) and changes ten things:

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
   scores 0. Two labels with the same sense are never rejected, by no rule (`synonyms`). The breadth vocabulary
   is the shipped reference vocabulary (`data/reference_vocabulary.txt`: the object
   labels of the 100 public FOON subgraphs and the example network) plus the pair's own
   two labels, so a pair's value depends neither on how small a network is nor on how
   many kinds of one thing it happens to hold (a matrix of fourteen bottles does not make
   `bottle.n.01` broad). A staple (`staple`: bread, pasta, whose WordNet kinds are mostly
   named or defined after them, `classes.staple`) is never broad with its kinds, unless it is
   a dish, a bake or a flavorer (`classes.NOT_STAPLES`: sauce, cake) or a compound known by its head. Nor are two
   senses WordNet defines one by the other (`classes.likened`: coriander, a "parsley-like herb"), nor, in two
   compounds of one head sense, two tool modifiers (pan lid~pot lid: what one thing fits, not what a cook swaps).

4. Variants (dish compounds) are not substitutes (`variant`), nor are two senses of prepared foods (`dishes`,
   under `NUTRIMENT`: club sandwich~wrap, sandwich~hamburger, buckeye candy~fudge); a stock (`INGREDIENTS`:
   `broth.n.01`, `broth.n.02`, which WordNet files under soup but defines as the liquid soups and
   sauces are made from) is an ingredient, so vegetable broth~broth stands; a modifier
   WordNet tags mostly as an adjective (`senses.adjective`: green) is no food.
5-8, 10. Kin (`cook_kin.py`): the category index's kin, a filed label with its kinds, a kind of tool for
   another food, a filed class; a label WordNet does not know, read as a class by an override, is one member of it.
9. A class of tools is no tool (`tool_class`): a kind pair whose generic is an artifact sense with at least
   `TOOL_CLASS_KINDS` WordNet kinds, fewer than `NAMED_SHARE` of them named after it (`named_kinds`), scores 0:
   the kinds of kitchen appliance (oven, toaster, food processor), drinking vessel (mug, tankard) or flatware
   (plate, saucer) go by names of their own and do different jobs; a bottle's kinds are mostly called bottles
   (beer bottle, water bottle: 35 %) and a bottle stands for them. Two kinds that meet only under such a class do
   different jobs (knife~scissors, scraper~spatula). Every label, filed or in the index. So for
   foods (`food class`): a kind pair whose generic is a food class whose kinds are classes too
   (`classes.food_class_of_classes`: salad mix~lettuce) is a category with a member; not a flavorer, a class WordNet
   defines by its job (`classes.flavorer_class`: sweetener~sugar stands, stop 54).

Senses are read as in the paper's rule, but a hyphenated WordNet lemma is read whole
(`senses.resolve(hyphens=True)`: iced-tea spoon is iced-tea_spoon, a kind of teaspoon).

The overrides (`data/cook_overrides.json`, `senses.parse_overrides` with `forbidden` pairs) fix
senses (mint the herb; pepper the spice, as the index files it) and forbid pairs WordNet puts close
that no cook swaps; a user file extends them. Cost: per sense pair one `deepest` call.
"""

from __future__ import annotations

from collections.abc import Iterable
from functools import lru_cache
from importlib import resources
from pathlib import Path

from ..model.foon import normalize_label
from .cache import digest
from .categories import CategoryIndex, index_path, shipped_index
from .classes import food_class_of_classes, likened, staple, tool_class
from .cook_kin import KinRules, kin
from .extend import Assignment
from .senses import Overrides, Resolution, adjective, mixed_roles, parse_overrides, resolve, role_senses
from .similarity import Evidence

#: Default share of the breadth vocabulary above which a common ancestor is a category (see docs).
DEFAULT_BREADTH = 0.02

#: Dishes: their kinds are variants of them (rule 4), so no dish is a staple (rule 3's exemption).
DISH = "dish.n.02"

#: What is eaten as prepared (WordNet splits food into foodstuffs, the ingredients, and nutriment: dishes, courses,
#: sweets, meals): two senses that meet under it are variants of one another (rule 4, `dishes`).
NUTRIMENT = "nutriment.n.01"

#: Prepared foods: a compound under one of these is a recipe's own dish, drink or bake (rule 4).
PREPARED: frozenset[str] = frozenset({DISH, "baked_goods.n.01", "beverage.n.01"})

#: Prepared foods that recipes use as ingredients (rule 4): stock and broth (under soup in WordNet; `broth.n.02`, "a
#: thin soup of meat or fish or vegetable stock", holds bouillon and consomme).
INGREDIENTS: frozenset[str] = frozenset({"broth.n.01", "broth.n.02"})


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
         " vessels hold liquids, breadth per pair, tool classes, staples, roles, regional senses, vessels named for food, food classes, starches, stand-ins, synonyms,"
         " dishes, food classes of classes, stand-ins and head compounds, tool class siblings, prepared foods, likeness,"
         " tools one part fits, flavorer classes")


def synonyms(found: Evidence) -> bool:
    """Whether `found` reads two whole terms as one sense (club soda, soda water: `soda_water.n.01`): synonyms name
    one thing and stand whatever the categories say (rules 5-10 judge two things). A compound known by its head
    shares the head's sense at a value below 1 (bowl~food processor bowl) and is no synonym."""
    return found.similarity == 1.0 and found.sense_a is not None and found.sense_a == found.sense_b


class CookSimilarity(KinRules):
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

    def filer(self) -> CookSimilarity:
        """The similarity rule 5 files unknown labels by (`filing_similarity`, same reader and overrides)."""
        return filing_similarity(self.reader, self.overrides)

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

    def dishes(self, sense: str, other: str, lcs: str) -> bool:
        """Rule 4 for whole terms: whether two senses meet under a prepared food (`NUTRIMENT`: a dish, a course, a
        sweet; club sandwich and wrap under sandwich, buckeye candy and fudge under candy, a sandwich and its kind),
        neither a stock (`INGREDIENTS`). A prepared food's kinds are variants of it whether named by a compound
        (greek salad) or by a word of their own (club sandwich). Only with the categories (rule 5 on): the filing
        similarity groups dishes."""
        if self.categories is None or sense == other or NUTRIMENT not in self._wup.ancestors(lcs):
            return False
        return not any(self._wup.ancestors(x) & INGREDIENTS for x in (sense, other))

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
            if found.similarity and not found.rejected and self.categories is not None and not synonyms(found):
                if mixed_roles(self.reader, found.sense_a, found.sense_b):  # rule 1: an ingredient and no ingredient
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "role")
                elif self.bare_category(a) or self.bare_category(b):  # rule 8: a class stands with nothing
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "class")
                elif not kin(self.categories, a, b, self.categories_of):
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "category")
                elif self.member_as_class(a, b, found):  # rule 10: a stand-in is one member of its class
                    found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "stand-in")
                elif self.kind_only(a) or self.kind_only(b):
                    why = self._kinds(a, b, found)
                    if why:
                        found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, why)
            if found.similarity and not found.rejected and self.categories is not None and tool_class(self.reader, found):
                found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "tool class")
            elif found.similarity and not found.rejected and self.categories is not None and food_class_of_classes(
                    self.reader, found):
                found = Evidence(0.0, found.ancestor, found.sense_a, found.sense_b, found.breadth, "food class")
            self._evidence[(a, b)] = found
        return found

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

    def _compute(self, a: str, b: str, breadth: float | None = None) -> Evidence:
        """Rules 1-4 for `a`, `b` (sorted); `breadth` replaces the mode's (rule 3 for two tools one part fits)."""
        fixed = self.overrides.pair(a, b)
        if fixed is not None:
            return Evidence(fixed, rejected="fixed")
        if self.overrides.forbids(a, b):
            return Evidence(0.0, rejected="forbidden")
        ra, rb = self.resolution(a), self.resolution(b)
        if not ra.senses or not rb.senses:
            return Evidence(0.0, rejected="unknown")
        if ra.modifier is None and rb.modifier is None:
            return self._best(ra.senses, rb.senses, 0, (a, b), breadth)
        if (ra.modifier is None) != (rb.modifier is None) and self.variant(ra if ra.modifier is not None else rb):
            return Evidence(0.0, rejected="variant")
        if ra.modifier is not None and rb.modifier is not None:
            heads = self._best(ra.senses, rb.senses, 0, (a, b))
            mod = self._modifiers(ra.modifier, rb.modifier)
            if mod.rejected == "broad" and heads.sense_a is not None and heads.sense_a == heads.sense_b and all(
                    self.reader.synset(x).lexname() == "noun.artifact" for x in (mod.sense_a, mod.sense_b)):
                mod = self._compute(*sorted((ra.modifier, rb.modifier)), breadth=1.0)  # what one thing fits
            if mod.rejected not in ("", "fixed", "same") and heads.similarity:  # same modifier: the heads decide
                return Evidence(0.0, mod.ancestor, mod.sense_a, mod.sense_b, mod.breadth, mod.rejected)
            return Evidence(heads.similarity * mod.similarity, heads.ancestor, heads.sense_a, heads.sense_b,
                            heads.breadth, heads.rejected)
        return self._best(ra.senses, rb.senses, 1, (a, b), breadth)

    def _best(self, senses_a: tuple[str, ...], senses_b: tuple[str, ...], extra: int, labels: tuple[str, str],
              breadth: float | None = None) -> Evidence:
        """Greatest accepted value over sense pairs (then first in WordNet order), no pair too broad (rule 3: unless
        a staple with its kind or `likened`, WordNet defining one as like the other) or of two dishes (rule 4); the
        best rejected one explains a 0. `extra` links are added below one side (a compound under its head); `labels`
        (the pair's) join the breadth vocabulary; `breadth` replaces the mode's."""
        best = Evidence(0.0)
        rejected = None
        for s in senses_a:
            for t in senses_b:
                found = self._wup.deepest(*sorted((s, t)))
                if found is None:
                    continue
                lcs, depth, la, lb = found
                value = 2.0 * depth / (la + lb + 2 * depth + extra)
                share = self.coverage(lcs, labels)
                why = ("broad" if s != t and share > (self.breadth if breadth is None else breadth)
                       and not self.staple(s, t, lcs, labels[0] if lcs == s else labels[1])
                       and not likened(self.reader, s, t)
                       else "dishes" if self.dishes(s, t, lcs) else "")
                if why:
                    if rejected is None or value > rejected.similarity:
                        rejected = Evidence(value, lcs, s, t, share, why)
                elif value > best.similarity:
                    best = Evidence(value, lcs, s, t, share)
        if best.similarity == 0.0 and rejected is not None:
            return Evidence(0.0, rejected.ancestor, rejected.sense_a, rejected.sense_b, rejected.breadth, rejected.rejected)
        return best


def filing_similarity(reader=None, overrides: Overrides | None = None) -> CookSimilarity:
    """The similarity unknown labels are filed by (`extend.assign`, `categories --extend`, rule 5): the cook
    mode's senses and deepest common ancestor, no breadth rejection (a category is meant to be broad) and no
    category rule (it would read the index being extended)."""
    return CookSimilarity(reader, overrides, breadth=1.0, categories=False)
