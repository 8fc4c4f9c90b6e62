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
from dataclasses import dataclass
from pathlib import Path

from .errors import UsageError
from .generalize.categories import CategoryIndex
from .generalize.network import DEFAULT_NETWORK, NetworkKind, get_network, network_view
from .io.inputs import Network, flat_paths
from .io.inputs import load_kitchen as _load_kitchen
from .io.inputs import load_network as _load_network
from .io.kitchen_files import read_node_lines
from .io.rates import Rates
from .io.tree_formats import render_tree
from .model.constraints import Constraint, Constraints, Kind, make_constraints
from .model.foon import Foon, ObjectNode
from .model.goal import Goal, GoalSpec
from .model.goal import resolve_goal as _resolve_goal
from .model.kitchen import Kitchen
from .pddl.compile import ENCODINGS, encoding_named
from .pddl.compile import compile_goal as _compile_goal
from .pddl.registry import Compiled
from .pddl.render import render
from .planners import DEFAULT_PLANNER
from .planners.solve import PlanOutcome
from .planners.solve import plan as _plan
from .retrieval.api import retrieve as _retrieve
from .retrieval.batch import GoalRow
from .retrieval.result import Retrieval
from .skills.run import SkillOutcome
from .status import BatchStatus, PlanStatus

__all__ = ["ENCODINGS", "Compiled", "Constraints", "Foon", "Goal", "GoalPlan", "GoalRow", "Kitchen", "Network",
           "PlanOutcome", "Retrieval", "compile_goal", "constraints_of", "kitchen_of", "load_kitchen", "load_network",
           "plan", "plan_goals", "render_tree", "resolve_goal", "retrieve", "retrieve_goals", "run_experiment",
           "skill_plan", "to_pddl", "to_up_problem"]


def _foon(network: Network | Foon, level: int) -> Foon:
    return network.at(level) if isinstance(network, Network) else network


def _network(network: Network | Foon) -> Network:
    return network if isinstance(network, Network) else Network(network, (), ())


def _spec(goal: Goal | str | GoalSpec) -> GoalSpec:
    from .io.goal_files import parse_goal_spec

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


def resolve_goal(network: Network | Foon, goal: str | GoalSpec, level: int = 3) -> Goal:
    """The goal `'label'`, `'label: state, state [obj]'` or `'label: contains {a, b}'`: the network's nodes it matches.

    Raises UsageError naming close labels when nothing matches.

    >>> resolve_goal(load_network(), "lemonade").candidates[0].label
    'lemonade'
    """
    from .io.goal_files import parse_goal_spec

    spec = parse_goal_spec(goal) if isinstance(goal, str) else goal
    return _resolve_goal(spec, _foon(network, level))


def retrieve(network: Network | Foon, kitchen: Kitchen | Iterable[ObjectNode], goal: Goal | str,
             method: str = "complete", *, level: int = 3, rates: Rates | None = None,
             constraints: Constraints | None = None, network_kind: str = DEFAULT_NETWORK, **limits: int) -> Retrieval:
    """Native task tree retrieval by `method` (greedy, complete, optimal, weighted; `limits`: budget, node_limit,
    time_limit), on the network of kind `network_kind`, under `constraints` (banned objects are replaced
    by similar ones on EXP, by category members on GEN), as `foon2pddl retrieve` does.

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
        return _retrieve(_foon(network, level), kitchen, goal, method, rates=rates, **limits)
    from .retrieval.constrained import retrieve_constrained

    kit = kitchen if isinstance(kitchen, Kitchen) else Kitchen(frozenset(kitchen), level)
    view, target = _view(network, kind, level, kit, cons, goal)
    if kind.as_read or not cons.items:
        return retrieve_constrained(view.foon, view.kitchen, target, cons, method, rates=rates, **limits).result
    from .generalize.substitution import category_must_use, retrieve_substituted, without_banned

    if view.index is not None:
        cons, _ = category_must_use(cons, view.index, kind.label)
    concrete = {n.label for n in without_banned(kit.project(level), cons).nodes}
    from .generalize.modes import make_similarity

    sim = view.matrix.or_else(make_similarity) if view.matrix is not None else None  # EXP: WordNet for misses only
    done, _ = retrieve_substituted(kind.name, view.foon, view.kitchen, target, cons, method, index=view.index,
                                   sim=sim, concrete_labels=concrete, rates=rates, **limits)
    return done.result


def _view(network: Network | Foon, kind: NetworkKind, level: int, kitchen: Kitchen, cons: Constraints,
          goal: Goal | str | GoalSpec):
    """The view of `kind` (from the kitchen without its banned objects when the kind substitutes them) and the goal."""
    from .generalize.network import Substitutes

    kit = kitchen.project(level)
    if cons.items and kind.substitutes is not Substitutes.NONE:
        from .generalize.substitution import without_banned

        kit = without_banned(kit, cons)
    view = network_view(_network(network), kind.name, level, kit)
    return view, view.resolve(_spec(goal))


def compile_goal(network: Network | Foon, kitchen: Kitchen, goal: Goal, encoding: str = "tree", *, level: int = 3,
            prune: bool = True, costs: str | None = None, rates: Rates | None = None,
            category_index: CategoryIndex | None = None) -> Compiled:
    """The goal compiled in a registered encoding (`ENCODINGS`): the task and how its plans map back.

    >>> net = load_network()
    >>> c = compile_goal(net, load_kitchen(net), resolve_goal(net, "guacamole"), "foon-compat")
    >>> c.task.domain, c.foon_semantics
    ('universal_foon', True)
    """
    foon = network.foon if isinstance(network, Network) and encoding_named(encoding).lifted else _foon(network, level)
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
        foon = _network(network).foon
        goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
    elif kind.as_read or kind.encoding is not None:
        foon = _foon(network, level)
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
    from .planners.registry import lookup

    if not lookup(planner, planner_cmd).configurable:
        raise UsageError(f"alias, search and evaluators configure Fast Downward, not planner {planner!r}")
    from .planners.fd import search_config

    try:
        return search_config(alias, search, evaluators, optimal)
    except ValueError as exc:
        raise UsageError(str(exc)) from None


def retrieve_goals(network: Network | Foon, kitchen: Kitchen, goals: Iterable[str | GoalSpec],
                   method: str = "complete", *, level: int = 3, rates: Rates | None = None,
                   network_kind: str = DEFAULT_NETWORK, **limits: int) -> list[GoalRow]:
    """Many goals on one loaded network (one fixpoint shared), as `retrieve` with several `--goal`: one row each
    (`status`: `status.BatchStatus`; a goal naming no produced node is `unmatched`, not an error).

    >>> net = load_network()
    >>> [str(r.status) for r in retrieve_goals(net, load_kitchen(net), ["guacamole", "lemonade", "unicorn"])]
    ['solved', 'unreachable', 'unmatched']
    """
    from .io.goal_lists import GoalEntry
    from .model.goal import resolve_goal as resolve
    from .retrieval.batch import solve_goals

    view = network_view(_network(network), get_network(network_kind).name, level, kitchen.project(level))
    entries = [GoalEntry(_spec(g), "<goal>", n) for n, g in enumerate(goals, 1)]
    return solve_goals(view.foon, view.kitchen.nodes, entries, lambda spec: resolve(view.map_goal(spec), view.foon),
                       method=method, rates=rates, **limits)


@dataclass(frozen=True)
class GoalPlan:
    """One goal of `plan_goals`: its outcome, or None with the reason it names no produced node."""

    goal: str
    outcome: PlanOutcome | None
    reason: str = ""

    @property
    def status(self) -> PlanStatus | BatchStatus:
        """The outcome's status, or `unmatched` for a goal naming no produced node (as `retrieve_goals` rows say)."""
        return self.outcome.status if self.outcome is not None else BatchStatus.UNMATCHED


