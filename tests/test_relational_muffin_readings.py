"""Two readings of the chocolate chip muffin's units (ACT-0009) that left its relational task without a plan."""

from __future__ import annotations

from node_words import contains, inside, n

from foon2pddl.model.aliases import unit_aliases
from foon2pddl.model.foon import FunctionalUnit, Motion, make_node, make_state
from foon2pddl.model.pairing import unit_roles

BATTER = ("brown sugar", "butter", "milk")


def test_a_name_already_in_the_container_is_no_other_name_for_what_is_poured_in():
    # the bowl lists `brown sugar` before and after the pour of `sugar (granulated, in [bowl])` from the bowl
    # that lists `sugar`: the brown sugar was there already, and the sugar is not in the receiving bowl
    full, sugar_bowl = n("bowl", contains(*BATTER)), n("bowl", contains("sugar"))
    sugar = n("sugar", "granulated", inside("bowl"))
    pour = FunctionalUnit((full, sugar_bowl, sugar), Motion("pour"),
                          (n("bowl", contains(*BATTER, "sugar")), n("bowl", "dirty")))
    assert ("brown sugar", "sugar") not in unit_aliases(pour)
    # the head-noun reading stays where the unit has no word of its own for the role's label
    cup = n("cup", contains("pepper"))
    ground = n("black pepper", "ground", inside("cup"))
    add = FunctionalUnit((cup, ground, n("bowl", "empty")), Motion("pour"), (n("bowl", contains("black pepper")),))
    assert ("pepper", "black pepper") in unit_aliases(add)


def test_of_two_containers_alike_the_one_foon_does_not_mark_as_moving_receives():
    # the chocolate chips are scraped out of the bowl marked 1 (in motion) into the bowl of batter marked 0
    chips_bowl = make_node("bowl", [make_state("contains", "", ("chocolate chip", "flour"))], motion_flag=1)
    chips = n("chocolate chip", make_state("floured", "", ("flour",)), inside("bowl"))
    batter_bowl = make_node("bowl", [make_state("contains", "", ("muffin batter",))], motion_flag=0)
    both = n("bowl", contains("muffin batter", "chocolate chip"))
    scrape = FunctionalUnit((chips_bowl, chips, n("spatula", "clean"), batter_bowl), Motion("scrape"),
                            (both, n("bowl", "dirty"), n("spatula", "dirty")))
    roles = {r.before: r.after for r in unit_roles(scrape) if r.label == "bowl"}
    assert roles[batter_bowl] == both and roles[chips_bowl] == n("bowl", "dirty")
