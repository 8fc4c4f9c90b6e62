"""What a node says, as words, and how two nodes' words compare: the tests a stitch (`input_stitch`) reads a node
by, and a way back's (`count_returns`) `said_less`.

A node says its states, a `contains` list item by item, and a state with a word in parentheses as both words;
places are one place by two names when both nodes name one, so most comparisons leave them aside.
"""

from __future__ import annotations

from functools import lru_cache

from ..model.foon import ObjectNode, State, make_state
from ..model.places import place_of

__all__ = ["rest_same", "said_less", "unsaid_by", "words_only_added"]


@lru_cache(maxsize=1 << 16)
def _said(node: ObjectNode, placed: bool = True) -> frozenset:
    """What a node says, as words: its states, a `contains` list item by item (`contains {a, b}` says `a` and
    `b`), a state with a word in parentheses as both words (`off (ready)` says `off` and `ready`); places only
    when `placed` is False. Cached per node (its states are its identity): `count_returns`' ways back ask it of
    the same few hundred nodes millions of times (3.7 million calls in GEN trial 10 goal 57)."""
    return frozenset(w for x in node.states if not (placed and x.label in ("in", "on"))
                     for w in ([("contains", i) for i in (*x.ingredients, x.related) if i] if x.label == "contains"
                               else _qualified(x)))


def _qualified(state: State) -> tuple[State, ...]:
    """`off (ready)` as `off` and `ready` (FOON's one state of that form: the switch is off, the appliance is
    ready); any other state as itself."""
    head, paren, rest = state.label.partition(" (")
    if not paren or not rest.endswith(")") or state.related or state.ingredients:
        return (state,)
    return make_state(head), make_state(rest[:-1])


def unsaid_by(a: ObjectNode, b: ObjectNode) -> tuple[str, ...]:
    """What `a` says and `b` does not, described (a list's items as one `contains {...}`); places only when `b`
    names none (else they are one place by two names)."""
    extra = _said(a, place_of(b) is not None) - _said(b, False)
    items = sorted(w[1] for w in extra if isinstance(w, tuple))
    return tuple(sorted(w.describe() for w in extra if not isinstance(w, tuple))) + (
        (f"contains {{{', '.join(items)}}}",) if items else ())


def said_less(node: ObjectNode, made: ObjectNode) -> bool:
    """Whether `node` says less than `made` and nothing else (places aside): the uncover's `pot (contains {soup},
    covered [pot lid], on [stove])` for the cover's `pot (contains {soup}, covered [pot lid], hot, on [stove])`."""
    return _said(node) < _said(made)


def rest_same(a: ObjectNode, b: ObjectNode) -> bool:
    """Whether two nodes say the same but their lists."""
    return {x for x in _said(a, False) if not isinstance(x, tuple)} == {x for x in _said(b, False) if not isinstance(x, tuple)}


def words_only_added(node: ObjectNode, made: ObjectNode) -> bool:
    """Whether reading `made` for `node` only assumes words (`node` says all `made` says, and more: `uncooked`, or
    more items of a list, the omelette that lists the egg mixture it was made of beside the bacon), or only drops
    the contents list of a node that names no contents (`soup broth (in [pot])` for the stirred broth that lists
    its stocks): never a state against its opposite (`uncooked` for `cooked`). Places aside (they are one)."""
    said, was = _said(node), _said(made)
    dropped = was - said
    return not dropped or (said <= was and all(isinstance(w, tuple) for w in dropped)
                           and not any(isinstance(w, tuple) for w in said))
