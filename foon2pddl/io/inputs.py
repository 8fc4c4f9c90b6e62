"""Loading what a command works on: network, kitchen, goal (I/O edge shared by the CLI)."""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import ParseWarning, UsageError
from ..model.foon import Foon
from ..model.levels import check_level, project
from .files import load

if TYPE_CHECKING:  # kitchens and goals load when used: `stats` and `merge` need neither
    from ..model.goal import Goal, GoalSpec
    from ..model.kitchen import Kitchen


def example_path(name: str = "example") -> Path:
    """Path inside the embedded example: `example` (directory of recipes) or `example_kitchen.txt`."""
    return Path(str(resources.files("foon2pddl") / "data" / name))


def flat_paths(given: Iterable[object], who: str) -> tuple[Path, ...]:
    """`given` as paths, each a path or a list (tuple) of paths, flattened one level (the API's call with a
    list, as the CLI's PATHS take several); UsageError naming `who` and the item for anything else. O(paths)."""
    def path(x: object) -> Path:
        if isinstance(x, (str, os.PathLike)):
            return Path(x)
        raise UsageError(f"{who}: {x!r} is not a path (give files and directories, or lists of them)")

    return tuple(path(x) for g in given for x in (g if isinstance(g, (list, tuple)) else (g,)))


@dataclass(frozen=True)
class Network:
    """A loaded network at level 3 with its warnings and the paths it came from."""

    foon: Foon
    warnings: tuple[ParseWarning, ...]
    paths: tuple[str, ...]
    is_example: bool = False

    def at(self, level: int) -> Foon:
        """The network projected to `level`."""
        return project(self.foon, check_level(level))


def load_network(paths: Sequence[str | Path], skip_invalid: bool = False) -> Network:
    """Merge the FOON files under `paths`, or the embedded example when none is given
    (`skip_invalid`: files that fail to parse are skipped with a warning, see `files.load`)."""
    if not paths:
        foon, warnings = load([example_path()])
        return Network(foon, warnings, (str(example_path()),), True)
    foon, warnings = load(paths, skip_invalid=skip_invalid)
    return Network(foon, warnings, tuple(str(p) for p in paths))


def load_kitchen(path: str | Path | None, network: Network, level: int) -> Kitchen:
    """The kitchen file given; `base` (raw ingredients and tools, `model.kitchen.base_kitchen`) or `default`
    (`default_kitchen`) when no such file exists; the example kitchen for the example network; else the
    kitchen `model.kitchen.chosen_kitchen` picks (base on a merge of recipes with half-made dishes)."""
    from ..model.kitchen import BASE_KITCHEN, DEFAULT_KITCHEN, base_kitchen, chosen_kitchen, default_kitchen
    from .kitchen_files import read_kitchen

    named = {BASE_KITCHEN: base_kitchen, DEFAULT_KITCHEN: default_kitchen}
    if path is not None and str(path) in named and not Path(path).exists():
        return named[str(path)](network.at(level))
    if path is None and network.is_example:
        path = example_path("example_kitchen.txt")
    if path is None:
        return chosen_kitchen(network.at(level))
    kitchen = read_kitchen(path)
    if kitchen.scene:  # a scene's nodes are completed against the network (`model.scene`)
        from .scene_file import placed_scene

        kitchen = placed_scene(kitchen, network.foon)
    return kitchen.project(level)


def load_goal_spec(goal: str | None, goal_file: str | Path | None) -> GoalSpec:
    """The goal from its text or from a goal file; exactly one must be given (UsageError otherwise)."""
    if (goal is None) == (goal_file is None):
        raise UsageError("give exactly one goal: as text or as a goal file")
    from .goal_files import parse_goal_spec, read_goal_file

    if goal_file is not None:
        return read_goal_file(goal_file)
    try:
        return parse_goal_spec(goal or "")
    except ValueError as exc:
        raise UsageError(f"{exc}: {goal!r}") from None


def load_goal(goal: str | None, goal_file: str | Path | None, foon: Foon) -> Goal:
    """Resolve the user's goal against a network (at the network's level)."""
    from ..model.goal import resolve_goal

    return resolve_goal(load_goal_spec(goal, goal_file), foon)
