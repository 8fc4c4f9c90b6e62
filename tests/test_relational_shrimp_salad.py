"""The shrimp mango salad's vinaigrette: the mix at `0048-shrimp-mango_salad.txt:76` leaves no node of the lemon
juice and the olive oil, and the mix at `:254`, on the bowl's path, takes those nodes again (`list_drops`). Read
as still in the bowl, as `instances` reads them, FOON's plan as counted makes the oil's pour (`:4`) and the
lemon's chain (`:16` to `:50`) once; read as consumed into the vinaigrette, it made them twice."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from relational_checks import clean_dish_plan

from foon2pddl.io.files import load
from foon2pddl.model.goal import resolve_goal, spec_of_node
from foon2pddl.model.kitchen import default_kitchen
from foon2pddl.pddl.compile import compile_goal

DATA = Path(__file__).parent / "data" / "foon-subgraphs"
SALAD = DATA / "0048-shrimp-mango_salad.txt"
NOODLES = DATA / "0044-egg_noodles_from_scratch.txt"


def test_the_vinaigrettes_lemon_and_oil_are_made_once():
    outcome = clean_dish_plan(SALAD)
    labels = Counter(x.label for x in outcome.task.instances)
    assert (labels["lemon"], labels["lemon juice"], labels["squeezer"]) == (1, 1, 1)
    foon, _ = load([SALAD])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    instances = compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "instances")
    assert len(outcome.task.objects) <= len(instances.task.objects)


def test_a_node_made_again_between_is_not_what_stayed():
    """The egg noodles' stir at `0044-egg_noodles_from_scratch.txt:118` mixes the flour into the dough; the stir at
    `:162` takes `flour (sifted, in [bowl])` again, but the pour at `:155` made that node again between them: new
    flour, not the first still in the bowl (the pair stays checked)."""
    foon, _ = load([NOODLES])
    dish = sorted(x for x in foon.nodes if x.dish is not None)[0]
    task = compile_goal(foon, default_kitchen(foon), resolve_goal(spec_of_node(dish), foon), "relational").task
    assert ("bowl", "flour") not in task.gaps
