"""The public Python API: the CLI's pipeline as functions, for notebooks and scripts.

Load a network (files, directories, or the embedded example), build or read a
kitchen, resolve a goal, then retrieve a task tree natively, compile PDDL in any
registered encoding, or plan with any planner; render the task tree as numbered
steps, FOON text, JSON, DOT or SVG. Every function takes a `Network` (from
`load_network`) or a plain `Foon`. As on the command line, `retrieve` and `plan`
take constraints (`constraints_of`), a network kind (`network_kind`: `reg`, `exp`,
`gen`, any registered `generalize.network.NETWORKS` entry) and, for Fast Downward,
a search configuration; `retrieve_goals` and `plan_goals` answer many goals on one
loaded network; `run_experiment` runs the experiment.
The modules: `inputs` (network, kitchen, goal, constraints), `solve` (what one
goal gets: retrieval, PDDL, a plan, robot skills), `batches` (many goals, and
the experiment); this package re-exports their public names.

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

from ..io.inputs import Network
from ..io.tree_formats import render_tree
from ..model.constraints import Constraints
from ..model.foon import Foon
from ..model.goal import Goal
from ..model.kitchen import Kitchen
from ..pddl.compile import ENCODINGS
from ..pddl.registry import Compiled
from ..planners.solve import PlanOutcome
from ..retrieval.batch import GoalRow
from ..retrieval.result import Retrieval
from .batches import GoalPlan, plan_goals, retrieve_goals, run_experiment
from .inputs import constraints_of, kitchen_of, load_kitchen, load_network, resolve_goal
from .solve import compile_goal, plan, retrieve, skill_plan, to_pddl, to_up_problem

__all__ = ["ENCODINGS", "Compiled", "Constraints", "Foon", "Goal", "GoalPlan", "GoalRow", "Kitchen", "Network",
           "PlanOutcome", "Retrieval", "compile_goal", "constraints_of", "kitchen_of", "load_kitchen", "load_network",
           "plan", "plan_goals", "render_tree", "resolve_goal", "retrieve", "retrieve_goals", "run_experiment",
           "skill_plan", "to_pddl", "to_up_problem", "batches", "inputs", "solve"]
