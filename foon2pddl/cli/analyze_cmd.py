"""`foon2pddl analyze`: network analysis (projections, centrality, components), GraphML and a PNG."""

from __future__ import annotations

from pathlib import Path

import click

from . import main
from .loading import read_network
from .options import output_option, paths_argument
from .outputs import cannot_write, emit
from .progress import slow_step


def _png_name(ctx: click.Context, param: click.Parameter, value: Path | None) -> Path | None:
    """--plot's file: it is written as PNG, so a name ending otherwise (`x.svg`) would hold the wrong format."""
    if value is not None and value.suffix.lower() != ".png":
        raise click.BadParameter(f"{value}: the plot is a PNG image: name the file *.png", ctx, param)
    return value


@main.command("analyze")
@paths_argument
@click.option("--top", type=click.IntRange(min=1), default=10, show_default=True,
              help="How many of the most central objects and motions to list.")
@click.option("--level", type=click.Choice(["1", "3"]), default="1", show_default=True,
              help="Objects by label (1, as Paulius et al. 2016 rank them) or as whole nodes with states (3).")
@click.option("--json", "as_json", is_flag=True, help="Machine-readable JSON output.")
@click.option("--graphml", "graphml", type=click.Path(path_type=Path, file_okay=False), default=None,
              help="Directory for foon.graphml (bipartite), objects.graphml and motions.graphml (Gephi, Cytoscape).")
@click.option("--plot", "plot", type=click.Path(path_type=Path, dir_okay=False), default=None,
              callback=_png_name, help="PNG of the most central objects and motions (FILE.png).")
@output_option
def analyze_(paths, top, level, as_json, graphml, plot, output) -> None:
    """One-mode projections of the network (object-object, motion-motion), degree and betweenness
    centrality, the most central objects and motions, connected components (docs/datasets.md)."""
    with slow_step("loading the network analysis (numpy, networkx)"):  # 1.1 s at load 15, before any other step
        from ..analysis.network import analyze, graphml_graphs  # networkx: imported only when needed
        from ..analysis.network_report import MAX_PLOT_BARS, format_text, plot_png, to_json, write_graphml
    from ..io.atomic import atomic_write

    net = read_network(paths)
    result = analyze(net.foon, int(level), step=slow_step)  # says what it does, and how far betweenness is
    try:
        if graphml is not None:
            with slow_step(f"writing the GraphML files to {graphml}"):  # the graphs and their XML: 1.9 s at load 18
                written = write_graphml(graphml, graphml_graphs(net.foon, result))
            for p in written:
                click.echo(f"wrote {p}", err=True)
        if plot is not None:
            with slow_step(f"drawing {plot}", after=0):  # matplotlib and the figure: 2.3 s at load 15, 15 s at 20
                png = plot_png(result, top)
            atomic_write(plot, png)
            shown = f" (the top {MAX_PLOT_BARS} of each ranking)" if top > MAX_PLOT_BARS else ""
            click.echo(f"wrote {plot}{shown}", err=True)
    except OSError as exc:
        raise cannot_write(graphml if plot is None else plot, exc) from None
    emit(to_json(result, top) if as_json else format_text(result, top), output)
