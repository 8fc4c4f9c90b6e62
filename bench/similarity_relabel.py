"""Blind relabellings of the shared subgraphs' pairs: the modes scored on each, and the labellings' agreement.

`bench/similarity_relabel.tsv` (the second labelling, relab50), `bench/similarity_relab51.tsv` (the third,
relab51), `bench/similarity_relab52.tsv` (the fourth, relab52), `bench/similarity_relab53.tsv` (the fifth,
relab53) and `bench/similarity_relab54.tsv` (the sixth, relab54; the last three from the rubric as first written
only) each relabel every pair of the `independent`, `fresh`, `tune` and `unsampled` splits of
`similarity_pairs.tsv` (the shared subgraphs' labels), by labellers who had seen neither the rules nor any earlier
label (`similarity_rubric.md`, its last five addenda). Reported
per relabelling and mode: precision and recall of good pairs, with Wilson 95 % intervals (`similarity.score`,
the same counting as area `similarity`), on all its pairs, on those of the first labels' `held-out` splits and
on the tuning splits; then, for each labelling (first, second, ...) and each later one, the share of pairs with
the same label, Cohen's kappa over good / marginal / bad, and the 3x3 confusion table (the earlier labelling by
row).
"""

from __future__ import annotations

import csv
from collections import Counter
from pathlib import Path

from .harness import Context
from .similarity import GROUPS, Pair, accepted, read_pairs, score

AREA = "similarity_relabel"
RELABEL = Path(__file__).with_name("similarity_relabel.tsv")
RELAB51 = Path(__file__).with_name("similarity_relab51.tsv")
RELAB52 = Path(__file__).with_name("similarity_relab52.tsv")
RELAB53 = Path(__file__).with_name("similarity_relab53.tsv")
RELAB54 = Path(__file__).with_name("similarity_relab54.tsv")
#: The blind relabellings, in the order they were made: (name in the report, file).
RELABELLINGS = (("relabel", RELABEL), ("relab51", RELAB51), ("relab52", RELAB52), ("relab53", RELAB53),
                ("relab54", RELAB54))
#: The splits the relabellings cover (the shared subgraphs' labels).
RELABELLED = ("independent", "fresh", "tune", "unsampled")
#: The first labels' splits by what they were used for: scored once (`held-out`), or tuning the rules.
SUBSETS = {"held-out": GROUPS["held-out"], "tuning": ("tune", "unsampled")}
LABELS = ("good", "marginal", "bad")
ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth")


def read_relabel(path: Path = RELABEL, name: str = "relabel") -> list[Pair]:
    """A relabelling's labels, as pairs whose source and split are the relabelling's `name`."""
    with open(path, encoding="utf-8", newline="") as fh:
        return [Pair(r["label_a"], r["label_b"], r["label"], name, name)
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


def agreements(labellings: list[list[Pair]]) -> list[tuple[str, str, dict[tuple[str, str], int]]]:
    """(earlier ordinal, later ordinal, confusion table) for every two labellings, in the order of
    `labellings` (first, second, third, ...): each with each later one, the earlier one by row."""
    return [(ORDINALS[i], ORDINALS[j], confusion(paired(labellings[i], labellings[j])))
            for i in range(len(labellings)) for j in range(i + 1, len(labellings))]


def subsets(first: list[Pair], relabelled: list[Pair]) -> dict[str, list[Pair]]:
    """A relabelling's pairs, all (key "") and by the first labels' split of each pair (SUBSETS), in its order."""
    split = {frozenset((p.a, p.b)): p.split for p in first}
    out = {"": relabelled}
    for name, splits in SUBSETS.items():
        out[name] = [p for p in relabelled if split[frozenset((p.a, p.b))] in splits]
    return out


def run(ctx: Context) -> None:
    from foon2pddl.generalize import wordnet
    from foon2pddl.generalize.modes import SIMILARITY_MODES

    first = [p for p in read_pairs() if p.split in RELABELLED]
    relabellings = [(name, read_relabel(path, name)) for name, path in RELABELLINGS]
    reader = wordnet.reader()
    for name, labels in relabellings:
        for mode in SIMILARITY_MODES:
            keys, reader = accepted(labels, mode, reader)
            for subset, pairs in subsets(first, labels).items():
                s = score(pairs, lambda a, b, keys=keys: frozenset((a, b)) in keys)
                (p, plo, phi), (r, rlo, rhi) = s.precision(), s.recall()
                where = name + (f", {subset}" if subset else "")
                note = f"{len(pairs)} pairs, {s.good} good, {s.accepted} accepted ({s.bad_accepted} bad)"
                ctx.report(AREA, f"{mode} precision ({where})", p, "", f"95 % CI {plo:.2f}-{phi:.2f}; {note}")
                ctx.report(AREA, f"{mode} recall ({where})", r, "", f"95 % CI {rlo:.2f}-{rhi:.2f}")
    for x_name, y_name, table in agreements([first, *(labels for _, labels in relabellings)]):
        po, kappa = agreement(table)
        versus = f"{x_name} vs {y_name}"
        ctx.report(AREA, f"same label ({versus})", po, "", f"{sum(table.values())} pairs")
        ctx.report(AREA, f"Cohen's kappa ({versus})", kappa, "")
        for x in LABELS:
            ctx.report(AREA, f"{x_name} {x}: {y_name} good / marginal / bad", sum(table[(x, y)] for y in LABELS),
                       "pairs", " / ".join(str(table[(x, y)]) for y in LABELS))
