"""A synthetic FOON of any size, for scaling benchmarks (10k .. 1M units), written as FOON text.

`write_synthetic(path, units, seed)` writes `units` functional units in recipes of `STEPS`
units each. Recipe r builds `dish r` step by step: every unit takes the dish in its last
state (from the second step on), one base ingredient in a container and a utensil, and
outputs the dish in its next state (holding the ingredients so far) and the utensil used.
Base ingredients, containers, utensils and motions come from fixed pools shared by all
recipes, so hub nodes (`knife clean`, `salt in [bowl]`) have consumers in every recipe,
as real universal FOONs do; one recipe in `SIDE_EVERY` also takes another recipe's
finished dish as input (cross-recipe dependencies). Deterministic for a seed: byte-identical
files. Every dish's last state (`dish r` with `STEPS` steps done) is reachable from the
base states, which form the default kitchen.
"""

from __future__ import annotations

import random
from pathlib import Path

STEPS = 10
SIDE_EVERY = 7
INGREDIENTS = [f"ingredient {i}" for i in range(400)]
CONTAINERS = [f"container {i}" for i in range(40)]
UTENSILS = [f"utensil {i}" for i in range(60)]
MOTIONS = [f"motion {i}" for i in range(80)]


def goal_of(recipe: int) -> str:
    """The `--goal` text of recipe `recipe`'s finished dish."""
    return f"dish {recipe}: step {STEPS}"


def _dish(recipe: int, step: int, ingredients: list[str]) -> str:
    line = f"O\tdish {recipe}\t1\nS\tstep {step}\n"
    if ingredients:
        line += "S\tcontains\t{" + ",".join(ingredients) + "}\n"
    return line


def write_synthetic(path: Path, units: int, seed: int = 0) -> int:
    """Write a synthetic FOON of `units` units (rounded up to whole recipes) to `path`; return the recipe count."""
    rng = random.Random(seed)
    recipes = -(-units // STEPS)
    finished: list[list[str]] = []
    with path.open("w", encoding="utf-8", newline="\n") as out:
        for r in range(recipes):
            used: list[str] = []
            side = r - 1 - rng.randrange(min(r, 50)) if r and r % SIDE_EVERY == 0 else None
            for step in range(STEPS):
                ingredient = rng.choice(INGREDIENTS)
                container = rng.choice(CONTAINERS)
                utensil = rng.choice(UTENSILS)
                block = ["//\n"]
                if step:
                    block.append(_dish(r, step, used))
                block.append(f"O\t{ingredient}\t1\nS\tin\t[{container}]\n")
                block.append(f"O\t{container}\t0\nS\tcontains\t{{{ingredient}}}\n")
                block.append(f"O\t{utensil}\t0\nS\tclean\n")
                if side is not None and step == STEPS - 1:
                    block.append(_dish(side, STEPS, finished[side]))
                block.append(f"M\t{rng.choice(MOTIONS)}\n")
                used = sorted({*used, ingredient})
                block.append(_dish(r, step + 1, used))
                block.append(f"O\t{container}\t0\nS\tempty\n")
                block.append(f"O\t{utensil}\t0\nS\tdirty\n")
                out.write("".join(block))
            finished.append(used)
        out.write("//\n")
    return recipes
