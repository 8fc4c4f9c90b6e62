"""The quantified effects by which a `relational` action consumes what it does not name: what was in or on an
object the unit consumes (and what was on that: the salt on the bean mix spread on the bread made into the
sandwich), what else of a label sits in a holder whose list drops it, what FOON restates as made, a dusting.

Each sweep is (holder variable, node, relation, name word, name key): every object in `node` that is `relation`
the holder becomes `consumed` and leaves it, by one conditional effect quantified over objects of the node's
label. A sweep keyed `inside` (the contents of a consumed object) reaches one level further: what is in or on
such an object in a node placed there goes too, by one effect quantified over both (a two-level `forall`; the
objects of two labels, not a parameter per possible holder). O(sweeps x nodes placed in their labels).
"""

from __future__ import annotations

from collections.abc import Callable

from ..model.foon import ObjectNode
from ..model.physical import Relation
from .encode_instances import IS
from .task import Atom, Conditional

__all__ = ["CONSUMED", "Sweep", "sweep_effects"]

#: The state constant of an object that became part of a mixture.
CONSUMED = "consumed"

#: (holder variable, node, relation to the holder, name word, name key) of one sweep.
Sweep = tuple[str, ObjectNode, Relation, str, tuple]


def sweep_effects(sweeps: list[Sweep], name: Callable[[str, tuple], str], const: dict[ObjectNode, str],
                  type_of: dict[str, str], inside: dict[str, list[tuple[ObjectNode, Relation]]]) -> list[Conditional]:
    """The conditional effects of `sweeps` (module doc); `name(word, key)` names a variable, `inside` gives per
    label the nodes placed in or on one."""
    out = []
    for h, node, rel, word, key in sweeps:
        if node.label not in type_of:
            continue
        c = f"?{name(word, key)}"
        there, was = Atom(rel.value, (h, c)), Atom(IS, (c, const[node]))
        out.append(Conditional((there, was), add=(Atom(IS, (c, CONSUMED)),), delete=(there, was), var=c,
                               type=type_of[node.label]))
        for deep, rel2 in (inside.get(node.label, ()) if key[0] == "inside" else ()):
            if deep.label in type_of and deep != node:
                d = f"?{name(f'{deep.label} on {word}', (*key, deep))}"
                on, was2 = Atom(rel2.value, (c, d)), Atom(IS, (d, const[deep]))
                out.append(Conditional((there, was, on, was2), add=(Atom(IS, (d, CONSUMED)),), delete=(on, was2),
                                       var=d, type=type_of[deep.label], more=((c, type_of[node.label]),)))
    return out
