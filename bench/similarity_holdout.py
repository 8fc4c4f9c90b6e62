"""The cook mode on labels its category index lacks, simulated on the tuning pairs.

Every pair of the labelled `outside`, `lemmas`, `lemmas2`, `lemmas3`, `lemmas4`, `lemmas5`, `lemmas6`, `lemmas7`,
`lemmas8` and `lemmas9` splits has a label the shipped index lacks, so rule 5 reads the category `categories --extend` files it in. To choose that
rule without looking at those splits, the tuning pairs (`tune` + `unsampled`, shared
labels) are scored with the index that `category_extend` builds (30 of the shared
subgraphs held out, seed 5, every label only they use removed): `extend` files each
removed label as `categories --extend` would; `unconstrained` leaves it in no category
(the cook mode before); `shipped` is the full index (what a hand-made category gives).
Reported per variant: precision and recall of good pairs on the tuning pairs with a
removed label, and on all tuning pairs.
"""

from __future__ import annotations

from foon2pddl.generalize import wordnet
from foon2pddl.generalize.cook import CookSimilarity
from foon2pddl.generalize.expand import DEFAULT_THRESHOLD

from .category_extend import held_out_index
from .harness import Context
from .similarity import read_pairs, score

AREA = "similarity_holdout"


def run(ctx: Context) -> None:
    small, removed = held_out_index(ctx.shared)
    pairs = [p for p in read_pairs() if p.split in ("tune", "unsampled")]
    touched = [p for p in pairs if {p.a, p.b} & set(removed)]
    reader = wordnet.reader()
    variants = {"shipped": CookSimilarity(reader), "unconstrained": CookSimilarity(reader, categories=small, extend=False),
                "extend": CookSimilarity(reader, categories=small)}
    for name, sim in variants.items():
        for which, chosen in (("removed labels", touched), ("all", pairs)):
            s = score(chosen, lambda a, b, sim=sim: sim(a, b) >= DEFAULT_THRESHOLD)
            (p, plo, phi), (r, rlo, rhi) = s.precision(), s.recall()
            note = f"{len(chosen)} pairs, {s.good} good, {s.accepted} accepted ({s.bad_accepted} bad)"
            ctx.report(AREA, f"{name} precision ({which})", p, "", f"95 % CI {plo:.2f}-{phi:.2f}; {note}")
            ctx.report(AREA, f"{name} recall ({which})", r, "", f"95 % CI {rlo:.2f}-{rhi:.2f}")
