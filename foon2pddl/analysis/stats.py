"""Network statistics: the paper's Table 1 (nodes per level) and label counts."""

from __future__ import annotations

from collections import Counter
from typing import Any

from ..errors import ParseWarning
from ..model.foon import Foon
from ..model.levels import LEVELS, project
from ..model.where import shown_path
from ..model.words import count


def level_row(foon: Foon) -> dict[str, int]:
    """Object nodes, motion nodes (one per unit) and units of a network at its level."""
    return {"level": foon.level, "object_nodes": len(foon.nodes), "motion_nodes": len(foon.units),
            "units": len(foon.units)}


def network_stats(foon: Foon, warnings: tuple[ParseWarning, ...] = ()) -> dict[str, Any]:
    """Everything `foon2pddl stats` reports, as plain data."""
    per_file = Counter(shown_path(s.path) for u in foon.units for s in u.sources)
    states = {s.label for n in foon.nodes for s in n.states}
    return {
        "levels": [level_row(project(foon, lv)) for lv in LEVELS],
        "object_labels": len({n.label for n in foon.nodes}),
        "state_labels": len(states),
        "motion_labels": len(foon.motions),
        "composite_units": sum(u.motion.composite for u in foon.units),
        "units_per_file": dict(sorted(per_file.items())),
        "warnings": [str(w) for w in warnings],
    }


def format_stats(stats: dict[str, Any]) -> str:
    """Plain-text report in the layout of the paper's Table 1."""
    lines = ["level  object nodes  motion nodes"]
    for row in stats["levels"]:
        lines.append(f"{row['level']:>5}  {row['object_nodes']:>12}  {row['motion_nodes']:>12}")
    lines += [
        "",
        f"distinct object labels: {stats['object_labels']}",
        f"distinct state labels:  {stats['state_labels']}",
        f"distinct motion labels: {stats['motion_labels']}",
        f"composite (*) units:    {stats['composite_units']}",
        "",
        f"units per source file ({count(len(stats['units_per_file']), 'file')}):",
    ]
    lines += [f"  {n:>5}  {p}" for p, n in stats["units_per_file"].items()]
    if stats["warnings"]:
        lines += ["", f"warnings ({len(stats['warnings'])}):"] + [f"  {w}" for w in stats["warnings"]]
    return "\n".join(lines) + "\n"
