"""A node's list read through aliases one way (`holder_words.listed_as`), whatever holds the aliases: a unit's
(`unit_words`, through which the unit's flows are read) or a task's (reread60's F5)."""

from __future__ import annotations

from node_words import contains, n

from foon2pddl.model.aliases import unit_aliases
from foon2pddl.model.foon import FunctionalUnit, Motion, make_state
from foon2pddl.model.places import listed
from foon2pddl.pddl.holder_flows import gained
from foon2pddl.pddl.holder_words import aliased, listed_as, mismatches, read_names

GREASED = n("pan", make_state("greased", "", ("butter",)))  # `greased {butter}`: the butter is in the pan
GREASE = FunctionalUnit((n("unsalted butter"), n("pan", "empty")), Motion("grease"), (GREASED,))


def test_a_list_of_another_state_is_read_through_the_units_aliases():
    # the unit's alias reads `butter` as its `unsalted butter`, and its note says so; `aliased` renamed only the
    # lists of `contains` and `with`, so the unit was read as putting a `butter` no role is into the pan
    assert dict(unit_aliases(GREASE)) == {"butter": "unsalted butter"}
    assert "pan lists butter, read as unsalted butter" in mismatches(GREASE)
    assert gained(GREASE) == {("pan", "unsalted butter")}


def test_a_list_read_through_aliases_one_way():
    # `read_names(listed(x))` and `listed(aliased(x))` were two readings, and differed on `greased {butter}`
    alias = {"butter": "unsalted butter", "oil": "olive oil"}
    for node in (GREASED, n("bowl", contains("oil", "salt")), n("pan", contains("oil"), make_state("with", "lid"))):
        assert listed_as(node, alias) == listed(aliased(node, alias)) == read_names(listed(node), alias)
    assert listed_as(GREASED, alias) == {"unsalted butter"}
    assert listed_as(GREASED, {}) == listed(GREASED) == {"butter"}
