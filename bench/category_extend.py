"""How well `categories --extend` files labels it has not seen, against the hand-made index.

Leave-out protocol: 30 of the shared subgraphs (seeded sample, seed 5) are held out;
every object label only they use is removed from the shipped category index; the
smaller index is extended to those labels (`extend.assign`, default
`--min-similarity`) and each assignment is compared with the shipped index's choice:
same category, and same top-level category. Also the coverage of each shared
subgraph (least per file) with the shipped index.
"""

from __future__ import annotations

import random
from pathlib import Path

from foon2pddl.generalize.categories import Category, CategoryIndex, coverage, shipped_index
from foon2pddl.generalize.cook import filing_similarity
from foon2pddl.generalize.extend import file_labels
from foon2pddl.io.inputs import load_network

from .harness import Context

AREA = "category_extend"
SEED, HELD_OUT = 5, 30


def _labels(paths) -> set[str]:
    return {n.label for n in load_network([str(p) for p in paths]).foon.nodes}


def held_out_index(shared: Path) -> tuple[CategoryIndex, list[str]]:
    """The shipped index without the labels only the held-out subgraphs use (module doc), and those labels."""
    files = sorted((shared / "foon-subgraphs").glob("*.txt"))
    held = set(random.Random(SEED).sample(files, min(HELD_OUT, len(files))))
    only = sorted(_labels(held) - _labels([f for f in files if f not in held]))
    small = CategoryIndex(tuple(Category(c.name, c.parent, c.description, tuple(m for m in c.members if m not in only))
                                for c in shipped_index().categories))
    return small, only


def run(ctx: Context) -> None:
    files = sorted((ctx.shared / "foon-subgraphs").glob("*.txt"))
    full = shipped_index()
    least = min(coverage(_labels([f]), full).percent for f in files)
    ctx.report(AREA, "least coverage of a shared subgraph (shipped index)", least, "%", f"{len(files)} subgraphs")
    small, only = held_out_index(ctx.shared)
    found = [a for a in file_labels(only, small, filing_similarity()) if a.category is not None]

    def top(name: str | None) -> str | None:
        return (name, *full.ancestors(name))[-1] if name else None

    same = sum(a.category == full.choose(a.label) for a in found)
    same_top = sum(top(a.category) == top(full.choose(a.label)) for a in found)
    note = f"{len(only)} held-out labels, {len(found)} assigned"
    ctx.report(AREA, "extend: same category as the shipped index", same / len(found) if found else 0.0, "", note)
    ctx.report(AREA, "extend: same top-level category", same_top / len(found) if found else 0.0, "", note)
