"""A second, blind labelling of the shared subgraphs' pairs: the modes scored on it, and its agreement with the first.

`bench/similarity_relabel.tsv` relabels every pair of the `independent`, `fresh`, `tune` and `unsampled`
splits of `similarity_pairs.tsv` (the shared subgraphs' labels), by a labeller who had not seen the rules
or the first labels (`similarity_rubric.md`, its last addendum). Reported: per mode, precision and recall
of good pairs over the second labels, with Wilson 95 % intervals (`similarity.score`, the same counting as
area `similarity`); then the agreement of the two labellings on the same pairs: the share of pairs with
the same label, Cohen's kappa over good / marginal / bad, and the 3x3 confusion table (first label by row).
"""

from __future__ import annotations

import csv
from collections import Counter
from pathlib import Path

from .harness import Context
from .similarity import Pair, accepted, read_pairs, score

AREA = "similarity_relabel"
RELABEL = Path(__file__).with_name("similarity_relabel.tsv")
#: The splits the second labelling covers (the shared subgraphs' labels).
RELABELLED = ("independent", "fresh", "tune", "unsampled")
LABELS = ("good", "marginal", "bad")


def read_relabel(path: Path = RELABEL) -> list[Pair]:
    """The second labels, as pairs of source `relabel` and split `relabel`."""
    with open(path, encoding="utf-8", newline="") as fh:
        return [Pair(r["label_a"], r["label_b"], r["label"], "relabel", "relabel")
                for r in csv.DictReader(fh, delimiter="\t")]


def paired(first: list[Pair], second: list[Pair]) -> list[tuple[str, str]]:
    """(first label, second label) of each pair both labellings hold, in `second`'s order; a pair of one
    alone is an error (the two must cover the same pairs)."""
    by_key = {frozenset((p.a, p.b)): p.label for p in first}
    missing = [(p.a, p.b) for p in second if frozenset((p.a, p.b)) not in by_key]
    if missing or len(by_key) != len(second):
        raise ValueError(f"the labellings cover different pairs ({len(by_key)} vs {len(second)}; "
                         f"first missing: {missing[:3]})")
    return [(by_key[frozenset((p.a, p.b))], p.label) for p in second]


def confusion(pairs: list[tuple[str, str]]) -> dict[tuple[str, str], int]:
    """Counts of (first, second) label pairs, every cell of LABELS x LABELS present."""
    counts = Counter(pairs)
    return {(x, y): counts[(x, y)] for x in LABELS for y in LABELS}


def agreement(table: dict[tuple[str, str], int]) -> tuple[float, float]:
    """Observed agreement and Cohen's kappa of a confusion table: kappa = (po - pe) / (1 - pe), pe the
    agreement expected from the two labellers' marginal shares (1.0 when pe is 1, both constant)."""
    n = sum(table.values())
    po = sum(table[(x, x)] for x in LABELS) / n
    pe = sum(sum(table[(x, y)] for y in LABELS) * sum(table[(y, x)] for y in LABELS) for x in LABELS) / (n * n)
    return po, (1.0 if pe == 1 else (po - pe) / (1 - pe))


def run(ctx: Context) -> None:
    from foon2pddl.generalize import wordnet
    from foon2pddl.generalize.modes import SIMILARITY_MODES

    second = read_relabel()
    first = [p for p in read_pairs() if p.split in RELABELLED]
    reader = wordnet.reader()
    for mode in SIMILARITY_MODES:
        keys, reader = accepted(second, mode, reader)
        s = score(second, lambda a, b, keys=keys: frozenset((a, b)) in keys)
        (p, plo, phi), (r, rlo, rhi) = s.precision(), s.recall()
        note = f"{len(second)} pairs, {s.good} good, {s.accepted} accepted ({s.bad_accepted} bad)"
        ctx.report(AREA, f"{mode} precision (relabel)", p, "", f"95 % CI {plo:.2f}-{phi:.2f}; {note}")
        ctx.report(AREA, f"{mode} recall (relabel)", r, "", f"95 % CI {rlo:.2f}-{rhi:.2f}")
    table = confusion(paired(first, second))
    po, kappa = agreement(table)
    ctx.report(AREA, "same label (first vs second)", po, "", f"{len(second)} pairs")
    ctx.report(AREA, "Cohen's kappa (first vs second)", kappa, "")
    for x in LABELS:
        ctx.report(AREA, f"first {x}: second good / marginal / bad", sum(table[(x, y)] for y in LABELS), "pairs",
                   " / ".join(str(table[(x, y)]) for y in LABELS))
