"""`foon2pddl generalize` (FOON-GEN) and `foon2pddl categories` (the category index)."""

from __future__ import annotations

from pathlib import Path

import click

from ..model.words import count
from . import main
from .loading import read_network
from .options import output_option, paths_argument
from .outputs import emit, emit_network
from .progress import slow_step

categories_option = click.option("--categories", "categories", type=click.Path(path_type=Path), default=None,
                                 help="Category index (JSON, see docs/generalization.md). Default: the shipped one.")


@main.command("generalize")
@paths_argument
@categories_option
@click.option("--provenance", is_flag=True, help="Precede each unit with '# from <file>:<line>' comments.")
@click.option("--format", "fmt", type=click.Choice(["foon", "json"]), default="foon", show_default=True,
              help="FOON text, or the JSON export.")
@click.option("--readings", is_flag=True,
              help="List each category reading (a name read as its unit's object) at its file:line; default: a count.")
@output_option
def generalize_(paths, categories, provenance, fmt, output, readings) -> None:
    """Write FOON-GEN of the network: each object replaced by its category, duplicate units removed.

    An object in several categories takes the most specific one (first in the index on
    ties); objects in no category keep their label. Statistics per level go to standard error.
    """
    from ..generalize.categories import load_index
    from ..generalize.compress import compress
    from ..generalize.stats import format_levels_table, levels_table

    index = load_index(categories)
    net = read_network(paths)
    with slow_step(f"generalizing {count(len(net.foon.units), 'unit', grouped=True)} to categories"):
        c = compress(net.foon, index)
    header = (f"FOON-GEN ({count(len(index), 'category')}, {count(len(c.mapping), 'label')} generalized): "
              f"{c.original_units} -> {count(len(c.foon.units), 'unit')}")
    with slow_step(f"writing FOON-GEN ({count(len(c.foon.units), 'unit', grouped=True)})"):
        emit_network(c.foon, fmt, provenance, header, output)
    table = format_levels_table(levels_table({"REG": net.foon, "GEN": c.foon}, step=slow_step))
    click.echo(table, err=True, nl=False)
    for r in c.readings if readings else ():  # a name read as its unit's object, generalized as that object
        click.echo(f"note: category reading: {r}", err=True)
    if c.readings and not readings:  # 204 on the 100 subgraphs: one line, not a screenful
        n = len(c.readings)
        click.echo(f"note: {count(n, 'category reading')} (a name a node uses read as its unit's object, "
                   "and generalized as it); --readings lists each at its unit's file:line", err=True)


@main.command("categories")
@paths_argument
@categories_option
@click.option("--check", is_flag=True, help="List the object labels of PATHS in no category, with the coverage.")
@click.option("--extend", is_flag=True,
              help="Write the index extended to the object labels of PATHS it lacks (through WordNet) to -o; "
                   "each new assignment is listed on stderr for review.")
@click.option("--min-similarity", "min_similarity", type=click.FloatRange(0, 1), default=0.65, show_default=True,
              help="--extend: least similarity to the nearest known label for a WordNet assignment.")
@output_option
def categories_(paths, categories, check, extend, min_similarity, output) -> None:
    """Show the category index (tree of categories with member counts), --check its coverage of a network,
    or --extend it to a network's labels.

    With --check, exit status 1 when some object label has no category. With --extend, the
    review list is TSV on stderr: label, category, the known label (or category name) it was
    matched to, similarity, and how (head noun, category name, wordnet, or none when no
    category was found).
    """
    from ..generalize.categories import coverage, load_index

    index = load_index(categories)
    if extend:
        from ..generalize.cook import filing_similarity
        from ..generalize.extend import extended_index, file_labels, index_json

        net = read_network(paths)
        labels = [n.label for n in net.foon.nodes]
        found: tuple = ()
        if coverage(labels, index).missing:  # else nothing to file: WordNet is not opened
            with slow_step("filing the object labels in no category (through WordNet)"):
                found = file_labels(labels, index, filing_similarity(), min_similarity)
        bigger = extended_index(index, found)
        emit(index_json(bigger, "Extended by foon2pddl categories --extend: review the assignments."), output)
        click.echo("label\tcategory\tvia\tsimilarity\thow", err=True)
        for a in found:
            click.echo(a.describe(), err=True)
        before, after = coverage(labels, index), coverage(labels, bigger)
        click.echo(f"{after.covered} of {len(after.labels)} object labels in some category ({after.percent:.1f} %; "
                   f"{before.percent:.1f} % before, {sum(a.category is not None for a in found)} added)", err=True)
        return
    if not check:
        lines = [f"{'  ' * index.depth(c.name)}{c.name} ({len(c.members)}): {c.description}" for c in _tree(index)]
        emit("\n".join(lines) + "\n", output)
        return
    net = read_network(paths)
    cov = coverage((n.label for n in net.foon.nodes), index)
    text = "".join(f"{label}\n" for label in cov.missing)
    emit(text, output)
    click.echo(f"{cov.covered} of {len(cov.labels)} object labels in some category ({cov.percent:.1f} %)", err=True)
    if cov.missing:
        click.get_current_context().exit(1)


def _tree(index):
    """Categories depth first under their parents, each level in index order."""
    children: dict[str | None, list] = {}
    for c in index.categories:
        children.setdefault(c.parent, []).append(c)
    out = []

    def walk(parent):
        for c in children.get(parent, ()):
            out.append(c)
            walk(c.name)

    walk(None)
    return out
