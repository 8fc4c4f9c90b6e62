"""What FOON's own words say about where an object is and what a container holds.

FOON writes relations into states: `onion (chopped, in [bowl])` names the onion's
place, `bowl (contains {onion, salt})` the bowl's contents. These readers are the
one reading of those words, shared by the encodings that model holders and the
independent replay that checks their plans (so both read FOON alike, and only the
plan's facts can make them disagree).

>>> from .foon import make_node, make_state
>>> onion = make_node("onion", [make_state("chopped"), make_state("in", "bowl")])
>>> places(onion), place_of(onion)
(((<Relation.IN: 'in'>, 'bowl'),), (<Relation.IN: 'in'>, 'bowl'))
>>> bowl = make_node("bowl", [make_state("contains", "", ["onion", "salt"])])
>>> sorted(listed(bowl)), describes_contents(bowl), describes_contents(onion)
(['onion', 'salt'], True, False)
"""

from __future__ import annotations

from functools import lru_cache

from .foon import ObjectNode, State, make_node, make_state
from .physical import Relation

__all__ = ["CONTENT_STATES", "contents", "describes_contents", "head_of", "holds_unsaid", "listed", "moved_into", "named_holder", "place_of", "place_state", "places"]

#: The states that say what is in or on an object: `contains {a, b}`, `empty`, `with [foil]`.
CONTENT_STATES = frozenset({"contains", "empty", "with"})


def head_of(name: str, label: str) -> bool:
    """`name` and `label` name one thing by the head-noun rule: one is the other's last words (`salad` /
    `carrot salad`, `pan` / `cooking pan`, `black pepper` / `pepper`)."""
    return label != name and (label.endswith(" " + name) or name.endswith(" " + label))


def named_holder(state: State) -> str:
    """The one object a state names as where something is, whatever its word: its related object (`[bowl]`), else
    the one object it lists (`{pizza dough}`: the public data's braces around one holder); "" for none."""
    return state.related or (state.ingredients[0] if len(state.ingredients) == 1 else "")


def place_state(state: State) -> tuple[Relation, str] | None:
    """The place one state names: `(in, bowl)` for `in [bowl]`, `(on, stove)` for `on [stove]`, and for `on
    {pizza dough}`, the public data's braces around one holder (`named_holder`); None for any other state (a bare
    `on` is an appliance switched on, not a place)."""
    holder = named_holder(state) if state.label in ("in", "on") else ""
    return (Relation(state.label), holder) if holder else None


#: Nodes whose reading `places`, `listed` and `describes_contents` remember (nodes are immutable; an encoding reads each many times).
READ_KEPT = 1 << 16


@lru_cache(maxsize=READ_KEPT)
def places(node: ObjectNode | None) -> tuple[tuple[Relation, str], ...]:
    """The places a node names, in order (`place_state`)."""
    if node is None:
        return ()
    return tuple(p for s in node.states if (p := place_state(s)) is not None)


def place_of(node: ObjectNode | None) -> tuple[Relation, str] | None:
    """The node's first place (`(in, bowl)` for `in [bowl]`), None when it names none."""
    named = places(node)
    return named[0] if named else None


@lru_cache(maxsize=READ_KEPT)
def listed(node: ObjectNode | None) -> frozenset[str]:
    """The labels a node lists: the ingredients and related objects of its `contains` states, the related
    object of a `with` state (`baking tray (with [aluminium foil])`: the foil is on the tray), and the
    ingredients of any other state (`cooking pan (greased {butter})`: the butter is in the pan; the next
    node that lists only the pork chop says the butter went into it)."""
    if node is None:
        return frozenset()
    items = {i for s in node.states if s.label == "contains" for i in (*s.ingredients, s.related) if i}
    items |= {s.related for s in node.states if s.label == "with" and s.related}
    items |= {i for s in node.states if s.label not in ("in", "on") for i in s.ingredients}
    return frozenset(items - {node.label})


def contents(node: ObjectNode) -> frozenset[str]:
    """The ingredients a node's `contains` states list (`bowl (contains {egg, salt})`: egg, salt); narrower than
    `listed`, for words about what moves between containers."""
    return frozenset(i for s in node.states if s.label == "contains" for i in s.ingredients)


def holds_unsaid(node: ObjectNode | None) -> bool:
    """Whether the node has a `contains` that names nothing: FOON's level 2 keeps the state and drops its list
    (`bowl (contains {onion, salt})` is `bowl (contains)` there), and `0082-homemade_cheese_pizza.txt:492` writes one
    at level 3. It says that the object holds something, not what: no list of nothing (that is `empty`)."""
    return node is not None and any(s.label == "contains" and not s.related and not s.ingredients for s in node.states)


@lru_cache(maxsize=READ_KEPT)
def describes_contents(node: ObjectNode | None) -> bool:
    """Whether the node says what is in or on the object (`contains`, `empty`, `with`): a node that does not
    (`cutting board (dirty)`, `bowl (clean)`), or that `holds_unsaid` (what it holds is left out, beside whatever
    else it names), is silent about its contents, and nothing is checked of them."""
    return node is not None and any(s.label in CONTENT_STATES for s in node.states) and not holds_unsaid(node)


def moved_into(node: ObjectNode, holder: str, relation: Relation = Relation.IN) -> ObjectNode:
    """`node` with its place replaced by `relation [holder]` (an implied node: `pddl.holders` rule 3)."""
    kept = [s for s in node.states if place_state(s) is None]
    return make_node(node.label, [*kept, make_state(relation.value, holder)])
