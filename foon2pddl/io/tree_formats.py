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
from collections.abc import Iterable

from ..errors import FoonError, MissingDependencyError, UsageError
from ..model.foon import FunctionalUnit, ObjectNode
from ..model.kitchen import Kitchen
from ..model.pairing import transfer, unit_roles
from ..model.places import contents
from ..model.tasktree import TaskTree
from .jsonio import node_to_dict
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

#: State labels that, naming another input as their related object, say where a step happens.
PLACE_WORDS = ("on", "in", "inside", "into", "onto", "under", "over", "above", "below")


def render_tree(tree: TaskTree, fmt: str, kitchen: Kitchen | Iterable[ObjectNode] | None = None) -> str:
    """The tree in `fmt` (one of FORMATS). `kitchen`, when given, lists what the tree takes from it.

    >>> from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
    >>> unit = FunctionalUnit((make_node("onion", [make_state("whole")]), make_node("knife")), Motion("chop"),
    ...                       (make_node("onion", [make_state("chopped")]), make_node("knife")))
    >>> print(render_tree(TaskTree((unit,), make_node("onion", [make_state("chopped")]), 3), "steps"), end="")
    task tree for onion (chopped): 1 units, level 3
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
    return f"task tree for {tree.goal.describe()}: {len(tree.units)} units, level {tree.level}"


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


#: How a recipe says where an object goes, per place state.
_INTO = {"in": "into", "inside": "into", "into": "into", "on": "onto", "onto": "onto", "under": "under",
         "over": "over", "above": "above", "below": "below"}


def _place(node: ObjectNode) -> tuple[str, str] | None:
    """(place word, related object) of the node's first place state, or None."""
    return next(((s.label, s.related) for s in node.states if s.label in PLACE_WORDS and s.related), None)


def _unplaced(node: ObjectNode) -> str:
    """The node in words without its place state (`lime juice`, `lime (whole)`)."""
    states = [s.describe() for s in node.states if not (s.label in PLACE_WORDS and s.related)]
    return node.label + (f" ({', '.join(states)})" if states else "")


def _without_contents(node: ObjectNode, contents: set[str]) -> str:
    """The node in words without an ingredient set listing only `contents` (said already)."""
    states = [s.describe() for s in node.states if not (s.ingredients and set(s.ingredients) <= contents)]
    return node.label + (f" ({', '.join(states)})" if states else "")


def _filled(unit: FunctionalUnit, new: dict[str, ObjectNode], before: dict[str, ObjectNode],
            moved: set[str]) -> list[tuple[ObjectNode, tuple[str, str] | None, tuple[str, str]]]:
    """(input, its place, (`in`, container)) for each input that a container's new node newly lists while the
    unit gives it no node of its own (0001's `pour*`: the cream and the sugar only in the mixing bowl's list);
    not an input already in it, or beside it in one holder (stirred in the pot where both are). An input two
    containers newly list goes into the one inside another of them (0071's cream into the pudding in the tray),
    else into the first: each input is said once."""
    into: dict[ObjectNode, list[str]] = {}
    for label, container in new.items():
        if label not in before:
            continue
        added = contents(container) - contents(before[label])
        for i in unit.inputs:
            if (i.label in added and i.label not in new and i.label not in moved
                    and (_place(i) or ("", ""))[1] != label and not (_place(i) and _place(i) == _place(before[label]))):
                into.setdefault(i, []).append(label)
    out = []
    for i, labels in into.items():
        inner = [c for c in labels if (_place(new[c]) or ("", ""))[1] in labels]
        out.append((i, _place(i), ("in", (inner or labels)[0])))
    return out


def _between(unit: FunctionalUnit) -> tuple[list[ObjectNode], ObjectNode, ObjectNode] | None:
    """(what moves, from which container, into which) when two inputs of one container label trade contents
    (`model.pairing.transfer` over the unit's roles, which say which input becomes which output). None otherwise."""
    roles = unit_roles(unit)
    found = transfer([(r.before, r.after) for r in roles])
    if found is None:
        return None
    src, dst, moved = found
    return [i for i in unit.inputs if i.label in moved], roles[src].before, roles[dst].before


