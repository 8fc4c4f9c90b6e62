"""The Python API for one goal: retrieve its task tree natively, compile it to PDDL, plan it, or plan it down to
robot skills, as `foon2pddl retrieve`, `compile` and `plan` (with `--skills`) do.

Each takes a `Network` (`api.inputs.load_network`) or a plain `Foon`, a kitchen and a goal (resolved, or a
goal text), the network kind (`reg`, `exp`, `gen`, any `generalize.network.NETWORKS` entry) and the
constraints (`api.inputs.constraints_of`), and for Fast Downward a search configuration.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from ..errors import UsageError
from ..generalize.categories import CategoryIndex
from ..generalize.network import DEFAULT_NETWORK, NetworkKind, get_network, network_view
from ..io.inputs import Network
from ..io.rates import Rates
from ..model.constraints import Constraints
from ..model.foon import Foon, ObjectNode
from ..model.goal import Goal, GoalSpec
from ..model.kitchen import Kitchen
from ..pddl.compile import compile_goal as _compile_goal
from ..pddl.compile import encoding_named
from ..pddl.registry import Compiled
from ..pddl.render import render
from ..planners import DEFAULT_PLANNER
from ..planners.solve import PlanOutcome
from ..planners.solve import plan as _plan
from ..retrieval.api import retrieve as _retrieve
from ..retrieval.result import Retrieval
from ..skills.run import SkillOutcome
from .inputs import foon_at, goal_spec, network_of, resolve_goal


def retrieve(network: Network | Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal | str,
             method: str = "complete", *, level: int = 3, rates: Rates | None = None,
             constraints: Constraints | None = None, network_kind: str = DEFAULT_NETWORK, **limits: int) -> Retrieval:
    """Native task tree retrieval by `method` (greedy, complete, optimal, weighted; `limits`: budget, node_limit,
    time_limit), on the network of kind `network_kind`, under `constraints` (banned objects are replaced
    by similar ones on EXP, by category members on GEN), as `foon2pddl retrieve` does.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> r = retrieve(net, load_kitchen(net), resolve_goal(net, "lemonade"))
    >>> r.found, r.reason
    (False, <RetrievalStatus.UNREACHABLE: 'unreachable'>)
    >>> retrieve(net, load_kitchen(net), "lemonade", network_kind="gen").found
    True
    """
    kind = get_network(network_kind)
    cons = constraints if constraints is not None else Constraints()
    if kind.as_read and not cons.items:
        goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
        return _retrieve(foon_at(network, level), kitchen, goal, method, rates=rates, **limits)
    from ..retrieval.constrained import retrieve_constrained

    kit = kitchen if isinstance(kitchen, Kitchen) else Kitchen(frozenset(kitchen), level)
    view, target = _view(network, kind, level, kit, cons, goal)
    if kind.as_read or not cons.items:
        return retrieve_constrained(view.foon, view.kitchen, target, cons, method, rates=rates, **limits).result
    from ..generalize.substitution import category_must_use, retrieve_substituted, without_banned

    if view.index is not None:
        cons, _ = category_must_use(cons, view.index, kind.label)
    concrete = {n.label for n in without_banned(kit.project(level), cons).nodes}
    from ..generalize.modes import make_similarity

    sim = view.matrix.or_else(make_similarity) if view.matrix is not None else None  # EXP: WordNet for misses only
    done, _ = retrieve_substituted(kind.name, view.foon, view.kitchen, target, cons, method, index=view.index,
                                   sim=sim, concrete_labels=concrete, rates=rates, **limits)
    return done.result


def _view(network: Network | Foon, kind: NetworkKind, level: int, kitchen: Kitchen, cons: Constraints,
          goal: Goal | str | GoalSpec):
    """The view of `kind` (from the kitchen without its banned objects when the kind substitutes them) and the goal."""
    from ..generalize.network import Substitutes

    kit = kitchen.project(level)
    if cons.items and kind.substitutes is not Substitutes.NONE:
        from ..generalize.substitution import without_banned

        kit = without_banned(kit, cons)
    view = network_view(network_of(network), kind.name, level, kit)
    return view, view.resolve(goal_spec(goal))


def compile_goal(network: Network | Foon, kitchen: Kitchen, goal: Goal, encoding: str = "tree", *, level: int = 3,
            prune: bool = True, costs: str | None = None, rates: Rates | None = None,
            category_index: CategoryIndex | None = None) -> Compiled:
    """The goal compiled in a registered encoding (`ENCODINGS`): the task and how its plans map back.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> c = compile_goal(net, load_kitchen(net), resolve_goal(net, "guacamole"), "foon-compat")
    >>> c.task.domain, c.foon_semantics
    ('universal_foon', True)
    """
    foon = network.foon if isinstance(network, Network) and encoding_named(encoding).lifted else foon_at(network, level)
    return _compile_goal(foon, kitchen, goal, encoding, level, prune=prune, costs=costs, rates=rates,
                         category_index=category_index)


def to_pddl(compiled: Compiled) -> tuple[str, str]:
    """The (domain, problem) PDDL text of a compiled goal.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> domain, problem = to_pddl(compile_goal(net, load_kitchen(net), resolve_goal(net, "guacamole")))
    >>> domain.splitlines()[0]
    '; foon2pddl, encoding tree, level 3: 37 of 101 units after relevance pruning'
    """
    return render(compiled.task)


def to_up_problem(compiled: Compiled):
    """The compiled goal as a unified-planning `Problem` (imports unified-planning: about 1.5 s)."""
    from ..pddl.up_problem import to_up_problem as _to_up

    return _to_up(compiled.task)


def plan(network: Network | Foon, kitchen: Kitchen, goal: Goal | str, encoding: str = "tree", *, level: int = 3,
         planner: str = DEFAULT_PLANNER, planner_cmd: str | None = None, optimal: bool = False,
         time_limit: float | None = 300.0, prune: bool = True, costs: str | None = None, rates: Rates | None = None,
         category_index: CategoryIndex | None = None, up_validate: bool = False,
         constraints: Constraints | None = None, network_kind: str = DEFAULT_NETWORK, alias: str | None = None,
         search: str | None = None, evaluators: Iterable[str] = ()) -> PlanOutcome:
    """Compile, run a planner (Fast Downward, a unified-planning engine, or a command), map the plan to a task tree.

    As `foon2pddl plan`: `constraints`, `network_kind` (a kind with its own encoding, GEN's lifted one,
    plans that encoding over the network as read), and Fast Downward's `alias` or `search` (with
    `evaluators`) as its driver takes them.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> out = plan(net, load_kitchen(net), resolve_goal(net, "lemonade"), "gen-lifted")
    >>> out.status, len(out.tree)
    (<PlanStatus.SOLVED: 'solved'>, 9)
    >>> plan(net, load_kitchen(net), "lemonade", network_kind="gen").status
    <PlanStatus.SOLVED: 'solved'>
    """
    config = _search(planner, planner_cmd, optimal, alias, search, tuple(evaluators))
    kind = get_network(network_kind)
    if kind.encoding is not None:
        if encoding not in ("tree", kind.encoding):
            raise UsageError(f"network kind {kind.name} plans the {kind.encoding} encoding, not {encoding}")
        encoding = kind.encoding
    cons = constraints if constraints is not None else Constraints()
    if encoding_named(encoding).lifted:
        foon = network_of(network).foon
        goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
    elif kind.as_read or kind.encoding is not None:
        foon = foon_at(network, level)
        goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
    else:
        view, goal = _view(network, kind, level, kitchen, cons, goal)
        foon, kitchen = view.foon, view.kitchen
    return _plan(foon, kitchen, goal, encoding, level, planner=planner, planner_cmd=planner_cmd, optimal=optimal,
                 time_limit=time_limit, prune=prune, costs=costs, rates=rates, category_index=category_index,
                 up_validate=up_validate, constraints=cons if cons.items else None, search=config)


def _search(planner: str, planner_cmd: str | None, optimal: bool, alias: str | None, search: str | None,
            evaluators: tuple[str, ...]):
    """Fast Downward's search configuration for the driver-style arguments (None: the default)."""
    if alias is None and search is None and not evaluators:
        return None
    from ..planners.registry import lookup

    if not lookup(planner, planner_cmd).configurable:
        raise UsageError(f"alias, search and evaluators configure Fast Downward, not planner {planner!r}")
    from ..planners.fd import search_config

    try:
        return search_config(alias, search, evaluators, optimal)
    except ValueError as exc:
        raise UsageError(str(exc)) from None


