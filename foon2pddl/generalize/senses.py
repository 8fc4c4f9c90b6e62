"""Which WordNet noun senses an object label stands for.

A label is looked up as one WordNet term (`corn starch` -> `corn_starch`, then
`cornstarch`; NLTK's morphy maps plurals), keeping only senses in the
kitchen-relevant lexicographer files (`KITCHEN_LEXNAMES`: with all senses,
"kale" and "lettuce" meet in a money-slang synset). A compound WordNet lacks
falls back to its head noun: leading words are dropped until the rest is a term
(`blueberry muffin` -> head `muffin`, modifier `blueberry`). The overrides file
(`generalize/data/similarity_overrides.json`) names the senses of labels WordNet
lacks or gets wrong, and fixes the similarity of particular pairs. The cook similarity
keeps the senses of a label's role (`role_senses`: food, else kitchen artifact, ...).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources
from pathlib import Path

from ..errors import FoonInputError, FoonSyntaxError
from ..io.json_text import key_line, load_json, unknown_key

#: Lexicographer files whose noun senses can name a kitchen object.
KITCHEN_LEXNAMES: frozenset[str] = frozenset(
    {"noun.food", "noun.plant", "noun.animal", "noun.artifact", "noun.substance", "noun.object"}
)

#: Senses of living things, dropped for tools and vessels (see `kitchen_senses`).
LIVING: frozenset[str] = frozenset({"noun.plant", "noun.animal"})

_SPLIT = re.compile(r"[\s\-_]+")
#: The keys of an overrides file (`_comment`: a note for its readers).
OVERRIDE_KEYS = ("senses", "pairs", "forbidden", "_comment")


def overrides_path() -> Path:
    """The shipped overrides file."""
    return Path(str(resources.files("foon2pddl") / "generalize" / "data" / "similarity_overrides.json"))


@dataclass(frozen=True)
class Overrides:
    """Senses for labels WordNet lacks (label -> synset names) and fixed pair similarities."""

    senses: dict[str, tuple[str, ...]]
    pairs: dict[frozenset[str], float]
    text: str = ""  # the file's content, part of the similarity cache key
    forbidden: frozenset[frozenset[str]] = frozenset()  # pairs never substituted (similarity 0)
    origin: dict[str, str] = field(default_factory=dict, compare=False)  # label -> file naming its senses

    def pair(self, a: str, b: str) -> float | None:
        return self.pairs.get(frozenset((a, b)))

    def forbids(self, a: str, b: str) -> bool:
        return frozenset((a, b)) in self.forbidden

    def extended(self, other: Overrides) -> Overrides:
        """These overrides with `other`'s added (its senses and pair values win)."""
        return Overrides({**self.senses, **other.senses}, {**self.pairs, **other.pairs},
                         self.text + "\n" + other.text, self.forbidden | other.forbidden,
                         {**self.origin, **other.origin})


def parse_overrides(text: str, path: str) -> Overrides:
    """Read `{"senses": {label: [synset, ...]}, "pairs": [[a, b, value], ...], "forbidden": [[a, b], ...]}`
    (every key optional, `_comment` a note); errors name the file, and the line of an unknown or repeated key."""
    data = load_json(text, path)
    if isinstance(data, dict) and (bad := unknown_key(data, OVERRIDE_KEYS)) is not None:
        raise FoonSyntaxError(path, key_line(text, bad[0]), bad[1])
    if not isinstance(data, dict) or not isinstance(data.get("senses", {}), dict) \
            or not isinstance(data.get("pairs", []), list):
        raise FoonInputError(path, 0, "expected {\"senses\": {label: [synset, ...]}, \"pairs\": [[a, b, value], ...]}")
    senses: dict[str, tuple[str, ...]] = {}
    for label, names in data.get("senses", {}).items():
        if not isinstance(names, list) or not names or not all(isinstance(n, str) for n in names):
            raise FoonInputError(path, 0, f"senses of {label!r}: expected a non-empty list of synset names")
        senses[_key(label)] = tuple(names)
    pairs: dict[frozenset[str], float] = {}
    for item in data.get("pairs", []):
        if not (isinstance(item, list) and len(item) == 3 and all(isinstance(x, str) for x in item[:2])
                and isinstance(item[2], int | float) and 0 <= item[2] <= 1):
            raise FoonInputError(path, 0, f"pair {item!r}: expected [label, label, value in 0..1]")
        pairs[frozenset((_key(item[0]), _key(item[1])))] = float(item[2])
    forbidden = data.get("forbidden", [])
    if not isinstance(forbidden, list) or not all(
            isinstance(x, list) and len(x) == 2 and all(isinstance(y, str) and y.strip() for y in x) for x in forbidden):
        raise FoonInputError(path, 0, "forbidden: expected a list of [label, label] pairs")
    return Overrides(senses, pairs, text, frozenset(frozenset((_key(a), _key(b))) for a, b in forbidden),
                     dict.fromkeys(senses, path))


