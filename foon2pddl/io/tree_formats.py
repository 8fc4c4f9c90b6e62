"""Task tree outputs: steps in a cook's words (the default), numbered FOON steps, FOON text, JSON,
Graphviz DOT and SVG.

Every format is deterministic (units in the tree's order, nodes numbered in
sorted order). Diagrams use the public FOON viewer's colours: object nodes
that enter the tree from the kitchen (inputs) green, object nodes some unit
of the tree makes (outputs) blue, motion nodes red; the goal has a bold border. A legend
says so, and a kitchen utensil several steps use is drawn once per use (dashed).
"""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Iterable, Sequence

from ..errors import FoonError, MissingDependencyError, UsageError
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.kitchen import Kitchen
from ..model.tasktree import TaskTree
from ..model.where import beyond_foon
from ..model.words import count
from .jsonio import node_to_dict
from .recipe_words import PLACE_WORDS, recipe_text, surfaces
from .writer import write_units

FORMATS = ("recipe", "steps", "foon", "json", "dot", "svg")
#: What `retrieve` and `plan` print: steps in a cook's words (what moves, from where, into what, with
#: which tool); `steps` lists each unit's FOON nodes, `foon` and `json` the units themselves.
DEFAULT_FORMAT = "recipe"
#: The formats that print numbered steps (a plan's physical objects follow them).
STEP_FORMATS = ("recipe", "steps")

INPUT_COLOUR = "#8fd18f"    # green
OUTPUT_COLOUR = "#8fb8ff"   # blue
MOTION_COLOUR = "#f08080"   # red

def render_tree(tree: TaskTree, fmt: str, kitchen: Kitchen | Iterable[ObjectNode] | None = None) -> str:
    """The tree in `fmt` (one of FORMATS). `kitchen`, when given, lists what the tree takes from it.

    >>> from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
    >>> unit = FunctionalUnit((make_node("onion", [make_state("whole")]), make_node("knife")), Motion("chop"),
    ...                       (make_node("onion", [make_state("chopped")]), make_node("knife")))
    >>> print(render_tree(TaskTree((unit,), make_node("onion", [make_state("chopped")]), 3), "steps"), end="")
    task tree for onion (chopped): 1 unit, level 3
    1. chop onion (whole) with knife -> onion (chopped)
    """
    if fmt not in FORMATS:
        raise UsageError(f"unknown task tree format {fmt!r} (expected one of {', '.join(FORMATS)})")
    return _RENDER[fmt](tree, _used_from_kitchen(tree, kitchen))


def _used_from_kitchen(tree: TaskTree, kitchen) -> list[ObjectNode] | None:
    """Inputs of the tree that come from the kitchen (not made by an earlier unit), sorted."""
    if kitchen is None:
        return None
    nodes = kitchen.nodes if isinstance(kitchen, Kitchen) else frozenset(kitchen)
    made: set[ObjectNode] = set()
    used: set[ObjectNode] = set()
    for u in tree.units:
        used.update(n for n in u.inputs if n not in made and n in nodes)
        made.update(u.outputs)
    if not tree.units and tree.goal in nodes:
        used.add(tree.goal)
    return sorted(used)


def _header(tree: TaskTree) -> str:
    return f"task tree for {tree.goal.describe()}: {count(len(tree.units), 'unit')}, level {tree.level}"


# -- steps ----------------------------------------------------------------------------------------