def skill_plan(network: Network | Foon, kitchen: Kitchen, goal: Goal | str, *, skills: str | Path | None = None,
               table: str | Path | None = None, hands: int = 1, without_skills: Iterable[str] = (),
               skill_costs: dict[str, int] | None = None, constraints: Constraints | None = None,
               encoding: str | None = None, level: int = 3, **options) -> SkillOutcome:
    """Plan `goal` and decompose every macro step into robot skills, as `foon2pddl plan --skills` (docs/skills.md).

    `skills`, `table`: a skill domain and a motion table instead of the shipped ones; the robot has
    `hands`, lacks `without_skills` (their motions are banned for the macro planner) and pays
    `skill_costs` (others cost 1). `options` as `planners.solve.plan` takes them. `encoding` None: the
    relational one, falling back to `instances` when it finds no plan (`skills.run`; `.first` is then its
    outcome). `.skills` is the `skills.SkillPlan` (None without a plan), `.json()` the skill list `--format
    json` prints.

    >>> from foon2pddl import load_kitchen, load_network
    >>> net = load_network()
    >>> done = skill_plan(net, load_kitchen(net), "whipped cream")
    >>> done.skills.ok, [c.skill for c in done.skills.calls][:2]
    (True, ['pick', 'pour'])
    """
    from ..skills import Robot, read_domain, read_table, shipped_domain, shipped_table
    from ..skills.run import plan_skills

    domain = read_domain(skills) if skills is not None else shipped_domain()
    motions = read_table(table) if table is not None else shipped_table()
    motions.check(domain)
    cons = constraints if constraints is not None else Constraints()
    robot = Robot.of(hands, (*cons.without_skills, *without_skills), {**dict(cons.skill_costs), **(skill_costs or {})})
    goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
    return plan_skills(foon_at(network, level), kitchen, goal, encoding=encoding, domain=domain, table=motions,
                       robot=robot, constraints=cons, level=level, **options)
