"""A place only a unit feeding nothing names (issue 21, the odd universal half's onion ring): the task keeps the
pizza's pick-and-place of an empty bowl onto a surface (`0085-mini_bacon_egg_breakfast_pizza.txt:104`), whose
labels the counts have, while the pour that takes the bowl on the surface is left out (its measuring cup and flour
are not counted). Nothing the task can do reads the bowl on the surface, yet a surface was added for it: 12 objects
in the problem against `instances`' 11. A holder only such a unit names is not added (`prune.feeding_units`)."""

from __future__ import annotations

import pytest
from conftest import SUBGRAPHS
from node_words import contains, inside, n
from relational_checks import clean_unit_plan, within_instances

from foon2pddl.io.files import load
from foon2pddl.model.foon import Foon, FunctionalUnit, Motion, Source, make_state
from foon2pddl.pddl.prune import feeding_units

ON_SURFACE = make_state("on", "surface")
CRACKED = n("egg", "cracked", inside("bowl"))


def _units() -> tuple[FunctionalUnit, ...]:
    """An egg cracked into an empty bowl (the goal); an empty bowl put on a surface; flour poured from a measuring
    cup into the bowl on the surface (no measuring cup or flour in the kitchen)."""
    return (
        FunctionalUnit((n("bowl", "empty"), n("egg", "uncracked")), Motion("crack"),
                       (n("bowl", contains("egg")), CRACKED), (Source("ring.txt", 54),)),
        FunctionalUnit((n("bowl", "empty"),), Motion("pick-and-place"), (n("bowl", "empty", ON_SURFACE),),
                       (Source("pizza.txt", 104),)),
        FunctionalUnit((n("measuring cup", contains("flour")), n("flour", inside("measuring cup")),
                        n("bowl", "empty", ON_SURFACE)), Motion("pour"),
                       (n("bowl", contains("flour"), ON_SURFACE), n("flour", inside("bowl"))), (Source("pizza.txt", 126),)),
    )


def test_feeding_units_follow_the_takers_back_from_the_targets():
    f = Foon(_units())
    assert feeding_units(f, range(3), [CRACKED]) == {0}
    assert feeding_units(f, range(3), [n("flour", inside("bowl"))]) == {1, 2}
    assert feeding_units(f, (0, 1), [n("flour", inside("bowl"))]) == frozenset()  # its maker not among the units


def test_no_surface_for_a_unit_whose_bowl_on_the_surface_nothing_takes():
    kitchen = {n("bowl", "empty"), n("egg", "uncracked")}
    # unpruned, every unit is the task's: the pick-and-place's labels are counted, the pour's are not
    outcome = clean_unit_plan(_units(), kitchen, CRACKED, prune=False, time_limit=60)
    labels = sorted(x.label for x in outcome.task.instances)
    assert labels == ["bowl", "egg"], labels


@pytest.fixture(scope="module")
def odd():
    """The universal FOON of the odd-index subgraphs."""
    return load(sorted(SUBGRAPHS.iterdir())[1::2])[0]


def test_the_odd_universal_onion_ring_has_no_more_objects_than_instances(odd):
    # 12 objects in the problem at 2714cc5, the surface among them; `instances` 11
    outcome = within_instances(odd, "onion ring")
    assert "surface" not in {x.label for x in outcome.task.instances}
