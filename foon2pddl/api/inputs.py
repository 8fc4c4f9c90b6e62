"""The Python API's inputs: networks, kitchens, goals and constraints, from files, node texts or plain values.

`load_network` and `load_kitchen` read what the command line's PATHS and `--kitchen` read; `kitchen_of`
builds a kitchen from node texts, `resolve_goal` finds a goal's nodes, `constraints_of` gathers what
`--without-motion`, `--without` and `--must-use` say. `foon_at`, `network_of` and `goal_spec` are how the
other API modules take a `Network` or a plain `Foon`, and a goal in any of its forms.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from ..errors import UsageError
from ..io.inputs import Network, flat_paths
from ..io.inputs import load_kitchen as _load_kitchen
from ..io.inputs import load_network as _load_network
from ..io.kitchen_files import read_node_lines
from ..model.constraints import Constraint, Constraints, Kind, make_constraints
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec
from ..model.goal import resolve_goal as _resolve_goal
from ..model.kitchen import Kitchen


def foon_at(network: Network | Foon, level: int) -> Foon:
    """The network's FOON at `level` (a plain `Foon` as given)."""
    return network.at(level) if isinstance(network, Network) else network


def network_of(network: Network | Foon) -> Network:
    """A `Network` (a plain `Foon` wrapped, with no files and no warnings)."""
    return network if isinstance(network, Network) else Network(network, (), ())


def goal_spec(goal: Goal | str | GoalSpec) -> GoalSpec:
    """The spec of a goal given as a resolved `Goal`, a goal text or a spec."""
    from ..io.goal_files import parse_goal_spec

    if isinstance(goal, Goal):
        return goal.spec
    return parse_goal_spec(goal) if isinstance(goal, str) else goal


def constraints_of(*, without_motions: Iterable[str] = (), without: Iterable[str] = (),
                   must_use: Iterable[str] = (), rates: Iterable[tuple[str, float]] = ()) -> Constraints:
    """Constraints as the CLI's `--without-motion`, `--without`, `--must-use` give them (and motion rates).

    >>> constraints_of(without=["knife"], must_use=["bowl"]).must_use
    ('bowl',)
    """
    items = [*(Constraint(Kind.WITHOUT_MOTION, m) for m in without_motions),
             *(Constraint(Kind.WITHOUT, x) for x in without), *(Constraint(Kind.MUST_USE, x) for x in must_use)]
    try:
        return make_constraints(items, rates)
    except ValueError as exc:
        raise UsageError(str(exc)) from None


def load_network(*paths: str | Path | list[str | Path] | tuple[str | Path, ...]) -> Network:
    """The universal FOON of FOON files and directories (merged, duplicates removed); none: the embedded example.

    What the command line's PATHS take: each argument a file or directory, or a list (tuple) of them, so
    `load_network("a.txt", "recipes/")` and `load_network(["a.txt", "recipes/"])` are one network. A missing
    path is a FoonInputError; anything else not a path a UsageError naming it.

    >>> net = load_network()
    >>> len(net.foon.units), net.is_example
    (101, True)
    >>> load_network([3])
    Traceback (most recent call last):
    foon2pddl.errors.UsageError: load_network: 3 is not a path (give files and directories, or lists of them)
    """
    return _load_network(flat_paths(paths, "load_network"))


def load_kitchen(network: Network, path: str | Path | None = None, level: int = 3) -> Kitchen:
    """The kitchen file at `path` (JSON, FOON O/S lines, or one node per line) at `level`.

    Without a path: the example kitchen for the example network; else the base kitchen (raw
    ingredients and tools) on a merge of recipes whose default kitchen holds half-made dishes,
    else the network's default kitchen (every object that no unit makes, in its starting states).
    `path` may be `"base"` or `"default"` to choose.

    >>> len(load_kitchen(load_network()).nodes)
    51
    """
    return _load_kitchen(path, network, level)


def kitchen_of(*items: str | ObjectNode, level: int = 3) -> Kitchen:
    """A kitchen from nodes or node texts, one per item as in a kitchen file (`onion: whole`, `knife`).

    >>> sorted(n.describe() for n in kitchen_of("onion: whole", "knife").nodes)
    ['knife', 'onion (whole)']
    """
    nodes = [i for i in items if isinstance(i, ObjectNode)]
    counted = read_node_lines("\n".join(i for i in items if isinstance(i, str)), "<kitchen>")
    nodes += [node for node, _ in counted]
    counts = tuple(sorted((node, k) for node, k in counted if k is not None))
    return Kitchen(frozenset(nodes), 3, counts=counts).project(level)


def resolve_goal(network: Network | Foon, goal: Goal | str | GoalSpec, level: int = 3) -> Goal:
    """The goal `'label'`, `'label: state, state [obj]'` or `'label: contains {a, b}'`: the network's nodes it matches (a resolved `Goal` by its spec, again).

    Raises UsageError naming close labels when nothing matches.

    >>> resolve_goal(load_network(), "lemonade").candidates[0].label
    'lemonade'
    """
    return _resolve_goal(goal_spec(goal), foon_at(network, level))
