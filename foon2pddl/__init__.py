"""foon2pddl: FOON functional object-oriented networks to PDDL, with native task tree retrieval.

The public Python API (the `api` package), importable from the package itself:

>>> import foon2pddl as fp
>>> net = fp.load_network()                       # files and directories, or none: the embedded example
>>> kitchen = fp.load_kitchen(net)
>>> goal = fp.resolve_goal(net, "guacamole")
>>> tree = fp.retrieve(net, kitchen, goal, method="optimal").tree
>>> len(tree), tree.goal.label
(20, 'guacamole')
>>> domain, problem = fp.to_pddl(fp.compile_goal(net, kitchen, goal, "state"))
>>> fp.plan(net, kitchen, goal).status
<PlanStatus.SOLVED: 'solved'>

The names are loaded on first use, so `import foon2pddl` stays cheap.
"""

__version__ = "0.1.0"

#: Public names, each from `api` (loaded on first access).
__all__ = ["ENCODINGS", "Compiled", "Constraints", "Foon", "Goal", "GoalPlan", "GoalRow", "Kitchen", "Network",
           "PlanOutcome", "Retrieval", "__version__", "compile_goal", "constraints_of", "kitchen_of", "load_kitchen",
           "load_network", "plan", "plan_goals", "render_tree", "resolve_goal", "retrieve", "retrieve_goals",
           "run_experiment", "skill_plan", "to_pddl", "to_up_problem"]


def __getattr__(name: str) -> object:
    if name in __all__:
        from . import api

        return getattr(api, name)
    raise AttributeError(f"module 'foon2pddl' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