def plan_goals(network: Network | Foon, kitchen: Kitchen, goals: Iterable[str | GoalSpec], encoding: str = "tree",
               **options) -> list[GoalPlan]:
    """`plan` for each goal, in order (`options` as `plan`'s); a goal that names no produced node is reported.

    >>> net = load_network()
    >>> [(p.goal, str(p.status), p.reason[:20]) for p in plan_goals(net, load_kitchen(net), ["guacamole", "unicorn"])]
    [('guacamole', 'solved', ''), ('unicorn', 'unmatched', 'unknown object label')]
    """
    rows = []
    for g in goals:
        spec = _spec(g)
        try:
            rows.append(GoalPlan(spec.describe(), plan(network, kitchen, spec, encoding, **options)))
        except UsageError as exc:
            try:  # a goal that names no produced node is a row; any other usage error is the caller's
                resolve_goal(network, spec, options.get("level", 3))
            except UsageError:
                rows.append(GoalPlan(spec.describe(), None, exc.message))
                continue
            raise
    return rows


def run_experiment(out_dir: str | Path, *paths: str | Path, networks: Iterable[str] | None = None,
                   solvers: Iterable[str] | None = None, trials: int | None = None, goals: int | None = None,
                   jobs: int = 1, time_limit: float | None = None, progress: bool = False, **protocol):
    """The experiment of `foon2pddl experiment` (cells appended to OUT_DIR/results.jsonl; a rerun resumes):
    `protocol` takes `kitchen_fraction`, `seed`, `level`, `threshold`, `similarity`. Returns the run's
    summary (`experiment.runner.RunSummary`: records, cells ran and reused, seconds)."""
    from .experiment import runner
    from .experiment.config import Config
    from .experiment.protocol import Protocol
    from .experiment.setting import DEFAULT_TIME_LIMIT
    from .experiment.solvers import DEFAULT_SOLVERS, get_solver
    from .generalize.network import NETWORKS

    counts = {k: v for k, v in (("trials", trials), ("goals", goals)) if v is not None}
    nets = tuple(get_network(n).name for n in (networks if networks is not None else NETWORKS))
    chosen = tuple(get_solver(s).name for s in (solvers if solvers is not None else DEFAULT_SOLVERS))
    config = Config(tuple(str(p) for p in paths), Protocol(**counts, **protocol), nets, chosen, Path(out_dir),
                    jobs, DEFAULT_TIME_LIMIT if time_limit is None else time_limit)
    return runner.run(config, progress=progress)


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

    >>> net = load_network()
    >>> done = skill_plan(net, load_kitchen(net), "whipped cream")
    >>> done.skills.ok, [c.skill for c in done.skills.calls][:2]
    (True, ['pick', 'pour'])
    """
    from .skills import Robot, read_domain, read_table, shipped_domain, shipped_table
    from .skills.run import plan_skills

    domain = read_domain(skills) if skills is not None else shipped_domain()
    motions = read_table(table) if table is not None else shipped_table()
    motions.check(domain)
    cons = constraints if constraints is not None else Constraints()
    robot = Robot.of(hands, (*cons.without_skills, *without_skills), {**dict(cons.skill_costs), **(skill_costs or {})})
    goal = goal if isinstance(goal, Goal) else resolve_goal(network, goal, level)
    return plan_skills(_foon(network, level), kitchen, goal, encoding=encoding, domain=domain, table=motions,
                       robot=robot, constraints=cons, level=level, **options)
