"""Draw the third labelled batch of substitution pairs (splits `outside` and `unsampled`), blind.

`python -m bench.similarity_sample [--shared DIR] BLIND KEY` writes BLIND, the candidate
pairs in a seeded shuffle with an empty `label` column and nothing else (no score, no
source), and KEY, each pair's split and source, which the labeller does not open until
the labels are committed. The populations (all pairs, not samples, so precision and
recall need no weights):

- `outside`: pairs of the labels of `foon-search-inputs/kitchen.json` and `goal_nodes.json`
  (object labels, ingredients and containers) with at least one label outside the
  reference vocabulary (`cook.reference_vocabulary`: the shared subgraphs' and the
  example's labels), that the paper's rule or the cook
  mode accepts (>= 0.89), plus `RANDOM_OUTSIDE` seeded pairs from the rest (`random`);
- `unsampled`: pairs of the reference vocabulary that either mode accepts and that
  `similarity_pairs.tsv` does not yet hold.

The sources (`paper+cook`, `paper`, `cook`, `random`) name the modes at the commit the
batch was drawn on (see `similarity_rubric.md`); rerun there to reproduce the file.
"""

from __future__ import annotations

import argparse
import csv
import itertools
import random
from pathlib import Path

from foon2pddl.generalize.cook import reference_vocabulary
from foon2pddl.generalize.expand import DEFAULT_THRESHOLD
from foon2pddl.generalize.modes import make_similarity

from .harness import run_main, shared_data
from .similarity import read_pairs, search_labels

SEED, RANDOM_OUTSIDE = 23, 36


def candidates(shared: Path) -> list[tuple[str, str, str, str]]:
    """(label_a, label_b, split, source) of the batch (module doc), in no particular order."""
    reference = sorted(reference_vocabulary())
    search = search_labels(shared)
    paper = make_similarity("paper")
    cook = make_similarity("cook", reader=paper.reader)
    have = {frozenset((p.a, p.b)) for p in read_pairs()}
    out, rest = [], []

    def source(a: str, b: str, cook) -> str | None:
        modes = [m for m, sim in (("paper", paper), ("cook", cook)) if sim(a, b) >= DEFAULT_THRESHOLD]
        return "+".join(modes) or None

    known = set(reference)
    for a, b in itertools.combinations(search, 2):
        if a in known and b in known:
            continue
        found = source(a, b, cook)
        if found:
            out.append((a, b, "outside", found))
        else:
            rest.append((a, b))
    out += [(a, b, "outside", "random") for a, b in random.Random(SEED).sample(rest, RANDOM_OUTSIDE)]
    for a, b in itertools.combinations(reference, 2):
        found = source(a, b, cook) if frozenset((a, b)) not in have else None
        if found:
            out.append((a, b, "unsampled", found))
    return out


def main(prog: str = "python -m bench.similarity_sample", doc: str | None = __doc__, draw=candidates,
         seeds: dict[str, int] | None = None) -> None:
    """`prog [--shared DIR] BLIND KEY`: write the batch `draw(shared)` gives (`write_batch`); with `seeds`
    (split -> seed) `--split` picks the batch, `draw(shared, split)`, shuffled with its seed."""
    ap = argparse.ArgumentParser(prog=prog, description=doc)
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"))
    if seeds:
        ap.add_argument("--split", choices=list(seeds), default=next(iter(seeds)))
    ap.add_argument("blind", type=Path, help="pairs to label (no scores, no sources)")
    ap.add_argument("key", type=Path, help="each pair's split and source (not opened while labelling)")
    args = ap.parse_args()
    shared_data(args.shared)
    if seeds:
        write_batch(draw(args.shared, args.split), args.blind, args.key, seeds[args.split])
    else:
        write_batch(draw(args.shared), args.blind, args.key, SEED)


def write_batch(rows: list[tuple[str, str, str, str]], blind: Path, key: Path, seed: int) -> None:
    """Write (label_a, label_b, split, source) rows in a seeded shuffle: BLIND (labels only) and KEY (module doc)."""
    rows = sorted(rows)
    random.Random(seed).shuffle(rows)
    with open(blind, "w", encoding="utf-8", newline="") as fh:
        w = csv.writer(fh, delimiter="\t", lineterminator="\n")
        w.writerow(["label_a", "label_b", "label"])
        w.writerows((a, b, "") for a, b, _, _ in rows)
    with open(key, "w", encoding="utf-8", newline="") as fh:
        w = csv.writer(fh, delimiter="\t", lineterminator="\n")
        w.writerow(["label_a", "label_b", "split", "source"])
        w.writerows(rows)
    print(f"{len(rows)} pairs -> {blind}; key -> {key}")


if __name__ == "__main__":
    run_main(main)