def step_text(unit: FunctionalUnit) -> str:
    """`chop onion (whole) with knife on cutting board -> onion (chopped)`.

    The objects acted on are the inputs that change into a new output of the same label;
    the other inputs are tools (`with`), or places when a changed object or a new output
    is in a state such as `on [cutting board]` naming them. Inputs that are themselves
    in or on an object acted on (a bowl's contents) are left out: that object's own
    states list them.
    """
    new_outputs = [o for o in unit.outputs if o not in unit.inputs]
    new_labels = {o.label for o in new_outputs}
    acted = [i for i in unit.inputs if i not in unit.outputs and i.label in new_labels]
    others = [i for i in unit.inputs if i not in acted]
    if not acted:
        acted, others = list(unit.inputs), []
    places: dict[str, list[str]] = {}
    tools: list[str] = []
    about = acted + new_outputs
    holders = {n.label for n in acted}
    for o in others:
        if any(s.label in PLACE_WORDS and s.related in holders for s in o.states):
            continue
        word = next((s.label for n in about for s in n.states if s.related == o.label and s.label in PLACE_WORDS),
                    None)
        if word is None:
            tools.append(o.describe())
        else:
            places.setdefault(word, []).append(o.describe())
    text = f"{unit.motion.label} " + ", ".join(n.describe() for n in acted)
    if tools:
        text += " with " + ", ".join(tools)
    for word in sorted(places):
        text += f" {word} " + ", ".join(places[word])
    return text + " -> " + ", ".join(n.describe() for n in (new_outputs or unit.outputs))


def _numbered(tree: TaskTree, used: list[ObjectNode] | None, say) -> str:
    """The header, the kitchen nodes used, then each unit as `say` words it, numbered from 1."""
    lines = [_header(tree)]
    if used is not None:
        lines.append("from the kitchen: " + ("; ".join(n.describe() for n in used) or "nothing"))
    if not tree.units:
        lines.append("nothing to do: the goal is already available")
    lines += [f"{i}. {say(u)}{_beyond(u)}" for i, u in enumerate(tree.units, start=1)]
    return "\n".join(lines) + "\n"


def _beyond(unit: FunctionalUnit) -> str:
    """` (beyond FOON: ...)` after an assumed transfer unit's step (`model.where.beyond_foon`), else nothing."""
    where = beyond_foon(unit)
    return f" (beyond FOON: poured over for FOON's unit at {where}, whose words leave it in another holder)" \
        if where else ""


