"""The experiment protocol: seeded random kitchens and goals, per trial.

As in the seed paper's evaluation: each trial draws a kitchen (a random subset
of the available objects) and goals (random nodes some unit produces), and
every network and solver is asked the same goals from the same kitchen.

- Kitchen: `kitchen_fraction` of the network's default kitchen (`kitchen.default_kitchen`),
  drawn by shuffling its sorted nodes with the trial's kitchen seed and keeping
  a prefix, so a smaller fraction gives a subset of a larger one (same seed).
- Goals: the goal pool is every node some unit produces that is not in the
  default kitchen (starting nodes and base-state inputs such as `mixer (off)`
  are excluded); the pool, sorted, is shuffled with the trial's goal seed and
  the first `goals` are taken, so asking for more goals extends the sample.
- Seeds: derived from the master seed, the trial number and the purpose by
  SHA-256 (`derive_seed`), so a trial can be regenerated alone and runs are
  reproducible across processes and Python versions.
"""

from __future__ import annotations

import hashlib
import random
from dataclasses import dataclass

from ..errors import UsageError
from ..generalize.expand import DEFAULT_THRESHOLD
from ..generalize.modes import DEFAULT_MODE, check_mode
from ..model.foon import Foon, ObjectNode
from ..model.kitchen import Kitchen, default_kitchen

#: Fraction of the default kitchen in a trial's kitchen (see docs/experiment.md for the sensitivity).
DEFAULT_KITCHEN_FRACTION = 0.9
DEFAULT_TRIALS = 10
DEFAULT_GOALS = 100
DEFAULT_SEED = 0


@dataclass(frozen=True)
class Protocol:
    """What varies between experiments: counts, kitchen fraction, master seed, hierarchy level, EXP threshold,
    EXP's similarity mode (`generalize.modes`) and the physical objects per kitchen item with which returned
    trees are scheduled (`planners.executable.schedule`)."""

    trials: int = DEFAULT_TRIALS
    goals: int = DEFAULT_GOALS
    kitchen_fraction: float = DEFAULT_KITCHEN_FRACTION
    seed: int = DEFAULT_SEED
    level: int = 3
    threshold: float = DEFAULT_THRESHOLD
    similarity: str = DEFAULT_MODE
    objects_per_item: int = 1

    def __post_init__(self) -> None:
        check_mode(self.similarity)
        if self.objects_per_item < 1:
            raise UsageError(f"objects per kitchen item must be at least 1, not {self.objects_per_item!r}")
        if self.trials < 1 or self.goals < 1:
            raise UsageError("trials and goals must be at least 1")
        if not 0.0 < self.kitchen_fraction <= 1.0:
            raise UsageError(f"kitchen fraction must be in (0, 1], not {self.kitchen_fraction!r}")
        if not 0.0 < self.threshold <= 1.0:
            raise UsageError(f"similarity threshold must be in (0, 1], not {self.threshold!r}")

    def identity(self) -> dict:
        """The parameters results depend on (counts excluded: more trials or goals extend a run).

        The threshold appears only when it is not the default, and the similarity mode
        only when it is not `paper` (the only rule before it was a parameter), and the objects
        per item only when not 1, so results written before either was a parameter keep their identity.
        """
        out = {"kitchen_fraction": self.kitchen_fraction, "seed": self.seed, "level": self.level}
        if self.threshold != DEFAULT_THRESHOLD:
            out["threshold"] = self.threshold
        if self.similarity != "paper":
            out["similarity"] = self.similarity
        if self.objects_per_item != 1:
            out["objects_per_item"] = self.objects_per_item
        return out


@dataclass(frozen=True)
class Trial:
    """One trial: its seeds, its kitchen (at the protocol's level) and its goal nodes."""

    index: int
    kitchen_seed: int
    goal_seed: int
    kitchen: Kitchen
    goals: tuple[ObjectNode, ...]

    def summary(self) -> dict:
        """Seeds, sizes and goals, as recorded in protocol.json."""
        return {"trial": self.index, "kitchen_seed": self.kitchen_seed, "goal_seed": self.goal_seed,
                "kitchen_nodes": len(self.kitchen), "goals": [g.describe() for g in self.goals]}


