"""`foon2pddl check`: defects of a FOON dataset, with the file and line of the units involved."""

from __future__ import annotations

import json

import click

from ..analysis.check import check, counts, has_errors
from ..io.files import load
from ..io.raw_objects import scan_paths
from ..model.words import first_of
from . import main
from .options import output_option, paths_argument
from .outputs import emit
from .progress import inputs, slow_step


def wordnet_lemma():
    """`lemma(word)` from WordNet (noun morphology), or None when WordNet cannot be opened."""
    try:
        from ..generalize.wordnet import reader

        wn = reader()
    except Exception as exc:  # noqa: BLE001 - any failure to open the corpus means: use the fallback
        click.echo(f"warning: WordNet unavailable ({exc}); spelling variants use string rules only", err=True)
        return None

    def lemma(word: str) -> str | None:
        return wn.morphy(word.replace(" ", "_"), "n")

    return lemma


def format_defects(defects, total: dict[str, int]) -> str:
    """`path:line: severity: kind: message (also at ...)` per defect, then the counts per kind."""
    lines = []
    for d in defects:
        where = str(d.places[0]) if d.places else "<network>:0"
        more = d.places[1:]
        also = f" (also at {first_of(more, len(more), sep=', ', total=d.total_places - 1)})" if more else ""
        lines.append(f"{where}: {d.severity}: {d.kind}: {d.message}{also}")
    lines.append("defects: " + ", ".join(f"{k} {n}" for k, n in total.items()))
    return "\n".join(lines) + "\n"


@main.command("check")
@paths_argument
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@click.option("--wordnet/--no-wordnet", default=True, show_default=True,
              help="Use WordNet to tell spelling variants from different words (else string rules only).")
@output_option
def check_(paths, as_json, wordnet, output) -> None:
    """Find defects in FOON files: self-supporting producers, cycles with no entry, units that change
    nothing, contents lists that disagree with `in [c]` nodes, unknown objects, spelling variants,
    state order and duplicated states (docs/datasets.md).

    Exit status: 0 no error-class defect (warnings allowed), 1 some error-class defect, 2 bad input.
    """
    net_paths = paths or ()
    if not net_paths:
        from ..io.inputs import example_path

        net_paths = (example_path(),)
    with slow_step(f"reading {inputs(paths)}"):
        foon, _ = load(net_paths)
    lemma = None
    if wordnet:  # most of a check's time on a fresh process (11.6 s of 13.3 at load 10 on the shared subgraphs)
        with slow_step("opening WordNet (to tell spelling variants from different words; --no-wordnet: string rules "
                       "only)"):
            lemma = wordnet_lemma()
    with slow_step(f"checking {inputs(paths)} for defects"):
        defects = check(foon, scan_paths(net_paths), lemma)
    total = counts(defects)
    if as_json:
        data = {"counts": total, "errors": sum(d.severity == "error" for d in defects),
                "warnings": sum(d.severity == "warning" for d in defects), "defects": [d.as_dict() for d in defects]}
        emit(json.dumps(data, indent=2, ensure_ascii=False) + "\n", output)
    else:
        emit(format_defects(defects, total), output)
    if has_errors(defects):
        click.get_current_context().exit(1)