def _recipe(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    """The steps in a cook's words (`recipe_text`, with the `surfaces` of the tree's units), numbered as `steps`
    numbers them."""
    on = surfaces(tree.units)
    return _numbered(tree, used, lambda u: recipe_text(u, on))


def _steps(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    """The steps as FOON nodes (`step_text`)."""
    return _numbered(tree, used, step_text)


# -- FOON text ------------------------------------------------------------------------------------


def _foon(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    header = _header(tree)
    if used is not None:
        header += "\nfrom the kitchen: " + "; ".join(n.describe() for n in used)
    return write_units(tree.units, header=header)


# -- JSON -----------------------------------------------------------------------------------------


def _json(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    data: dict = {
        "goal": node_to_dict(tree.goal),
        "level": tree.level,
        "units": len(tree.units),
        "steps": [
            {"step": i, "text": step_text(u) + _beyond(u), "motion": u.motion.label,
             "inputs": [node_to_dict(n) for n in u.inputs],
             "outputs": [node_to_dict(n) for n in u.outputs]}
            for i, u in enumerate(tree.units, start=1)
        ],
    }
    if used is not None:
        data["from_kitchen"] = [node_to_dict(n) for n in used]
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def no_tree_json(goal: str, method: str, status: str, reason: str, hints: Sequence[str] = (),
                 additions: Iterable[Iterable[ObjectNode]] = ()) -> str:
    """`--format json` for a goal with no tree: the batch row's `goal`, `status` and `reason` (the words after the
    text output's `cannot make ...:`), the `method`, the `hints` (its `hint:` lines' words) and the kitchen
    `additions` its reason names (each a way: the nodes to add, in the node schema of the tree's steps)."""
    data = {"goal": goal, "status": status, "method": method, "reason": reason, "hints": list(hints),
            "additions": [[node_to_dict(n) for n in way] for way in additions]}
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


# -- Graphviz -------------------------------------------------------------------------------------


def _quote(text: str) -> str:
    """A DOT double-quoted string (escapes backslashes and quotes; newlines become \\n)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def _node_label(node: ObjectNode) -> str:
    if not node.states:
        return node.label
    return node.label + "\n" + "\n".join(s.describe() for s in node.states)


def _legend() -> list[str]:
    """A legend cluster: what each colour and shape means."""
    items = [
        ("legend_kitchen", "from the kitchen", f'shape=ellipse, style=filled, fillcolor="{INPUT_COLOUR}"'),
        ("legend_made", "made by a step", f'shape=ellipse, style=filled, fillcolor="{OUTPUT_COLOUR}"'),
        ("legend_motion", "step (motion)", f'shape=box, style=filled, fillcolor="{MOTION_COLOUR}"'),
        ("legend_goal", "goal", f'shape=ellipse, style=filled, fillcolor="{OUTPUT_COLOUR}", penwidth=3'),
        ("legend_utensil", "utensil (drawn once per use)",
         f'shape=ellipse, style="filled,dashed", fillcolor="{INPUT_COLOUR}"'),
    ]
    lines = ["  subgraph cluster_legend {", '    label="legend"; fontsize=10; color="#999999";']
    lines += [f"    {name} [label={_quote(text)}, {style}];" for name, text, style in items]
    lines.append("    " + " -> ".join(name for name, _, _ in items) + " [style=invis];")
    lines.append("  }")
    return lines


def _dot(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    """The tree as a graph: objects -> motion -> objects, with a legend.

    A kitchen object that several steps use (a knife, a cutting board) would pull edges from
    all over the diagram into one node; it is drawn once per use instead (dashed), next to
    its step, and its unchanged pass-through output is not drawn again.
    """
    made = {n for u in tree.units for n in u.outputs if n not in u.inputs}
    uses: dict[ObjectNode, int] = {}
    for u in tree.units:
        for n in dict.fromkeys(u.inputs):
            if n not in made:
                uses[n] = uses.get(n, 0) + 1
    per_use = {n for n, k in uses.items() if k > 1 and n != tree.goal}
    shared = sorted(per_use)
    nodes = sorted(({n for u in tree.units for n in u.inputs + u.outputs} | {tree.goal}) - per_use)
    ids = {n: f"o{i}" for i, n in enumerate(nodes)}
    lines = [
        "digraph task_tree {",
        f"  graph [label={_quote(_header(tree))}, labelloc=t, rankdir=TB];",
        '  node [fontname="Helvetica", fontsize=10];',
        *_legend(),
    ]
    for n in nodes:
        colour = OUTPUT_COLOUR if n in made else INPUT_COLOUR
        extra = ", penwidth=3" if n == tree.goal else ""
        lines.append(f"  {ids[n]} [label={_quote(_node_label(n))}, shape=ellipse, style=filled, "
                     f'fillcolor="{colour}"{extra}];')
    for i, u in enumerate(tree.units, start=1):
        lines.append(f"  m{i} [label={_quote(f'{i}. {u.motion.label}')}, shape=box, style=filled, "
                     f'fillcolor="{MOTION_COLOUR}"];')
        for n in dict.fromkeys(u.inputs):
            if n in per_use:
                copy = f"t{shared.index(n)}_{i}"
                lines.append(f"  {copy} [label={_quote(_node_label(n))}, shape=ellipse, "
                             f'style="filled,dashed", fillcolor="{INPUT_COLOUR}"];')
                lines.append(f"  {copy} -> m{i};")
            else:
                lines.append(f"  {ids[n]} -> m{i};")
        lines += [f"  m{i} -> {ids[n]};" for n in dict.fromkeys(u.outputs) if n not in per_use]
    lines.append("}")
    return "\n".join(lines) + "\n"


def _svg(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    dot = shutil.which("dot")
    if dot is None:
        raise MissingDependencyError("Graphviz 'dot' is not installed",
                                     "`make install` installs the Debian package graphviz; "
                                     "the dot format gives the graph source without it")
    try:
        done = subprocess.run([dot, "-Tsvg"], input=_dot(tree, used), capture_output=True, text=True,
                              timeout=120, check=False)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise FoonError(f"Graphviz 'dot' failed: {exc}") from None
    if done.returncode != 0:
        raise FoonError(f"Graphviz 'dot' failed: {done.stderr.strip()}")
    return done.stdout


_RENDER = {"steps": _steps, "recipe": _recipe, "foon": _foon, "json": _json, "dot": _dot, "svg": _svg}