def recipe_text(unit: FunctionalUnit) -> str:
    """A step in a cook's words: what moves, from where, into what, with which tool, and what it makes.

    `pour sugar (granulated) into the pitcher (contains {lime juice})`, where `step_text` lists the
    pitcher first as if it were poured. An input moves when its output of the same label is in a
    place state (`in [pitcher]`) other than its own; the containers named so, and the contents of
    moved objects, are not tools. Without a move: what changes, then the tools and the place, said
    once (`cut lime (whole), with the knife, on the cutting board`). Labels no input has are what the
    step makes.
    """
    new = {o.label: o for o in unit.outputs if o not in unit.inputs}
    by_label = {i.label: i for i in unit.inputs}
    moves = [(i, _place(i), _place(new[i.label])) for i in unit.inputs
             if i.label in new and _place(new[i.label]) not in (None, _place(i))]
    moves += _filled(unit, new, by_label, {i.label for i, _, _ in moves})
    named = {i.label for i, _, _ in moves} | {p[1] for _, a, b in moves for p in (a, b) if p}
    between = None if moves else _between(unit)
    if between:  # two containers of one label: `pour lettuce from the bowl (...) into the bowl (...)`
        what, src, dst = between
        text = (f"{unit.motion.label} " + ", ".join(_unplaced(i) for i in what)
                + f" from the {src.describe()} into the {dst.describe()}")
        named = {src.label} | {i.label for i in what}
    elif moves:
        parts: list[tuple[list[str], str]] = []  # (what moves from where, into what): one destination said once
        for i, src, dst in moves:
            phrase = _unplaced(i) + (f" from the {src[1]}" if src else "")
            where = by_label.get(dst[1])
            into = f"{_INTO.get(dst[0], dst[0])} the {where.describe() if where else dst[1]}"
            if parts and parts[-1][1] == into:
                parts[-1][0].append(phrase)
            else:
                parts.append(([phrase], into))
        text = f"{unit.motion.label} " + "; ".join(
            (", ".join(what[:-1]) + " and " if len(what) > 1 else "") + f"{what[-1]} {into}" for what, into in parts)
    else:
        receivers = {p[1] for o in new.values() if o.label not in by_label and (p := _place(o))}
        changed = ([i for i in unit.inputs if i.label in new and i.label not in receivers]
                   or [i for i in unit.inputs if i.label in new] or list(unit.inputs))
        named = {i.label for i in changed}
    holders = {i.label for i, _, _ in moves} | named
    rest = [i for i in unit.inputs if i.label not in named
            and not any(s.label in PLACE_WORDS and s.related in holders for s in i.states)]
    places = [i for i in rest if any(_place(n) and _place(n)[1] == i.label for n in unit.inputs)]
    tools = [i for i in rest if i not in places]
    if not moves and not between:  # a place said once: `cut lime (whole), with the knife, on the cutting board`
        at = {p.label for p in places}
        text = f"{unit.motion.label} " + ", ".join(_unplaced(i) if (_place(i) or ("", ""))[1] in at
                                                   else i.describe() for i in changed)
    if tools:
        text += ", with the " + ", ".join(t.describe() for t in tools)
    if places:
        text += ", on the " + ", ".join(_without_contents(p, holders) for p in places)
    made = [o for label, o in sorted(new.items()) if label not in by_label]
    if made:
        text += ", making " + ", ".join(_unplaced(o) + (f" {p[0]} the {p[1]}" if (p := _place(o)) else "")
                                        for o in made)
    return text


def _numbered(tree: TaskTree, used: list[ObjectNode] | None, say) -> str:
    """The header, the kitchen nodes used, then each unit as `say` words it, numbered from 1."""
    lines = [_header(tree)]
    if used is not None:
        lines.append("from the kitchen: " + ("; ".join(n.describe() for n in used) or "nothing"))
    if not tree.units:
        lines.append("nothing to do: the goal is already available")
    lines += [f"{i}. {say(u)}" for i, u in enumerate(tree.units, start=1)]
    return "\n".join(lines) + "\n"


def _recipe(tree: TaskTree, used: list[ObjectNode] | None) -> str:
    """The steps in a cook's words (`recipe_text`), numbered as `steps` numbers them."""
    return _numbered(tree, used, recipe_text)


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
            {"step": i, "text": step_text(u), "motion": u.motion.label,
             "inputs": [node_to_dict(n) for n in u.inputs],
             "outputs": [node_to_dict(n) for n in u.outputs]}
            for i, u in enumerate(tree.units, start=1)
        ],
    }
    if used is not None:
        data["from_kitchen"] = [node_to_dict(n) for n in used]
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