def derive_seed(seed: int, trial: int, purpose: str) -> int:
    """A 32-bit seed for one purpose of one trial, stable everywhere."""
    digest = hashlib.sha256(f"{seed}:{trial}:{purpose}".encode()).digest()
    return int.from_bytes(digest[:4], "big")


def goal_pool(foon: Foon, kitchen: Kitchen | None = None) -> tuple[ObjectNode, ...]:
    """Nodes some unit produces that are not in `kitchen` (default: the default kitchen), sorted."""
    kitchen = kitchen if kitchen is not None else default_kitchen(foon)
    return tuple(sorted(n for n in foon.producers if n not in kitchen.nodes))


def shuffled_prefix(items: tuple[ObjectNode, ...], count: int, seed: int) -> tuple[ObjectNode, ...]:
    """The first `count` items after a seeded shuffle of `items` (sorted first, so input order never matters)."""
    order = sorted(items)
    random.Random(seed).shuffle(order)
    return tuple(order[:count])


def sample_kitchen(kitchen: Kitchen, fraction: float, seed: int) -> Kitchen:
    """`fraction` of `kitchen`'s nodes (rounded, at least one), chosen by `seed`."""
    count = max(1, round(fraction * len(kitchen)))
    nodes = shuffled_prefix(tuple(kitchen.nodes), count, seed)
    return Kitchen(frozenset(nodes), kitchen.level, f"{fraction:g} of the default kitchen, seed {seed}")


def make_trial(foon: Foon, protocol: Protocol, index: int, full: Kitchen | None = None,
               pool: tuple[ObjectNode, ...] | None = None) -> Trial:
    """Trial `index` of `protocol` over `foon` (the REG network at the protocol's level); `full` and
    `pool`, the default kitchen and the goal pool, when the caller has them already."""
    full = full if full is not None else default_kitchen(foon)
    pool = pool if pool is not None else goal_pool(foon, full)
    kitchen_seed = derive_seed(protocol.seed, index, "kitchen")
    goal_seed = derive_seed(protocol.seed, index, "goals")
    kitchen = sample_kitchen(full, protocol.kitchen_fraction, kitchen_seed)
    goals = shuffled_prefix(pool, protocol.goals, goal_seed)
    return Trial(index, kitchen_seed, goal_seed, kitchen, goals)


@dataclass(frozen=True)
class Draw:
    """Every trial of a protocol over one network, and what they were drawn from."""

    kitchen: Kitchen  # the network's default kitchen
    pool: tuple[ObjectNode, ...]  # the goal pool, sorted
    trials: tuple[Trial, ...]


def draw(foon: Foon, protocol: Protocol) -> Draw:
    """Every trial of `protocol` (numbered from 1), the default kitchen and goal pool computed once."""
    full = default_kitchen(foon)
    pool = goal_pool(foon, full)
    return Draw(full, pool, tuple(make_trial(foon, protocol, i, full, pool) for i in range(1, protocol.trials + 1)))


def make_trials(foon: Foon, protocol: Protocol) -> tuple[Trial, ...]:
    """Every trial of `protocol` (numbered from 1)."""
    return draw(foon, protocol).trials


def identity_difference(old, new: dict) -> str:
    """What differs between two protocol identities, in words (`seed 7 there, 8 here`; the inputs' hash
    is named as input files, not shown)."""
    if not isinstance(old, dict):
        return "its protocol file names no identity"
    words = []
    for key in sorted(set(old) | set(new)):
        if old.get(key) == new.get(key):
            continue
        name = key.replace("_", " ")
        if key == "inputs":
            words.append("the input files differ (other FOON files or other contents)")
        elif key not in old:
            words.append(f"{name} {new[key]} here, not set there")
        elif key not in new:
            words.append(f"{name} {old[key]} there, not set here")
        else:
            words.append(f"{name} {old[key]} there, {new[key]} here")
    return "; ".join(words) or "the identities differ"
