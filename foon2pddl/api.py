"""The public Python API: the CLI's pipeline as functions, for notebooks and scripts.

Load a network (files, directories, or the embedded example), build or read a
kitchen, resolve a goal, then retrieve a task tree natively, compile PDDL in any
registered encoding, or plan with any planner; render the task tree as numbered
steps, FOON text, JSON, DOT or SVG. Every function takes a `Network` (from
`load_network`) or a plain `Foon`.

>>> import foon2pddl as fp
>>> net = fp.load_network()                 # the embedded example: 9 recipes
>>> kitchen = fp.load_kitchen(net)          # its example kitchen
>>> goal = fp.resolve_goal(net, "guacamole")
>>> found = fp.retrieve(net, kitchen, goal, method="optimal")
>>> len(found.tree)
20
>>> print(fp.render_tree(found.tree, "steps").splitlines()[1])
1. pick-and-place cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from .generalize.categories import CategoryIndex
from .io.inputs import Network
from .io.inputs import load_kitchen as _load_kitchen
from .io.inputs import load_network as _load_network
from .io.kitchen_files import read_node_lines
from .io.rates import Rates
from .io.tree_formats import render_tree
from .model.foon import Foon, ObjectNode
from .model.goal import Goal, GoalSpec
from .model.goal import resolve_goal as _resolve_goal
from .model.kitchen import Kitchen
from .pddl.compile import ENCODINGS
from .pddl.compile import compile_goal as _compile_goal
from .pddl.registry import Compiled
from .pddl.render import render
from .planners import DEFAULT_PLANNER
from .planners.solve import PlanOutcome
from .planners.solve import plan as _plan
from .retrieval.api import retrieve as _retrieve
from .retrieval.result import Retrieval

__all__ = ["ENCODINGS", "Compiled", "Foon", "Goal", "Kitchen", "Network", "PlanOutcome", "Retrieval", "compile_goal",
           "kitchen_of", "load_kitchen", "load_network", "plan", "render_tree", "resolve_goal", "retrieve", "to_pddl",
           "to_up_problem"]


def _foon(network: Network | Foon, level: int) -> Foon:
    return network.at(level) if isinstance(network, Network) else network


def load_network(*paths: str | Path) -> Network:
    """The universal FOON of FOON files and directories (merged, duplicates removed); none: the embedded example.

    >>> net = load_network()
    >>> len(net.foon.units), net.is_example
    (101, True)
    """
    return _load_network(paths)


def load_kitchen(network: Network, path: str | Path | None = None, level: int = 3) -> Kitchen:
    """The kitchen file at `path` (JSON, FOON O/S lines, or one node per line) at `level`.

    Without a path: the example kitchen for the example network, else the network's
    default kitchen (every object that no unit makes, in its starting states).

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


def resolve_goal(network: Network | Foon, goal: str | GoalSpec, level: int = 3) -> Goal:
    """The goal `'label'`, `'label: state, state [obj]'` or `'label: contains {a, b}'`: the network's nodes it matches.

    Raises UsageError naming close labels when nothing matches.

    >>> resolve_goal(load_network(), "lemonade").candidates[0].label
    'lemonade'
    """
    from .io.goal_files import parse_goal_spec

    spec = parse_goal_spec(goal) if isinstance(goal, str) else goal
    return _resolve_goal(spec, _foon(network, level))


def retrieve(network: Network | Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal, method: str = "complete",
             *, level: int = 3, rates: Rates | None = None, **limits: int) -> Retrieval:
    """Native task tree retrieval by `method` (greedy, complete, optimal, weighted; `limits`: budget, node_limit).

    >>> net = load_network()
    >>> r = retrieve(net, load_kitchen(net), resolve_goal(net, "lemonade"))
    >>> r.found, r.reason
    (False, <RetrievalStatus.UNREACHABLE: 'unreachable'>)
    """
    return _retrieve(_foon(network, level), kitchen, goal, method, rates=rates, **limits)


def compile_goal(network: Network | Foon, kitchen: Kitchen, goal: Goal, encoding: str = "tree", *, level: int = 3,
            prune: bool = True, costs: str | None = None, rates: Rates | None = None,
            category_index: CategoryIndex | None = None) -> Compiled:
    """The goal compiled in a registered encoding (`ENCODINGS`): the task and how its plans map back.

    >>> net = load_network()
    >>> c = compile_goal(net, load_kitchen(net), resolve_goal(net, "guacamole"), "foon-compat")
    >>> c.task.domain, c.foon_semantics
    ('universal_foon', True)
    """
    foon = network.foon if isinstance(network, Network) and ENCODINGS[encoding].lifted else _foon(network, level)
    return _compile_goal(foon, kitchen, goal, encoding, level, prune=prune, costs=costs, rates=rates,
                         category_index=category_index)


def to_pddl(compiled: Compiled) -> tuple[str, str]:
    """The (domain, problem) PDDL text of a compiled goal.

    >>> net = load_network()
    >>> domain, problem = to_pddl(compile_goal(net, load_kitchen(net), resolve_goal(net, "guacamole")))
    >>> domain.splitlines()[0]
    '; foon2pddl, encoding tree, level 3: 37 of 101 units after relevance pruning'
    """
    return render(compiled.task)


def to_up_problem(compiled: Compiled):
    """The compiled goal as a unified-planning `Problem` (imports unified-planning: about 1.5 s)."""
    from .pddl.up_problem import to_up_problem as _to_up

    return _to_up(compiled.task)


def plan(network: Network | Foon, kitchen: Kitchen, goal: Goal, encoding: str = "tree", *, level: int = 3,
         planner: str = DEFAULT_PLANNER, planner_cmd: str | None = None, optimal: bool = False,
         time_limit: float | None = 300.0, prune: bool = True, costs: str | None = None, rates: Rates | None = None,
         category_index: CategoryIndex | None = None, up_validate: bool = False) -> PlanOutcome:
    """Compile, run a planner (Fast Downward, a unified-planning engine, or a command), map the plan to a task tree.

    >>> net = load_network()
    >>> out = plan(net, load_kitchen(net), resolve_goal(net, "lemonade"), "gen-lifted")
    >>> out.status, len(out.tree)
    (<PlanStatus.SOLVED: 'solved'>, 7)
    """
    foon = network.foon if isinstance(network, Network) and ENCODINGS[encoding].lifted else _foon(network, level)
    return _plan(foon, kitchen, goal, encoding, level, planner=planner, planner_cmd=planner_cmd, optimal=optimal,
                 time_limit=time_limit, prune=prune, costs=costs, rates=rates, category_index=category_index,
                 up_validate=up_validate)
