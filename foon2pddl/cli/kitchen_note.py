"""The stderr line naming the kitchen a run without `--kitchen` uses, and the other one."""

from __future__ import annotations

from ..model.foon import Foon
from ..model.kitchen import Kitchen, default_kitchen, half_made
from ..model.words import count


def kitchen_note(kitchen: Kitchen, foon: Foon) -> str:
    """`note: kitchen: base (...)` or `note: kitchen: default (...)`: which kitchen `model.kitchen.chosen_kitchen`
    gave (`kitchen`), its size, and how to get the other one with its count of half-made dishes."""
    full = default_kitchen(foon)
    half = len(half_made(foon, kitchen=full))
    if kitchen.nodes != full.nodes:
        return (f"note: kitchen: base (raw ingredients and tools in their base states, {count(len(kitchen.nodes), 'node', grouped=True)}: "
                f"this network merges recipes, and one recipe's start is another's middle); `--kitchen default` "
                f"for the network's default kitchen ({count(len(full.nodes), 'node', grouped=True)}, {count(half, 'half-made dish', grouped=True)} included)")
    base = (f"`--kitchen base` leaves out its {count(half, 'half-made dish', grouped=True)}" if half
            else "the same as `--kitchen base`: no half-made dishes")
    return (f"note: kitchen: default (the network's default kitchen, {count(len(kitchen.nodes), 'node', grouped=True)}: what no unit "
            f"makes, and inputs in base states); {base}")
