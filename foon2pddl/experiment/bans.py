"""Random constraints for the experiment's ban axis and for tests: k motions, j objects banned.

`random_bans(foon, kitchen, seed, motions=k, objects=j)` draws, with its own seeded
generator, `k` distinct motion labels of the network (uniformly: "k of the robot's
motions are unavailable") and `j` distinct object labels of the kitchen's nodes (the
ingredients and tools the cook may have to do without). Sorted pools, so the draw
depends only on the network, the kitchen and the seed; `k` larger than the pool bans
every motion. The same seed with a larger `k` bans a superset (prefix of one shuffle),
so success can only fall as `k` grows within a trial.

The experiment's ban axis (`--sweep banned-motions=0,5,10`, `--sweep excluded-objects=0,2,4`;
`params.py`) filters the network read, before the REG/EXP/GEN views are built, with one
draw per network (`AXIS_SEED`): every trial, network and solver faces the same bans.
"""

from __future__ import annotations

import random

from ..analysis.constraints import removal
from ..model.constraints import Constraint, Constraints, Kind, make_constraints
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, spec_of_node
from ..model.kitchen import Kitchen, default_kitchen


def _prefix(pool: list[str], count: int, rng: random.Random) -> list[str]:
    order = sorted(pool)
    rng.shuffle(order)
    return order[:count]


def random_bans(foon: Foon, kitchen: Kitchen, seed: int, motions: int = 0, objects: int = 0) -> Constraints:
    """`motions` motion bans and `objects` object bans drawn with `seed` (module doc)."""
    motion_pool = list(foon.motions)
    object_pool = sorted({n.label for n in kitchen.nodes})
    chosen = [Constraint(Kind.WITHOUT_MOTION, m, f"seed {seed}")
              for m in _prefix(motion_pool, motions, random.Random(f"{seed}:motions"))]
    chosen += [Constraint(Kind.WITHOUT, x, f"seed {seed}")
               for x in _prefix(object_pool, objects, random.Random(f"{seed}:objects"))]
    return make_constraints(chosen)


def sample_pairs(foon: Foon, kitchen: Kitchen, count: int, seed: int) -> list[tuple[ObjectNode, Constraints]]:
    """`count` seeded (goal node, constraints) pairs for checking native retrieval against planners.

    Goals from the goal pool; constraints: `random_bans` with 0-6 motions and 0-2 objects, and
    half of the time one more ban of a motion or an object of the goal's unconstrained `complete`
    tree (so bans often matter), a quarter of the time a must-use object of the kitchen.
    """
    from ..retrieval.api import retrieve
    from .protocol import goal_pool

    rng = random.Random(seed)
    pool = goal_pool(foon, kitchen)
    labels = sorted({n.label for n in kitchen.nodes})
    pairs = []
    for i in range(count):
        node = rng.choice(pool)
        base = random_bans(foon, kitchen, rng.randrange(1 << 30), rng.randint(0, 6), rng.randint(0, 2))
        extra: list[Constraint] = []
        if rng.random() < 0.5:
            tree = retrieve(foon, kitchen, Goal(spec_of_node(node), (node,), foon.level), "complete").tree
            if tree is not None and tree.units:
                unit = rng.choice(tree.units)
                if rng.random() < 0.5:
                    extra.append(Constraint(Kind.WITHOUT_MOTION, unit.motion.label, f"pair {i}"))
                else:
                    extra.append(Constraint(Kind.WITHOUT, rng.choice(sorted(unit.inputs)).label, f"pair {i}"))
        if rng.random() < 0.25:
            extra.append(Constraint(Kind.MUST_USE, rng.choice(labels), f"pair {i}"))
        pairs.append((node, make_constraints((*base.items, *extra))))
    return pairs


#: Seed of the experiment's ban axis: one draw per network, so k + 1 bans are k bans plus one.
AXIS_SEED = 0


def ban_motions(foon: Foon, k: int) -> Foon:
    """The network without the units of `k` random motions (the `banned-motions` sweep parameter)."""
    return removal(foon, random_bans(foon, default_kitchen(foon), AXIS_SEED, motions=k)).network


def exclude_objects(foon: Foon, k: int) -> Foon:
    """The network without the units mentioning `k` random objects of its default kitchen
    (the `excluded-objects` sweep parameter)."""
    return removal(foon, random_bans(foon, default_kitchen(foon), AXIS_SEED, objects=k)).network
