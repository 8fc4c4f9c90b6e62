"""A unit taking a container's node as it was before a mix in it, listing what the mixture it holds now was made of,
read as the mix left it (`input_stitch._mixed_in`): the caesar salad's sprinkle at `ACT-0080-caesar_salad.txt:345`
takes `bowl (contains {lettuce, crouton, salad dressing})`, which the mix at `:324` moves on to `bowl (contains
{salad mix})` with `salad mix (contains {lettuce, crouton, salad dressing}, in [bowl])`."""

from __future__ import annotations

import re
from pathlib import Path

from node_words import contains, inside, n
from relational_checks import dish_goal, instances_objects, rejected_dish_plan

from foon2pddl.model.foon import Foon, FunctionalUnit, Motion
from foon2pddl.model.goal import Goal, GoalSpec
from foon2pddl.model.kitchen import Kitchen, default_kitchen
from foon2pddl.pddl.compile import compile_goal
from foon2pddl.pddl.input_stitch import stitches
from foon2pddl.planners.solve import plan

DATA = Path(__file__).parent / "data" / "foon-subgraphs"

# the caesar salad's shape (ACT-0080, lines 313-388): the dressing poured onto the lettuce, the two mixed into the
# salad mix, then the parmesan sprinkled into the bowl FOON still lists as lettuce and dressing, and the last mix
# takes the salad mix in that bowl
B_DRESSING, DRESSING = n("bowl", contains("dressing")), n("dressing", inside("bowl"))
B_LETTUCE, LETTUCE = n("bowl", contains("lettuce")), n("lettuce", inside("bowl"))
B_BOTH = n("bowl", contains("lettuce", "dressing"))
B_MIX, MIX = n("bowl", contains("salad mix")), n("salad mix", contains("lettuce", "dressing"), inside("bowl"))
B_PARMESAN, PARMESAN = n("bowl", contains("parmesan")), n("parmesan", "grated", inside("bowl"))
B_ALL = n("bowl", contains("lettuce", "dressing", "parmesan"))
SALAD = n("caesar salad", contains("lettuce", "dressing", "parmesan"), inside("bowl"))
SPOON = n("spoon", "clean")
POUR = FunctionalUnit((B_DRESSING, DRESSING, B_LETTUCE), Motion("pour"), (B_BOTH,))
MIXING = FunctionalUnit((B_BOTH, DRESSING, LETTUCE, SPOON), Motion("mix"), (B_MIX, MIX))
SPRINKLE = FunctionalUnit((B_BOTH, B_PARMESAN, PARMESAN), Motion("sprinkle"), (B_ALL,))
LAST = FunctionalUnit((B_ALL, MIX, PARMESAN, SPOON), Motion("mix"), (n("bowl", contains("caesar salad")), SALAD))
UNITS = (POUR, MIXING, SPRINKLE, LAST)
KITCHEN = (B_DRESSING, DRESSING, B_LETTUCE, LETTUCE, B_PARMESAN, PARMESAN, SPOON)


def test_a_bowl_taken_as_it_was_before_the_mix_is_read_as_the_mix_left_it():
    (found,) = stitches(Foon(UNITS), range(4))
    assert (found.unit, found.node, found.reads_as) == (2, B_BOTH, B_MIX)
    assert "salad mix" in found.describe() and "lettuce" in found.describe()


def test_a_unit_putting_in_what_the_mix_takes_is_read_before_the_mix():
    # the greek salad's grind (`ACT-0034-greek_salad.txt:236`) takes the bowl the mix (`:272`) takes, and puts in
    # the salt the mix mixes in: it comes before the mix, not after it
    salt = n("salt", inside("bowl"))
    grind = FunctionalUnit((B_BOTH, n("grinder", contains("salt"))), Motion("grind"), (B_BOTH, salt))
    mixing = FunctionalUnit((*MIXING.inputs, salt), Motion("mix"), MIXING.outputs)
    assert stitches(Foon((POUR, grind, mixing, LAST)), range(4)) == ()


def test_the_salad_is_mixed_once_in_one_bowl():
    goal = Goal(GoalSpec("caesar salad"), (SALAD,))
    small = compile_goal(Foon(UNITS), Kitchen(frozenset(KITCHEN)), goal, "relational", narrow=True)
    # FOON's own plan fires the pour twice (the mix moves one bowl on, the sprinkle takes another as poured)
    labels = sorted(x.label for x in small.task.instances)
    assert labels.count("lettuce") == 1 and labels.count("dressing") == 1
    # FOON's last mix takes the salad mix `in [bowl]` and makes the salad `in [bowl]`, listing neither in the
    # other's bowl: the plan mixes the salad mix left in the first bowl into a salad made in another, physically
    # wrong (issue 21): the replay rejects it there, and every step before replays right
    outcome = plan(Foon(UNITS), Kitchen(frozenset(KITCHEN)), goal, "relational")
    assert [s.unit.motion.label for s in outcome.trace.steps] == ["pour", "mix", "sprinkle", "mix"]
    assert outcome.status == "error"
    (problem,) = outcome.rejected
    assert re.fullmatch(r"step 4: mix: salad_mix_1 is consumed in (bowl_\d+), but the step makes caesar_salad_1 in "
                        r"(?!\1)bowl_\d+ \[consumed-elsewhere\]", problem), problem


def test_the_caesar_salad_makes_its_dressing_once():
    # counted as FOON's plan fires it, the dressing's blender chain (`:1` to `:199`) fired twice: 44 objects in the
    # problem, `instances` 37. Its plan mixes the salad mix in another bowl than the salad's (`:367`, issue 21)
    # (the small count's plan, and the wide one's tried after it, too)
    path = DATA / "ACT-0080-caesar_salad.txt"
    rejected_dish_plan(path, "367")
    foon, goal = dish_goal(path)
    small = compile_goal(foon, default_kitchen(foon), goal, "relational", narrow=True).task
    assert len(small.objects) <= instances_objects(path)
    assert [x.label for x in small.instances].count("salad dressing") == 1
