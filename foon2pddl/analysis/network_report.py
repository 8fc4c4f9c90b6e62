"""Network analysis outputs: text tables, JSON, GraphML files and a PNG of the most central nodes."""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import networkx as nx

from ..io.atomic import atomic_write_many
from ..model.words import count
from .network import BETWEENNESS_WORK, Analysis

KEYS = (("degree_centrality", "degree centrality"), ("betweenness", "betweenness centrality"))
#: Characters XML 1.0 cannot hold even as references (controls but tab and newlines, surrogates, U+FFFE,
#: U+FFFF), and the backslash that escapes them.
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]|\\\\")


def xml_text(text: str) -> str:
    """`text` with what XML cannot hold written as `\\uXXXX` (and `\\` as `\\\\`, so distinct labels stay
    distinct): parsers (ElementTree, `networkx.read_graphml`) reject `&#65535;` and the like."""
    return _NOT_XML.sub(lambda m: "\\\\" if m.group() == "\\" else f"\\u{ord(m.group()):04x}", text)


def _xml_safe(g: nx.Graph) -> nx.Graph:
    """A copy of `g` whose node names and string attributes are `xml_text` (the graph itself when they are)."""
    def bad(x) -> bool:
        return isinstance(x, str) and _NOT_XML.search(x) is not None

    if not any(bad(n) or any(bad(v) for v in d.values()) for n, d in g.nodes(data=True)):
        return g
    out = g.__class__()
    fix = {n: xml_text(n) if isinstance(n, str) else n for n in g.nodes}
    out.add_nodes_from((fix[n], {k: xml_text(v) if isinstance(v, str) else v for k, v in d.items()})
                       for n, d in g.nodes(data=True))
    out.add_edges_from((fix[a], fix[b], d) for a, b, d in g.edges(data=True))
    return out


def format_text(a: Analysis, top: int) -> str:
    """The `top` objects and motions by degree and betweenness centrality, and the components."""
    what = "object label" if a.level == 1 else "object node"
    lines = [f"{count(a.object_count, what)}, {count(len(a.motions), 'motion')}, {count(a.unit_count, 'unit')}; "
             f"{count(len(a.components), 'connected component')}, {'size' if len(a.components) == 1 else 'sizes'} {', '.join(map(str, a.components[:10]))}"
             + (" ..." if len(a.components) > 10 else "")]
    lines += [f"betweenness of {which} estimated from {k} sampled source nodes (exact betweenness would exceed "
              f"{BETWEENNESS_WORK:,} edge visits)" for which, k in a.sampled]
    for which in ("objects", "motions"):
        for key, title in KEYS:
            lines.append(f"\ntop {top} {which} by {title}:")
            for i, r in enumerate(a.top(which, key, top), start=1):
                lines.append(f"{i:>3}. {r.name:<40} {getattr(r, key):.4f}  (degree {r.degree})")
    return "\n".join(lines) + "\n"


def to_json(a: Analysis, top: int) -> str:
    data = {"level": a.level, "objects": a.object_count, "motions": len(a.motions), "units": a.unit_count,
            "components": list(a.components),
            **({"betweenness_sampled": dict(a.sampled)} if a.sampled else {}),
            "top": {which: {key: [r.as_dict() for r in a.top(which, key, top)] for key, _ in KEYS}
                    for which in ("objects", "motions")}}
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def graphml_text(g: nx.Graph) -> str:
    """GraphML of `g` (deterministic: nodes and edges in insertion order)."""
    return "\n".join(nx.generate_graphml(_xml_safe(g), prettyprint=True)) + "\n"


def write_graphml(directory: Path, graphs: dict[str, nx.Graph]) -> list[Path]:
    """DIR/<name>.graphml for each graph (atomically, all or none); the paths written."""
    files = {directory / f"{name}.graphml": graphml_text(g) for name, g in graphs.items()}
    atomic_write_many(files)
    return list(files)


#: Most bars a plot panel shows (the figure's height grows with them; the text output lists any number).
MAX_PLOT_BARS = 100


def plot_rows(a: Analysis, top: int) -> int:
    """Bars per panel of `plot_png`: `top`, but no more than there are objects or motions, nor MAX_PLOT_BARS."""
    return max(1, min(top, max(len(a.objects), len(a.motions)), MAX_PLOT_BARS))


def plot_png(a: Analysis, top: int) -> bytes:
    """Horizontal bars of the `top` objects and motions by both centralities (2 x 2 panels), as PNG;
    the figure is sized by the bars shown (`plot_rows`), never by `top` alone."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    top = plot_rows(a, top)
    fig, axes = plt.subplots(2, 2, figsize=(12, 2 + 0.35 * top * 2))
    for row, which in enumerate(("objects", "motions")):
        for col, (key, title) in enumerate(KEYS):
            items = a.top(which, key, top)[::-1]
            ax = axes[row][col]
            ax.barh([r.name for r in items], [getattr(r, key) for r in items], color="#8fb8ff" if row else "#8fd18f")
            ax.set_title(f"{which}: {title}")
            ax.tick_params(axis="y", labelsize=8)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, metadata={"Software": None})
    plt.close(fig)
    return buf.getvalue()
