"""Precision and recall of good substitution pairs per similarity mode, on the labelled pairs.

The pairs (`bench/similarity_pairs.tsv`, labelled per `bench/similarity_rubric.md`)
come from the shared subgraphs. A mode accepts a pair when its similarity is at
least the FOON-EXP threshold (0.89). Per mode and split (`independent`, `tune`, all):
precision = good accepted / accepted, recall = good accepted / good, each with a
Wilson 95 % score interval (`fresh`: a second batch labelled after tuning; `held-out`:
it and `independent`; `outside` and `unsampled`: a third batch, every pair either mode
accepts on the search inputs' labels outside the shared subgraphs and on the shared
labels not sampled before, see `similarity_sample.py`; `unseen`: both; the lemma batches `lemmas`,
`lemmas2`, `lemmas3`, `lemmas4`, `lemmas5`, `lemmas6`, `lemmas7`, `lemmas8`, `lemmas9`, `similarity_lemmas.py`).
A pair's value does not depend on the other labels scored (the cook mode's breadth is measured per pair, `cook.py` rule 3).
Also reported per mode: the share of accepted pairs labelled bad.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass
from pathlib import Path

from foon2pddl.generalize.expand import DEFAULT_THRESHOLD
from foon2pddl.generalize.modes import SIMILARITY_MODES, make_similarity
from foon2pddl.model.foon import normalize_label

from .harness import Context

AREA = "similarity"
PAIRS = Path(__file__).with_name("similarity_pairs.tsv")
SPLITS = ("independent", "fresh", "held-out", "outside", "unsampled", "unseen", "lemmas", "lemmas2", "lemmas3",
          "lemmas4", "lemmas5", "lemmas6", "lemmas7", "lemmas8", "lemmas9", "tune", "all")
#: Groups of splits reported together: the held-out batches, and the third batch (`similarity_sample`).
GROUPS = {"held-out": ("independent", "fresh"), "unseen": ("outside", "unsampled")}
Z95 = 1.959963984540054


@dataclass(frozen=True)
class Pair:
    a: str
    b: str
    label: str  # good | marginal | bad
    source: str
    split: str


def read_pairs(path: Path = PAIRS) -> list[Pair]:
    with open(path, encoding="utf-8", newline="") as fh:
        return [Pair(r["label_a"], r["label_b"], r["label"], r["source"], r["split"])
                for r in csv.DictReader(fh, delimiter="\t")]


def wilson(successes: int, n: int, z: float = Z95) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion (0..1 when n is 0)."""
    if n == 0:
        return 0.0, 1.0
    p = successes / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


@dataclass(frozen=True)
class Scores:
    accepted: int
    good_accepted: int
    good: int
    bad_accepted: int

    def precision(self) -> tuple[float, float, float]:
        p = self.good_accepted / self.accepted if self.accepted else 0.0
        return (p, *wilson(self.good_accepted, self.accepted))

    def recall(self) -> tuple[float, float, float]:
        r = self.good_accepted / self.good if self.good else 0.0
        return (r, *wilson(self.good_accepted, self.good))


def score(pairs: list[Pair], accepts) -> Scores:
    """Counts over `pairs` for the predicate `accepts(a, b)`."""
    acc = [p for p in pairs if accepts(p.a, p.b)]
    return Scores(len(acc), sum(p.label == "good" for p in acc), sum(p.label == "good" for p in pairs),
                  sum(p.label == "bad" for p in acc))


def search_labels(shared: Path) -> list[str]:
    """Object, ingredient and container labels of the search inputs (`foon-search-inputs/kitchen.json`
    and `goal_nodes.json`), normalized and sorted: the outside vocabulary of the `outside` split."""
    out: set[str] = set()
    for name in ("kitchen.json", "goal_nodes.json"):
        for item in json.loads((shared / "foon-search-inputs" / name).read_text(encoding="utf-8")):
            out.update(normalize_label(x) for x in [item["label"], *(item.get("ingredients") or []),
                                                     item.get("container") or ""])
    return sorted(out - {""})


def accepted(pairs: list[Pair], mode: str, reader=None):
    """Keys (frozensets) of the pairs `mode` accepts, and the WordNet reader."""
    sim = make_similarity(mode, reader=reader)
    return {frozenset((p.a, p.b)) for p in pairs if sim(p.a, p.b) >= DEFAULT_THRESHOLD}, sim.reader


def run(ctx: Context) -> None:
    from foon2pddl.generalize import wordnet

    pairs = read_pairs()
    reader = wordnet.reader()
    for mode in SIMILARITY_MODES:
        keys, reader = accepted(pairs, mode, reader)
        for split in SPLITS:
            chosen = [p for p in pairs if split == "all" or p.split == split or p.split in GROUPS.get(split, ())]
            s = score(chosen, lambda a, b, keys=keys: frozenset((a, b)) in keys)
            p, plo, phi = s.precision()
            r, rlo, rhi = s.recall()
            note = (f"{len(chosen)} pairs, {s.good} good, {s.accepted} accepted ({s.bad_accepted} bad)")
            ctx.report(AREA, f"{mode} precision ({split})", p, "", f"95 % CI {plo:.2f}-{phi:.2f}; {note}")
            ctx.report(AREA, f"{mode} recall ({split})", r, "", f"95 % CI {rlo:.2f}-{rhi:.2f}")
