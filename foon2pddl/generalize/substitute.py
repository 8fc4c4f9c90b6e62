"""Renaming objects inside nodes and units: the one substitution FOON-EXP and lifted GEN share.

A substitution maps whole object labels to labels. It applies to a node's label,
to the related object of each state (`in [bowl]`) and to each item of its
ingredient lists, never to parts of other labels: replacing `lemon` leaves
`lemon juice` alone. Nodes are rebuilt with `make_state`/`make_node`, so
ingredient lists stay sorted and duplicate-free when two items become one.

`product_renames` extends a substitution to what a unit *makes from* the replaced
object: squeezing a lime instead of a lemon makes `lime juice`, not `lemon juice`.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..model.constraints import node_labels
from ..model.foon import FunctionalUnit, ObjectNode, Source, State, make_node, make_state


def substitute_node(node: ObjectNode, mapping: Mapping[str, str]) -> ObjectNode:
    """`node` with every label in `mapping` replaced (attributes other than identity kept).

    Nodes and states that mention no mapped label are kept as they are: they are built
    normalized, so rebuilding them would give equal objects (FOON-EXP renames ~1 in 6).
    """
    def touched(s: State) -> bool:
        return s.related in mapping or any(i in mapping for i in s.ingredients)

    hits = [touched(s) for s in node.states]
    if node.label not in mapping and not any(hits):
        return node
    get = mapping.get
    states = [make_state(s.label, get(s.related, s.related) if s.related else "",
                         (get(i, i) for i in s.ingredients)) if hit else s
              for s, hit in zip(node.states, hits, strict=True)]
    return make_node(get(node.label, node.label), states,
                     motion_flag=node.motion_flag, goal=node.goal, dish=node.dish)


def unit_labels(unit: FunctionalUnit) -> frozenset[str]:
    """Every object label a unit mentions: node labels, related objects and ingredients."""
    return frozenset().union(*(node_labels(n) for n in (*unit.inputs, *unit.outputs)))


def node_mapping(node: ObjectNode, mapping: Mapping[str, str],
                 per_node: Mapping[ObjectNode, Mapping[str, str]] | None = None) -> Mapping[str, str]:
    """`mapping` with the names `per_node` gives `node` itself added (FOON-GEN's readings, `readings.py`)."""
    extra = per_node.get(node) if per_node else None
    return {**mapping, **extra} if extra else mapping


def substitute_unit(unit: FunctionalUnit, mapping: Mapping[str, str], note: str | None = None,
                    to: str | None = None,
                    per_node: Mapping[ObjectNode, Mapping[str, str]] | None = None) -> FunctionalUnit:
    """`unit` with labels replaced in every node (a node in `per_node` also with its own names replaced);
    `note` marks its sources `expanded_from` (and `to`, the label that replaced it, `expanded_to`)."""
    ins = tuple(dict.fromkeys(substitute_node(n, node_mapping(n, mapping, per_node)) for n in unit.inputs))
    outs = tuple(dict.fromkeys(substitute_node(n, node_mapping(n, mapping, per_node)) for n in unit.outputs))
    sources = unit.sources
    if note is not None:
        sources = tuple(Source(s.path, s.line, s.url, note, to) for s in unit.sources) \
            or (Source("", 0, None, note, to),)
    return FunctionalUnit(ins, unit.motion, outs, sources)


def replace_words(label: str, old: str, new: str) -> str | None:
    """`label` with each whole-word occurrence of `old` replaced by `new`; None when there is none
    (or `label` is `old` itself): `lemon juice` -> `lime juice`, but `lemonade` stays."""
    words, target = label.split(), old.split()
    if not target or words == target:
        return None
    out, i, hit = [], 0, False
    while i < len(words):
        if words[i:i + len(target)] == target:
            out.extend(new.split())
            i += len(target)
            hit = True
        else:
            out.append(words[i])
            i += 1
    return " ".join(out) if hit else None


def product_renames(unit: FunctionalUnit, mapping: Mapping[str, str]) -> dict[str, str]:
    """Derived products renamed with their source: the labels of `unit`'s outputs that are no input's
    label and contain a replaced label as whole words, mapped to the same words with the replacement
    (`squeeze lemon -> lemon juice` under lemon -> lime: `lemon juice` -> `lime juice`). A new name the
    unit already mentions is left out (two objects would become one)."""
    inputs = {n.label for n in unit.inputs}
    mentioned = unit_labels(unit)
    out: dict[str, str] = {}
    for n in unit.outputs:
        if n.label in inputs or n.label in mapping or n.label in out:
            continue
        for old, new in sorted(mapping.items()):
            renamed = replace_words(n.label, old, new)
            if renamed is not None and renamed not in mentioned:
                out[n.label] = renamed
                break
    return out


def renames_product_away(unit: FunctionalUnit, old: str, new: str) -> bool:
    """Whether replacing `old` by `new` in `unit` would rename a product away from what it is made of:
    `old` is one of the unit's outputs (no input's label) containing an input's label as whole words,
    and `new` does not (`squeeze lime -> lime juice` with `lime juice` -> `lemon juice`)."""
    inputs = {n.label for n in unit.inputs}
    if old in inputs or all(n.label != old for n in unit.outputs):
        return False
    sources = [x for x in inputs if replace_words(old, x, x) is not None]
    return any(replace_words(new, x, x) is None for x in sources)


def rename_derived(units: tuple[FunctionalUnit, ...], pairs: Mapping[str, str],
                   fixed: frozenset[str] = frozenset()) -> dict[str, str]:
    """Derived products to rename in a tree whose units had objects substituted (`pairs`: old -> new):
    a label a unit makes (no input's label) from a substituted object (`new` among its input labels),
    containing `old` as whole words, is renamed with it (`lemon juice` -> `lime juice` where a lime
    was squeezed); labels in `fixed` (the kitchen's) never. Apply the result to every unit of the
    tree and to its goal, so the product keeps one name throughout."""
    out: dict[str, str] = {}
    for unit in units:
        inputs = {n.label for n in unit.inputs}
        for old, new in sorted(pairs.items()):
            if new not in inputs:
                continue
            for n in unit.outputs:
                if n.label in inputs or n.label in fixed or n.label in out:
                    continue
                renamed = replace_words(n.label, old, new)
                if renamed is not None:
                    out[n.label] = renamed
    return out
