"""FOON's evidence for a label listed by a holder and by what is in or on it (`holder_words.takers`).

    python -m bench.nested_lists [--shared DIR] [-v]

Over every unit of `DIR/foon-subgraphs` (file by file), per side of the unit: a node C listing a label X beside
a node P of the same side placed in or on C (by P's own place word) that lists X too. Counts the pairs, units
and files; of the pairs on the output side, those where both C and P newly list X and the unit gives X no output
node (rule 3 of `holders` decides where X goes then: the inner P). `-v`: one line per pair.
"""

from __future__ import annotations

import argparse
from collections import Counter
from pathlib import Path

from foon2pddl.io.files import load
from foon2pddl.model.places import listed, places

from .harness import run_main, shared_data


def pairs(unit):
    """(side, C node, P node, X) for every label X a node C and a node P in or on C both list."""
    for side, nodes in (("in", unit.inputs), ("out", unit.outputs)):
        for c in nodes:
            for p in nodes:
                if p is not c and any(h == c.label for _, h in places(p)):
                    yield from ((side, c, p, x) for x in sorted((listed(c) & listed(p)) - {p.label}))


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(prog="python -m bench.nested_lists", description=__doc__.split("\n\n")[0])
    ap.add_argument("--shared", type=Path, default=Path("../shared/data"))
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args(argv)
    shared_data(args.shared)
    found, units, kinds = [], 0, Counter()
    for f in sorted((args.shared / "foon-subgraphs").iterdir()):
        foon, _ = load([f])
        for u in foon.units:
            units += 1
            for side, c, p, x in pairs(u):
                before = {n.label: listed(n) for n in u.inputs}
                fresh = side == "out" and not any(x in before.get(n.label, ()) for n in (c, p))
                alone = fresh and not any(o.label == x for o in u.outputs)
                kinds[side] += 1
                kinds["newly listed by both, X given no output node"] += alone
                found.append((f.name, u.source.line, side, c, p, x))
                if args.verbose:
                    print(f"{f.name}:{u.source.line}: {side}: {c.describe()} | {p.describe()} | {x}"
                          + ("  [newly by both, no node of X]" if alone else ""))
    print(f"{units} units: {len(found)} pairs in {len({r[:2] for r in found})} units of "
          f"{len({r[0] for r in found})} files; " + ", ".join(f"{k}: {v}" for k, v in sorted(kinds.items())))


if __name__ == "__main__":
    run_main(main)
