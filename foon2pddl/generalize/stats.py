"""Statistics of REG, EXP and GEN side by side: the seed paper's table of nodes per level."""

from __future__ import annotations

from collections.abc import Mapping

from ..analysis.stats import level_row
from ..io.steps import Step, silent_step
from ..model.foon import Foon
from ..model.levels import LEVELS, project
from ..model.words import count


def levels_table(networks: Mapping[str, Foon], step: Step = silent_step) -> list[dict[str, int | str]]:
    """One row per network and level: object nodes, motion nodes (= units), in the order given; each row
    in `step` (a series: a projection of a large network takes seconds)."""
    rows: list[dict[str, int | str]] = []
    names = " and ".join(networks)
    for name, foon in networks.items():
        for level in LEVELS:
            with step(f"counting the nodes of {names} at each level: {name} ({count(len(foon.units), 'unit', grouped=True)}) at level "
                      f"{level}", series=f"counting the nodes of {names}"):
                rows.append({"network": name, **level_row(project(foon, level))})
    return rows


def format_levels_table(rows: list[dict[str, int | str]]) -> str:
    """Markdown table: network, level, object nodes, motion nodes."""
    lines = ["| network | level | object nodes | motion nodes (units) |", "|---|---|---|---|"]
    lines += [f"| {r['network']} | {r['level']} | {r['object_nodes']} | {r['motion_nodes']} |" for r in rows]
    return "\n".join(lines) + "\n"