@lru_cache(maxsize=1)
def shipped_overrides() -> Overrides:
    """The overrides shipped with the package."""
    p = overrides_path()
    return parse_overrides(p.read_text(encoding="utf-8"), str(p))


def _key(label: str) -> str:
    return " ".join(w for w in _SPLIT.split(label.lower()) if w)


@dataclass(frozen=True)
class Resolution:
    """The senses a label stands for: synset names, the term found, and a modifier when a head was used."""

    label: str
    senses: tuple[str, ...]
    term: str = ""
    modifier: str | None = None  # dropped leading words when only the head noun was found
    source: str = "wordnet"  # wordnet | head | override | none
    lexnames: tuple[str, ...] = ()  # lexicographer file of each sense

    def describe(self) -> str:
        if not self.senses:
            return f"{self.label}: no kitchen sense in WordNet"
        via = {"head": f" (head noun {self.term!r}, modifier {self.modifier!r})", "override": " (override)"}
        return f"{self.label}: {', '.join(self.senses)}{via.get(self.source, '')}"


def kitchen_senses(reader, term: str) -> dict[str, str]:
    """Noun senses of `term` in kitchen-relevant lexicographer files (name -> file), in WordNet order.

    A tool or vessel (a term with artifact senses and no food sense) drops its plant and
    animal senses: `box` the container is not the box shrub that is similar to blueberries.
    """
    found = {s.name(): s.lexname() for s in reader.synsets(term, "n") if s.lexname() in KITCHEN_LEXNAMES}
    kinds = set(found.values())
    if "noun.artifact" in kinds and "noun.food" not in kinds:
        found = {n: k for n, k in found.items() if k not in LIVING}
    return found


def _override(reader, label: str, names: tuple[str, ...], term: str, modifier: str | None, source: str,
              path: str = "") -> Resolution:
    from nltk.corpus.reader.wordnet import WordNetError

    try:
        kinds = tuple(reader.synset(n).lexname() for n in names)
    except (WordNetError, ValueError) as exc:
        raise FoonInputError(path or str(overrides_path()), 0, f"senses of {term!r}: {exc}") from None
    return Resolution(label, names, term, modifier, source, kinds)


def resolve(reader, label: str, overrides: Overrides, senses_of=kitchen_senses, *, hyphens: bool = False
            ) -> Resolution:
    """The senses of `label`: override, whole term (`a_b`, then `ab`), else head noun with a modifier.

    `senses_of(reader, term)` picks a term's senses (name -> lexicographer file). `hyphens` (the cook mode)
    tries the whole term with its hyphens first (`iced-tea_spoon`, `patty-pan`: WordNet lemmas that would
    otherwise be found only by their heads, spoon and pan); the paper's rule reads `iced tea spoon`.
    """
    key = _key(label)
    if key in overrides.senses:
        return _override(reader, label, overrides.senses[key], key, None, "override", overrides.origin.get(key, ""))
    words = key.split()
    if not words:
        return Resolution(label, (), "", None, "none")
    hyphenated = ("_".join(label.lower().split()),) if hyphens and "-" in label else ()
    for term in dict.fromkeys((*hyphenated, "_".join(words), "".join(words))):
        found = senses_of(reader, term)
        if found:
            return Resolution(label, tuple(found), term, None, "wordnet", tuple(found.values()))
    for i in range(1, len(words)):
        head, modifier = " ".join(words[i:]), " ".join(words[:i])
        if head in overrides.senses:
            return _override(reader, label, overrides.senses[head], head, modifier, "head",
                             overrides.origin.get(head, ""))
        found = senses_of(reader, "_".join(words[i:]))
        if found:
            return Resolution(label, tuple(found), "_".join(words[i:]), modifier, "head", tuple(found.values()))
    return Resolution(label, (), "", None, "none")


