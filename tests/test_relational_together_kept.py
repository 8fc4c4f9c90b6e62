"""`count_together` keeps what it finds on a fixpoint while the fixpoint lives: `count_plans._chosen` asks the makers
of the same units for each plan it makes, and the rules ask which nodes a unit needs as often. What is kept must be
what the rules as stated give, asked in any order, and must not outlive or cross fixpoints."""

from __future__ import annotations

from test_relational_first_makers import _scrambled_eggs

from foon2pddl.analysis.reachability import reachable
from foon2pddl.model.foon import Foon
from foon2pddl.pddl import count_together
from foon2pddl.pddl.count_together import makers_together, needs


def _needs_as_stated(reach, u: int, nodes: set[int]) -> bool:
    """The walk back through first achievers from `u`'s inputs, stopping at a node of `nodes`."""
    seen, stack = set(), list(reach.index.inputs[u])
    while stack:
        n = stack.pop()
        if n in nodes:
            return True
        if n not in seen and reach.node_round[n] > 0:
            seen.add(n)
            stack.extend(reach.index.inputs[reach.achiever[n]])
    return False


def test_needs_answers_as_the_walk_for_every_unit_and_node(universal):
    net = universal[0]
    for foon, kitchen in ((Foon(_scrambled_eggs()[0]), _scrambled_eggs()[1]),
                          (net, frozenset(u.inputs[0] for u in net.units[::7]))):
        reach = reachable(foon, kitchen)
        nodes = range(len(reach.index.nodes))
        for u in (*reach.fired[::-1], *range(0, len(foon.units), 5)):
            assert [needs(reach, u, {n}) for n in nodes] == [_needs_as_stated(reach, u, {n}) for n in nodes]
            assert needs(reach, u, set(nodes[::3])) == _needs_as_stated(reach, u, set(nodes[::3]))


def test_makers_together_is_found_once_per_fixpoint_and_unit(monkeypatch):
    found: list[tuple] = []
    real = count_together._makers_together
    monkeypatch.setattr(count_together, "_makers_together", lambda r, u, *a: found.append((id(r), u, *a)) or real(r, u, *a))
    units, kitchen = _scrambled_eggs()
    reach = reachable(Foon(units), kitchen)
    cook = 3  # A's cook and stir: the pan's node and the mixture in it, made by two units (first achievers)
    first = makers_together(reach, cook)
    assert first and makers_together(reach, cook) is first and len(found) == 1
    assert makers_together(reach, cook, True) != first and len(found) == 2  # other flags: found again
    other = reachable(Foon(units), kitchen)  # another fixpoint of the same network and kitchen
    assert makers_together(other, cook) == first and len(found) == 3
    del reach, other
    assert not count_together._KEPT  # none kept once the fixpoints are gone
