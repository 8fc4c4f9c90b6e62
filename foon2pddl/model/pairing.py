"""Object roles of a functional unit: which input node becomes which output node.

The `instances` encoding gives every object a unit touches one role, i.e. one
parameter of the unit's action, bound to a physical instance:

* **moved**: an input node paired with an output node of the same label that it
  becomes (`onion (whole)` -> `onion (chopped)`): the instance leaves the first
  node's state for the second's;
* **kept**: an input node that reappears unchanged among the outputs (a knife
  listed on both sides): the instance must be in that state and stays there;
* **read-only**: an input node with no output of its label left to pair with
  (a carton poured from, a utensil FOON omits from the outputs): the instance
  must be in that state and stays there (FOON does not say what became of it,
  so it is not consumed);
* **new**: an output node with no input of its label left (the juice a
  squeeze makes): the action brings a not-yet-made instance into being.

Pairing rule, per label: among all (input, output) pairs of that label, the
pair of identical nodes first, then the greatest number of shared states, then
of shared ingredients (`bowl (contains {a})` becomes `bowl (contains {a, b})`),
then of shared ingredients that no input FOON marks as in motion (its motion identifier,
1: a scoop of bacon, `bacon (fried, in [skillet])` marked 1, from `skillet (contains
{bacon})` into `skillet (contains {white sauce})` gives `skillet (contains {white
sauce, bacon})`: the white sauce was there already, the bacon is what the hand moves), then the input FOON
does not mark as in motion itself (the chocolate chips scraped from the bowl marked 1 into the bowl of
batter marked 0: the batter's bowl is the one that lists both after), ties broken by input position then output
position (the order FOON lists them in);
pairs are taken greedily, each node at most once. Ambiguity: when a unit has
several inputs of one label and fewer outputs (two bowls combined into one), the
rule picks the input most like the output as the one that "becomes" it; FOON
does not say which physical object it was. A node listed twice on one side
is two objects: at levels 1 and 2, two nodes that differ only in what the
level leaves out (`levels.project_unit`: the two bowls of a pour are both
`bowl (contains)` at level 2). A line written twice in a file is one object:
the readers keep it once (`io.parser`, `io.jsonio`; in the public data,
`0019-garlic-parmesan_chicken.txt:64` lists `breadcrumb (in [bowl])` twice).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum
from functools import cached_property, lru_cache

from .foon import FunctionalUnit, ObjectNode
from .places import contents


class RoleKind(StrEnum):
    """How a unit treats one of its objects."""

    MOVED = "moved"
    KEPT = "kept"
    READ_ONLY = "read-only"
    NEW = "new"


@dataclass(frozen=True)
class Role:
    """One object of a unit: its node before (None: new) and after (None: read-only) the unit."""

    label: str
    before: ObjectNode | None
    after: ObjectNode | None

    @cached_property
    def kind(self) -> RoleKind:
        """New, read-only, kept or moved; worked out once per role, as `changes` is (the counts asked it 1.4 million
        times in GEN trial 10 goal 57, each a comparison of two nodes)."""
        if self.before is None:
            return RoleKind.NEW
        if self.after is None:
            return RoleKind.READ_ONLY
        return RoleKind.KEPT if self.before == self.after else RoleKind.MOVED

    @cached_property
    def changes(self) -> bool:
        """Whether the unit changes this object's state (moved or new); worked out once per role (the counts ask it
        of the same roles millions of times: 5.2 million comparisons of two nodes in one GEN experiment cell)."""
        return self.after is not None and self.before != self.after


def _overlap(a: ObjectNode, b: ObjectNode) -> tuple[int, int]:
    """(shared states, shared ingredients): `bowl (contains {a})` is more like `bowl (contains {a, b})`."""
    return len(set(a.states) & set(b.states)), len(a.ingredients & b.ingredients)


@lru_cache(maxsize=1 << 14)
def unit_roles(unit: FunctionalUnit) -> tuple[Role, ...]:
    """The roles of `unit`: one per input (in input order), then one per unpaired output (in order).

    O(k^2 log k) for k nodes of one label (k is tiny in practice); cached per unit.
    """
    inputs, outputs = unit.inputs, unit.outputs
    moving = {n.label for n in inputs if n.motion_flag}  # FOON's motion identifier: the objects the hand moves
    pairs = []
    for i, a in enumerate(inputs):
        for j, b in enumerate(outputs):
            if a.label == b.label:
                states, ingredients = _overlap(a, b)
                resident = len((a.ingredients & b.ingredients) - moving)
                pairs.append((a != b, -states, -ingredients, -resident, a.motion_flag, i, j))
    partner: dict[int, int] = {}
    taken: set[int] = set()
    for *_, i, j in sorted(pairs):
        if i not in partner and j not in taken:
            partner[i] = j
            taken.add(j)
    roles = [Role(a.label, a, outputs[partner[i]] if i in partner else None) for i, a in enumerate(inputs)]
    roles += [Role(b.label, None, b) for j, b in enumerate(outputs) if j not in taken]
    return tuple(roles)


def transfer(sides: Sequence[tuple[ObjectNode | None, ObjectNode | None]]) -> tuple[int, int, frozenset[str]] | None:
    """(source, destination, labels moved) over objects given as (before, after) nodes, in order: the first two of
    one label whose contents one loses and the other gains (the lettuce's bowl poured into the dressing's bowl,
    the first left empty). None when no two do. O(n^2) for n objects."""
    known = [(k, a, b) for k, (a, b) in enumerate(sides) if a is not None and b is not None]
    for s, a, b in known:
        lost = contents(a) - contents(b)
        for d, c, e in known:
            moved = lost & (contents(e) - contents(c)) if d != s and c.label == a.label else frozenset()
            if moved:
                return s, d, moved
    return None