@lru_cache(maxsize=4096)
def adjective(reader, word: str) -> bool:
    """Whether WordNet tags `word` more often as an adjective than as a noun (its lemmas' sense counts in the
    tagged corpus): `green` 26 to 7 is an adjective, `peanut` and `garlic` (no tags) are not (the cook similarity's rule 4).
    Kept per word: nltk searches the count file on disk for each lemma's count, and a matrix asks of the same
    few modifiers tens of thousands of times."""
    def tags(pos: str) -> int:
        return sum(x.count() for s in reader.synsets(word, pos) for x in s.lemmas() if x.name().lower() == word)
    return tags("a") > tags("n")


#: Artifact synsets under which a tool or container sense is a kitchen one.
KITCHEN_ARTIFACTS: frozenset[str] = frozenset({
    "container.n.01", "implement.n.01", "device.n.01", "tableware.n.01", "home_appliance.n.01",
    "kitchen_appliance.n.01", "furniture.n.01", "covering.n.02", "crockery.n.01", "cutlery.n.02",
    "wrapping.n.01", "sheet.n.06", "utensil.n.01", "vessel.n.03",
})


def mixed_roles(reader, sense_a: str, sense_b: str) -> bool:
    """Whether one of two senses is a food (an ingredient's, `role_senses`) and the other is not: the cook
    similarity's pairs stand within one role (drying oil, a substance, is no olive oil)."""
    foods = [reader.synset(x).lexname() == "noun.food" for x in (sense_a, sense_b) if x]
    return len(foods) == 2 and foods[0] != foods[1]


def role_senses(reader, term: str) -> dict[str, str]:
    """Senses of `term` for the role it plays: food, else kitchen artifact (under `KITCHEN_ARTIFACTS`, all its
    artifact senses when none is), else substance, else any (the cook similarity's rule 1, `cook.py`); of those,
    the senses WordNet marks with no region when some are (`regional`: biscuit the quick bread, not the British
    cookie)."""
    found = kitchen_senses(reader, term)
    for kind in ("noun.food", "noun.artifact", "noun.substance"):
        picked = {n: k for n, k in found.items() if k == kind}
        if kind == "noun.artifact" and picked:
            kitchen = {n: k for n, k in picked.items() if _under(reader, n, KITCHEN_ARTIFACTS)}
            picked = kitchen or picked
        if picked:
            return _unregional(reader, picked)
    return _unregional(reader, found)


def regional(reader, name: str) -> bool:
    """Whether WordNet files synset `name` under a region (`cookie.n.01`: "`biscuit' is the British term")."""
    return bool(reader.synset(name).region_domains())


def _unregional(reader, senses: dict[str, str]) -> dict[str, str]:
    """`senses` but those WordNet marks as regional, unless all are: a FOON is read in no region's usage."""
    plain = {n: k for n, k in senses.items() if not regional(reader, n)}
    return plain or senses


def _under(reader, name: str, roots: frozenset[str]) -> bool:
    seen, stack = set(), [reader.synset(name)]
    while stack:
        s = stack.pop()
        if s.name() in roots:
            return True
        for h in s.hypernyms() + s.instance_hypernyms():
            if h.name() not in seen:
                seen.add(h.name())
                stack.append(h)
    return False
