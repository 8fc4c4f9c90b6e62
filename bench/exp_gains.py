"""How many of FOON-EXP's gains over REG rest on good substitutions alone, per similarity mode.

On the default experiment protocol (10 trials of 100 goals, kitchen fraction 0.9,
seed 0, level 3) over the shared subgraphs: a gain is a goal native complete
retrieval makes on EXP but not on REG; its substitutions are those its EXP tree
relies on (`substitution.expansion_substitutions`). The pairs are labelled in
`bench/exp_gain_pairs.tsv` (and `bench/similarity_pairs.tsv`), per
`bench/similarity_rubric.md`; a gain rests on good substitutions alone when every
pair its tree uses is labelled good. Unlabelled pairs are reported, not guessed.
"""

from __future__ import annotations

import csv
from pathlib import Path

from foon2pddl.experiment.networks import build_view
from foon2pddl.experiment.protocol import Protocol, draw
from foon2pddl.generalize.modes import SIMILARITY_MODES, make_similarity
from foon2pddl.generalize.substitution import expansion_substitutions
from foon2pddl.io.inputs import load_network
from foon2pddl.retrieval.api import retrieve

from .harness import Context
from .similarity import PAIRS

AREA = "exp_gains"
GAIN_PAIRS = Path(__file__).with_name("exp_gain_pairs.tsv")


def labels() -> dict[frozenset[str], str]:
    out = {}
    for path in (PAIRS, GAIN_PAIRS):
        with open(path, encoding="utf-8", newline="") as fh:
            for r in csv.DictReader(fh, delimiter="\t"):
                out[frozenset((r["label_a"], r["label_b"]))] = r["label"]
    return out


def gains(net, mode: str, protocol: Protocol) -> list[tuple[str, ...]]:
    """Per gain, the (original, replacement) pairs its EXP tree relies on."""
    reg = build_view("reg", net, protocol.level)
    exp = build_view("exp", net, protocol.level, similarity=mode)
    sim = make_similarity(mode)
    out = []
    for trial in draw(reg.foon, protocol).trials:
        kit = exp.map_kitchen(trial.kitchen).nodes
        for goal in trial.goals:
            if retrieve(reg.foon, trial.kitchen.nodes, reg.goal_of(goal)).tree is not None:
                continue
            tree = retrieve(exp.foon, kit, exp.goal_of(goal)).tree
            if tree is not None:
                out.append(tuple(frozenset((s.original, s.replacement)) for s in expansion_substitutions(tree, sim)))
    return out


def run(ctx: Context) -> None:
    net = load_network([str(ctx.shared / "foon-subgraphs")])
    known = labels()
    protocol = Protocol(trials=3 if ctx.quick else 10)
    for mode in SIMILARITY_MODES:
        found = gains(net, mode, protocol)
        unlabelled = sorted({" ~ ".join(sorted(p)) for g in found for p in g if p not in known})
        good = sum(all(known.get(p) == "good" for p in g) for g in found)
        usable = sum(all(known.get(p) in ("good", "marginal") for p in g) for g in found)
        bad = sum(any(known.get(p) == "bad" for p in g) for g in found)
        share = good / len(found) if found else 0.0
        ctx.report(AREA, f"{mode}: EXP gains on good substitutions alone", share, "",
                   f"{good} of {len(found)} gains; {usable} on good or marginal ones, {bad} need a bad one; "
                   f"{len(unlabelled)} unlabelled pairs" + (f": {', '.join(unlabelled[:10])}" if unlabelled else ""))
