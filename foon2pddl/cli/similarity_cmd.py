"""`foon2pddl similarity`: Wu-Palmer similarity of object labels (WordNet)."""

from __future__ import annotations

import json

import click

from ..errors import UsageError
from ..model.foon import normalize_label
from ..model.words import count
from . import main
from .loading import load_overrides
from .options import output_option, similarity_options
from .outputs import emit
from .progress import slow_step


@main.command("similarity")
@click.argument("labels", nargs=-1, required=True)
@click.option("--pairs", "as_pairs", is_flag=True, help="Read LABELS as consecutive pairs (A B C D: A~B, C~D).")
@click.option("--senses", is_flag=True, help="Also print the WordNet senses each label stands for.")
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@similarity_options
@output_option
def similarity(labels, as_pairs, senses, as_json, similarity, overrides, output) -> None:
    """Similarity of object labels: one value for two labels, a matrix for more (or --pairs).

    Wu-Palmer similarity over WordNet noun senses, with head-noun fallback for
    compounds and the shipped overrides (docs/generalization.md). `cook` (the default)
    keeps the senses of a label's role (food, else kitchen artifact), uses the deepest
    common ancestor and gives 0 to pairs whose ancestor is a broad class (--senses says
    which); `paper` is the seed paper's rule. FOON-EXP substitutes labels at least 0.89 similar.
    A label with no kitchen sense in WordNet gets a warning on stderr (exit status 0):
    its similarity to every other label is 0.
    """
    from ..generalize.modes import make_similarity

    labels = [normalize_label(x) for x in labels]
    if any(not x for x in labels):
        raise UsageError("empty label")
    if as_pairs and len(labels) % 2:
        raise UsageError(f"--pairs needs an even number of labels, got {len(labels)}")
    if len(labels) < 2:
        raise UsageError("give at least two labels")
    extra = load_overrides(overrides)
    names = list(dict.fromkeys(labels))
    pairs = list(zip(labels[::2], labels[1::2], strict=True)) if as_pairs or len(labels) == 2 else None
    with slow_step(f"comparing {count(len(names), 'label')} in WordNet ({similarity} similarity)"):
        sim = make_similarity(similarity, extra=extra)
        values = [(a, b, sim(a, b)) for a, b in pairs] if pairs is not None else None
        rows = [[sim(a, b) for b in names] for a in names] if pairs is None else None
    if values is not None:
        if as_json:
            text = json.dumps([{"a": a, "b": b, "similarity": round(v, 6)} for a, b, v in values], indent=2) + "\n"
        elif len(values) == 1:
            text = f"{values[0][2]:.4f}\n"
        else:
            text = "".join(f"{v:.4f}\t{a}\t{b}\n" for a, b, v in values)
    else:
        if as_json:
            text = json.dumps({"labels": names, "matrix": [[round(v, 6) for v in r] for r in rows]}, indent=2) + "\n"
        else:
            width = max(len(n) for n in names)
            text = " " * width + "".join(f"  {i + 1:>6}" for i in range(len(names))) + "\n"
            text += "".join(f"{n:<{width}}" + "".join(f"  {v:6.4f}" for v in r) + f"   ({i + 1})\n"
                            for i, (n, r) in enumerate(zip(names, rows, strict=True)))
    for label in dict.fromkeys(labels):
        if not sim.resolution(label).senses:
            known = bool(sim.reader.synsets(label.replace(" ", "_")))
            what = "has no kitchen sense in WordNet" if known else "is not in WordNet"
            click.echo(f"warning: {label!r} {what} (nor its head noun, nor in the overrides): "
                       "its similarity to any other label is 0", err=True)
    if senses and not as_json:
        text += "".join(sim.resolution(x).describe() + "\n" for x in dict.fromkeys(labels))
        if similarity != "paper":
            text += "".join(_why(a, b, sim.explain(a, b)) for a, b in
                            (pairs if pairs is not None else _distinct_pairs(labels)))
    emit(text, output)


def _distinct_pairs(labels):
    names = list(dict.fromkeys(labels))
    return [(a, b) for i, a in enumerate(names) for b in names[i + 1:]]


def _why(a: str, b: str, ev) -> str:
    """One line: the sense pair and common ancestor a cook-mode value comes from, or why it is 0."""
    a, b = sorted((a, b))  # the evidence's sense order
    if ev.rejected in ("same", "unknown", "fixed", "forbidden", "variant"):
        what = {"same": "the same label", "unknown": "a label has no sense", "fixed": "fixed by the overrides",
                "forbidden": "forbidden by the overrides",
                "variant": "rejected: a recipe's own preparation of the other"}[ev.rejected]
        return f"{a} ~ {b}: {what}\n"
    if not ev.ancestor:
        return f"{a} ~ {b}: no common ancestor\n"
    verdict = {"broad": f"rejected: the ancestor covers {ev.breadth:.1%} of the vocabulary",
               "category": "rejected: the categories do not group them",
               "sibling": "rejected: a label filed through one member stands only with its kinds",
               "purpose": "rejected: a kind of tool for a food its generic is not for",
               "class": "rejected: a filed label with many WordNet kinds is a class, not a substitute",
               "tool class": "rejected: a class of tools whose kinds go by names of their own",
               "food class": "rejected: a class of foods whose kinds are classes too, not a substitute for one",
               "role": "rejected: an ingredient and no ingredient",
               "dishes": "rejected: two dishes are variants of one another, not substitutes",
               "stand-in": "rejected: a label the overrides read as its class is one member of it, not its generic"}.get(
        ev.rejected, f"ancestor covers {ev.breadth:.1%} of the vocabulary")
    return f"{a} ~ {b}: {ev.sense_a} ~ {ev.sense_b} under {ev.ancestor} ({verdict})\n"
